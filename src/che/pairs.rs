//! Grouping half-edges by unordered vertex pair, for the build's matching step and for `O`
//! computed from `V` (raising level 0, and queries at level 0): a two-pass radix buckets the
//! half-edges by their smaller vertex (see [`for_each_group`]), then each (small) bucket is
//! sorted by the larger vertex. O(T) plus tiny sorts; no hash map, no global comparison sort.

use super::ids::next;
use crate::NONE;
use crate::error::Result;
use crate::util::alloc::{try_resize, try_to_vec, try_vec};

/// Calls `f(min, max, group)` for every unordered vertex pair of `v`, in increasing
/// (min, max) order; `group` holds packed keys `(max << 32) | h` whose low 32 bits are the
/// half-edges on that pair, in increasing order.
///
/// A two-pass radix on the smaller vertex: the first pass scatters to at most 2048 coarse
/// buckets (streaming writes, where one scatter per vertex would miss the cache on every
/// half-edge of a large mesh), the second sorts one coarse bucket at a time in cache.
/// The first pass stores one `u64` per half-edge, `[fine | max | h]`, where `fine` is the low
/// bits of the smaller vertex (the coarse bucket holds the rest): 8 bytes of fresh memory
/// per half-edge instead of 12. When those three fields need more than 64 bits (see
/// `Layout::new`), the fine bits go to a second array.
pub(crate) fn for_each_group(
    v: &[u32], n_vertices: usize, f: impl FnMut(u32, u32, &[u64]) + Send,
) -> Result<()> {
    let mut f = Some(f);
    let grouping = Grouping {
        threads: 1,
        allow_packed: true,
    };
    groups(
        v,
        n_vertices,
        grouping,
        || f.take().expect("one thread, one state"),
        |f, a, b, g| f(a, b, g),
    )?;
    Ok(())
}

/// [`for_each_group`] on up to `threads` threads: each takes the pairs of a range of
/// smaller vertices, in order, with a state of its own from `state()`; the states come
/// back in the order of their ranges.
pub(crate) fn for_each_group_par<S: Send>(
    v: &[u32], n_vertices: usize, threads: usize, state: impl FnMut() -> S,
    f: impl Fn(&mut S, u32, u32, &[u64]) + Sync,
) -> Result<Vec<S>> {
    let grouping = Grouping {
        threads,
        allow_packed: true,
    };
    groups(v, n_vertices, grouping, state, f)
}

/// How to group: on how many threads, and whether the packed keys may be used (tests take
/// every path).
#[derive(Clone, Copy)]
struct Grouping {
    threads: usize,
    allow_packed: bool,
}

/// [`for_each_group_par`] on `threads` threads whatever the size: the first pass scatters
/// to coarse buckets, then each thread visits a run of them.
fn groups<S: Send>(
    v: &[u32], n_vertices: usize, grouping: Grouping, mut state: impl FnMut() -> S,
    f: impl Fn(&mut S, u32, u32, &[u64]) + Sync,
) -> Result<Vec<S>> {
    let layout = Layout::new(n_vertices, v.len(), grouping.allow_packed);
    let threads = grouping.threads.clamp(1, layout.n_coarse);
    let scattered = scatter(v, &layout, threads)?;
    let cuts = cuts(&scattered, &layout, threads, v.len());
    let jobs: Vec<_> = cuts.windows(2).map(|w| (w[0], w[1], state())).collect();
    let (scattered, layout, f) = (&scattered, &layout, &f);
    crate::util::par::run_all(jobs, |(first, last, mut s)| {
        visit_buckets(scattered, layout, first..last, &mut s, f)?;
        Ok(s)
    })
    .into_iter()
    .collect()
}

/// Where the fields of a key sit, and the sizes of the buckets.
struct Layout {
    /// Bits of a vertex id below the coarse bucket.
    shift: u32,
    n_coarse: usize,
    /// One `u64` per half-edge, `[fine | max | h]`; else the fine bits live in `mins`.
    packed: bool,
    max_at: u32,
    fine_at: u32,
    fine_mask: u32,
}

