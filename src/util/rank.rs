//! A bit vector with O(1) rank: 64 bits of payload plus a 32-bit running count per word,
//! 1.5 bits per element. Used for edge ids (rank over canonical half-edges) and boundary
//! curve lookup (rank over boundary half-edges) without a full per-element map.

use crate::error::Result;
use crate::util::alloc::{try_reserve, try_with_capacity};

#[derive(Clone, Debug, Default)]
pub struct RankBits {
    words: Vec<u64>,
    before: Vec<u32>,
    ones: usize,
}

impl RankBits {
    pub fn from_fn(len: usize, mut bit: impl FnMut(usize) -> bool) -> Result<Self> {
        let n_words = len.div_ceil(64);
        let mut words = try_with_capacity(n_words, "a rank directory")?;
        let mut before = try_with_capacity(n_words, "a rank directory")?;
        let mut ones = 0usize;
        for w in 0..n_words {
            let base = w * 64;
            let end = (base + 64).min(len);
            let mut word = 0u64;
            for i in base..end {
                word |= (bit(i) as u64) << (i - base);
            }
            before.push(ones as u32);
            ones += word.count_ones() as usize;
            words.push(word);
        }
        Ok(RankBits {
            words,
            before,
            ones,
        })
    }

    /// From `len` bits packed in words (bit `i` is bit `i & 63` of word `i >> 6`); bits
    /// past `len` must be clear.
    pub fn from_words(words: Vec<u64>, len: usize) -> Result<Self> {
        assert_eq!(words.len(), len.div_ceil(64));
        let mut before = try_with_capacity(words.len(), "a rank directory")?;
        let mut ones = 0usize;
        for w in &words {
            before.push(ones as u32);
            ones += w.count_ones() as usize;
        }
        debug_assert!(len.is_multiple_of(64) || words.last().is_none_or(|w| w >> (len % 64) == 0));
        Ok(RankBits {
            words,
            before,
            ones,
        })
    }

    /// The positions of the set bits, in increasing order, each mapped by `f`.
    pub fn ones_map<T>(&self, out: &mut Vec<T>, f: impl Fn(usize) -> T, what: &str) -> Result<()> {
        if out.capacity() - out.len() < self.ones {
            try_reserve(out, self.ones, what)?;
        }
        for (w, &word) in self.words.iter().enumerate() {
            for_each_one(word, 64 * w, |i| out.push(f(i)));
        }
        Ok(())
    }

    pub fn ones(&self) -> usize {
        self.ones
    }

    /// The packed bits (bit `i` is bit `i & 63` of word `i >> 6`), as a level file stores
    /// them.
    pub fn words(&self) -> &[u64] {
        &self.words
    }

    #[inline]
    pub fn get(&self, i: usize) -> bool {
        (self.words[i >> 6] >> (i & 63)) & 1 == 1
    }

    /// Reads what [`RankBits::rank`] of bit `i` reads (to have it in cache ahead of
    /// time); the value means nothing.
    #[inline]
    pub fn word(&self, i: usize) -> u32 {
        self.bits_word(i) ^ self.before.get(i >> 6).map_or(0, |&b| b)
    }

    /// Reads what [`RankBits::get`] of bit `i` reads; the value means nothing.
    #[inline]
    pub fn bits_word(&self, i: usize) -> u32 {
        self.words.get(i >> 6).map_or(0, |&w| w as u32)
    }

    /// Number of set bits strictly before `i`.
    #[inline]
    pub fn rank(&self, i: usize) -> usize {
        let w = i >> 6;
        let mask = (1u64 << (i & 63)) - 1;
        self.before[w] as usize + (self.words[w] & mask).count_ones() as usize
    }

    pub fn memory_bytes(&self) -> usize {
        self.words.len() * 8 + self.before.len() * 4
    }
}

/// Test helper for both rank structures: `get`, `rank` and `ones` (the three `answers`)
/// agree with `pattern` and its prefix counts on `0..len`.
/// `f(base + i)` for every set bit `i` of `bits`, in increasing order: a step per set bit,
/// not per bit, and no branch on each bit.
#[inline]
pub(crate) fn for_each_one(bits: u64, base: usize, mut f: impl FnMut(usize)) {
    let done = try_for_each_one::<std::convert::Infallible>(bits, base, |i| {
        f(i);
        Ok(())
    });
    match done {
        Ok(()) => {}
        Err(never) => match never {},
    }
}

/// [`for_each_one`] for an `f` that can fail: stops at the first error.
#[inline]
pub(crate) fn try_for_each_one<E>(
    mut bits: u64, base: usize, mut f: impl FnMut(usize) -> std::result::Result<(), E>,
) -> std::result::Result<(), E> {
    while bits != 0 {
        f(base + bits.trailing_zeros() as usize)?;
        bits &= bits - 1;
    }
    Ok(())
}

#[cfg(test)]
pub(crate) fn assert_prefix_counts(
    len: usize, pattern: impl Fn(usize) -> bool,
    answers: (impl Fn(usize) -> bool, impl Fn(usize) -> usize, usize),
) {
    let (get, rank, ones) = answers;
    let mut count = 0;
    for i in 0..len {
        assert_eq!(rank(i), count, "len {len} i {i}");
        assert_eq!(get(i), pattern(i));
        count += pattern(i) as usize;
    }
    assert_eq!(ones, count);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rank_matches_prefix_count() {
        let pattern = |i: usize| (i * 7 + i / 3) % 5 < 2;
        for len in [0usize, 1, 63, 64, 65, 200, 1000] {
            let bits = RankBits::from_fn(len, pattern).unwrap();
            let answers = (|i| bits.get(i), |i| bits.rank(i), bits.ones());
            assert_prefix_counts(len, pattern, answers);
            let words = bits.words.clone();
            let again = RankBits::from_words(words, len).unwrap();
            assert_eq!((again.before, again.ones), (bits.before.clone(), bits.ones));
        }
    }
}
