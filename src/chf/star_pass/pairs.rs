//! Writing `O` from pairs found in any order, by any number of threads. A random write per
//! half-face would miss the cache on a large mesh (twins are far apart in memory), so each
//! pair is first appended, in both directions, to the window of half-faces its first
//! half-face falls in (at most 512 windows: a few sequential write streams); `finish` then
//! fills `O` one window at a time, in cache. A window has room for one record per
//! half-face, which is all it can receive: 8 bytes per half-face until `finish`.
//!
//! Threads share the windows: each stages a cache line of records per window
//! ([`Writer`]) and claims room for it with one atomic add, so that the windows fill in no
//! particular order, which `finish` does not need (each half-face has one record).

use crate::NONE;
use crate::error::Result;
use crate::util::alloc::{try_resize, try_vec};
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering::Relaxed};

const WINDOWS_BITS: u32 = 9;

pub(crate) struct Opposites {
    n_hf: usize,
    shift: u32,
    /// Window `w` is `records[w << shift ..]`, filled up to `fill[w]`; a record is
    /// `(h << 32) | g` for `O[h] = g`.
    records: Vec<AtomicU64>,
    fill: Vec<AtomicU32>,
}

/// One thread's way into [`Opposites`]: per window, the last records not yet written (a
/// cache line's worth): written together they cost one miss and one atomic add, against
/// one each per record written alone.
pub(crate) struct Writer<'a> {
    to: &'a Opposites,
    staged: Vec<[u64; STAGE]>,
    staged_len: Vec<u8>,
}

const STAGE: usize = 8;

impl Opposites {
    pub(crate) fn new(n_hf: usize) -> Result<Self> {
        let bits = usize::BITS - n_hf.saturating_sub(1).leading_zeros();
        let shift = bits.saturating_sub(WINDOWS_BITS);
        let n_windows = (n_hf.saturating_sub(1) >> shift) + 1;
        let records = crate::util::pages::from_fn(n_hf, || AtomicU64::new(0), "the face pairs")?;
        Ok(Opposites {
            n_hf,
            shift,
            records,
            // At most 512 windows.
            fill: (0..n_windows as u32)
                .map(|w| AtomicU32::new(w << shift))
                .collect(),
        })
    }

    pub(crate) fn writer(&self) -> Result<Writer<'_>> {
        let n_windows = self.fill.len();
        Ok(Writer {
            to: self,
            staged: try_vec(n_windows, [0; STAGE], "a thread's staged pairs")?,
            staged_len: try_vec(n_windows, 0, "a thread's staged pairs")?,
        })
    }

    /// Appends `records` to window `w`.
    #[inline]
    fn append(&self, w: usize, records: &[u64]) {
        let at = self.fill[w].fetch_add(records.len() as u32, Relaxed) as usize;
        for (slot, &r) in self.records[at..at + records.len()].iter().zip(records) {
            slot.store(r, Relaxed);
        }
    }

    /// `O`, in `buffer`'s memory (its contents are dropped), and the records' memory for
    /// the caller to reuse. Every writer must have been flushed.
    pub(crate) fn finish(self, buffer: Vec<u32>) -> Result<(Vec<u32>, Vec<u64>)> {
        let mut o = buffer;
        o.clear();
        if o.capacity() < self.n_hf {
            // Too small: let it go before the new one comes (the build's peak).
            drop(o);
            o = crate::util::pages::with_capacity(self.n_hf, "the opposites O (level 1)")?;
        }
        try_resize(&mut o, self.n_hf, NONE, "the opposites O (level 1)")?;
        // A buffer much larger than `O` gives the rest back (in place: no copy).
        if o.capacity() - o.len() > o.len() / 16 {
            o.shrink_to_fit();
        }
        for (w, end) in self.fill.iter().enumerate() {
            for r in &self.records[w << self.shift..end.load(Relaxed) as usize] {
                let r = r.load(Relaxed);
                o[(r >> 32) as usize] = r as u32;
            }
        }
        let mut records = self.records;
        records.clear();
        // Empty, so in place and without a pass: the memory only.
        Ok((o, records.into_iter().map(AtomicU64::into_inner).collect()))
    }
}

impl Writer<'_> {
    /// `O[h] = g` and `O[g] = h`. Each half-face is paired at most once.
    #[inline]
    pub(crate) fn pair(&mut self, h: u32, g: u32) {
        self.push(h, g);
        self.push(g, h);
    }

    #[inline]
    fn push(&mut self, h: u32, g: u32) {
        let w = (h >> self.to.shift) as usize;
        let len = &mut self.staged_len[w];
        self.staged[w][*len as usize] = ((h as u64) << 32) | g as u64;
        *len += 1;
        if *len as usize == STAGE {
            *len = 0;
            self.to.append(w, &self.staged[w]);
        }
    }

    /// Writes what is still staged.
    pub(crate) fn flush(self) {
        for (w, (staged, &len)) in self.staged.iter().zip(&self.staged_len).enumerate() {
            self.to.append(w, &staged[..len as usize]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_land_in_place() {
        for n in [0usize, 1, 2, 5, 4096, 4097, 100_000] {
            let o = Opposites::new(n).unwrap();
            let mut expected = vec![NONE; n];
            // Pair i with n - 1 - i for every third i, in a scrambled order.
            let mut pairs: Vec<(u32, u32)> = (0..n as u32 / 2)
                .filter(|i| i % 3 == 0)
                .map(|i| (n as u32 - 1 - i, i))
                .collect();
            pairs.reverse();
            let mut w = o.writer().unwrap();
            for &(h, g) in &pairs {
                w.pair(h, g);
                expected[h as usize] = g;
                expected[g as usize] = h;
            }
            w.flush();
            assert_eq!(o.finish(vec![7; 3]).unwrap().0, expected, "n = {n}");
        }
    }
}
