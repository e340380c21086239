//! The ring split: a new vertex on an edge, each tetrahedron around it cut in two.

use super::plan::{Plan, replaced};
use super::refusal::{Named, context};
use crate::chf::Chf;
use crate::error::Result;
use glam::DVec3;

impl Chf {
    pub(super) fn plan_split_edge(&self, e: u32, position: Option<DVec3>) -> Result<Plan> {
        self.check_live_edge(e)?;
        let [a, b] = self.edge_vertices(e);
        let (mut plan, x) = self.split_plan(position, &[a, b])?;
        for t in self.edge_tetrahedra(e) {
            let q = self.tetrahedron_vertices(t);
            plan.remove.push(t);
            plan.add.push(replaced(q, a, x));
            plan.add.push(replaced(q, b, x));
        }
        Ok(plan)
    }

    /// Splits edge `e` at a new vertex (returned), at `position` or the midpoint: each of
    /// the k tetrahedra around it becomes two. O(k) stars.
    pub fn split_edge(&mut self, e: u32, position: Option<DVec3>) -> Result<u32> {
        let plan = self.plan_split_edge(e, position)?;
        self.run_split(plan, "split_edge", Named("edge", u64::from(e)))
    }

    /// Would [`Chf::split_edge`] succeed? Changes nothing.
    pub fn check_split_edge(&self, e: u32, position: Option<DVec3>) -> Result<()> {
        let plan = self.plan_split_edge(e, position)?;
        self.check_plan(&plan)
            .map_err(context("split_edge", Named("edge", u64::from(e))))
    }
}
