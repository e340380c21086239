//! Whole-mesh passes that answer only "valid or not" for the pairs of `O`, the rotations
//! from `VH` (from level 2 both in one walk of the stars) and the edge directory. They are
//! what a full open of a level file pays on a valid file, so they are written for the
//! memory system: arrays read in order where the invariant allows it, each pair checked
//! once, several rotations walked at once so that their cache misses overlap instead of
//! waiting one after another, and the far reads
//! (a partner, a rotation's next triangle) prefetched: a prefetch retires at once, where a
//! load that misses holds up every instruction behind it. They name no element: on a
//! failure the per-element checks of `validate` run and name the first.

use crate::NONE;
use crate::che::ids::{next, prev};
use crate::che::tables::is_canonical;
use crate::util::par::{planned_threads, run_all};
use crate::util::prefetch::prefetch;
use crate::util::rank::try_for_each_one;
use crate::util::rank_directory::SPAN;
use std::ops::Range;

/// Contiguous parts of `0..n`, one per thread the machine runs.
fn parts(n: usize) -> Vec<Range<usize>> {
    let part = n.div_ceil(planned_threads(0, n).max(1)).max(1);
    (0..n).step_by(part).map(|a| a..(a + part).min(n)).collect()
}

/// `f` on the [`parts`] of `0..n`, each on a thread; the sum of the answers, or `None`
/// when one part has none.
fn sum_over_parts(n: usize, f: impl Fn(Range<usize>) -> Option<usize> + Sync) -> Option<usize> {
    run_all(parts(n), f).into_iter().sum()
}

/// The live canonical half-edges (the edges), when every `O[h]` pairs `h` with a live
/// half-edge on the same vertex pair run the other way whose `O` is `h`, and a removed
/// half-edge pairs with nothing; else `None`. `o` and `v` have the same length, a multiple
/// of 3.
///
/// Every `h` reads `O[O[h]]`, but the vertex pair is compared from the smaller half-edge
/// only: the condition is the same from either side, and the larger side's `O[O[h]] = h`
/// sends it there.
pub(super) fn pairs_hold(v: &[u32], o: &[u32]) -> Option<usize> {
    sum_over_parts(o.len(), |hs| {
        let mut edges = 0;
        let end = hs.end;
        for h in hs {
            if h + PAIRS_AHEAD < end {
                let g = o[h + PAIRS_AHEAD] as usize;
                prefetch(o, g);
                prefetch(v, g);
                // `V[next(g)]` too, on another line in 2 triangles of 16 (and `next` only
                // of a half-edge: of `NONE` it would overflow).
                if g < v.len() {
                    prefetch(v, next(g as u32) as usize);
                }
            }
            let (g, live) = (o[h], v[h] != NONE);
            if g == NONE {
                edges += usize::from(live);
                continue;
            }
            let gu = g as usize;
            if !live || gu >= o.len() || gu == h || o[gu] != h as u32 {
                return None;
            }
            if h < gu {
                let h32 = h as u32;
                if v[gu] != v[next(h32) as usize] || v[next(g) as usize] != v[h] {
                    return None;
                }
                edges += 1;
            }
        }
        Some(edges)
    })
}

/// How far ahead of its check a pair's partner is prefetched, in half-edges: far enough
/// for the line to arrive first, near enough to stay in cache until then.
const PAIRS_AHEAD: usize = 96;

/// Rotations walked at once by one thread: enough independent misses to keep the memory
/// system busy while each lane's next triangle is fetched.
const LANES: usize = 32;

/// Whether the rotations from `VH` meet `live` outgoing half-edges in all, each `VH[x]`
/// starting at `x`. With `O` an involution on matching edges (checked before), a rotation
/// stays among its vertex's outgoing half-edges and meets none twice, so the rotations
/// are disjoint; the total is `live` exactly when each meets all of its vertex's, that is
/// when every star is one fan, entered at its boundary half-edge when it has one.
pub(super) fn rotations_cover(v: &[u32], o: &[u32], vh: &[u32], live: usize) -> bool {
    sum_over_parts(vh.len(), |xs| rotation_steps(v, o, vh, xs)) == Some(live)
}

