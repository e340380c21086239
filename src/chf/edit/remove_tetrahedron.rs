//! Removing one tetrahedron (its vertices stay, isolated if it was their last).

use super::plan::Plan;
use super::refusal::{Named, context};
use crate::chf::Chf;
use crate::error::Result;

impl Chf {
    /// Removes tetrahedron `t`; refused when that would split a vertex star or an edge
    /// fan in two (a pinch). O(the stars of its vertices).
    pub fn remove_tetrahedron(&mut self, t: u32) -> Result<()> {
        self.check_tetrahedron(t)?;
        self.run(Plan {
            remove: vec![t],
            ..Plan::default()
        })
        .map_err(context(
            "remove_tetrahedron",
            Named("tetrahedron", u64::from(t)),
        ))?;
        Ok(())
    }

    /// Would [`Chf::remove_tetrahedron`] succeed? Changes nothing.
    pub fn check_remove_tetrahedron(&self, t: u32) -> Result<()> {
        self.check_tetrahedron(t)?;
        self.verify(Plan {
            remove: vec![t],
            ..Plan::default()
        })
        .map(|_| ())
        .map_err(context(
            "remove_tetrahedron",
            Named("tetrahedron", u64::from(t)),
        ))
    }
}