impl Layout {
    fn new(n_vertices: usize, n_half_edges: usize, allow_packed: bool) -> Self {
        const COARSE_BITS: u32 = 11;
        let bits_of = |n: usize| usize::BITS - n.saturating_sub(1).leading_zeros();
        let vertex_bits = bits_of(n_vertices);
        let shift = vertex_bits.saturating_sub(COARSE_BITS);
        let h_bits = bits_of(n_half_edges);
        let packed = allow_packed && shift + vertex_bits + h_bits <= 64;
        let (max_at, fine_at) = if packed {
            (h_bits, h_bits + vertex_bits)
        } else {
            (32, 64)
        };
        Layout {
            shift,
            n_coarse: (n_vertices.saturating_sub(1) >> shift) + 1,
            packed,
            max_at,
            fine_at,
            fine_mask: (1u32 << shift) - 1,
        }
    }
}

/// The ends of half-edge `h`, smaller first.
#[inline(always)]
fn ends(v: &[u32], h: u32) -> (u32, u32) {
    let (a, b) = (v[h as usize], v[next(h) as usize]);
    (a.min(b), a.max(b))
}

/// The first pass's output: each thread's part of the half-edges, its coarse bucket
/// starts in its region, and the keys (and smaller vertices when not packed).
struct Scattered {
    parts: Vec<(u32, u32)>,
    starts: Vec<Vec<u32>>,
    keys: Vec<u64>,
    mins: Vec<u32>,
}

impl Scattered {
    /// Half-edges in coarse bucket `c`.
    fn count(&self, c: usize) -> usize {
        self.starts.iter().map(|s| (s[c + 1] - s[c]) as usize).sum()
    }
}

/// What the per-thread cursors of the coarse buckets are called when they do not fit.
const COARSE: &str = "the coarse buckets";

/// First pass: each thread scatters a contiguous part of the half-edges to a region of its
/// own of the keys, bucket after bucket; a coarse bucket is then its piece of every region
/// in turn (in half-edge order).
fn scatter(v: &[u32], layout: &Layout, threads: usize) -> Result<Scattered> {
    let shift = layout.shift;
    let part_len = v.len().div_ceil(threads).max(1);
    let parts: Vec<(u32, u32)> = (0..v.len())
        .step_by(part_len)
        .map(|a| (a as u32, (a + part_len).min(v.len()) as u32))
        .collect();
    let starts = crate::util::par::run_all(parts.clone(), |(a, b)| {
        let mut start = try_vec(layout.n_coarse + 1, 0u32, COARSE)?;
        for h in a..b {
            start[(ends(v, h).0 >> shift) as usize + 1] += 1;
        }
        for c in 0..layout.n_coarse {
            start[c + 1] += start[c];
        }
        Ok(start)
    });
    let starts: Vec<Vec<u32>> = starts.into_iter().collect::<Result<_>>()?;
    let mut keys: Vec<u64> = crate::util::pages::zeroed(v.len(), "the half-edge pair keys")?;
    let mut mins: Vec<u32> = if layout.packed {
        Vec::new()
    } else {
        crate::util::pages::zeroed(v.len(), "the half-edge pair keys")?
    };
    {
        let mut min_parts: Vec<&mut [u32]> = if layout.packed {
            parts.iter().map(|_| &mut [][..]).collect()
        } else {
            mins.chunks_mut(part_len).collect()
        };
        let jobs: Vec<_> = keys
            .chunks_mut(part_len)
            .zip(min_parts.drain(..))
            .zip(parts.iter().zip(&starts))
            .collect();
        let filled = crate::util::par::run_all(jobs, |((keys, mins), (&(a, b), start))| {
            let mut fill = try_to_vec(start, COARSE)?;
            for h in a..b {
                let (min, max) = ends(v, h);
                let slot = &mut fill[(min >> shift) as usize];
                let fine = if layout.packed {
                    ((min & layout.fine_mask) as u64) << layout.fine_at
                } else {
                    mins[*slot as usize] = min;
                    0
                };
                keys[*slot as usize] = fine | ((max as u64) << layout.max_at) | h as u64;
                *slot += 1;
            }
            Ok(())
        });
        filled.into_iter().collect::<Result<()>>()?;
    }
    Ok(Scattered {
        parts,
        starts,
        keys,
        mins,
    })
}

