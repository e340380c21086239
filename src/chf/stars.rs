//! One pass over the star of every vertex, from `V` alone: the faces and their pairs (`O`
//! and the face counts of the build report), whether every star is one piece (else the
//! vertex split must run), `VH`, the canonical slot of every fan (edge ids) and the edge
//! census. `link/` does the work on one star.
//!
//! Why one bucketed pass and no walks: on a large mesh the neighbours of a tetrahedron are
//! far away in memory, so every step of a walk through `O` misses the cache (and a random
//! write misses it too). One sequential scan of `V` writes a record per occurrence
//! (tetrahedron, vertex) to its vertex's bucket with a two-pass radix: the first pass
//! streams records to at most 512 coarse buckets (few enough write streams for the cache
//! and the TLB), the second sorts one coarse bucket at a time, in cache, by the low bits of
//! the vertex. The records of a vertex are then in tetrahedron order, hence half-face
//! order. Large meshes run in rounds over ranges of coarse buckets (each round rescans
//! `V`) so that the records never take more than 16 bytes per tetrahedron.
//! The pairs found and the canonical slots are written in place the same way, through
//! windows (`pairs.rs`, [`bits_from_slots`]).

use super::edges::EdgeCensus;
use super::link::{FaceCensus, Link, Record, Sums};
use super::pairs::Opposites;
use crate::NONE;
use crate::rank::RankBits;

/// 256 coarse buckets: the scatter's 256 write heads (a cache line each) stay in the L1
/// cache (512 took about 4% longer on the 1M-tetrahedron build; 128 no better).
const COARSE_BITS: u32 = 8;

/// What the pass found.
pub(crate) struct Stars {
    /// Some star is in several pieces: the vertex split must run (then the pass again),
    /// and `VH`, the edges and the census are incomplete.
    pub split_needed: bool,
    /// The number of edges (fans).
    pub num_edges: usize,
    /// With `tables`: `VH` and the canonical edge slots (else empty).
    pub vh: Vec<u32>,
    pub edge_bits: RankBits,
    /// The fans grouped by vertex pair (the ids of `V`).
    pub census: EdgeCensus,
    /// With pairs asked for: the face counts and the pairs, as a table like `O` (empty
    /// for the counts only).
    pub faces: Option<(FaceCensus, Vec<u32>)>,
}

/// Which pairs of half-faces to collect, with the face counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pairs {
    No,
    /// The face counts only.
    Census,
    /// Every triple of exactly two half-faces, whatever their direction (the build's
    /// partners, on the input's `V`).
    Partners,
    /// The twins by the rule of `O` (running opposite ways, not flagged).
    Opposites,
}

