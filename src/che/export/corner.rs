//! The corner table (Rossignac) and directed edges (Campagna, Kobbelt and Seidel).
//!
//! Corner `c` is half-edge `c`: corner `3t + i` is the corner of triangle `t` at vertex
//! `V[c]`, the tail of half-edge `c`, so the corner table's `V` *is* CHE's `V` (lent
//! without a copy). The edge facing corner `c` is half-edge `next(c)`, from `V[next(c)]`
//! to `V[prev(c)]`; the opposite corner `O_corner[c]` faces the same edge from the other
//! triangle: `prev(O[next(c)])`, `NONE` on the boundary.
//!
//! Directed edges number the half-edges of triangle `t` as `3t + i` too, each with its
//! start vertex and its neighbour: CHE's `V` and `O` at level 1 are exactly that
//! structure (with `VH` from level 2 as the per-vertex half-edge), so it needs no export.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev};
use crate::error::Result;
use crate::util::sparse::reserve;

/// The corner table: `v` (borrowed: CHE's `V`) and the opposite corners.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CornerTable<'a> {
    pub v: &'a [u32],
    pub o: Vec<u32>,
}

impl Che {
    /// The corner table; see the module documentation for the relation to `V` and `O`.
    pub fn corner_table(&self) -> Result<CornerTable<'_>> {
        self.check_collected("the corner table")?;
        let o = self.try_opposites_or_computed()?;
        let mut oc = Vec::new();
        reserve(&mut oc, o.len(), "opposite corners")?;
        oc.extend((0..o.len() as u32).map(|c| match o[next(c) as usize] {
            NONE => NONE,
            g => prev(g),
        }));
        Ok(CornerTable { v: &self.v, o: oc })
    }
}
