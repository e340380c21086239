//! The summary and the checks of an edited CHE: the live elements only, as a fresh build of
//! the live triangles would report them (the build's repairs are history by then).

use crate::NONE;
use crate::che::Che;
use crate::che::Summary;
use crate::che::ids::{next, tri};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_vec};
use crate::util::dsu::{BoundaryMarks, Dsu};
use crate::util::live_ranks::LiveRanks;

impl Che {
    /// [`Che::try_summary`] of an edited CHE.
    pub(crate) fn edited_summary(&self) -> Result<Summary> {
        let st = self.edits().expect("an edited CHE");
        let o = self.try_opposites_or_computed()?;
        let n = self.n_vertices;
        let mut used = try_vec(n, false, "the summary's vertex marks")?;
        let mut dsu = Dsu::new(n)?;
        for c in self.v.chunks_exact(3).filter(|c| c[0] != NONE) {
            c.iter().for_each(|&x| used[x as usize] = true);
            dsu.union(c[0], c[1]);
            dsu.union(c[1], c[2]);
        }
        let components = dsu.roots_among(&used);
        let isolated = (st.live_vertices - used.iter().filter(|&&u| u).count()) as u64;
        // Unpaired half-edges by vertex pair: one of a pair is on the boundary, two a seam,
        // more a non-manifold edge.
        let unpaired = (0..self.v.len())
            .filter(|&h| self.v[h] != NONE && o[h] == NONE)
            .map(|h| {
                let (a, b) = (self.v[h], self.v[next(h as u32) as usize]);
                (a.min(b), a.max(b))
            });
        let mut unpaired = try_collect(unpaired, "the unpaired half-edges")?;
        unpaired.sort_unstable();
        let paired = (0..o.len())
            .filter(|&h| o[h] != NONE && (h as u32) < o[h])
            .count();
        let (mut edges, mut boundary_edges, mut non_manifold_edges) = (paired as u64, 0u64, 0u64);
        let mut boundary = BoundaryMarks::new(n)?;
        for group in unpaired.chunk_by(|x, y| x == y) {
            edges += 1;
            match group.len() {
                1 => {
                    let (a, b) = group[0];
                    boundary_edges += 1;
                    boundary.edge(a, b);
                }
                2 => {}
                _ => non_manifold_edges += 1,
            }
        }
        let boundary_curves = boundary.components();
        let seam_roots = self.seams.iter().map(|&h| dsu.find(self.v[h as usize]));
        let mut seam_roots = try_collect(seam_roots, "the seams' components")?;
        seam_roots.sort_unstable();
        seam_roots.dedup();
        Ok(Summary {
            vertices: st.live_vertices as u64,
            edges,
            triangles: st.live_triangles as u64,
            boundary_edges,
            boundary_curves,
            components,
            isolated_vertices: isolated,
            orientable: seam_roots.is_empty(),
            manifold: non_manifold_edges == 0,
            non_manifold_edges,
            non_orientable_components: seam_roots.len() as u64,
            ..Summary::default()
        }
        .with_genus())
    }

    /// [`Che::validate`] of an edited CHE: the invariants over the live elements, plus the
    /// edit state's counts, ids and curves.
    pub(crate) fn validate_edited(&self) -> Result<()> {
        let broken = |what: String| Err(Error::invalid(format!("invalid CHE: {what}")));
        let st = self.edits().expect("an edited CHE");
        let nt = self.num_triangles();
        let mut live_t = 0;
        for (t, c) in self.v.chunks_exact(3).enumerate() {
            match c.iter().filter(|&&x| x == NONE).count() {
                3 => continue,
                0 => live_t += 1,
                _ => return broken(format!("triangle {t} is partly removed ({c:?})")),
            }
            if let Some(&x) = c.iter().find(|&&x| x as usize >= self.n_vertices) {
                return broken(format!(
                    "triangle {t} names vertex {x} (of {})",
                    self.n_vertices
                ));
            }
            if let Some(&x) = c.iter().find(|&&x| st.removed_vertex[x as usize]) {
                return broken(format!("triangle {t} names removed vertex {x}"));
            }
            if c[0] == c[1] || c[1] == c[2] || c[0] == c[2] {
                return broken(format!("triangle {t} is degenerate ({c:?})"));
            }
        }
        let live_v = st.removed_vertex.count_clear();
        if live_t != st.live_triangles || live_v != st.live_vertices || nt * 3 != self.v.len() {
            return broken(format!(
                "{live_t} live triangles and {live_v} live vertices, {} and {} counted",
                st.live_triangles, st.live_vertices
            ));
        }
        if st.removed_vertex.len() != self.n_vertices {
            return broken("the removed-vertex flags do not cover the vertices".into());
        }
        if self.level >= 1 {
            self.validate_o()?;
        } else {
            let o = self.live_opposites()?;
            let edges = (0..o.len())
                .filter(|&h| self.is_live_canonical(&o, h))
                .count();
            if edges != st.live_edges || edges != self.num_edges {
                return broken(format!("{edges} edges, {} counted", st.live_edges));
            }
            self.validate_kept_o(&o)?;
        }
        if self.level < 2 {
            self.validate_kept_vh()?;
            self.validate_edge_ranks()?;
        }
        if self.level >= 2 {
            self.validate_vh()?;
            self.validate_edited_edges()?;
        }
        if self.level >= 3 {
            self.validate_edited_curves()?;
        }
        Ok(())
    }

