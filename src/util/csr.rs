//! Compressed sparse rows, the bulk relations' container for both structures: CHE's
//! offsets are `usize`, CHF's `u32` (half the memory where `4T` fits in 32 bits).

/// A relation for every element: row `i` is `indices[offsets[i]..offsets[i + 1]]`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Csr<O> {
    pub offsets: Vec<O>,
    pub indices: Vec<u32>,
}

/// An offset type of [`Csr`].
pub trait Offset: Copy {
    fn index(self) -> usize;
}

impl Offset for usize {
    #[inline]
    fn index(self) -> usize {
        self
    }
}

impl Offset for u32 {
    #[inline]
    fn index(self) -> usize {
        self as usize
    }
}

impl<O: Offset> Csr<O> {
    /// The number of rows.
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Row `i`.
    pub fn row(&self, i: usize) -> &[u32] {
        &self.indices[self.offsets[i].index()..self.offsets[i + 1].index()]
    }
}