/// The outgoing half-edges the rotations of the vertices `xs` meet, walked `LANES` at a
/// time; `None` when a `VH[x]` is out of range or does not start at `x`, or after more
/// steps than half-edges (an `O` that is no involution can send a rotation round a loop
/// that misses its start).
fn rotation_steps(v: &[u32], o: &[u32], vh: &[u32], xs: Range<usize>) -> Option<usize> {
    // Each lane: the rotation's start and its next outgoing half-edge (`NONE`: idle).
    let (mut start, mut cur) = ([NONE; LANES], [NONE; LANES]);
    let (mut next_x, mut steps) = (xs.start, 0usize);
    loop {
        let mut busy = false;
        for lane in 0..LANES {
            if cur[lane] == NONE {
                // Refill the lane with the next vertex that has a star.
                let Some((_, h)) = next_star(v, o, vh, &mut next_x, xs.end).ok()? else {
                    continue;
                };
                (start[lane], cur[lane]) = (h, h);
            }
            busy = true;
            steps += 1;
            if steps > v.len() {
                return None;
            }
            let around = o[prev(cur[lane]) as usize];
            // The lane's next step reads `around`'s triangle, after the other lanes' steps.
            prefetch(o, around as usize);
            cur[lane] = if around == start[lane] { NONE } else { around };
        }
        if !busy {
            return Some(steps);
        }
    }
}

/// [`pairs_hold`] and [`rotations_cover`] in one walk, for a mesh with no removed
/// half-edge: how many half-edges have no partner when every rotation from `VH` is one fan
/// entered at its boundary half-edge and `O` is an involution on matching edges, else
/// `None`. Each step from `c` (outgoing from `x`) reads `g = O[prev(c)]`, and its next
/// step, which reads `g`'s triangle anyway, checks `O[g] = prev(c)` and `V[g] = x`, so
/// that each pair costs the walk's one line of `O` and one of `V` instead of a pass of its
/// own. Why that is the whole of both checks:
/// with every step's pair checked, two steps cannot reach one half-edge (their `prev`s
/// would both be its partner), so the walks are simple and, one per vertex, disjoint;
/// meeting all `len(V)` half-edges, they check every paired half-edge once as a `prev`,
/// and each pair from both of its sides.
pub(super) fn stars_hold(v: &[u32], o: &[u32], vh: &[u32]) -> Option<usize> {
    let walked = run_all(parts(vh.len()), |xs| walk_stars(v, o, vh, xs));
    let (mut steps, mut unpaired) = (0, 0);
    for part in walked {
        let (s, u) = part?;
        steps += s;
        unpaired += u;
    }
    (steps == v.len()).then_some(unpaired)
}

/// One lane of [`walk_stars`]: the rotation's start and vertex, its next outgoing
/// half-edge (`NONE`: idle), and the half-edge that led there (`NONE`: none to check).
#[derive(Clone, Copy)]
struct Lane {
    start: u32,
    x: u32,
    cur: u32,
    from: u32,
}

const IDLE: Lane = Lane {
    start: NONE,
    x: NONE,
    cur: NONE,
    from: NONE,
};

/// The steps and unpaired half-edges of the rotations of the vertices `xs`, each
/// pair checked as [`stars_hold`] says; `None` on the first violation.
fn walk_stars(v: &[u32], o: &[u32], vh: &[u32], xs: Range<usize>) -> Option<(usize, usize)> {
    let mut lanes = [IDLE; STAR_LANES];
    let (mut next_x, mut steps, mut unpaired) = (xs.start, 0usize, 0usize);
    loop {
        let mut busy = false;
        for lane in &mut lanes {
            if lane.cur == NONE {
                let Some((x, h)) = next_star(v, o, vh, &mut next_x, xs.end).ok()? else {
                    continue;
                };
                *lane = Lane {
                    start: h,
                    x,
                    cur: h,
                    from: NONE,
                };
            }
            busy = true;
            let c = lane.cur;
            if lane.from != NONE {
                if o[c as usize] != lane.from || v[c as usize] != lane.x {
                    return None;
                }
                if c == lane.start {
                    // The fan closed, its last pair checked here like any other step's
                    // (on lines prefetched a round of the lanes ago, not on the spot).
                    lane.cur = NONE;
                    continue;
                }
            }
            steps += 1;
            if steps > v.len() {
                return None;
            }
            let p = prev(c);
            let g = o[p as usize];
            if g == NONE {
                unpaired += 1;
                lane.cur = NONE;
                continue;
            }
            if g as usize >= o.len() {
                return None;
            }
            // What the lane's next visit reads: `O[g]` and `V[g]` (the check), `O[prev(g)]`
            // (the step). A triangle's entries of `O` straddle two lines in 2 triangles of
            // 16, and a step that waits on the second line holds up every lane behind it.
            prefetch(o, g as usize);
            prefetch(o, prev(g) as usize);
            prefetch(v, g as usize);
            (lane.cur, lane.from) = (g, p);
        }
        if !busy {
            return Some((steps, unpaired));
        }
    }
}

/// Rotations walked at once by [`walk_stars`], whose steps wait on two lines each.
const STAR_LANES: usize = 128;

