//! The 3-2 flip: the three tetrahedra around an interior edge become two sharing the
//! triangle of their ring.

use super::plan::{Plan, replaced};
use super::refusal::{Named, refuse, yes_or_no};
use crate::chf::Chf;
use crate::error::Result;

impl Chf {
    pub(super) fn plan_flip_32(&self, e: u32) -> Result<Plan> {
        self.check_live_edge(e)?;
        if self.is_boundary_edge(e) {
            return Err(refuse(format_args!("edge {e} is on the boundary")));
        }
        // Most edges have more than three: the walk stops at the fourth, and a refusal
        // allocates nothing (most checks of a flip storm are refusals).
        let mut around = self.edge_tetrahedra(e);
        let (mut ring, mut n) = ([0; 3], 0);
        for (r, t) in ring.iter_mut().zip(around.by_ref()) {
            *r = t;
            n += 1;
        }
        if n != 3 || around.next().is_some() {
            let more = if n == 3 { "more than " } else { "" };
            return Err(refuse(format_args!(
                "edge {e} has {more}{n} tetrahedra around it, not 3"
            )));
        }
        let [a, b] = self.edge_vertices(e);
        let q = self.tetrahedron_vertices(ring[0]);
        let far = ring[1..]
            .iter()
            .flat_map(|&t| self.tetrahedron_vertices(t))
            .find(|x| !q.contains(x))
            .expect("a closed ring of three has a third vertex");
        // The ring triangle separates `a` from `b` exactly when both new tetrahedra are
        // positive (with positions), which is what makes the union convex.
        Ok(Plan {
            remove: ring.to_vec(),
            add: vec![replaced(q, b, far), replaced(q, a, far)],
            ..Plan::default()
        })
    }

    /// Flips interior edge `e` with three tetrahedra around it (3-2); returns the two new
    /// tetrahedra. Refused on a boundary edge, another number of tetrahedra, an existing
    /// ring triangle, or, with positions, a union not strictly convex. O(1) stars.
    pub fn flip_32(&mut self, e: u32) -> Result<[u32; 2]> {
        let ids = self.run_op("flip_32", Named("edge", u64::from(e)), |c| {
            c.plan_flip_32(e)
        })?;
        Ok([ids[0], ids[1]])
    }

    /// Can edge `e` be flipped (3-2)? [`Chf::check_flip_32`] without the reason:
    /// `Ok(false)` for a refusal, `Err` for a bad or removed id. Changes nothing.
    pub fn is_flip_32_ok(&self, e: u32) -> Result<bool> {
        yes_or_no(|| self.check_flip_32(e))
    }

    /// Would [`Chf::flip_32`] succeed? Changes nothing.
    pub fn check_flip_32(&self, e: u32) -> Result<()> {
        self.check_op("flip_32", Named("edge", u64::from(e)), |c| {
            c.plan_flip_32(e)
        })
    }
}
