//! Boundary curves at every level: stored at level 3, walked from `VH` at level 2, found
//! by scanning below. A curve is the cycle of boundary half-edges `h -> VH[target(h)]`.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::next;
use crate::error::{Error, Result};
use crate::util::alloc::{or_panic, try_collect, try_push, try_vec};
use std::borrow::Cow;

/// The half-edges of one boundary curve, in order (the interior on the left).
#[derive(Clone, Debug)]
pub struct BoundaryWalk<'a> {
    che: &'a Che,
    /// `O`, borrowed from level 1, computed for the walk at level 0: below level 2 the
    /// next boundary half-edge is found by a rotation around the target.
    o: Cow<'a, [u32]>,
    start: u32,
    cur: u32,
}

impl Iterator for BoundaryWalk<'_> {
    type Item = u32;
    fn next(&mut self) -> Option<u32> {
        let h = self.cur;
        if h == NONE {
            return None;
        }
        let g = self.che.next_boundary(&self.o, h);
        self.cur = if g == self.start { NONE } else { g };
        Some(h)
    }
}

impl Che {
    /// The first half-edge of every boundary curve, in increasing order. Borrowed at
    /// level 3; O(T) below.
    pub fn boundary_curve_starts(&self) -> Cow<'_, [u32]> {
        or_panic(self.try_boundary_curve_starts())
    }

    /// [`Che::boundary_curve_starts`], or an [`ErrorKind::OutOfMemory`](crate::ErrorKind)
    /// error when the arrays the scan below level 3 needs do not fit.
    pub fn try_boundary_curve_starts(&self) -> Result<Cow<'_, [u32]>> {
        if self.level >= 3 {
            if self.edits().is_some() {
                return Ok(Cow::Borrowed(&self.try_edited_curves()?.ch));
            }
            return Ok(Cow::Borrowed(&self.ch));
        }
        let o = self.try_opposites_or_computed()?;
        let mut seen = try_vec(self.v.len(), false, "the boundary half-edges seen")?;
        let mut starts = Vec::new();
        for h in 0..self.v.len() as u32 {
            if o[h as usize] != NONE || seen[h as usize] || self.v[h as usize] == NONE {
                continue;
            }
            try_push(&mut starts, h, "the boundary curves")?;
            let mut g = h;
            loop {
                seen[g as usize] = true;
                g = self.next_boundary(&o, g);
                if g == h {
                    break;
                }
            }
        }
        Ok(Cow::Owned(starts))
    }

    /// The boundary half-edge after `h`, with opposites at hand (any level).
    fn next_boundary(&self, o: &[u32], h: u32) -> u32 {
        if self.level >= 2 {
            return self.vh[self.v[next(h) as usize] as usize];
        }
        // Rotate clockwise around the target until the boundary.
        let mut g = next(h);
        while o[g as usize] != NONE {
            g = next(o[g as usize]);
        }
        g
    }

    /// Number of boundary curves of the structure.
    pub fn num_boundary_curves(&self) -> usize {
        self.boundary_curve_starts().len()
    }

    /// The curve of boundary half-edge `h` (`NONE` when `h` is interior). O(1) at level 3;
    /// O(T) below (the curves are walked), and O(T) memory at level 0.
    pub fn curve_of(&self, h: u32) -> u32 {
        if self.level >= 3 {
            if self.edits().is_some() {
                return self.edited_curve_of(h);
            }
            if self.o[h as usize] != NONE {
                return NONE;
            }
            return self.curve_of[self.boundary_bits.rank(h as usize)];
        }
        let o = self.opposites_or_computed();
        if o[h as usize] != NONE {
            return NONE;
        }
        let starts = self.boundary_curve_starts();
        for (c, &s) in starts.iter().enumerate() {
            if self.walk(Cow::Borrowed(&o), s).any(|g| g == h) {
                return c as u32;
            }
        }
        NONE
    }

    /// The half-edges of the curve through boundary half-edge `start`, in order. O(L) for
    /// a curve of L half-edges at level 2, O(T) in all below (a rotation around each
    /// vertex at level 1; `O` computed first at level 0, O(T) time and memory).
    pub fn boundary_curve(&self, start: u32) -> BoundaryWalk<'_> {
        or_panic(self.try_boundary_curve(start))
    }

    /// [`Che::boundary_curve`], out of memory (`O` computed at level 0) an error.
    pub(crate) fn try_boundary_curve(&self, start: u32) -> Result<BoundaryWalk<'_>> {
        Ok(self.walk(self.try_opposites_or_computed()?, start))
    }

    /// The walk from `start` over the opposites `o`.
    fn walk<'a>(&'a self, o: Cow<'a, [u32]>, start: u32) -> BoundaryWalk<'a> {
        BoundaryWalk {
            che: self,
            o,
            start,
            cur: start,
        }
    }

    /// The vertices of curve `c` (an index into [`Che::boundary_curve_starts`]), in order;
    /// an out-of-range error when there is no curve `c`.
    pub fn boundary_curve_vertices(&self, c: u32) -> Result<Vec<u32>> {
        let starts = self.try_boundary_curve_starts()?;
        let &s = starts.get(c as usize).ok_or_else(|| {
            Error::out_of_range(format!(
                "boundary curve {c} out of range (the mesh has {} curves)",
                starts.len()
            ))
        })?;
        let walk = self.try_boundary_curve(s)?;
        try_collect(walk.map(|h| self.v[h as usize]), "the curve's vertices")
    }
}
