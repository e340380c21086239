//! The invariants of every level, checked: [`Che::validate`] returns the first violation
//! with the element and what is wrong. O(T) time and memory.

mod named;
mod sweep;

use crate::NONE;
use crate::che::Che;
use crate::che::ids::tri;
use crate::che::tables::is_canonical;
use crate::error::{Error, Result};
use crate::util::alloc::try_vec;
use crate::util::origin::increasing_below_violation;

/// A violation: an invalid-input error naming the element.
fn broken(what: String) -> Result<()> {
    Err(Error::invalid(format!("invalid CHE: {what}")))
}

/// `Err` unless `xs` increases strictly and stays below `n`.
fn increasing_below(xs: &[u32], n: usize, name: &str) -> Result<()> {
    increasing_below_violation(xs, n, name).map_or(Ok(()), broken)
}

impl Che {
    /// Checks every invariant of the current level: `V` (ids in range, no degenerate
    /// triangle), `O` (an involution pairing half-edges on the same vertex pair run the
    /// other way, none on a non-manifold or seam half-edge), `VH` (one outgoing half-edge
    /// per vertex, the boundary one on a boundary vertex, whose rotation reaches all of
    /// them), the edge directory and `EH`, and the boundary curves. The first violation
    /// is an `InvalidInput` error naming the element.
    pub fn validate(&self) -> Result<()> {
        if self.edits().is_some() {
            return self.validate_edited();
        }
        self.validate_v()?;
        self.validate_maps()?;
        if self.level >= 2 {
            self.validate_o_and_vh()?;
            self.validate_edges()?;
        } else if self.level == 1 {
            self.validate_o()?;
        } else {
            // Level 0 stores no `O`, but its edge count must match the rule's pairs, which
            // the edge queries enumerate.
            self.validate_edge_count(&self.try_opposites_or_computed()?)?;
        }
        if self.level >= 3 {
            self.validate_curves()?;
        }
        Ok(())
    }

    /// The origin maps, which the summary and the queries use as indices.
    fn validate_maps(&self) -> Result<()> {
        let n_input = self.n_input_vertices;
        if let Some(what) = self
            .vertex_origin
            .vertex_violation(self.n_vertices, n_input)
        {
            return broken(what);
        }
        let n_tris = self.num_triangles();
        let tris = &self.triangle_origin;
        if !tris.is_empty() && tris.len() != n_tris {
            return broken(format!(
                "{} triangle origins for {n_tris} triangles",
                tris.len()
            ));
        }
        let n_input_tris = self.report.input_triangles.max(n_tris);
        increasing_below(tris, n_input_tris, "triangle origin")
    }

    fn validate_v(&self) -> Result<()> {
        if !self.v.len().is_multiple_of(3) {
            return broken(format!(
                "V has {} entries, not 3 per triangle",
                self.v.len()
            ));
        }
        if !sweep::triangles_hold(&self.v, self.n_vertices) {
            return broken(self.first_v_violation().unwrap_or_else(|| {
                "V holds a triangle that is not three distinct vertices".into()
            }));
        }
        increasing_below(&self.non_manifold, self.v.len(), "non-manifold half-edge")?;
        increasing_below(&self.seams, self.v.len(), "seam half-edge")
    }

    pub(crate) fn validate_o(&self) -> Result<()> {
        let (v, o) = (&self.v, &self.o);
        if o.len() != v.len() {
            return broken(format!(
                "O has {} entries for {} half-edges",
                o.len(),
                v.len()
            ));
        }
        let edges = match sweep::pairs_hold(v, o) {
            Some(edges) => edges,
            None => {
                let what = self.first_o_violation();
                return broken(what.unwrap_or_else(|| "O breaks the pairing".into()));
            }
        };
        self.validate_flagged()?;
        self.validate_paired_edges(edges)
    }

    /// `O` and `VH` of a mesh with no removed triangle, in one walk of the stars
    /// ([`sweep::stars_hold`]); on a violation the passes of their own name it.
    fn validate_o_and_vh(&self) -> Result<()> {
        let (v, o, vh) = (&self.v, &self.o, &self.vh);
        let sizes_hold = o.len() == v.len() && vh.len() == self.n_vertices;
        let Some(unpaired) = sizes_hold.then(|| sweep::stars_hold(v, o, vh)).flatten() else {
            self.validate_o()?;
            self.validate_vh()?;
            return broken("O and VH fail the walk of the stars".into());
        };
        self.validate_flagged()?;
        // Each paired half-edge shares its edge with one other, each unpaired one not.
        self.validate_paired_edges((v.len() + unpaired) / 2)
    }

