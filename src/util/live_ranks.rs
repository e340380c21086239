//! Rank and select over a bit vector that changes a few bits at a time: the count of set
//! bits of each block of [`BLOCK`] positions, in a Fenwick tree, so that finding the block
//! of the `e`-th set bit, or counting the set bits before a block, costs O(log n), and so
//! does a block's change. A static
//! [`RankDirectory`](crate::util::rank_directory::RankDirectory) answers in O(1) but is
//! rebuilt whole, O(n), after any change.
//!
//! The bits live elsewhere (here: whether a half-edge is a live canonical one); this type
//! keeps only their counts. A writer [`touch`](LiveRanks::touch)es each position it may
//! have changed, and [`refresh`](LiveRanks::refresh) recounts the touched blocks from the
//! bits as they are then. Between a touch and the refresh, `select` answers for the old
//! bits.

use crate::error::Result;
use crate::util::alloc::{try_grow, try_vec};

/// Positions per counted block: one 64-bit word's worth, scanned whole by a select.
pub(crate) const BLOCK: usize = 64;

#[derive(Clone, Debug, Default)]
pub(crate) struct LiveRanks {
    /// The Fenwick tree over the blocks' counts, 1-based: `tree[i - 1]` sums the blocks
    /// `i - lowbit(i) .. i`.
    tree: Vec<u32>,
    /// Each block's count as the tree holds it.
    counts: Vec<u8>,
    /// The blocks touched since the last refresh, each once (`stale` flags them).
    touched: Vec<u32>,
    stale: Vec<bool>,
}

impl LiveRanks {
    /// The counts of `len` positions whose bits `bit` gives.
    pub(crate) fn new(len: usize, bit: impl Fn(usize) -> bool) -> Result<LiveRanks> {
        let blocks = len.div_ceil(BLOCK);
        let mut counts = try_vec(blocks, 0u8, "the live edge counts")?;
        for (k, c) in counts.iter_mut().enumerate() {
            *c = count_block(k, len, &bit) as u8;
        }
        let mut tree: Vec<u32> = try_vec(blocks, 0, "the live edge count tree")?;
        for i in 1..=blocks {
            tree[i - 1] += u32::from(counts[i - 1]);
            let up = i + lowbit(i);
            if up <= blocks {
                tree[up - 1] += tree[i - 1];
            }
        }
        let mut touched = Vec::new();
        try_grow(&mut touched, blocks, "the touched blocks")?;
        let stale = try_vec(blocks, false, "the touched blocks")?;
        Ok(LiveRanks {
            tree,
            counts,
            touched,
            stale,
        })
    }

    /// Room for `len` positions, so that neither [`LiveRanks::touch`] nor a refresh
    /// allocates.
    pub(crate) fn reserve(&mut self, len: usize) -> Result<()> {
        let more = len.div_ceil(BLOCK).saturating_sub(self.counts.len());
        try_grow(&mut self.tree, more, "the live edge count tree")?;
        try_grow(&mut self.counts, more, "the live edge counts")?;
        try_grow(&mut self.stale, more, "the touched blocks")?;
        let missing = (self.counts.len() + more).saturating_sub(self.touched.len());
        try_grow(&mut self.touched, missing, "the touched blocks")
    }

    /// Position `i` may have changed (room made for it first).
    pub(crate) fn touch(&mut self, i: usize) {
        let k = i / BLOCK;
        while self.counts.len() <= k {
            self.push_block();
        }
        if !self.stale[k] {
            self.stale[k] = true;
            self.touched.push(k as u32);
        }
    }

    /// A new last block, counted empty: its tree node sums the blocks it covers before it.
    fn push_block(&mut self) {
        let i = self.counts.len() + 1;
        let below = self.prefix(i - 1) - self.prefix(i - lowbit(i));
        self.tree.push(below);
        self.counts.push(0);
        self.stale.push(false);
    }

