//! A bit vector with O(1) rank in one load: one 64-bit entry per 32 bits, the bits in its
//! low half and the count of set bits before them in its high half (2 bits per element).
//! Edge ids of a surface are this rank over the canonical half-edges; the C API lends the
//! entries as they are (`che_mesh_edge_ranks`), so that a C host computes an edge id
//! inline with the same arithmetic (`che_edge_of` in `topomesh_inline.h`).

use crate::error::{Error, Result};
use crate::util::store::Store;

/// Elements per entry.
pub const SPAN: usize = 32;

#[derive(Clone, Debug, Default)]
pub struct RankDirectory {
    entries: Store<u64>,
    ones: usize,
}

impl RankDirectory {
    /// Bit `i` is `bit(i)`, for `i < len`; an error when more than `u32::MAX` bits are set
    /// or memory runs out.
    pub fn from_fn(len: usize, mut bit: impl FnMut(usize) -> bool) -> Result<Self> {
        let mut entries =
            crate::util::pages::with_capacity(len.div_ceil(SPAN), "the edge-id directory")?;
        let mut ones = 0u32;
        for base in (0..len).step_by(SPAN) {
            let mut flags = 0u32;
            for i in base..(base + SPAN).min(len) {
                flags |= u32::from(bit(i)) << (i - base);
            }
            entries.push(u64::from(ones) << 32 | u64::from(flags));
            ones = (ones.checked_add(flags.count_ones()))
                .ok_or_else(|| Error::too_large(format!("more than 2^32 - 1 of {len} bits set")))?;
        }
        Ok(RankDirectory {
            entries: entries.into(),
            ones: ones as usize,
        })
    }

    /// From stored entries over `len` bits (a level file): `None` unless there is one entry
    /// per 32 bits, each high half counts the set bits before it, and no bit past `len` is
    /// set, so that `get` and `rank` answer as for the directory that was saved.
    pub fn from_entries(entries: Store<u64>, len: usize) -> Option<Self> {
        if entries.len() != len.div_ceil(SPAN) {
            return None;
        }
        let mut ones = 0u32;
        for (k, &d) in entries.iter().enumerate() {
            let flags = d as u32;
            let tail = len - k * SPAN;
            if (d >> 32) as u32 != ones || (tail < SPAN && flags >> tail != 0) {
                return None;
            }
            ones = ones.checked_add(flags.count_ones())?;
        }
        Some(RankDirectory {
            entries,
            ones: ones as usize,
        })
    }

    /// From stored entries over `len` bits, unchecked but for their number (a trusted level
    /// file): a wrong entry makes `rank` answer wrongly, never read out of bounds.
    pub(crate) fn from_entries_trusted(
        entries: Store<u64>, len: usize, ones: usize,
    ) -> Option<Self> {
        (entries.len() == len.div_ceil(SPAN)).then_some(RankDirectory { entries, ones })
    }

    /// The entries, as lent to C.
    pub fn entries(&self) -> &[u64] {
        &self.entries
    }

    pub fn ones(&self) -> usize {
        self.ones
    }

    #[inline]
    pub fn get(&self, i: usize) -> bool {
        (self.entries[i / SPAN] >> (i % SPAN)) & 1 == 1
    }

    /// Number of set bits strictly before `i`.
    #[inline]
    pub fn rank(&self, i: usize) -> usize {
        let d = self.entries[i / SPAN];
        let mask = (1u32 << (i % SPAN)) - 1;
        (d >> 32) as usize + (d as u32 & mask).count_ones() as usize
    }

    /// The positions of the set bits, in increasing order, each mapped by `f`, pushed onto
    /// `out` (room for them reserved first).
    pub(crate) fn ones_map<T>(
        &self, out: &mut Vec<T>, f: impl Fn(usize) -> T, what: &str,
    ) -> Result<()> {
        crate::util::alloc::try_reserve(out, self.ones, what)?;
        for (k, &d) in self.entries.iter().enumerate() {
            super::rank::for_each_one(d & u64::from(u32::MAX), k * SPAN, |i| out.push(f(i)));
        }
        Ok(())
    }

    pub fn memory_bytes(&self) -> usize {
        self.entries.len() * 8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rank_matches_prefix_count() {
        let pattern = |i: usize| (i * 7 + i / 3) % 5 < 2;
        for len in [0usize, 1, 31, 32, 33, 64, 200, 1000] {
            let bits = RankDirectory::from_fn(len, pattern).unwrap();
            let answers = (|i| bits.get(i), |i| bits.rank(i), bits.ones());
            crate::util::rank::assert_prefix_counts(len, pattern, answers);
            assert_eq!(bits.entries().len(), len.div_ceil(SPAN));
        }
    }
}
