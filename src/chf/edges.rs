//! Edges: walking around an edge, and which edge slot names each edge.
//!
//! An edge of the structure is a **fan**: the edge slots (`6t + k`) reached from one
//! another by walking `mate, radial, mate, ...` (tetrahedra around the edge connected
//! through paired faces that contain it). Usually one fan per vertex pair; a pair whose
//! tetrahedra form several fans that the vertex split did not separate keeps one edge id
//! per fan, like a non-manifold edge of a CHE keeps one per unpaired half-edge.
//!
//! The **canonical slot** of a fan is the slot of its canonical half-edge: on a boundary
//! fan the smaller of the two half-edges that lie on boundary half-faces (one at each end;
//! the rotation starts there), on a closed fan the smallest of all its half-edges. The rule
//! only depends on `V` and `O`, so edge ids are the same at every level; edge `e` is the
//! `e`-th canonical slot. Level 2 stores one bit per slot (a rank: 1.5 bits per slot) and
//! finding the canonical slot of any half-edge walks around the edge until a marked slot,
//! O(k) for k tetrahedra around it; a per-slot id array would make that O(1) for 24 bytes
//! per tetrahedron, 3/4 of level 1, which we judged too much: TE and EE, which name edges
//! from half-edges, are the relations that pay for it.

use crate::chf::build::report::push_example;
use crate::chf::ids::{HalfEdge, NO_HALF_EDGE, mate, radial, slot_half_edges, slot_of};
use crate::util::rank::RankBits;

/// How a walk around an edge ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FanEnd {
    /// Back at the start: an interior (closed) fan.
    Closed,
    /// At the boundary: the last exit half-edge, on a boundary half-face.
    Boundary(HalfEdge),
}

/// Walks around an edge from `start`: in each tetrahedron, `visit(entry, exit)` with the
/// entry half-edge `g` and its mate, the exit; the next entry is `radial(exit)`. Stops at
/// the start or the boundary; `visit` returning `true` stops early (reported as `Closed`).
#[inline]
pub(crate) fn walk(
    v: &[u32], o: &[u32], start: HalfEdge, mut visit: impl FnMut(HalfEdge, HalfEdge) -> bool,
) -> FanEnd {
    let mut g = start;
    loop {
        let m = mate(g);
        if visit(g, m) {
            return FanEnd::Closed;
        }
        let n = radial(v, o, m);
        if n == NO_HALF_EDGE {
            return FanEnd::Boundary(m);
        }
        if n == start {
            return FanEnd::Closed;
        }
        g = n;
    }
}

/// One bit per edge slot: set on the canonical slot of each fan, by walking from every
/// slot. The builds use the star pass (`stars.rs`); this is its reference in tests.
#[cfg(test)]
pub(crate) fn canonical_slots(v: &[u32], o: &[u32]) -> RankBits {
    let n_slots = 6 * (v.len() / 4);
    let mut visited = vec![0u64; n_slots.div_ceil(64)];
    let mut canonical = vec![0u64; n_slots.div_ceil(64)];
    fn set(bits: &mut [u64], i: u64) {
        bits[(i >> 6) as usize] |= 1 << (i & 63);
    }
    let test = |bits: &[u64], i: u64| (bits[(i >> 6) as usize] >> (i & 63)) & 1 == 1;
    for s in 0..n_slots as u64 {
        if test(&visited, s) {
            continue;
        }
        let he = slot_half_edges(s)[0];
        let mut min = he;
        let end = walk(v, o, he, |g, m| {
            set(&mut visited, slot_of(g));
            min = min.min(g).min(m);
            false
        });
        let c = match end {
            FanEnd::Closed => min,
            FanEnd::Boundary(last) => {
                let other = walk(v, o, mate(he), |g, _| {
                    set(&mut visited, slot_of(g));
                    false
                });
                match other {
                    FanEnd::Boundary(first) => last.min(first),
                    FanEnd::Closed => unreachable!("a fan open one way is open both ways"),
                }
            }
        };
        set(&mut canonical, slot_of(c));
    }
    RankBits::from_fn(n_slots, |i| test(&canonical, i as u64)).unwrap()
}

