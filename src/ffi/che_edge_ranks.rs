//! The edge-id rank directory a C host needs to turn a half-edge into its edge id inline.
//!
//! Edge ids are the rank of the canonical half-edge (`O[h] == NONE || h < O[h]`) among the
//! canonical half-edges. The directory has one 64-bit entry per 32 half-edges: its low 32
//! bits flag the canonical ones (bit `i` for half-edge `32 k + i`), its high 32 bits count
//! the canonical half-edges before `32 k`. The edge of `h` is then
//! `(d[c / 32] >> 32) + popcount(d[c / 32] & ((1 << c % 32) - 1))` with `c` the canonical
//! half-edge of `h` (`che_edge_of` in `topomesh_inline.h`): one load besides `O`, which a
//! star walk has at hand. It is computed from `O` alone (2 bits per half-edge), on the
//! first request, and kept with the handle until its level changes. The core keeps similar
//! bits internally but does not expose them; a borrowed view of those would spare this
//! copy, though its split layout (bits and counts apart) costs a second load per lookup.

use crate::NONE;

/// Half-edges per directory entry.
const SPAN: usize = 32;

/// One entry per 32 half-edges: canonical flags (low half), count before (high half).
#[derive(Debug, Default)]
pub(crate) struct EdgeRanks {
    pub(crate) entries: Box<[u64]>,
}

impl EdgeRanks {
    /// From the opposites `o` (one per half-edge). Fails (`None`) when the edge count does
    /// not fit 32 bits, which a built mesh never has.
    pub(crate) fn from_opposites(o: &[u32]) -> Option<Self> {
        let mut entries = Vec::with_capacity(o.len().div_ceil(SPAN));
        let mut total = 0u32;
        for (k, chunk) in o.chunks(SPAN).enumerate() {
            let base = SPAN * k;
            let mut flags = 0u32;
            for (i, &g) in chunk.iter().enumerate() {
                let canonical = g == NONE || ((base + i) as u64) < u64::from(g);
                flags |= u32::from(canonical) << i;
            }
            entries.push(u64::from(total) << 32 | u64::from(flags));
            total = total.checked_add(flags.count_ones())?;
        }
        Some(EdgeRanks {
            entries: entries.into_boxed_slice(),
        })
    }

    /// The edge of half-edge `h` (the arithmetic of `che_edge_of`); `h < o.len()`.
    #[cfg(test)]
    pub(crate) fn edge_of(&self, o: &[u32], h: u32) -> u32 {
        let g = o[h as usize];
        let c = if g != NONE && g < h { g } else { h } as usize;
        let d = self.entries[c / SPAN];
        let mask = (1u32 << (c % SPAN)) - 1;
        (d >> 32) as u32 + (d as u32 & mask).count_ones()
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
