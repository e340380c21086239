//! A new isolated vertex.

use super::plan::Plan;
use crate::chf::Chf;
use crate::error::{Error, Result};
use glam::DVec3;

impl Chf {
    /// Adds an isolated vertex and returns its id; `position` is required when the mesh
    /// has positions and refused when it has none. O(1) (amortised).
    pub fn add_vertex(&mut self, position: Option<DVec3>) -> Result<u32> {
        self.check_add_vertex(position)?;
        let v = self.n_vertices as u32;
        self.run(Plan {
            new_vertex: Some(position),
            ..Plan::default()
        })?;
        Ok(v)
    }

    /// Would [`Chf::add_vertex`] succeed? Changes nothing.
    pub fn check_add_vertex(&self, position: Option<DVec3>) -> Result<()> {
        if !self.positions.is_empty() && position.is_none() {
            return Err(Error::invalid(
                "the mesh has positions: a new vertex needs one",
            ));
        }
        if self.n_vertices as u64 + 1 >= crate::NONE as u64 {
            return Err(Error::too_large("the vertex ids are exhausted"));
        }
        self.new_position(position, || DVec3::ZERO).map(|_| ())
    }
}