    /// `edges`, the edges `O` pairs, is the count.
    fn validate_paired_edges(&self, edges: usize) -> Result<()> {
        if edges != self.num_live_edges() {
            return broken(format!(
                "{edges} edges in O, {} counted",
                self.num_live_edges()
            ));
        }
        Ok(())
    }

    /// The half-edges flagged non-manifold or seams: live, and unpaired.
    fn validate_flagged(&self) -> Result<()> {
        let (v, o) = (&self.v, &self.o);
        for &h in self.non_manifold.iter().chain(&self.seams) {
            if v.get(h as usize).is_none_or(|&x| x == NONE) {
                return broken(format!("flagged half-edge {h} is out of range or removed"));
            }
            if o[h as usize] != NONE {
                return broken(format!(
                    "half-edge {h} is flagged unpaired but O[{h}] = {}",
                    o[h as usize]
                ));
            }
        }
        Ok(())
    }

    /// The live edges of `o` (the canonical half-edges of live triangles) are the count.
    fn validate_edge_count(&self, o: &[u32]) -> Result<()> {
        let v = &self.v;
        let edges = (0..o.len())
            .filter(|&h| v[h] != NONE && is_canonical(o, h))
            .count();
        if edges != self.num_live_edges() {
            return broken(format!(
                "{edges} edges in O, {} counted",
                self.num_live_edges()
            ));
        }
        Ok(())
    }

    pub(crate) fn validate_vh(&self) -> Result<()> {
        let (v, o, vh) = (&self.v, &self.o, &self.vh);
        if vh.len() != self.n_vertices {
            return broken(format!(
                "VH has {} entries for {} vertices",
                vh.len(),
                self.n_vertices
            ));
        }
        let live = self.edits().map_or(v.len(), |st| 3 * st.live_triangles);
        if sweep::rotations_cover(v, o, vh, live) {
            return Ok(());
        }
        let what = self.first_vh_violation()?;
        broken(what.unwrap_or_else(|| "the rotations from VH do not cover the half-edges".into()))
    }

    /// Whether the rotations from `vh` over `o` meet `live` live outgoing half-edges, each
    /// vertex's all of them from its boundary one (the `VH` rules), `o` checked before.
    pub(crate) fn rotations_cover(&self, o: &[u32], vh: &[u32], live: usize) -> bool {
        vh.len() == self.n_vertices && sweep::rotations_cover(&self.v, o, vh, live)
    }

    fn validate_edges(&self) -> Result<()> {
        let o = &self.o;
        if self.eh.len() != self.num_edges || self.edge_bits.ones() != self.num_edges {
            return broken(format!(
                "EH has {} entries and the directory {} edges, for {} edges",
                self.eh.len(),
                self.edge_bits.ones(),
                self.num_edges
            ));
        }
        if sweep::edge_directory_holds(o, &self.eh, self.edge_bits.entries()) {
            return Ok(());
        }
        broken(
            self.first_edge_violation()
                .unwrap_or_else(|| "EH does not list the canonical half-edges in order".into()),
        )
    }