/// The pass over `V`. `flagged` (sorted) are half-faces never to pair: the build's
/// non-manifold faces and seams once `V` is split or oriented. With `tables`, also `VH` and
/// the edge bits (level 2); without, the build keeps less memory at levels 0 and 1.
pub(crate) fn stars(
    v: &[u32],
    n_vertices: usize,
    flagged: &[u32],
    pairs: Pairs,
    tables: bool,
) -> Stars {
    let faces = pairs != Pairs::No;
    let collect = matches!(pairs, Pairs::Partners | Pairs::Opposites);
    let bits = usize::BITS - n_vertices.saturating_sub(1).leading_zeros();
    // At most 2^16 vertices per coarse bucket, so that the second pass's counts stay small
    // (past 2^24 vertices there are more than 256 coarse buckets).
    let shift = bits.saturating_sub(COARSE_BITS).min(16);
    let n_coarse = (n_vertices.saturating_sub(1) >> shift) + 1;
    let mut count = vec![0u32; n_coarse + 1];
    for &x in v {
        count[(x >> shift) as usize] += 1;
    }
    let mut census = FaceCensus::default();
    let mut opposites = Opposites::new(if collect { v.len() } else { 0 });
    let mut sums = Sums {
        flagged,
        faces: faces.then_some((&mut census, &mut opposites)),
        collect,
        partners: pairs == Pairs::Partners,
        tables,
        split_needed: false,
        vh: if tables {
            crate::pages::filled(n_vertices, NONE)
        } else {
            Vec::new()
        },
        // About one edge per vertex and per tetrahedron, plus one per boundary face pair
        // (Euler): reserved at once, so that growing by doubling copies nothing at the peak.
        edge_slots: if tables {
            crate::pages::with_capacity(n_vertices + v.len() / 4 + v.len() / 16)
        } else {
            Vec::new()
        },
        num_edges: 0,
        input_edges: 0,
        non_manifold_edges: 0,
        non_manifold_edge_examples: Vec::new(),
        multi_fan: Vec::new(),
    };
    let mut link = Link::new(n_vertices);
    // Rounds of coarse buckets, so that the records stay under 16 bytes per tetrahedron
    // (all of them would take 80): as many `u32` as `O` has entries, so that `O` can then
    // take over the buffer (fresh memory costs a page fault per 4 KB).
    // With the level-2 tables the final structure is larger, so the records may take 20
    // bytes per tetrahedron at the same peak ratio: four rounds instead of five, each a
    // pass over `V` (about 4% of the build; three rounds would take 27 bytes and lift the
    // level-2 peak to about twice the final size).
    let budget = (v.len() / if tables { 4 } else { 5 }).max(1 << 16);
    let n_fine = 1usize << shift;
    let mask = (n_fine - 1) as u32;
    let mut fine_start = vec![0u32; n_fine + 1];
    let mut cursor = vec![0u32; n_fine];
    // Flat records, five `u32` each; one spare record at the end takes the writes of the
    // occurrences outside the round (so that the scatter has no branch).
    // (A small mesh reserves what its one round needs, not the budget.)
    let mut records: Vec<u32> =
        crate::pages::with_capacity(v.len().max(5 * (budget.min(v.len()) + 1)));
    let mut local: Vec<Record> = Vec::new();
    let mut first = 0;
    while first < n_coarse {
        let mut last = first + 1;
        let mut total = count[first] as usize;
        while last < n_coarse && total + count[last] as usize <= budget {
            total += count[last] as usize;
            last += 1;
        }
        let span = (last - first) as u32;
        let mut start = vec![0u32; last - first + 2];
        for c in first..last {
            start[c - first + 1] = start[c - first] + count[c];
        }
        let mut fill = start.clone();
        // The spare record, never advanced.
        fill[span as usize] = total as u32;
        // Grown once to the largest round; never cleared (every record is overwritten).
        if records.len() < 5 * (total + 1) {
            records.resize(5 * (total + 1), 0);
        }
        for (t, q) in v.chunks_exact(4).enumerate() {
            for i in 0..4u32 {
                let x = q[i as usize];
                let c = (x >> shift).wrapping_sub(first as u32);
                let inside = c < span;
                let bucket = if inside { c } else { span } as usize;
                let [a, b, c] = super::link::OTHERS[i as usize].map(|j| q[j as usize]);
                let at = 5 * fill[bucket] as usize;
                records[at..at + 5].copy_from_slice(&[4 * t as u32 + i, x, a, b, c]);
                fill[bucket] += inside as u32;
            }
        }
        drop(fill);
        for c in first..last {
            let bucket = &records[5 * start[c - first] as usize..5 * start[c - first + 1] as usize];
            if bucket.is_empty() {
                continue;
            }
            let bucket = || {
                bucket
                    .chunks_exact(5)
                    .map(|r| [r[0], r[1], r[2], r[3], r[4]])
            };
            fine_start.fill(0);
            for r in bucket() {
                fine_start[(r[1] & mask) as usize + 1] += 1;
            }
            for i in 0..n_fine {
                fine_start[i + 1] += fine_start[i];
            }
            let size = fine_start[n_fine] as usize;
            if local.len() < size {
                local.resize(size, [0; 5]);
            }
            cursor.copy_from_slice(&fine_start[..n_fine]);
            for r in bucket() {
                let slot = &mut cursor[(r[1] & mask) as usize];
                local[*slot as usize] = r;
                *slot += 1;
            }
            for i in 0..n_fine {
                let star = &local[fine_start[i] as usize..fine_start[i + 1] as usize];
                if !star.is_empty() {
                    link.star(star, &mut sums);
                }
            }
        }
        first = last;
    }
    let Sums {
        split_needed,
        vh,
        edge_slots,
        num_edges,
        input_edges,
        non_manifold_edges,
        non_manifold_edge_examples,
        mut multi_fan,
        ..
    } = sums;
    // The pairs' memory then serves the edge bits.
    let (o, scratch) = if collect {
        let (o, scratch) = opposites.finish(records);
        (o, scratch)
    } else {
        (Vec::new(), Vec::new())
    };
    let edge_bits = if tables {
        bits_from_slots(&edge_slots, 6 * (v.len() / 4), scratch)
    } else {
        RankBits::default()
    };
    multi_fan.sort_unstable();
    let edge_census = EdgeCensus {
        input_edges,
        non_manifold: non_manifold_edges,
        non_manifold_examples: non_manifold_edge_examples.clone(),
        // Without a split the structure pairs are the input pairs.
        kept: non_manifold_edges,
        kept_examples: non_manifold_edge_examples,
        multi_fan,
    };
    let faces_out = faces.then_some((census, o));
    Stars {
        split_needed,
        num_edges,
        vh,
        edge_bits,
        census: edge_census,
        faces: faces_out,
    }
}