/// Where the threads' runs of coarse buckets begin (and the last ends): about an equal
/// share of the half-edges each.
fn cuts(scattered: &Scattered, layout: &Layout, threads: usize, total: usize) -> Vec<usize> {
    let mut cuts = vec![0];
    let mut acc = 0;
    for c in 0..layout.n_coarse {
        acc += scattered.count(c);
        if cuts.len() < threads && acc * threads >= total * cuts.len() {
            cuts.push(c + 1);
        }
    }
    while cuts.len() <= threads {
        cuts.push(layout.n_coarse);
    }
    cuts
}

/// Second pass over the coarse buckets `range`, one at a time: by the low bits of the
/// smaller vertex, then each fine bucket sorted and cut into groups for `f`.
fn visit_buckets<S>(
    sc: &Scattered, layout: &Layout, range: std::ops::Range<usize>, s: &mut S,
    f: &impl Fn(&mut S, u32, u32, &[u64]),
) -> Result<()> {
    let shift = layout.shift;
    let n_fine = 1usize << shift;
    let mut fine_start = try_vec(n_fine + 1, 0u32, "the pair grouping's fine buckets")?;
    let mut cursor = try_vec(n_fine + 1, 0u32, "the pair grouping's fine buckets")?;
    let mut local: Vec<u64> = Vec::new();
    let h_mask = (1u64 << layout.max_at) - 1;
    let max_mask = (1u64 << (layout.fine_at - layout.max_at)) - 1;
    for c in range {
        let len = sc.count(c);
        if len == 0 {
            continue;
        }
        // The bucket's keys (and smaller vertices), part after part, with their fine bits.
        let pieces = Pieces {
            parts: &sc.parts,
            starts: &sc.starts,
            keys: &sc.keys,
            mins: &sc.mins,
            c,
            fine: if layout.packed {
                Some(layout.fine_at)
            } else {
                None
            },
            fine_mask: layout.fine_mask,
        };
        fine_start.fill(0);
        pieces.each(|fine, _| fine_start[fine as usize + 1] += 1);
        for i in 0..n_fine {
            fine_start[i + 1] += fine_start[i];
        }
        local.clear();
        try_resize(&mut local, len, 0, "the pair grouping's bucket")?;
        cursor.copy_from_slice(&fine_start);
        pieces.each(|fine, k| {
            let slot = &mut cursor[fine as usize];
            // The group format: (max << 32) | h.
            local[*slot as usize] = ((k >> layout.max_at) & max_mask) << 32 | (k & h_mask);
            *slot += 1;
        });
        for i in 0..n_fine {
            let bucket = &mut local[fine_start[i] as usize..fine_start[i + 1] as usize];
            visit_fine_bucket(bucket, ((c << shift) | i) as u32, s, f);
        }
    }
    Ok(())
}

/// Sorts one fine bucket (the pairs of smaller vertex `min`) and calls `f` per group.
#[inline(always)]
fn visit_fine_bucket<S>(
    bucket: &mut [u64], min: u32, s: &mut S, f: &impl Fn(&mut S, u32, u32, &[u64]),
) {
    if bucket.len() > 1 {
        bucket.sort_unstable();
    }
    let mut j = 0;
    while j < bucket.len() {
        let max = bucket[j] >> 32;
        let mut k = j + 1;
        while k < bucket.len() && bucket[k] >> 32 == max {
            k += 1;
        }
        f(s, min, max as u32, &bucket[j..k]);
        j = k;
    }
}