/// How many vertices ahead of a refill [`next_star`] prefetches a star's start.
const STARTS_AHEAD: usize = 16;

/// The next vertex from `*next_x` on (below `end`) that has a star, and its `VH`,
/// `*next_x` moved past it: `Ok(None)` when none is left, `Err` when its `VH` is out of
/// range or does not start at it. `o` is only prefetched from.
#[inline]
fn next_star(
    v: &[u32], o: &[u32], vh: &[u32], next_x: &mut usize, end: usize,
) -> Result<Option<(u32, u32)>, ()> {
    while *next_x < end && vh[*next_x] == NONE {
        *next_x += 1;
    }
    if *next_x == end {
        return Ok(None);
    }
    let (x, h) = (*next_x, vh[*next_x]);
    // What this check and the first step read of a star a few vertices on: the starts
    // lie far apart, and a refill that waits on them holds up every lane.
    // (Only a half-edge: `prev` of `NONE` or of a corrupted id past `V` would overflow.)
    if let Some(&ahead) = vh.get(x + STARTS_AHEAD)
        && (ahead as usize) < v.len()
    {
        prefetch(v, ahead as usize);
        prefetch(o, prev(ahead) as usize);
    }
    if h as usize >= v.len() || v[h as usize] as usize != x {
        return Err(());
    }
    *next_x += 1;
    Ok(Some((x as u32, h)))
}

/// Whether every triangle of `v` is three distinct vertices below `n`.
pub(super) fn triangles_hold(v: &[u32], n: usize) -> bool {
    let holds = |c: &[u32]| {
        let below = |x: u32| (x as usize) < n;
        below(c[0]) && below(c[1]) && below(c[2]) && c[0] != c[1] && c[1] != c[2] && c[0] != c[2]
    };
    sum_over_parts(v.len() / 3, |ts| {
        v[3 * ts.start..3 * ts.end]
            .chunks_exact(3)
            .all(holds)
            .then_some(0)
    })
    .is_some()
}

/// Whether the edge directory (its `entries`: flags in the low half, the rank before them
/// in the high half) flags exactly the canonical half-edges of `o`, each rank counts the
/// flags before it, and `EH` (as many entries as the directory has flags, checked before)
/// lists them in increasing order: edge `e` is the `e`-th. An entry at a time: the
/// canonical half-edges of its span as a mask, compared with its flags, then its set bits
/// with `EH` from its rank on, with no branch on whether a half-edge is canonical (a coin
/// toss, which a branch predictor loses half the time). Each part of the entries checks
/// its ranks from its first; the parts' ranks then chain from 0 to the length of `EH`.
pub(super) fn edge_directory_holds(o: &[u32], eh: &[u32], entries: &[u64]) -> bool {
    if entries.len() != o.len().div_ceil(SPAN) {
        return false;
    }
    let ranks = run_all(parts(entries.len()), |ks| {
        let first = entries.get(ks.start).map_or(0, |&d| (d >> 32) as usize);
        ks.into_iter()
            .try_fold(first, |e, k| entry_holds(o, eh, entries[k], k * SPAN, e))
            .map(|end| (first, end))
    });
    let mut e = 0;
    for part in ranks {
        match part {
            Some((first, end)) if first == e => e = end,
            _ => return false,
        }
    }
    e == eh.len()
}

/// The rank after directory entry `d`, whose span of `O` starts at `base`, when its rank is
/// `e`, its flags are the canonical half-edges of the span and `EH` lists them from `e` on.
fn entry_holds(o: &[u32], eh: &[u32], d: u64, base: usize, e: usize) -> Option<usize> {
    let mask = (base..(base + SPAN).min(o.len()))
        .fold(0u32, |m, h| m | u32::from(is_canonical(o, h)) << (h - base));
    if mask != d as u32 || (d >> 32) as usize != e {
        return None;
    }
    let n = mask.count_ones() as usize;
    let mut listed = eh.get(e..e + n)?.iter();
    try_for_each_one(u64::from(mask), base, |h| match listed.next() {
        Some(&x) if x as usize == h => Ok(()),
        _ => Err(()),
    })
    .ok()?;
    Some(e + n)
}

#[cfg(test)]
mod tests {
    use super::{edge_directory_holds, pairs_hold, rotations_cover, stars_hold, triangles_hold};
    use crate::NONE;
    use crate::che::{BuildOptions, Che};
    use crate::generate;
    use crate::util::rank_directory::RankDirectory;

