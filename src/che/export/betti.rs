//! Betti numbers over Z/2 of the surface as given: the kept triangles over the input
//! vertices, so that what the build split apart counts joined again (a seam of a
//! Moebius strip, a vertex where two cones touch, the triangles of a non-manifold edge).

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, tri};
use crate::error::Result;
use crate::util::alloc::{try_collect, try_push, try_with_capacity};
use crate::util::betti::{Grounded, column_rank};
use crate::util::dsu::element_components;

impl Che {
    /// `[b0, b1, b2]` over Z/2 of the input complex: every input vertex (an isolated one
    /// is a component), the distinct vertex pairs of the kept triangles as edges, the kept
    /// triangles. `b0 - b1 + b2` is the Euler characteristic of `Che::summary`.
    ///
    /// Near-linear: `rank d1` is the vertex count minus the components (a union-find);
    /// `rank d2` comes from a union-find over the triangles across the edges with two
    /// triangles, where an edge with one grounds its component, and a column reduction
    /// only over what the edges with three or more triangles (non-manifold input) leave.
    pub fn betti_numbers(&self) -> Result<[u64; 3]> {
        self.check_collected("the Betti numbers")?;
        let n_in = self.n_input_vertices;
        let (used, isolated) = element_components::<3>(&self.v, n_in, |x| self.vertex_origin(x))?;
        let b0 = used + isolated;
        let rank1 = n_in as u64 - b0;
        let o = self.try_opposites_or_computed()?;
        let special = self.rejoined_edges()?;
        let n_edges = (self.num_edges - special.len() + distinct_pairs(&special)) as u64;
        let rank2 = self.rank_d2(&o, &special)? as u64;
        let nt = self.num_triangles() as u64;
        Ok([b0, n_edges - rank1 - rank2, nt - rank2])
    }

    /// The unpaired half-edges that share an input edge with others (seams and
    /// non-manifold edges), as `(input vertex pair, half-edge)` sorted by pair.
    fn rejoined_edges(&self) -> Result<Vec<((u32, u32), u32)>> {
        let edges = self.seams.iter().chain(&self.non_manifold).map(|&h| {
            let a = self.vertex_origin(self.v[h as usize]);
            let b = self.vertex_origin(self.v[next(h) as usize]);
            ((a.min(b), a.max(b)), h)
        });
        let mut out = try_collect(edges, "the rejoined edges")?;
        out.sort_unstable();
        Ok(out)
    }

    /// The rank of `d2` of the input complex over Z/2.
    fn rank_d2(&self, o: &[u32], special: &[((u32, u32), u32)]) -> Result<usize> {
        let nt = self.num_triangles();
        let mut by_half_edge = try_collect(special.iter().map(|s| s.1), "the rejoined edges")?;
        by_half_edge.sort_unstable();
        let lone = |h: u32| by_half_edge.binary_search(&h).is_ok();
        let mut wide: Vec<Vec<u32>> = Vec::new();
        let lines = o.iter().enumerate().filter_map(|(h, &g)| {
            let h = h as u32;
            let line = (tri(h), if g == NONE { NONE } else { tri(g) });
            (!lone(h) && (g == NONE || g > h)).then_some(line)
        });
        let mut lines = try_collect(lines, "the dual graph")?;
        for group in special.chunk_by(|a, b| a.0 == b.0) {
            match group {
                [(_, h)] => try_push(&mut lines, (tri(*h), NONE), "the dual graph")?,
                [(_, h), (_, g)] => try_push(&mut lines, (tri(*h), tri(*g)), "the dual graph")?,
                _ => {
                    let row = try_collect(group.iter().map(|s| tri(s.1)), "the wide rows")?;
                    try_push(&mut wide, row, "the wide rows")?;
                }
            }
        }
        let mut graph = Grounded::new(nt, lines.into_iter())?;
        let rank = graph.rank();
        if wide.is_empty() {
            return Ok(rank);
        }
        Ok(rank + wide_rank(&mut graph, nt, &wide)?)
    }
}

/// What the rows with three or more triangles add to the rank: the kernel of the graph
/// rows is spanned by the components that reach no ground, so the rank grows by the rank
/// of the wide rows restricted to those components (each row's parity in each).
fn wide_rank(graph: &mut Grounded, nt: usize, wide: &[Vec<u32>]) -> Result<usize> {
    let mut columns = try_with_capacity(wide.len(), "the wide rows")?;
    for row in wide {
        let free = row.iter().filter_map(|&t| graph.free_root(t));
        let mut free = try_collect(free, "a wide row")?;
        free.sort_unstable();
        // Triangles of one component cancel in pairs over Z/2.
        let odd = free.chunk_by(|a, b| a == b).filter(|c| c.len() % 2 == 1);
        columns.push(try_collect(odd.map(|c| c[0]), "a wide row")?);
    }
    // The rows of the restricted matrix as the columns of its transpose: the same rank.
    column_rank(nt, columns.into_iter())
}

/// The number of distinct pairs in a list sorted by pair.
fn distinct_pairs(special: &[((u32, u32), u32)]) -> usize {
    special.chunk_by(|a, b| a.0 == b.0).count()
}
