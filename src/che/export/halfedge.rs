//! Half-edge (DCEL) arrays, as OpenMesh, CGAL's `Surface_mesh` or a textbook DCEL hold them.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev, tri};
use crate::error::Result;
use crate::util::sparse::filled;

/// How boundary half-edges appear in [`HalfEdgeArrays`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HalfEdgeOptions {
    /// `false` (default): the `3T` half-edges of the triangles only, a boundary half-edge
    /// marked by `twin == NONE`. `true` (OpenMesh style): one extra half-edge per boundary
    /// half-edge, numbered from `3T` in the order of the boundary half-edges they twin,
    /// with `face == NONE`, linked by `next` into loops around each hole.
    pub explicit_boundary: bool,
}

/// Half-edge arrays. Half-edges `0..3T` are CHE's: `3t, 3t + 1, 3t + 2` go round
/// triangle `t` counter-clockwise.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct HalfEdgeArrays {
    /// The next half-edge round the same face (or the same hole).
    pub next: Vec<u32>,
    /// The previous half-edge round the same face (or hole).
    pub prev: Vec<u32>,
    /// The opposite half-edge: `NONE` on the boundary unless explicit.
    pub twin: Vec<u32>,
    /// The tail (origin) of each half-edge, as CHE's `V`; the head is `vertex[next[h]]`.
    pub vertex: Vec<u32>,
    /// The triangle of each half-edge, `NONE` for an explicit boundary half-edge.
    pub face: Vec<u32>,
    /// The edge of each half-edge (the ids of `Che::edge_of`).
    pub edge: Vec<u32>,
    /// One outgoing half-edge per vertex, `NONE` for an isolated vertex. On a boundary
    /// vertex the boundary one: the triangle's when marked, the hole's when explicit (as
    /// OpenMesh keeps it).
    pub vertex_half_edge: Vec<u32>,
    /// One half-edge per triangle: `3t`.
    pub face_half_edge: Vec<u32>,
}

impl Che {
    /// The half-edge arrays; see [`HalfEdgeArrays`] for the layout.
    pub fn half_edge_arrays(&self, options: HalfEdgeOptions) -> Result<HalfEdgeArrays> {
        let t = self.export_tables()?;
        let n = self.v.len();
        let boundary: Vec<u32> = (0..n as u32).filter(|&h| t.o[h as usize] == NONE).collect();
        let total = if options.explicit_boundary {
            n + boundary.len()
        } else {
            n
        };
        let mut a = HalfEdgeArrays {
            next: filled(total, NONE, "half-edge next")?,
            prev: filled(total, NONE, "half-edge prev")?,
            twin: filled(total, NONE, "half-edge twins")?,
            vertex: filled(total, NONE, "half-edge vertices")?,
            face: filled(total, NONE, "half-edge faces")?,
            edge: filled(total, NONE, "half-edge edges")?,
            vertex_half_edge: t.vh.to_vec(),
            face_half_edge: (0..self.num_triangles() as u32).map(|f| 3 * f).collect(),
        };
        for h in 0..n {
            let g = h as u32;
            a.next[h] = next(g);
            a.prev[h] = prev(g);
            a.twin[h] = t.o[h];
            a.vertex[h] = self.v[h];
            a.face[h] = tri(g);
            a.edge[h] = t.edge[h];
        }
        if options.explicit_boundary {
            self.link_boundary(&mut a, &boundary)?;
        }
        Ok(a)
    }

    /// Appends the twin `3T + k` of the `k`-th boundary half-edge `h = (u -> w)`: it runs
    /// `w -> u`, and its next is the twin of the boundary half-edge that ends at `u` (each
    /// vertex of a built CHE is one fan, so it has at most one).
    fn link_boundary(&self, a: &mut HalfEdgeArrays, boundary: &[u32]) -> Result<()> {
        let n = self.v.len() as u32;
        let mut outside_from = filled(self.n_vertices, NONE, "boundary half-edges")?;
        for (k, &h) in boundary.iter().enumerate() {
            let b = n + k as u32;
            let tail = self.v[next(h) as usize];
            a.twin[h as usize] = b;
            a.twin[b as usize] = h;
            a.vertex[b as usize] = tail;
            a.edge[b as usize] = a.edge[h as usize];
            outside_from[tail as usize] = b;
        }
        for (k, &h) in boundary.iter().enumerate() {
            let b = n + k as u32;
            let after = outside_from[self.v[h as usize] as usize];
            a.next[b as usize] = after;
            a.prev[after as usize] = b;
        }
        for (v, slot) in a.vertex_half_edge.iter_mut().enumerate() {
            if outside_from[v] != NONE {
                *slot = outside_from[v];
            }
        }
        Ok(())
    }
}
