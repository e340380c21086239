//! The 1-4 split: a new vertex inside a tetrahedron, joined to its four faces.

use super::plan::{Plan, Shape, context, replaced};
use crate::chf::Chf;
use crate::error::Result;
use glam::DVec3;

impl Chf {
    pub(super) fn plan_split_tetrahedron(&self, t: u32, position: Option<DVec3>) -> Result<Plan> {
        self.check_tetrahedron(t)?;
        let q = self.tetrahedron_vertices(t);
        let (mut plan, x) = self.split_plan(position, &q)?;
        plan.remove.push(t);
        plan.add.extend(q.map(|c| replaced(q, c, x)));
        plan.shape = Shape::OneToFour;
        Ok(plan)
    }

    /// Splits tetrahedron `t` in four at a new vertex (returned), at `position` or the
    /// centroid; refused when the position is not strictly inside. O(1) stars.
    pub fn split_tetrahedron(&mut self, t: u32, position: Option<DVec3>) -> Result<u32> {
        let plan = self.plan_split_tetrahedron(t, position)?;
        self.run_split(plan, "split_tetrahedron", || format!("tetrahedron {t}"))
    }

    /// Would [`Chf::split_tetrahedron`] succeed? Changes nothing.
    pub fn check_split_tetrahedron(&self, t: u32, position: Option<DVec3>) -> Result<()> {
        let plan = self.plan_split_tetrahedron(t, position)?;
        self.check_plan(plan)
            .map_err(context("split_tetrahedron", || format!("tetrahedron {t}")))
    }
}
