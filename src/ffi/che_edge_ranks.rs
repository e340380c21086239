//! The edge-id rank directory a C host needs to turn a half-edge into its edge id inline.
//!
//! Edge ids are the rank of the canonical half-edge (`O[h] == NONE || h < O[h]`) among the
//! canonical half-edges. The directory is one bit per half-edge (set on canonical ones,
//! 64 per word) and, per word, the number of set bits before it: the edge of `h` is
//! `counts[c / 64] + popcount(bits[c / 64] & ((1 << c % 64) - 1))` with `c` the canonical
//! half-edge of `h` (`che_edge_of` in `topomesh_inline.h`). It is computed from `O` alone
//! (1.5 bits per half-edge), on the first request, and kept with the handle until its
//! level changes. The core keeps the same bits internally but does not expose them; a
//! borrowed view of those would spare this copy.

use crate::NONE;

/// Bits and per-word counts of the canonical half-edges.
#[derive(Debug, Default)]
pub(crate) struct EdgeRanks {
    pub(crate) bits: Box<[u64]>,
    pub(crate) counts: Box<[u32]>,
}

impl EdgeRanks {
    /// From the opposites `o` (one per half-edge). Fails (`None`) when the edge count does
    /// not fit 32 bits, which a built mesh never has.
    pub(crate) fn from_opposites(o: &[u32]) -> Option<Self> {
        let mut bits = Vec::with_capacity(o.len().div_ceil(64));
        let mut counts = Vec::with_capacity(o.len().div_ceil(64));
        let mut total = 0u32;
        for (w, chunk) in o.chunks(64).enumerate() {
            let base = 64 * w;
            let mut word = 0u64;
            for (i, &g) in chunk.iter().enumerate() {
                let canonical = g == NONE || ((base + i) as u64) < u64::from(g);
                word |= u64::from(canonical) << i;
            }
            counts.push(total);
            total = total.checked_add(word.count_ones())?;
            bits.push(word);
        }
        Some(EdgeRanks {
            bits: bits.into_boxed_slice(),
            counts: counts.into_boxed_slice(),
        })
    }

    /// The edge of half-edge `h` (the arithmetic of `che_edge_of`); `h < o.len()`.
    #[cfg(test)]
    pub(crate) fn edge_of(&self, o: &[u32], h: u32) -> u32 {
        let g = o[h as usize];
        let c = if g != NONE && g < h { g } else { h } as usize;
        let mask = (1u64 << (c & 63)) - 1;
        self.counts[c >> 6] + (self.bits[c >> 6] & mask).count_ones()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::che::{BuildOptions, Che};

    #[test]
    fn ranks_give_the_core_edge_ids() {
        // A strip of 40 triangles (120 half-edges: two words, boundary and interior edges).
        let mut tris = Vec::new();
        for i in 0..40u32 {
            if i % 2 == 0 {
                tris.extend([i, i + 1, i + 2]);
            } else {
                tris.extend([i, i + 2, i + 1]);
            }
        }
        for level in 1..=3 {
            let che = Che::from_flat(&tris, 42, &[], BuildOptions::level(level)).unwrap();
            let o = che.opposites().unwrap();
            let r = EdgeRanks::from_opposites(o).unwrap();
            for h in 0..o.len() as u32 {
                assert_eq!(r.edge_of(o, h), che.edge_of(h), "level {level} h {h}");
            }
        }
    }
}
