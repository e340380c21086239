//! A build's input, borrowed or handed over. Borrowed arrays are copied where the
//! structure keeps them; handed-over ones become the structure's own (the elements turn
//! into `V` in place, the positions move in), so that the input is never held twice: what
//! lets a build of hundreds of millions of elements fit beside its result.

use crate::error::Result;
use crate::util::alloc::{try_reserve, try_to_vec};
use glam::DVec3;
use std::borrow::Cow;

/// Elements of `K` corners over vertices `0..n_vertices`, and the positions (empty, or one
/// per vertex).
pub(crate) struct Input<'a, const K: usize> {
    pub elements: Cow<'a, [[u32; K]]>,
    pub n_vertices: usize,
    pub positions: Cow<'a, [DVec3]>,
}

impl<'a, const K: usize> Input<'a, K> {
    /// The caller keeps the arrays.
    pub fn borrowed(elements: &'a [[u32; K]], n_vertices: usize, positions: &'a [DVec3]) -> Self {
        Input {
            elements: Cow::Borrowed(elements),
            n_vertices,
            positions: Cow::Borrowed(positions),
        }
    }

    /// The caller hands the arrays over.
    pub fn owned(elements: Vec<[u32; K]>, n_vertices: usize, positions: Vec<DVec3>) -> Self {
        Input {
            elements: Cow::Owned(elements),
            n_vertices,
            positions: Cow::Owned(positions),
        }
    }
}

/// The structure's positions: the input's (copied when borrowed, moved when owned), then
/// one for each vertex copy of the split, repeating its origin's. Empty stays empty.
pub(crate) fn positions_with_copies(
    positions: Cow<'_, [DVec3]>, copies: &[u32],
) -> Result<Vec<DVec3>> {
    let mut positions = match positions {
        Cow::Borrowed(p) => try_to_vec(p, "the positions")?,
        Cow::Owned(p) => p,
    };
    if !positions.is_empty() {
        try_reserve(&mut positions, copies.len(), "the positions")?;
        for &c in copies {
            positions.push(positions[c as usize]);
        }
    }
    Ok(positions)
}
