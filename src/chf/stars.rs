//! One pass over the star of every vertex, from `V` alone: the faces and their pairs (`O`
//! and the face counts of the build report), whether every star is one piece (else the
//! vertex split must run), `VH`, the canonical slot of every fan (edge ids) and the edge
//! census. `link.rs` does the work on one star.
//!
//! Why one bucketed pass and no walks: on a large mesh the neighbours of a tetrahedron are
//! far away in memory, so every step of a walk through `O` misses the cache (and a random
//! write misses it too). One sequential scan of `V` writes a record per occurrence
//! (tetrahedron, vertex) to its vertex's bucket with a two-pass radix: the first pass
//! streams records to at most 512 coarse buckets (few enough write streams for the cache
//! and the TLB), the second sorts one coarse bucket at a time, in cache, by the low bits of
//! the vertex. The records of a vertex are then in tetrahedron order, hence half-face
//! order. Large meshes run in rounds over ranges of coarse buckets (each round rescans
//! `V`) so that the records never take more than about 20 bytes per tetrahedron.
//! The pairs found and the canonical slots are written in place the same way, through
//! windows (`pairs.rs`, [`bits_from_slots`]).

use super::edges::EdgeCensus;
use super::link::{FaceCensus, Link, Record, Sums};
use super::pairs::Opposites;
use crate::NONE;
use crate::rank::RankBits;

const COARSE_BITS: u32 = 9;

/// What the pass found.
pub(crate) struct Stars {
    /// Some star is in several pieces: the vertex split must run (then the pass again),
    /// and `VH`, the edges and the census are incomplete.
    pub split_needed: bool,
    pub vh: Vec<u32>,
    /// Canonical edge slots.
    pub edge_bits: RankBits,
    /// The fans grouped by vertex pair (the ids of `V`).
    pub census: EdgeCensus,
    /// With pairs asked for: the face counts and the pairs, as a table like `O`.
    pub faces: Option<(FaceCensus, Vec<u32>)>,
}

/// Which pairs of half-faces to collect, with the face counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pairs {
    No,
    /// Every triple of exactly two half-faces, whatever their direction (the build's
    /// partners, on the input's `V`).
    Partners,
    /// The twins by the rule of `O` (running opposite ways, not flagged).
    Opposites,
}