/// One coarse bucket of the keys: its piece of every part's region in turn.
struct Pieces<'a> {
    parts: &'a [(u32, u32)],
    starts: &'a [Vec<u32>],
    keys: &'a [u64],
    mins: &'a [u32],
    c: usize,
    /// Where the fine bits sit in a packed key; `None`: in `mins`.
    fine: Option<u32>,
    fine_mask: u32,
}

impl Pieces<'_> {
    /// `g(fine bits, key)` for every key of the bucket, in half-edge order.
    #[inline(always)]
    fn each(&self, mut g: impl FnMut(u32, u64)) {
        let c = self.c;
        for (&(a, _), st) in self.parts.iter().zip(self.starts) {
            let range = a as usize + st[c] as usize..a as usize + st[c + 1] as usize;
            match self.fine {
                Some(at) => {
                    for &k in &self.keys[range] {
                        g((k >> at) as u32 & self.fine_mask, k);
                    }
                }
                None => {
                    for (&k, &m) in self.keys[range.clone()].iter().zip(&self.mins[range]) {
                        g(m & self.fine_mask, k);
                    }
                }
            }
        }
    }
}

/// The half-edge packed in a group key.
#[inline]
pub(crate) fn half_edge(key: u64) -> u32 {
    key as u32
}

/// Opposites of an already canonical `V` (oriented, split): `h` and `g` are opposite when
/// they are the only two half-edges on their vertex pair, run opposite ways, and are not
/// flagged non-manifold. Level 0 queries answer with the same rule by scanning.
pub(crate) fn opposites_by_rule(
    v: &[u32], n_vertices: usize, non_manifold: &[u32],
) -> Result<Vec<u32>> {
    let mut o = try_vec(v.len(), NONE, "the opposites O")?;
    for_each_group(v, n_vertices, |_, _, group| {
        if let [a, b] = *group {
            let (h, g) = (half_edge(a), half_edge(b));
            if v[h as usize] != v[g as usize] && non_manifold.binary_search(&h).is_err() {
                o[h as usize] = g;
                o[g as usize] = h;
            }
        }
    })?;
    Ok(o)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_collect_both_directions() {
        // Two triangles sharing edge {1, 2}: (0,1,2) and (2,1,3).
        let v = [0, 1, 2, 2, 1, 3];
        let mut seen = Vec::new();
        for_each_group(&v, 4, |a, b, g| {
            seen.push((a, b, g.iter().map(|&k| half_edge(k)).collect::<Vec<_>>()))
        })
        .unwrap();
        assert_eq!(
            seen,
            vec![
                (0, 1, vec![0]),
                (0, 2, vec![2]),
                (1, 2, vec![1, 3]),
                (1, 3, vec![4]),
                (2, 3, vec![5]),
            ]
        );
        let o = opposites_by_rule(&v, 4, &[]).unwrap();
        assert_eq!(o, vec![NONE, 3, NONE, 1, NONE, NONE]);
    }

    #[test]
    fn groups_match_a_map_on_many_vertices() {
        // Enough vertices for both radix passes to have more than one bucket.
        for n in [2047usize, 2048, 2049, 5000, 70_000] {
            let mut rnd = crate::util::test_rng(12345u64);
            let v: Vec<u32> = (0..3 * 4000).map(|_| rnd(n)).collect();
            let mut expected = std::collections::BTreeMap::<(u32, u32), Vec<u32>>::new();
            for h in 0..v.len() as u32 {
                let (a, b) = (v[h as usize], v[next(h) as usize]);
                expected.entry((a.min(b), a.max(b))).or_default().push(h);
            }
            let expected: Vec<_> = expected.into_iter().collect();
            for packed in [true, false] {
                for threads in [1, 3] {
                    let grouping = Grouping {
                        threads,
                        allow_packed: packed,
                    };
                    let got: Vec<_> = groups(&v, n, grouping, Vec::new, |got, a, b, g| {
                        got.push(((a, b), g.iter().map(|&k| half_edge(k)).collect::<Vec<_>>()))
                    })
                    .unwrap()
                    .concat();
                    assert_eq!(got, expected, "n = {n}, packed {packed}, {threads} threads");
                }
            }
        }
    }
}