/// The canonical slot of the fan of `he`, found by walking until a slot marked in `bits`.
pub(crate) fn canonical_slot(v: &[u32], o: &[u32], bits: &RankBits, he: HalfEdge) -> u64 {
    let mut found = slot_of(he);
    if bits.get(found as usize) {
        return found;
    }
    let mut look = |g: HalfEdge, _| {
        let s = slot_of(g);
        let hit = bits.get(s as usize);
        if hit {
            found = s;
        }
        hit
    };
    if walk(v, o, he, &mut look) == FanEnd::Closed {
        return found;
    }
    walk(v, o, mate(he), &mut look);
    found
}

/// The canonical half-edge of canonical slot `s`: the one on a boundary half-face if
/// exactly one is, else the smaller.
#[inline]
pub(crate) fn slot_canonical_half_edge(o: &[u32], s: u64) -> HalfEdge {
    let [a, b] = slot_half_edges(s);
    let open = |he: HalfEdge| o[crate::chf::ids::he_face(he) as usize] == crate::NONE;
    if open(b) && !open(a) { b } else { a }
}

/// A vertex pair of the structure carrying several fans: VV reports its far end once,
/// from the fan with the smallest canonical slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct MultiFan {
    pub a: u32,
    pub b: u32,
    pub first_slot: u64,
}

/// What the fans say about the input edges.
#[derive(Debug, Default)]
pub(crate) struct EdgeCensus {
    pub input_edges: usize,
    pub non_manifold: usize,
    pub non_manifold_examples: Vec<[u32; 2]>,
    pub kept: usize,
    pub kept_examples: Vec<[u32; 2]>,
    /// Sorted by `(a, b)`.
    pub multi_fan: Vec<MultiFan>,
}

/// Groups the canonical slots (one per fan) by input vertex pair (bucketed by the smaller
/// input vertex, each bucket sorted), then by structure pair.
pub(crate) fn census(
    v: &[u32], bits: &RankBits, n_input: usize, origin: impl Fn(u32) -> u32,
) -> crate::error::Result<EdgeCensus> {
    use crate::util::alloc::{try_push, try_to_vec, try_vec};
    let ends = |s: u64| {
        let [p, q] = crate::chf::ids::EDGE[(s % 6) as usize];
        let base = 4 * (s / 6) as usize;
        let (a, b) = (v[base + p as usize], v[base + q as usize]);
        (a.min(b), a.max(b))
    };
    let input_ends = |s: u64| {
        let (a, b) = ends(s);
        let (x, y) = (origin(a), origin(b));
        (x.min(y), x.max(y))
    };
    let n_slots = 6 * (v.len() / 4);
    let mut start = try_vec(n_input + 1, 0u32, "the edge census")?;
    let canonical = || (0..n_slots as u64).filter(|&s| bits.get(s as usize));
    for s in canonical() {
        start[input_ends(s).0 as usize + 1] += 1;
    }
    for i in 0..n_input {
        start[i + 1] += start[i];
    }
    let mut fill = try_to_vec(&start, "the edge census")?;
    let mut slots: Vec<u64> = crate::util::pages::zeroed(bits.ones(), "the edge census")?;
    for s in canonical() {
        let f = &mut fill[input_ends(s).0 as usize];
        slots[*f as usize] = s;
        *f += 1;
    }
    drop(fill);
    let key = |s: u64| {
        let ((_, y), (a, b)) = (input_ends(s), ends(s));
        (y, a, b, s)
    };
    let mut out = EdgeCensus::default();
    for w in start.windows(2) {
        let bucket = &mut slots[w[0] as usize..w[1] as usize];
        bucket.sort_unstable_by_key(|&s| key(s));
        for group in bucket.chunk_by(|&s, &t| key(s).0 == key(t).0) {
            out.input_edges += 1;
            if group.len() == 1 {
                continue;
            }
            let (x, y) = input_ends(group[0]);
            out.non_manifold += 1;
            push_example(&mut out.non_manifold_examples, [x, y]);
            let mut kept = false;
            for same in group.chunk_by(|&s, &t| ends(s) == ends(t)) {
                if same.len() > 1 {
                    kept = true;
                    let (a, b) = ends(same[0]);
                    let fan = MultiFan {
                        a,
                        b,
                        first_slot: same[0],
                    };
                    try_push(&mut out.multi_fan, fan, "the multi-fan edges")?;
                }
            }
            if kept {
                out.kept += 1;
                push_example(&mut out.kept_examples, [x, y]);
            }
        }
    }
    out.multi_fan.sort_unstable();
    Ok(out)
}