/// The rank bits of `n` slots with `slots` set: the slots are bucketed by window of bits
/// first (at most 512 windows), then each window's bits are set in cache. `scratch` is
/// memory to reuse.
pub(crate) fn bits_from_slots(slots: &[u64], n: usize, scratch: Vec<u64>) -> RankBits {
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
    let mut low = scratch;
    low.clear();
    low.resize(slots.len(), 0);
    for &s in slots {
        let f = &mut fill[(s >> shift) as usize];
        low[*f as usize] = s & ((1 << shift) - 1);
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
            let bits = bits_from_slots(&slots, n, Vec::new());
            for s in 0..n {
                assert_eq!(bits.get(s), s % 7 == 3 || s % 11 == 0, "n = {n}, slot {s}");
            }
            assert_eq!(bits.ones(), slots.len());
        }
    }
}

#[cfg(test)]
mod against_walks {
    use super::*;
    use crate::chf::ids::{FACE, first, local, tet};
    use crate::chf::{Chf, ChfBuildOptions, edges};

    /// The first boundary half-face holding each vertex, else the first half-face.
    fn vh_by_scan(v: &[u32], o: &[u32], n: usize) -> Vec<u32> {
        let mut vh = vec![NONE; n];
        for hf in 0..v.len() as u32 {
            let base = first(tet(hf)) as usize;
            for l in FACE[local(hf) as usize] {
                let slot = &mut vh[v[base + l as usize] as usize];
                if *slot == NONE || (o[hf as usize] == NONE && o[*slot as usize] != NONE) {
                    *slot = hf;
                }
            }
        }
        vh
    }

    #[test]
    fn stars_match_walking_the_fans() {
        let mut x = 0x1234_5678_9ABC_DEF0u64;
        let mut rnd = |m: usize| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % m as u64) as u32
        };
        for round in 0..200 {
            // Random soups: duplicates, non-manifold faces and edges, pinched links, seams.
            let n = 6 + round % 20;
            let tets: Vec<[u32; 4]> = (0..10 + round % 60)
                .map(|_| [0; 4].map(|_| rnd(n)))
                .collect();
            let chf = Chf::from_tetrahedra(&tets, n, &[], ChfBuildOptions::level(1)).unwrap();
            let flagged = crate::chf::build::merged(&chf.non_manifold, &chf.seams);
            let stars = stars(&chf.v, chf.n_vertices, &flagged, Pairs::Opposites, true);
            assert!(!stars.split_needed);
            let walked = edges::canonical_slots(&chf.v, &chf.o);
            let n_slots = 6 * chf.num_tetrahedra();
            for s in 0..n_slots {
                assert_eq!(
                    stars.edge_bits.get(s),
                    walked.get(s),
                    "round {round}, slot {s}"
                );
            }
            assert_eq!(
                stars.vh,
                vh_by_scan(&chf.v, &chf.o, chf.n_vertices),
                "round {round}"
            );
            assert_eq!(stars.faces.unwrap().1, chf.o, "round {round}");
        }
    }
}