/// The pass over `V`. `flagged` (sorted) are half-faces never to pair: the build's
/// non-manifold faces and seams once `V` is split or oriented.
pub(crate) fn stars(v: &[u32], n_vertices: usize, flagged: &[u32], pairs: Pairs) -> Stars {
    let faces = pairs != Pairs::No;
    let bits = usize::BITS - n_vertices.saturating_sub(1).leading_zeros();
    let shift = bits.saturating_sub(COARSE_BITS);
    let n_coarse = (n_vertices.saturating_sub(1) >> shift) + 1;
    let mut count = vec![0u32; n_coarse + 1];
    for &x in v {
        count[(x >> shift) as usize] += 1;
    }
    let mut census = FaceCensus::default();
    let mut opposites = Opposites::new(if faces { v.len() } else { 0 });
    let mut sums = Sums {
        flagged,
        faces: faces.then_some((&mut census, &mut opposites)),
        partners: pairs == Pairs::Partners,
        split_needed: false,
        vh: vec![NONE; n_vertices],
        edge_slots: Vec::new(),
        input_edges: 0,
        non_manifold_edges: 0,
        non_manifold_edge_examples: Vec::new(),
        multi_fan: Vec::new(),
    };
    let mut link = Link::new(n_vertices);
    // Rounds of coarse buckets, so that the records stay under 20 bytes per tetrahedron
    // (all of them would take 80).
    let budget = (v.len() / 4).max(1 << 16);
    let n_fine = 1usize << shift;
    let mask = (n_fine - 1) as u32;
    let mut fine_start = vec![0u32; n_fine + 1];
    let mut cursor = vec![0u32; n_fine];
    let mut records: Vec<Record> = Vec::new();
    let mut local: Vec<Record> = Vec::new();
    let cpu = || -> u64 {
        std::fs::read_to_string("/proc/thread-self/schedstat")
            .ok()
            .and_then(|s| s.split_whitespace().next().and_then(|x| x.parse().ok()))
            .unwrap_or(0)
    };
    let skip: u32 = std::env::var("STARS_SKIP")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    let (mut t_scatter, mut t_rest) = (0u64, 0u64);
    let mut first = 0;
    while first < n_coarse {
        let c0 = cpu();
        let mut last = first + 1;
        let mut total = count[first] as usize;
        while last < n_coarse && total + count[last] as usize <= budget {
            total += count[last] as usize;
            last += 1;
        }
        let mut start = vec![0u32; last - first + 1];
        for c in first..last {
            start[c - first + 1] = start[c - first] + count[c];
        }
        let mut fill = start.clone();
        // Grown once to the largest round; never cleared (every record is overwritten).
        if records.len() < total {
            records.resize(total, [0; 5]);
        }
        let (lo, hi) = ((first as u32) << shift, (last as u64) << shift);
        for (t, q) in v.chunks_exact(4).enumerate() {
            for i in 0..4u32 {
                let x = q[i as usize];
                if x < lo || x as u64 >= hi {
                    continue;
                }
                let [a, b, c] = super::link::OTHERS[i as usize].map(|j| q[j as usize]);
                let slot = &mut fill[((x >> shift) - first as u32) as usize];
                records[*slot as usize] = [4 * t as u32 + i, x, a, b, c];
                *slot += 1;
            }
        }
        drop(fill);
        let c1 = cpu();
        t_scatter += c1 - c0;
        for c in first..last {
            let bucket = &records[start[c - first] as usize..start[c - first + 1] as usize];
            if bucket.is_empty() {
                continue;
            }
            fine_start.fill(0);
            for r in bucket {
                fine_start[(r[1] & mask) as usize + 1] += 1;
            }
            for i in 0..n_fine {
                fine_start[i + 1] += fine_start[i];
            }
            if local.len() < bucket.len() {
                local.resize(bucket.len(), [0; 5]);
            }
            cursor.copy_from_slice(&fine_start[..n_fine]);
            for r in bucket {
                let slot = &mut cursor[(r[1] & mask) as usize];
                local[*slot as usize] = *r;
                *slot += 1;
            }
            for i in 0..n_fine {
                let star = &local[fine_start[i] as usize..fine_start[i + 1] as usize];
                if !star.is_empty() && skip != 1 {
                    link.star(star, &mut sums);
                }
            }
        }
        t_rest += cpu() - c1;
        first = last;
    }
    let c2 = cpu();
    let edge_bits = bits_from_slots(&sums.edge_slots, 6 * (v.len() / 4));
    let c3 = cpu();
    let mut multi_fan = sums.multi_fan;
    multi_fan.sort_unstable();
    let edge_census = EdgeCensus {
        input_edges: sums.input_edges,
        non_manifold: sums.non_manifold_edges,
        non_manifold_examples: sums.non_manifold_edge_examples.clone(),
        // Without a split the structure pairs are the input pairs.
        kept: sums.non_manifold_edges,
        kept_examples: sums.non_manifold_edge_examples,
        multi_fan,
    };
    let (vh, split_needed) = (sums.vh, sums.split_needed);
    let faces_out = faces.then(|| (census, opposites.finish()));
    if std::env::var("CHF_TIMING").is_ok() {
        let nt = (v.len() / 4) as f64;
        eprintln!(
            "    stars: scatter {:.1}, fine+work {:.1}, bits {:.1}, finish {:.1}",
            t_scatter as f64 / nt,
            t_rest as f64 / nt,
            (c3 - c2) as f64 / nt,
            (cpu() - c3) as f64 / nt
        );
    }
    Stars {
        split_needed,
        vh,
        edge_bits,
        census: edge_census,
        faces: faces_out,
    }
}

/// The rank bits of `n` slots with `slots` set: the slots are bucketed by window of bits
/// first (at most 512 windows), then each window's bits are set in cache.
pub(crate) fn bits_from_slots(slots: &[u64], n: usize) -> RankBits {
    let bits = u64::BITS - (n as u64).saturating_sub(1).leading_zeros();
    // Windows of at least one word, so that each word is written by one window.
    let shift = bits.saturating_sub(COARSE_BITS).max(6);
    let n_windows = (n.saturating_sub(1) >> shift) + 1;
    let mut start = vec![0u32; n_windows + 1];
    for &s in slots {
        start[(s >> shift) as usize + 1] += 1;
    }
    for w in 0..n_windows {
        start[w + 1] += start[w];
    }
    let mut fill = start.clone();
    let mut low = vec![0u32; slots.len()];
    for &s in slots {
        let f = &mut fill[(s >> shift) as usize];
        low[*f as usize] = (s & ((1 << shift) - 1)) as u32;
        *f += 1;
    }
    let mut words = vec![0u64; n.div_ceil(64)];
    for w in 0..n_windows {
        let base = w << (shift - 6);
        for &l in &low[start[w] as usize..start[w + 1] as usize] {
            words[base + (l >> 6) as usize] |= 1 << (l & 63);
        }
    }
    RankBits::from_words(words, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_land_in_place() {
        for n in [0usize, 1, 64, 65, 1000, 100_000] {
            let slots: Vec<u64> = (0..n as u64)
                .filter(|s| s % 7 == 3 || s % 11 == 0)
                .rev()
                .collect();
            let bits = bits_from_slots(&slots, n);
            for s in 0..n {
                assert_eq!(bits.get(s), s % 7 == 3 || s % 11 == 0, "n = {n}, slot {s}");
            }
            assert_eq!(bits.ones(), slots.len());
        }
    }
}
