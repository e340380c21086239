//! Storage of a structure's big arrays: owned, or a range of a level file mapped into
//! memory (`levelfile::map`). Reads see a slice either way (`Deref`), so every query runs
//! unchanged on a mapped structure; a writer asks for [`Store::to_mut`], which copies a
//! mapped range into memory first (the mapping is read-only).

use crate::error::Result;
use bytemuck::Pod;
use memmap2::Mmap;
use std::ops::{Deref, Range};
use std::sync::Arc;

/// An array of `T`, owned or borrowed from a shared read-only mapping.
pub(crate) enum Store<T> {
    Owned(Vec<T>),
    /// `bytes` of `map`, checked at construction to be in bounds, aligned for `T` and a
    /// whole number of `T`, so that the cast in `deref` never fails.
    Mapped {
        map: Arc<Mmap>,
        bytes: Range<usize>,
    },
}

impl<T: Pod> Store<T> {
    /// The elements at `bytes` of `map`; `None` when the range is out of the mapping or
    /// not aligned for `T` (the caller copies instead).
    pub(crate) fn mapped(map: &Arc<Mmap>, bytes: Range<usize>) -> Option<Self> {
        let slice = map.get(bytes.clone())?;
        bytemuck::try_cast_slice::<u8, T>(slice).ok()?;
        Some(Store::Mapped {
            map: Arc::clone(map),
            bytes,
        })
    }

    /// Whether the elements live in a mapped file.
    pub(crate) fn is_mapped(&self) -> bool {
        matches!(self, Store::Mapped { .. })
    }

    /// The mapping the elements live in, if they do.
    pub(crate) fn mapping(&self) -> Option<&Mmap> {
        match self {
            Store::Mapped { map, .. } => Some(map),
            Store::Owned(_) => None,
        }
    }

    /// The elements as an owned vector to write to: a mapped range is copied first, into
    /// memory reserved fallibly (`what` names the array in the error).
    #[inline]
    pub(crate) fn to_mut(&mut self, what: &str) -> Result<&mut Vec<T>> {
        if let Store::Mapped { .. } = self {
            self.promote(what)?;
        }
        match self {
            Store::Owned(v) => Ok(v),
            Store::Mapped { .. } => unreachable!("promoted above"),
        }
    }

    /// A mapped array copied into memory: once per array, on the first write (every edit
    /// asks, so the question stays inline and the copy out of line).
    #[cold]
    fn promote(&mut self, what: &str) -> Result<()> {
        let mut owned = crate::util::alloc::try_with_capacity(self.len(), what)?;
        owned.extend_from_slice(self);
        *self = Store::Owned(owned);
        Ok(())
    }
}

impl<T> Store<T> {
    /// The owned vector of an array its writer has already promoted with
    /// [`Store::to_mut`]: the editors promote every array at the start of an edit, where
    /// running out of memory is still a status, so the writes after it cannot fail.
    pub(crate) fn owned_mut(&mut self) -> &mut Vec<T> {
        match self {
            Store::Owned(v) => v,
            Store::Mapped { .. } => unreachable!("a writer promotes the array before writing"),
        }
    }
}

impl<T: Pod> Deref for Store<T> {
    type Target = [T];
    #[inline]
    fn deref(&self) -> &[T] {
        match self {
            Store::Owned(v) => v,
            Store::Mapped { map, bytes } => bytemuck::cast_slice(&map[bytes.clone()]),
        }
    }
}

impl<T> Default for Store<T> {
    fn default() -> Self {
        Store::Owned(Vec::new())
    }
}

impl<T> From<Vec<T>> for Store<T> {
    fn from(v: Vec<T>) -> Self {
        Store::Owned(v)
    }
}

impl<T: Clone> Clone for Store<T> {
    /// A mapped range is shared, not copied.
    fn clone(&self) -> Self {
        match self {
            Store::Owned(v) => Store::Owned(v.clone()),
            Store::Mapped { map, bytes } => Store::Mapped {
                map: Arc::clone(map),
                bytes: bytes.clone(),
            },
        }
    }
}

impl<T: Pod + std::fmt::Debug> std::fmt::Debug for Store<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl<T: Pod + PartialEq> PartialEq for Store<T> {
    fn eq(&self, other: &Self) -> bool {
        self[..] == other[..]
    }
}

impl<T: Pod + PartialEq> PartialEq<Vec<T>> for Store<T> {
    fn eq(&self, other: &Vec<T>) -> bool {
        self[..] == other[..]
    }
}

impl<T: Pod + PartialEq> PartialEq<Store<T>> for Vec<T> {
    fn eq(&self, other: &Store<T>) -> bool {
        self[..] == other[..]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owned_reads_and_writes_as_a_vector() {
        let mut s: Store<u32> = vec![1, 2, 3].into();
        assert_eq!(&s[..], &[1, 2, 3]);
        assert!(!s.is_mapped());
        s.to_mut("test").unwrap().push(4);
        assert_eq!(s, vec![1, 2, 3, 4]);
    }
}