    /// Recounts the touched blocks from the bits as they are now.
    pub(crate) fn refresh(&mut self, len: usize, bit: impl Fn(usize) -> bool) {
        // By index, not by taking the list: it keeps the room `reserve` made.
        for j in 0..self.touched.len() {
            let k = self.touched[j] as usize;
            let now = count_block(k, len, &bit);
            let was = usize::from(self.counts[k]);
            self.counts[k] = now as u8;
            self.stale[k] = false;
            let mut i = k + 1;
            while i <= self.counts.len() {
                self.tree[i - 1] = (self.tree[i - 1] as usize + now - was) as u32;
                i += lowbit(i);
            }
        }
        self.touched.clear();
    }

    /// Whether the counts are those of `fresh` (the same bits counted anew), none touched.
    pub(crate) fn same_counts(&self, fresh: &LiveRanks) -> bool {
        self.touched.is_empty() && self.counts == fresh.counts && self.tree == fresh.tree
    }

    /// Bytes held (lengths, as [`crate::che::Memory`]).
    pub(crate) fn memory_bytes(&self) -> usize {
        4 * self.tree.len() + self.counts.len() + self.stale.len() + 4 * self.touched.len()
    }

    /// The set bits in the blocks before block `k`.
    fn prefix(&self, mut k: usize) -> u32 {
        let mut sum = 0;
        while k > 0 {
            sum += self.tree[k - 1];
            k -= lowbit(k);
        }
        sum
    }

    /// The set bits before position `i`, those of its block counted by `bit`.
    pub(crate) fn rank(&self, i: usize, bit: impl Fn(usize) -> bool) -> u32 {
        let k = i / BLOCK;
        self.prefix(k) + (k * BLOCK..i).filter(|&j| bit(j)).count() as u32
    }

    /// The block holding the `e`-th set bit (from 0) and how many set bits of that block
    /// come before it; `None` when fewer than `e + 1` bits are set.
    pub(crate) fn select(&self, mut e: u32) -> Option<(usize, u32)> {
        let n = self.counts.len();
        let mut pos = 0;
        let mut step = if n == 0 { 0 } else { 1 << n.ilog2() };
        while step > 0 {
            if pos + step <= n && self.tree[pos + step - 1] <= e {
                pos += step;
                e -= self.tree[pos - 1];
            }
            step >>= 1;
        }
        (pos < n).then_some((pos, e))
    }
}

/// The set bits of block `k` of `len` positions.
fn count_block(k: usize, len: usize, bit: impl Fn(usize) -> bool) -> usize {
    (k * BLOCK..(k * BLOCK + BLOCK).min(len))
        .filter(|&i| bit(i))
        .count()
}

fn lowbit(i: usize) -> usize {
    i & i.wrapping_neg()
}

#[cfg(test)]
mod tests {
    use super::{BLOCK, LiveRanks};

    /// After random changes (touched and refreshed, the bit vector growing too), select
    /// finds the same block and offset as a count of the bits, and rank the same count.
    #[test]
    fn select_agrees_with_a_count_after_changes() {
        let mut rnd = crate::util::test_rng(17);
        for len in [0usize, 1, 63, 64, 65, 700, 3000] {
            let mut bits: Vec<bool> = (0..len).map(|_| rnd(3) == 0).collect();
            let mut ranks = LiveRanks::new(len, |i| bits[i]).unwrap();
            for round in 0..40 {
                let grown = bits.len() + rnd(70) as usize * usize::from(round % 3 == 0);
                ranks.reserve(grown).unwrap();
                for i in bits.len()..grown {
                    bits.push(rnd(2) == 0);
                    ranks.touch(i);
                }
                for _ in 0..rnd(20) {
                    if bits.is_empty() {
                        break;
                    }
                    let i = rnd(bits.len()) as usize;
                    bits[i] = !bits[i];
                    ranks.touch(i);
                }
                ranks.refresh(bits.len(), |i| bits[i]);
                let set: Vec<usize> = (0..bits.len()).filter(|&i| bits[i]).collect();
                for (e, &i) in set.iter().enumerate() {
                    let before = set[..e].iter().filter(|&&j| j / BLOCK == i / BLOCK).count();
                    assert_eq!(ranks.select(e as u32), Some((i / BLOCK, before as u32)));
                    assert_eq!(ranks.rank(i, |j| bits[j]), e as u32);
                }
                assert_eq!(ranks.select(set.len() as u32), None);
            }
        }
    }
}
