//! Up to `N` ids on the stack: the bounded answers (wings, edge triangles, ...) of both
//! structures, returned without allocation.

use crate::NONE;

/// Up to `N` ids without allocation (edge wings, triangles of an edge).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ids<const N: usize> {
    ids: [u32; N],
    len: u8,
}

impl<const N: usize> Ids<N> {
    pub(crate) fn new() -> Self {
        Ids {
            ids: [NONE; N],
            len: 0,
        }
    }
    pub(crate) fn push(&mut self, id: u32) {
        self.ids[self.len as usize] = id;
        self.len += 1;
    }
}

impl Ids<2> {
    /// The element of `h`, then that of its opposite `o` unless `o` is `NONE`: the one or
    /// two elements on either side of a shared edge or face.
    pub(crate) fn both_sides(h: u32, o: u32, element: impl Fn(u32) -> u32) -> Self {
        let mut out = Ids::new();
        out.push(element(h));
        if o != crate::NONE {
            out.push(element(o));
        }
        out
    }
}

impl<const N: usize> std::ops::Deref for Ids<N> {
    type Target = [u32];
    fn deref(&self) -> &[u32] {
        &self.ids[..self.len as usize]
    }
}

impl<const N: usize> IntoIterator for Ids<N> {
    type Item = u32;
    type IntoIter = std::iter::Take<std::array::IntoIter<u32, N>>;
    fn into_iter(self) -> Self::IntoIter {
        self.ids.into_iter().take(self.len as usize)
    }
}
