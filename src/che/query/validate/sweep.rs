//! Whole-mesh passes that answer only "valid or not" for the pairs of `O`, the rotations
//! from `VH` and the edge directory. They are what a full open of a level file pays on a
//! valid file, so they are written for the memory system: arrays read in order where the
//! invariant allows it, each pair checked once, and several rotations walked at once so
//! that their cache misses overlap instead of waiting one after another. They name no
//! element: on a failure the per-element checks of `validate` run and name the first.

use crate::NONE;
use crate::che::ids::{next, prev};
use crate::che::tables::is_canonical;
use crate::util::par::{planned_threads, run_all};
use std::ops::Range;

/// `f` on contiguous parts of `0..n`, one per thread the machine runs; the sum of the
/// answers, or `None` when one part has none.
fn sum_over_parts(n: usize, f: impl Fn(Range<usize>) -> Option<usize> + Sync) -> Option<usize> {
    let part = n.div_ceil(planned_threads(0, n).max(1)).max(1);
    let parts: Vec<_> = (0..n).step_by(part).map(|a| a..(a + part).min(n)).collect();
    run_all(parts, f).into_iter().sum()
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
        for h in hs {
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

/// Rotations walked at once by one thread: enough independent misses to keep the memory
/// system busy, few enough to stay in registers.
const LANES: usize = 16;

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
                while next_x < xs.end && vh[next_x] == NONE {
                    next_x += 1;
                }
                if next_x == xs.end {
                    continue;
                }
                let h = vh[next_x];
                if h as usize >= v.len() || v[h as usize] as usize != next_x {
                    return None;
                }
                (start[lane], cur[lane], next_x) = (h, h, next_x + 1);
            }
            busy = true;
            steps += 1;
            if steps > v.len() {
                return None;
            }
            let around = o[prev(cur[lane]) as usize];
            cur[lane] = if around == start[lane] { NONE } else { around };
        }
        if !busy {
            return Some(steps);
        }
    }
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

/// Whether the edge directory (`flagged`, `rank`) flags exactly the canonical half-edges
/// and `EH` lists them in increasing order (edge `e` is the `e`-th), for an `EH` as long as
/// the directory has flags (checked before): passes in order over parts of `O`, each
/// starting at the rank of its first half-edge.
pub(super) fn edge_directory_holds(
    o: &[u32], eh: &[u32], flagged: impl Fn(usize) -> bool + Sync,
    rank: impl Fn(usize) -> usize + Sync,
) -> bool {
    sum_over_parts(o.len(), |hs| {
        let mut e = rank(hs.start);
        for h in hs {
            let canonical = is_canonical(o, h);
            if flagged(h) != canonical {
                return None;
            }
            if canonical {
                if eh.get(e) != Some(&(h as u32)) {
                    return None;
                }
                e += 1;
            }
        }
        Some(0)
    })
    .is_some()
}

#[cfg(test)]
mod tests {
    use super::{edge_directory_holds, pairs_hold, rotations_cover, triangles_hold};
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
                match rng.below(5) {
                    0 => rng.corrupt(c.v.to_mut("test").unwrap(), nv),
                    1 => rng.corrupt(c.o.to_mut("test").unwrap(), nh),
                    2 => rng.corrupt(c.vh.to_mut("test").unwrap(), nh),
                    3 => rng.corrupt(c.eh.to_mut("test").unwrap(), nh),
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
                let pairs = pairs_hold(&c.v, &c.o);
                assert_eq!(pairs.is_some(), c.first_o_violation().is_none());
                if pairs.is_none() {
                    continue;
                }
                let covered = rotations_cover(&c.v, &c.o, &c.vh, nh);
                assert_eq!(covered, c.first_vh_violation().unwrap().is_none());
                let bits = &c.edge_bits;
                let listed = edge_directory_holds(&c.o, &c.eh, |h| bits.get(h), |h| bits.rank(h));
                assert_eq!(listed, c.first_edge_violation().is_none());
                assert_eq!(
                    c.validate().is_ok(),
                    pairs == Some(c.num_edges) && covered && listed
                );
            }
        }
    }
}
