//! The 2-3 flip: the two tetrahedra of an interior face become three around the edge
//! joining their apexes.

use super::plan::{Plan, replaced};
use super::refusal::{Named, refuse, yes_or_no};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{local, tet};
use crate::error::Result;

impl Chf {
    pub(super) fn plan_flip_23(&self, f: u32) -> Result<Plan> {
        self.check_face(f)?;
        let hf = self.face_half_face(f);
        let g = self.opposite(hf);
        if g == NONE {
            return Err(refuse(format_args!("face {f} is on the boundary")));
        }
        let q = self.tetrahedron_vertices(tet(hf));
        let apex = self.tetrahedron_vertices(tet(g))[local(g) as usize];
        let tri = self.half_face_vertices_of(hf);
        // With positions, the three new tetrahedra are positive exactly when the union
        // is convex across the face (the segment between the apexes crosses it).
        Ok(Plan {
            remove: vec![tet(hf), tet(g)],
            add: tri.iter().map(|&c| replaced(q, c, apex)).collect(),
            ..Plan::default()
        })
    }

    /// Flips interior face `f` (2-3); returns the three new tetrahedra. Refused on a
    /// boundary face, when the edge between the apexes exists already, or, with
    /// positions, when the union of the two tetrahedra is not strictly convex there (a
    /// new tetrahedron would be flat or inverted). O(1) stars.
    pub fn flip_23(&mut self, f: u32) -> Result<[u32; 3]> {
        let ids = self.run_op("flip_23", Named("face", u64::from(f)), |c| {
            c.plan_flip_23(f)
        })?;
        Ok([ids[0], ids[1], ids[2]])
    }

    /// Can face `f` be flipped (2-3)? [`Chf::check_flip_23`] without the reason, as
    /// [`crate::Che::is_flip_ok`]: `Ok(false)` for a refusal (worded by nothing, so cheaper
    /// to ask), `Err` for a bad or removed id. Changes nothing.
    pub fn is_flip_23_ok(&self, f: u32) -> Result<bool> {
        yes_or_no(|| self.check_flip_23(f))
    }

    /// Would [`Chf::flip_23`] succeed? Changes nothing.
    pub fn check_flip_23(&self, f: u32) -> Result<()> {
        self.check_op("flip_23", Named("face", u64::from(f)), |c| {
            c.plan_flip_23(f)
        })
    }
}
