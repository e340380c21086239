//! Writing `O` from pairs found in any order. A random write per half-face would miss the
//! cache on a large mesh (twins are far apart in memory), so each pair is first appended,
//! in both directions, to the window of half-faces its first half-face falls in (at most
//! 4096 windows: a few sequential write streams); `finish` then fills `O` one window at a
//! time, in cache. A window has room for one record per half-face, which is all it can
//! receive: 8 bytes per half-face until `finish`.

use crate::NONE;

const WINDOWS_BITS: u32 = 9;

pub(crate) struct Opposites {
    n_hf: usize,
    shift: u32,
    /// Window `w` is `records[w << shift ..]`, filled up to `fill[w]`; a record is
    /// `(h << 32) | g` for `O[h] = g`.
    records: Vec<u64>,
    fill: Vec<u32>,
    /// Per window, the last records not yet written (a cache line's worth): written
    /// together they cost one miss, against one per record written alone.
    staged: Vec<[u64; STAGE]>,
    staged_len: Vec<u8>,
}

const STAGE: usize = 8;

impl Opposites {
    pub(crate) fn new(n_hf: usize) -> Self {
        let bits = usize::BITS - n_hf.saturating_sub(1).leading_zeros();
        let shift = bits.saturating_sub(WINDOWS_BITS);
        let n_windows = (n_hf.saturating_sub(1) >> shift) + 1;
        Opposites {
            n_hf,
            shift,
            records: crate::pages::zeroed(n_hf),
            fill: (0..n_windows as u32).map(|w| w << shift).collect(),
            staged: vec![[0; STAGE]; n_windows],
            staged_len: vec![0; n_windows],
        }
    }

    /// `O[h] = g` and `O[g] = h`. Each half-face is paired at most once.
    #[inline]
    pub(crate) fn pair(&mut self, h: u32, g: u32) {
        self.push(h, g);
        self.push(g, h);
    }

    #[inline]
    fn push(&mut self, h: u32, g: u32) {
        let w = (h >> self.shift) as usize;
        let len = &mut self.staged_len[w];
        self.staged[w][*len as usize] = ((h as u64) << 32) | g as u64;
        *len += 1;
        if *len as usize == STAGE {
            *len = 0;
            let at = self.fill[w] as usize;
            self.records[at..at + STAGE].copy_from_slice(&self.staged[w]);
            self.fill[w] += STAGE as u32;
        }
    }

    /// `O`, in `buffer`'s memory (its contents are dropped), and the records' memory for
    /// the caller to reuse.
    pub(crate) fn finish(mut self, buffer: Vec<u32>) -> (Vec<u32>, Vec<u64>) {
        for w in 0..self.fill.len() {
            let (at, len) = (self.fill[w] as usize, self.staged_len[w] as usize);
            self.records[at..at + len].copy_from_slice(&self.staged[w][..len]);
            self.fill[w] += len as u32;
        }
        let mut o = buffer;
        o.clear();
        o.resize(self.n_hf, NONE);
        // A buffer much larger than `O` gives the rest back (in place: no copy).
        if o.capacity() - o.len() > o.len() / 16 {
            o.shrink_to_fit();
        }
        for (w, &end) in self.fill.iter().enumerate() {
            for &r in &self.records[w << self.shift..end as usize] {
                o[(r >> 32) as usize] = r as u32;
            }
        }
        (o, self.records)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_land_in_place() {
        for n in [0usize, 1, 2, 5, 4096, 4097, 100_000] {
            let mut o = Opposites::new(n);
            let mut expected = vec![NONE; n];
            // Pair i with n - 1 - i for every third i, in a scrambled order.
            let mut pairs: Vec<(u32, u32)> = (0..n as u32 / 2)
                .filter(|i| i % 3 == 0)
                .map(|i| (n as u32 - 1 - i, i))
                .collect();
            pairs.reverse();
            for &(h, g) in &pairs {
                o.pair(h, g);
                expected[h as usize] = g;
                expected[g as usize] = h;
            }
            assert_eq!(o.finish(vec![7; 3]).0, expected, "n = {n}");
        }
    }
}