    fn validate_curves(&self) -> Result<()> {
        let o = &self.o;
        if let Some(h) = (0..o.len()).find(|&h| self.boundary_bits.get(h) != (o[h] == NONE)) {
            return broken(format!("the boundary bits flag half-edge {h} wrongly"));
        }
        let mut seen = try_vec(self.curve_of.len(), false, "the curve marks")?;
        for (c, &start) in self.ch.iter().enumerate() {
            if start as usize >= o.len() || o[start as usize] != NONE {
                return broken(format!("CH[{c}] = {start} is not a boundary half-edge"));
            }
            for h in self.try_boundary_curve(start)? {
                if h < start {
                    return broken(format!(
                        "CH[{c}] = {start} is not the smallest half-edge of its curve ({h} is)"
                    ));
                }
                let r = self.boundary_bits.rank(h as usize);
                if self.curve_of[r] != c as u32 || seen[r] {
                    return broken(format!(
                        "boundary half-edge {h} (curve {c}, triangle {}) is filed as curve {}",
                        tri(h),
                        self.curve_of[r]
                    ));
                }
                seen[r] = true;
            }
        }
        if let Some(r) = seen.iter().position(|&s| !s) {
            return broken(format!(
                "boundary half-edge number {r} is on no curve of CH"
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::NONE;
    use crate::che::{BuildOptions, Che};

    /// A fan of 5 triangles around vertex 0 (open), plus a closed tetrahedron.
    fn mesh(level: u8) -> Che {
        let tris = [
            0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 7, 9, 8, 7, 8, 10, 7, 10, 9, 8, 9, 10,
        ];
        Che::from_flat(&tris, 11, &[], BuildOptions::level(level)).unwrap()
    }

    fn fails(che: &Che, what: &str) {
        let e = che.validate().unwrap_err();
        assert!(e.message.contains(what), "{what}: {}", e.message);
    }

    #[test]
    fn every_level_is_valid() {
        for level in 0..=3 {
            mesh(level).validate().unwrap();
        }
    }

    #[test]
    fn each_invariant_fails_when_its_array_is_corrupted() {
        let mut c = mesh(3);
        c.v.to_mut("test").unwrap()[4] = 99;
        fails(&c, "is not a vertex");
        let mut c = mesh(3);
        c.v.to_mut("test").unwrap()[1] = c.v[0];
        fails(&c, "degenerate");
        let mut c = mesh(3);
        c.o.to_mut("test").unwrap().swap(1, 2);
        fails(&c, "not an involution");
        let mut c = mesh(3);
        let t = *c.o.iter().find(|&&g| g != NONE).unwrap() as usize / 3;
        c.v.to_mut("test").unwrap().swap(3 * t + 1, 3 * t + 2);
        fails(&c, "same vertex pair");
        let mut c = mesh(3);
        c.non_manifold = vec![c.o.iter().position(|&g| g != NONE).unwrap() as u32];
        fails(&c, "flagged unpaired");
        let mut c = mesh(3);
        assert_eq!(c.vh[0], 0);
        c.vh.to_mut("test").unwrap()[0] = 3;
        fails(&c, "not the boundary half-edge");
        let mut c = mesh(3);
        c.vh.to_mut("test").unwrap()[0] = 1;
        fails(&c, "does not start at vertex 0");
        let mut c = mesh(3);
        c.edge_bits = crate::util::rank_directory::RankDirectory::from_fn(27, |h| h < 20).unwrap();
        fails(&c, "EH has");
        let mut c = mesh(3);
        c.vh.to_mut("test").unwrap()[1] = NONE;
        fails(&c, "VH[1] is NONE");
        let mut c = mesh(3);
        c.eh.to_mut("test").unwrap().swap(0, 1);
        fails(&c, "EH[0]");
        let mut c = mesh(3);
        c.curve_of.to_mut("test").unwrap()[0] = 5;
        fails(&c, "is filed as curve");
        let mut c = mesh(3);
        c.ch.to_mut("test").unwrap()[0] = 1;
        fails(&c, "CH[0]");
    }

    /// Level 0 stores no edge table, yet its edge queries enumerate the edges up to the
    /// stated count: a level file stating more (the `levelfile` fuzz target found one with
    /// 2048 edges for 4 triangles) would send them past the arrays.
    #[test]
    fn the_edge_count_is_checked_at_level_0() {
        let mut c = mesh(0);
        c.num_edges += 1;
        fails(&c, "edges in O");
    }

    /// The maps the summary indexes by: a level file can state them wrongly (the `levelfile`
    /// fuzz target found a file with 0 input vertices for 5 vertices and no origin map,
    /// whose summary indexed past its marks).
    #[test]
    fn origin_maps_are_checked() {
        let mut c = mesh(0);
        c.n_input_vertices = 0;
        fails(&c, "no vertex origins for 11 copies");
        let mut c = mesh(1);
        c.n_input_vertices = 12;
        fails(&c, "fewer than the 12 input vertices");
        let mut c = mesh(2);
        c.n_input_vertices = 10;
        c.vertex_origin = (0..11).collect::<Vec<u32>>().into();
        fails(&c, "vertex 10 has origin 10");
        let mut c = mesh(2);
        c.vertex_origin = vec![0; 3].into();
        fails(&c, "3 vertex origins for 11 vertices");
        let mut c = mesh(3);
        c.triangle_origin = vec![0, 1, 2, 3, 4, 5, 6, 8, 7].into();
        fails(&c, "triangle origin[8] = 7 does not increase");
        let mut c = mesh(3);
        c.seams = vec![5, 3];
        fails(&c, "seam half-edge[1] = 3 does not increase");
        let mut c = mesh(3);
        c.non_manifold = vec![c.v.len() as u32];
        fails(&c, "non-manifold half-edge[0] = 27 is not below 27");
    }
}
