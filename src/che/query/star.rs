//! The rotation around a vertex: its outgoing half-edges counter-clockwise (seen from
//! outside), starting at the outgoing boundary half-edge on a boundary vertex, then, on a
//! boundary vertex, the incoming boundary half-edge that closes the fan. No allocation.
//!
//! This is the only walk of a star in the crate: [`StarCursor`] holds its state as plain
//! data, and the Rust iterator ([`Rotation`]), the bulk sweeps and the C API's star
//! iterator all step it.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev, tri};
use std::borrow::Cow;

/// One step of a rotation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StarStep {
    /// An outgoing half-edge `v -> w`; its triangle is in the star.
    Out(u32),
    /// On a boundary vertex, after the last outgoing half-edge: the incoming boundary
    /// half-edge `u -> v` that ends the fan (its edge and `u` are in the star too).
    LastIn(u32),
}

impl StarStep {
    /// The half-edge of the step (outgoing, or the closing incoming one).
    #[inline(always)]
    pub fn half_edge(self) -> u32 {
        match self {
            StarStep::Out(h) | StarStep::LastIn(h) => h,
        }
    }
}

/// The state of a rotation, independent of where `O` is read from. `repr(C)` because the
/// C API's iterator embeds it (its layout is mirrored in `topomesh_inline.h`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StarCursor {
    /// The first outgoing half-edge (`VH[v]`), `NONE` for an isolated vertex.
    pub start: u32,
    /// The next outgoing half-edge to yield, `NONE` once they are all out.
    pub cur: u32,
    /// The incoming boundary half-edge still to yield, else `NONE`.
    pub tail: u32,
}

impl StarCursor {
    /// A rotation from the outgoing half-edge `start` (`NONE`: no steps).
    #[inline]
    pub fn new(start: u32) -> Self {
        StarCursor {
            start,
            cur: start,
            tail: NONE,
        }
    }

    /// The rule of the rotation: after the outgoing half-edge `cur`, whose previous
    /// half-edge `p` has the opposite `around`, comes `around`, unless it is the boundary
    /// (then the closing step `p`) or the start again (then the end).
    #[inline(always)]
    fn turn(&mut self, p: u32, around: u32) {
        if around == NONE {
            self.cur = NONE;
            self.tail = p;
        } else if around == self.start {
            self.cur = NONE;
        } else {
            self.cur = around;
        }
    }

    /// The next step; `opposite(p)` answers `O[p]`.
    #[inline(always)]
    pub fn step(&mut self, opposite: impl FnOnce(u32) -> u32) -> Option<StarStep> {
        if self.cur != NONE {
            let h = self.cur;
            let p = prev(h);
            self.turn(p, opposite(p));
            return Some(StarStep::Out(h));
        }
        if self.tail != NONE {
            let t = self.tail;
            self.tail = NONE;
            return Some(StarStep::LastIn(t));
        }
        None
    }
}

/// Every step of the rotation from `start` over a table of opposites: the steps of
/// [`StarCursor::step`], as one loop for the sweeps.
#[inline(always)]
pub(crate) fn for_each_step(o: &[u32], start: u32, mut f: impl FnMut(StarStep)) {
    let mut c = StarCursor::new(start);
    while c.cur != NONE {
        let h = c.cur;
        f(StarStep::Out(h));
        let p = prev(h);
        c.turn(p, o[p as usize]);
    }
    if c.tail != NONE {
        f(StarStep::LastIn(c.tail));
    }
}

/// The VV entry of a step over `V`: the far end of an outgoing half-edge, the near end of
/// the closing incoming one.
#[inline(always)]
pub(crate) fn vv_item(v: &[u32], s: StarStep) -> u32 {
    match s {
        StarStep::Out(h) => v[next(h) as usize],
        StarStep::LastIn(h) => v[h as usize],
    }
}

impl Che {
    /// The VE entry of a step: the edge of its half-edge.
    #[inline(always)]
    pub(crate) fn ve_item(&self, s: StarStep) -> u32 {
        match s {
            StarStep::Out(h) | StarStep::LastIn(h) => self.edge_of(h),
        }
    }
}

/// The VF entry of a step: the triangle of an outgoing half-edge (none for the closing one).
#[inline(always)]
pub(crate) fn vf_item(s: StarStep) -> Option<u32> {
    match s {
        StarStep::Out(h) => Some(tri(h)),
        StarStep::LastIn(_) => None,
    }
}

/// Iterator over the star of a vertex; see [`Che::vertex_star`].
#[derive(Clone, Debug)]
pub struct Rotation<'a> {
    /// `O`: borrowed from level 1, computed for this rotation at level 0.
    o: Cow<'a, [u32]>,
    cursor: StarCursor,
}

impl<'a> Rotation<'a> {
    pub(crate) fn new(o: Cow<'a, [u32]>, start: u32) -> Self {
        Rotation {
            o,
            cursor: StarCursor::new(start),
        }
    }
}

impl Iterator for Rotation<'_> {
    type Item = StarStep;

    #[inline]
    fn next(&mut self) -> Option<StarStep> {
        let o: &[u32] = &self.o;
        self.cursor.step(|p| o[p as usize])
    }
}

impl std::iter::FusedIterator for Rotation<'_> {}
