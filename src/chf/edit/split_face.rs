//! The 2-6 split (1-3 on the boundary): a new vertex on a face, each tetrahedron of the
//! face cut in three.

use super::plan::{Plan, replaced};
use super::refusal::{Named, context};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::tet;
use crate::error::Result;
use glam::DVec3;

impl Chf {
    pub(super) fn plan_split_face(&self, f: u32, position: Option<DVec3>) -> Result<Plan> {
        self.check_face(f)?;
        let hf = self.face_half_face(f);
        let tri = self.half_face_vertices_of(hf);
        let (mut plan, x) = self.split_plan(position, &tri)?;
        for side in [hf, self.opposite(hf)] {
            if side == NONE {
                continue;
            }
            let q = self.tetrahedron_vertices(tet(side));
            plan.remove.push(tet(side));
            plan.add.extend(tri.iter().map(|&c| replaced(q, c, x)));
        }
        Ok(plan)
    }

    /// Splits face `f` at a new vertex (returned), at `position` or the face's centroid:
    /// its two tetrahedra become six (one becomes three on the boundary). Refused when
    /// the position is not strictly inside the face's tetrahedra union. O(1) stars.
    pub fn split_face(&mut self, f: u32, position: Option<DVec3>) -> Result<u32> {
        let plan = self.plan_split_face(f, position)?;
        self.run_split(plan, "split_face", Named("face", u64::from(f)))
    }

    /// Would [`Chf::split_face`] succeed? Changes nothing.
    pub fn check_split_face(&self, f: u32, position: Option<DVec3>) -> Result<()> {
        let plan = self.plan_split_face(f, position)?;
        self.check_plan(&plan)
            .map_err(context("split_face", Named("face", u64::from(f))))
    }
}