    /// The `O` the edits keep at level 0 is the level-0 rule's `o` of the live triangles,
    /// which the queries of a mesh never edited compute.
    fn validate_kept_o(&self, o: &[u32]) -> Result<()> {
        let Some(kept) = self.kept_opposites() else {
            return Ok(());
        };
        match (0..o.len()).find(|&h| kept.get(h) != Some(&o[h])) {
            Some(h) => Err(Error::invalid(format!(
                "invalid CHE: the kept O[{h}] = {:?}, the rule pairs {}",
                kept.get(h),
                o[h]
            ))),
            None if kept.len() != o.len() => Err(Error::invalid(format!(
                "invalid CHE: the kept O has {} entries for {} half-edges",
                kept.len(),
                o.len()
            ))),
            None => Ok(()),
        }
    }

    /// The `VH` the edits keep below level 2 follows the rules of level 2's.
    fn validate_kept_vh(&self) -> Result<()> {
        let Some(vh) = self.kept_vertex_half_edges() else {
            return Ok(());
        };
        let o = self.try_opposites_or_computed()?;
        let live = 3 * self.st().live_triangles;
        if self.rotations_cover(&o, vh, live) {
            return Ok(());
        }
        Err(Error::invalid(
            "invalid CHE: the rotations from the kept VH do not cover the half-edges",
        ))
    }

    /// The live edges' counts kept below level 2 are those of the live edges now.
    fn validate_edge_ranks(&self) -> Result<()> {
        let Some(ranks) = self.st().edge_ranks.as_ref() else {
            return Ok(());
        };
        let o = self.try_opposites_or_computed()?;
        let fresh = LiveRanks::new(o.len(), |h| self.is_live_canonical(&o, h))?;
        if ranks.same_counts(&fresh) {
            return Ok(());
        }
        Err(Error::invalid(
            "invalid CHE: the kept counts of live edges are not the live edges'",
        ))
    }

    fn validate_edited_edges(&self) -> Result<()> {
        let broken = |what: String| Err(Error::invalid(format!("invalid CHE: {what}")));
        let o = &self.o;
        if self.eh.len() != self.num_edges {
            return broken(format!(
                "EH has {} entries, {} edge ids",
                self.eh.len(),
                self.num_edges
            ));
        }
        let mut live = 0;
        for (e, &h) in self.eh.iter().enumerate() {
            if h == NONE {
                continue;
            }
            live += 1;
            if h as usize >= o.len()
                || !self.is_live_canonical(o, h as usize)
                || self.edge_of(h) != e as u32
            {
                return broken(format!(
                    "EH[{e}] = {h} is not the canonical half-edge of edge {e}"
                ));
            }
        }
        if live != self.st().live_edges {
            return broken(format!(
                "{live} edges in EH, {} counted",
                self.st().live_edges
            ));
        }
        for h in (0..o.len() as u32).filter(|&h| self.v[h as usize] != NONE) {
            let e = self.edge_of(h);
            let c = if o[h as usize] != NONE && o[h as usize] < h {
                o[h as usize]
            } else {
                h
            };
            if e as usize >= self.eh.len() || self.eh[e as usize] != c {
                return broken(format!(
                    "half-edge {h} (triangle {}) names edge {e} wrongly",
                    tri(h)
                ));
            }
        }
        Ok(())
    }

    fn validate_edited_curves(&self) -> Result<()> {
        let curves = self.try_edited_curves()?;
        let boundary = (0..self.v.len())
            .filter(|&h| self.v[h] != NONE && self.o[h] == NONE)
            .count();
        let mut walked = 0;
        for &s in curves.ch.iter() {
            walked += self.try_boundary_curve(s)?.count();
        }
        if walked != boundary || curves.boundary.len() != boundary {
            return Err(Error::invalid(format!(
                "invalid CHE: the curves walk {walked} of {boundary} boundary half-edges"
            )));
        }
        Ok(())
    }
}