    /// Closed meshes, meshes with a boundary, a vertex the build splits into two fans and
    /// an isolated vertex, at level 2.
    fn meshes() -> Vec<Che> {
        let surfaces = [
            generate::torus(5, 4),
            generate::grid(4, 3),
            generate::sphere(6, 5),
        ];
        let mut out: Vec<Che> = surfaces
            .iter()
            .map(|s| {
                let n = s.positions.len();
                Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(2))
            })
            .collect::<Result<_, _>>()
            .unwrap();
        let fans = [[0, 1, 2], [0, 2, 3], [0, 4, 5], [0, 5, 6]];
        out.push(Che::from_triangles(&fans, 8, &[], BuildOptions::level(2)).unwrap());
        out
    }

    /// xorshift64: the same corruptions on every run.
    struct Rng(u64);

    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 % n as u64) as usize
        }

        /// What a corrupted entry may hold: `NONE`, any id below `n` or past it, or a
        /// neighbour of `old` (the ids a subtle corruption gives).
        fn value(&mut self, old: u32, n: usize) -> u32 {
            match self.below(4) {
                0 => NONE,
                1 => self.below(n + 2) as u32,
                _ => old.wrapping_add([1, 2, u32::MAX, u32::MAX - 1][self.below(4)]),
            }
        }

        /// One entry of `xs` rewritten, or two swapped.
        fn corrupt(&mut self, xs: &mut [u32], n: usize) {
            let i = self.below(xs.len());
            if self.below(3) == 0 {
                let j = self.below(xs.len());
                xs.swap(i, j);
            } else {
                xs[i] = self.value(xs[i], n);
            }
        }
    }

    /// A pass says "valid" exactly when the checks element by element find nothing, on
    /// meshes with one array corrupted (the arrays each pass assumes valid left intact).
    #[test]
    fn each_pass_agrees_with_the_checks_element_by_element() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for base in meshes() {
            base.validate().unwrap();
            let (nh, nv) = (base.v.len(), base.n_vertices);
            for _ in 0..500 {
                let mut c = base.clone();
                match rng.below(6) {
                    0 => rng.corrupt(c.v.to_mut("test").unwrap(), nv),
                    1 => rng.corrupt(c.o.to_mut("test").unwrap(), nh),
                    2 => rng.corrupt(c.vh.to_mut("test").unwrap(), nh),
                    3 => rng.corrupt(c.eh.to_mut("test").unwrap(), nh),
                    4 => {
                        // One rank of the directory off by one, as a file opened trusted
                        // can hold: the flags and `EH` are right.
                        let mut entries = c.edge_bits.entries().to_vec();
                        let k = rng.below(entries.len());
                        let up = rng.below(2) == 0 || entries[k] >> 32 == 0;
                        entries[k] = if up {
                            entries[k] + (1 << 32)
                        } else {
                            entries[k] - (1 << 32)
                        };
                        let (n, ones) = (nh, c.edge_bits.ones());
                        c.edge_bits =
                            RankDirectory::from_entries_trusted(entries.into(), n, ones).unwrap();
                    }
                    _ => {
                        // Two flags of the directory moved: its count stays EH's.
                        let (a, b) = (rng.below(nh), rng.below(nh));
                        let bits = &c.edge_bits;
                        let (fa, fb) = (bits.get(a), bits.get(b));
                        c.edge_bits = RankDirectory::from_fn(nh, |h| match h {
                            _ if h == a => fb,
                            _ if h == b => fa,
                            _ => bits.get(h),
                        })
                        .unwrap();
                    }
                }
                assert_eq!(triangles_hold(&c.v, nv), c.first_v_violation().is_none());
                if c.first_v_violation().is_some() {
                    continue;
                }
                // The one walk of O and VH says what their passes say together.
                let o_holds = c.first_o_violation().is_none();
                let stars_ok = o_holds && c.first_vh_violation().unwrap().is_none();
                let stars = stars_hold(&c.v, &c.o, &c.vh);
                assert_eq!(stars.is_some(), stars_ok);
                if let Some(unpaired) = stars {
                    assert_eq!(unpaired, c.o.iter().filter(|&&g| g == NONE).count());
                }
                let pairs = pairs_hold(&c.v, &c.o);
                assert_eq!(pairs.is_some(), c.first_o_violation().is_none());
                if pairs.is_none() {
                    continue;
                }
                let covered = rotations_cover(&c.v, &c.o, &c.vh, nh);
                assert_eq!(covered, c.first_vh_violation().unwrap().is_none());
                let bits = &c.edge_bits;
                let listed = edge_directory_holds(&c.o, &c.eh, bits.entries());
                assert_eq!(listed, c.first_edge_violation().is_none());
                assert_eq!(
                    c.validate().is_ok(),
                    pairs == Some(c.num_edges) && covered && listed
                );
            }
        }
    }
}
