//! A new tetrahedron over existing vertices, paired with the boundary half-faces it
//! matches.

use super::plan::Plan;
use super::refusal::{Corners, context};
use crate::chf::Chf;
use crate::chf::geometry::orient_of;
use crate::error::Result;

impl Chf {
    /// The plan of [`Chf::add_tetrahedron`]: oriented by the determinant when the mesh has
    /// positions, else by the faces it pairs with (the given order if it pairs with none).
    fn plan_add_tetrahedron(&self, q: [u32; 4]) -> Result<Plan> {
        for x in q {
            self.check_live_vertex(x)?;
        }
        let mut q = q;
        let flipped = [q[0], q[1], q[3], q[2]];
        if !self.positions.is_empty() {
            if orient_of(q, |x| self.positions[x as usize]) < 0.0 {
                q = flipped;
            }
        } else if self.meets_a_face_the_same_way(q)? && self.verify(one(flipped)).is_ok() {
            // Turned over only when that makes it fit: a refusal for any other reason
            // stays the refusal of the order given.
            q = flipped;
        }
        Ok(one(q))
    }

    /// Adds tetrahedron `q` (any vertex order) and returns its id. Refused (with the
    /// reason) when a face would have three tetrahedra or two running the same way, a
    /// vertex star or an edge fan would fall apart, or it is flat. O(the stars of `q`).
    pub fn add_tetrahedron(&mut self, q: [u32; 4]) -> Result<u32> {
        let ids = self.run_op("add_tetrahedron", Corners(q), |c| c.plan_add_tetrahedron(q))?;
        Ok(ids[0])
    }

    /// Would [`Chf::add_tetrahedron`] succeed? Changes nothing.
    pub fn check_add_tetrahedron(&self, q: [u32; 4]) -> Result<()> {
        let plan = self.plan_add_tetrahedron(q)?;
        self.check_plan(&plan)
            .map_err(context("add_tetrahedron", Corners(q)))
    }
}

fn one(q: [u32; 4]) -> Plan {
    Plan {
        add: vec![q],
        ..Plan::default()
    }
}
