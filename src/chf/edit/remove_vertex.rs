//! Removing a vertex with its star.

use super::plan::Plan;
use super::refusal::{Named, context};
use crate::chf::Chf;
use crate::error::Result;
use crate::util::alloc::try_collect;

impl Chf {
    fn plan_remove_vertex(&self, v: u32) -> Result<Plan> {
        self.check_live_vertex(v)?;
        Ok(Plan {
            remove: try_collect(self.vertex_tetrahedra(v), "the star of a removed vertex")?,
            retire: vec![v],
            ..Plan::default()
        })
    }

    /// Removes vertex `v` and every tetrahedron around it; refused when that would leave
    /// a pinched vertex or edge around the hole. O(the stars of its neighbours).
    pub fn remove_vertex(&mut self, v: u32) -> Result<()> {
        let plan = self.plan_remove_vertex(v)?;
        self.run(plan)
            .map_err(context("remove_vertex", Named("vertex", u64::from(v))))?;
        Ok(())
    }

    /// Would [`Chf::remove_vertex`] succeed? Changes nothing.
    pub fn check_remove_vertex(&self, v: u32) -> Result<()> {
        let plan = self.plan_remove_vertex(v)?;
        self.check_plan(&plan)
            .map_err(context("remove_vertex", Named("vertex", u64::from(v))))
    }
}
