//! The rotation around a vertex: its outgoing half-edges counter-clockwise (seen from
//! outside), starting at the outgoing boundary half-edge on a boundary vertex, then, on a
//! boundary vertex, the incoming boundary half-edge that closes the fan. No allocation.

use super::Che;
use super::ids::prev;
use crate::NONE;

/// One step of a rotation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StarStep {
    /// An outgoing half-edge `v -> w`; its triangle is in the star.
    Out(u32),
    /// On a boundary vertex, after the last outgoing half-edge: the incoming boundary
    /// half-edge `u -> v` that ends the fan (its edge and `u` are in the star too).
    LastIn(u32),
}

/// Iterator over the star of a vertex; see [`Che::vertex_star`].
#[derive(Clone, Debug)]
pub struct Rotation<'a> {
    che: &'a Che,
    /// `O` from level 1 (read directly in the loop); empty at level 0, which scans.
    o: &'a [u32],
    start: u32,
    cur: u32,
    tail: u32,
}

impl<'a> Rotation<'a> {
    pub(crate) fn new(che: &'a Che, start: u32) -> Self {
        Rotation {
            che,
            o: che.opposites().unwrap_or(&[]),
            start,
            cur: start,
            tail: NONE,
        }
    }
}

impl Iterator for Rotation<'_> {
    type Item = StarStep;

    #[inline]
    fn next(&mut self) -> Option<StarStep> {
        if self.cur != NONE {
            let h = self.cur;
            let p = prev(h);
            let around = match self.o.get(p as usize) {
                Some(&g) => g,
                None => self.che.opposite(p),
            };
            if around == NONE {
                self.cur = NONE;
                self.tail = p;
            } else if around == self.start {
                self.cur = NONE;
            } else {
                self.cur = around;
            }
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

impl std::iter::FusedIterator for Rotation<'_> {}
