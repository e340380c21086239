//! The star of a vertex: its tetrahedra, breadth-first from the start half-face (`VH`),
//! crossing the three half-faces of each that hold the vertex. Every tetrahedron is met
//! three times or so, so the walk keeps a visited set inline in the iterator: the
//! tetrahedra met so far, checked by a branch-free scan of the used part (eight at a time)
//! while there are at most [`STAR_INLINE`] (no allocation, no hash), then a hash set on the
//! heap, doubling as it grows: the one allocation a vertex query may make. (A star cannot
//! be enumerated without marks in general: its dual is the link of the vertex, an
//! arbitrary surface.)
//!
//! The answers (VV, VE, VF, VT) come in increasing id order: the walk collects them in a
//! second set of the same kind and sorts it, so that they are the rows the bulk calls
//! build by counting (`bulk.rs`), and the same at every level. The walk runs when the
//! query is made; the iterator then hands out the sorted ids.
//!
//! Why the walk goes a breadth-first level at a time: on a large mesh the tetrahedra of a
//! star are far apart in memory, and each one read is a cache miss (its `V` and its `O`).
//! Read one after the other, with the next one's address known only once the previous
//! has arrived, a star costs its size in memory latencies; so when a level starts, every
//! tetrahedron of it is read once at the same time (the misses overlap) and then visited
//! from the cache.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{edge_index, first, tet};
use crate::chf::query::view::{Need, View};
use crate::error::{Error, Result};
use crate::util::alloc::{bytes_of, or_panic, try_grow, try_to_vec, try_vec};

/// Stars up to this many tetrahedra are walked without allocation.
pub const STAR_INLINE: usize = 64;

/// Ids in the order they came, [`STAR_INLINE`] of them inline, then all of them on the heap.
#[derive(Clone, Debug)]
struct Ids {
    items: [u32; STAR_INLINE],
    len: usize,
    heap: Vec<u32>,
    /// The heap could not grow: the ids are incomplete, and no more are taken.
    failed: bool,
}

impl Ids {
    fn new() -> Self {
        Ids {
            items: [NONE; STAR_INLINE],
            len: 0,
            heap: Vec::new(),
            failed: false,
        }
    }

    #[inline]
    fn get(&self, i: usize) -> u32 {
        if self.heap.is_empty() {
            self.items[i]
        } else {
            self.heap[i]
        }
    }

    #[inline]
    fn push(&mut self, x: u32) {
        if self.len < STAR_INLINE {
            self.items[self.len] = x;
        } else {
            let more = if self.heap.is_empty() {
                4 * STAR_INLINE
            } else {
                1
            };
            if try_grow(&mut self.heap, more, STAR_HEAP).is_err() {
                self.failed = true;
                return;
            }
            if self.heap.is_empty() {
                self.heap.extend_from_slice(&self.items);
            }
            self.heap.push(x);
        }
        self.len += 1;
    }

    /// Out of memory an error: the ids are incomplete.
    fn complete(&self) -> Result<()> {
        match self.failed {
            true => Err(Error::out_of_memory(
                bytes_of::<u32>(2 * self.len),
                STAR_HEAP,
            )),
            false => Ok(()),
        }
    }

    /// The ids, in the order they came (or sorted after [`Ids::sort`]).
    #[inline]
    fn as_slice(&self) -> &[u32] {
        if self.heap.is_empty() {
            &self.items[..self.len]
        } else {
            &self.heap
        }
    }

    /// Sorts `from` and takes its ids (`self` empty): the used part only, or the heap.
    fn copy_sorted(&mut self, from: &mut Ids) {
        from.sort();
        if from.heap.is_empty() {
            self.items[..from.len].copy_from_slice(&from.items[..from.len]);
        } else {
            self.heap = std::mem::take(&mut from.heap);
        }
        self.len = from.len;
    }

    fn sort(&mut self) {
        if self.heap.is_empty() {
            self.items[..self.len].sort_unstable();
        } else {
            self.heap.sort_unstable();
        }
    }
}

/// What a star's ids past [`STAR_INLINE`] are called when they do not fit in memory. The
/// walk then stops taking ids and says so ([`Star::complete`]): an edit returns the
/// error before it writes, a query panics with it as payload (`or_panic`), never an abort.
const STAR_HEAP: &str = "the tetrahedra of a vertex star";

/// Slots of the inline hash table: twice [`STAR_INLINE`], so at most half full.
const TABLE: usize = 2 * STAR_INLINE;

/// A set of ids with their order of arrival: an open-addressing hash table of
/// [`TABLE`] inline slots (scalar loads and stores: no vector scan over entries just
/// written, which would wait on store forwarding), then, past [`STAR_INLINE`] ids, a table on
/// the heap that doubles as it grows.
#[derive(Clone, Debug)]
struct Visited {
    ids: Ids,
    table: [u32; TABLE],
    heap_table: Vec<u32>,
}

#[inline]
fn probe_start(x: u32, cap: usize) -> usize {
    // Fibonacci hashing; `cap` is a power of two.
    (x.wrapping_mul(0x9E37_79B9) >> (32 - cap.trailing_zeros())) as usize
}

/// Inserts into an open-addressing table; false if already there.
#[inline(always)]
fn insert(table: &mut [u32], x: u32) -> bool {
    let mask = table.len() - 1;
    let mut i = probe_start(x, table.len());
    loop {
        let y = table[i];
        if y == x {
            return false;
        }
        if y == NONE {
            table[i] = x;
            return true;
        }
        i = (i + 1) & mask;
    }
}

impl Visited {
    fn new() -> Self {
        Visited {
            ids: Ids::new(),
            table: [NONE; TABLE],
            heap_table: Vec::new(),
        }
    }

    #[inline]
    fn len(&self) -> usize {
        self.ids.len
    }

    #[inline]
    fn get(&self, i: usize) -> u32 {
        self.ids.get(i)
    }

    /// Adds `x` unless already there; false if it was. The common case (inline, and the
    /// first slot probed holds `x` or nothing) takes no branch on whether `x` is new: the
    /// slot and the next list entry are written whatever the answer (an entry past the
    /// end is never read), and the length grows by the answer.
    #[inline(always)]
    fn add(&mut self, x: u32) -> bool {
        if self.ids.len < STAR_INLINE - 1 && self.heap_table.is_empty() {
            let h = probe_start(x, TABLE);
            let y = self.table[h];
            let new = y == NONE;
            if new | (y == x) {
                self.table[h] = x;
                self.ids.items[self.ids.len] = x;
                self.ids.len += new as usize;
                return new;
            }
        }
        self.add_probing(x)
    }

    /// [`Visited::add`] past a collision, near the inline capacity or on the heap.
    #[inline(never)]
    fn add_probing(&mut self, x: u32) -> bool {
        if self.ids.failed {
            return false;
        }
        let new = if self.heap_table.is_empty() {
            insert(&mut self.table, x)
        } else {
            insert(&mut self.heap_table, x)
        };
        if new {
            self.ids.push(x);
            if self.ids.len == STAR_INLINE || 2 * self.ids.len > self.heap_table.len().max(TABLE) {
                self.grow();
            }
        }
        new
    }

    /// The table is half full: a table twice as large on the heap.
    #[cold]
    fn grow(&mut self) {
        let cap = (2 * self.heap_table.len()).max(2 * TABLE);
        let Ok(mut table) = try_vec(cap, NONE, STAR_HEAP) else {
            self.ids.failed = true;
            return;
        };
        for &x in self.ids.as_slice() {
            insert(&mut table, x);
        }
        self.heap_table = table;
    }
}

/// Breadth-first walk over the star of one vertex.
#[derive(Clone, Debug)]
pub(crate) struct Star {
    vertex: u32,
    seen: Visited,
    head: usize,
    /// End of the breadth-first level being visited.
    level_end: usize,
    /// What the reads ahead of each level loaded (kept so they are not optimized away).
    touched: u32,
}

impl Star {
    /// After the walk: out of memory an error, the walk having stopped short.
    pub(crate) fn complete(&self) -> Result<()> {
        self.seen.ids.complete()
    }

    pub(crate) fn new(vertex: u32, start_half_face: u32) -> Self {
        let mut seen = Visited::new();
        if start_half_face != NONE {
            seen.add(tet(start_half_face));
        }
        Star {
            vertex,
            seen,
            head: 0,
            level_end: 0,
            touched: 0,
        }
    }

    /// The next tetrahedron and the local index of the vertex in it. `ahead` reads what
    /// the caller will need of each tetrahedron besides `V` and `O` (see the module doc).
    #[inline]
    pub(crate) fn next(&mut self, view: &View, ahead: impl Fn(u32) -> u32) -> Option<(u32, u32)> {
        if self.head == self.seen.len() {
            return None;
        }
        if self.head == self.level_end {
            // A new level: read all of it at once.
            self.level_end = self.seen.len();
            let mut touched = self.touched;
            for k in self.head..self.level_end {
                let t = self.seen.get(k) as usize;
                touched ^= view.v[4 * t] ^ view.o[4 * t] ^ ahead(t as u32);
            }
            self.touched = touched;
        }
        let t = self.seen.get(self.head);
        self.head += 1;
        let base = first(t);
        let q = &view.v[base as usize..base as usize + 4];
        let i = (q[1] == self.vertex) as u32
            + 2 * (q[2] == self.vertex) as u32
            + 3 * (q[3] == self.vertex) as u32;
        debug_assert_eq!(
            q[i as usize], self.vertex,
            "a star tetrahedron holds its vertex"
        );
        // The three faces holding the vertex: all but face `i`.
        for k in 1..4 {
            let g = view.o[(base + ((i + k) & 3)) as usize];
            if g != NONE {
                self.seen.add(tet(g));
            }
        }
        Some((t, i))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Vertices,
    Edges,
    Faces,
    Tetrahedra,
}

/// The vertices, edges, faces or tetrahedra around a vertex, each once, in increasing id
/// order (there is no rotation order around a vertex in 3D). Allocation-free for stars of
/// up to [`crate::chf::STAR_INLINE`] tetrahedra (and answers of up to as many ids).
#[derive(Clone, Debug)]
pub struct VertexIds<'a> {
    ids: Ids,
    pos: usize,
    _mesh: std::marker::PhantomData<&'a Chf>,
}

impl Iterator for VertexIds<'_> {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        let x = self.ids.as_slice().get(self.pos).copied();
        self.pos += x.is_some() as usize;
        x
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.ids.len - self.pos;
        (n, Some(n))
    }
}

impl ExactSizeIterator for VertexIds<'_> {}
impl std::iter::FusedIterator for VertexIds<'_> {}

/// The tetrahedra around `x` on `view`, sorted, out of memory an error: what an edit
/// plans from, before it writes.
pub(crate) fn star_tetrahedra(view: &View, x: u32) -> Result<Vec<u32>> {
    let mut star = Star::new(x, view.start_half_face(x));
    while star.next(view, |_| 0).is_some() {}
    star.complete()?;
    let mut out = try_to_vec(star.seen.ids.as_slice(), STAR_HEAP)?;
    out.sort_unstable();
    Ok(out)
}

/// Walks the star of `x` on `view` and collects the ids of `kind`, sorted.
/// The answer lands in `into` (empty), sorted: only the ids are copied, not the arrays.
fn collect(view: &View, x: u32, kind: Kind, into: &mut Ids) {
    let mut star = Star::new(x, view.start_half_face(x));
    if kind == Kind::Tetrahedra {
        while star.next(view, |_| 0).is_some() {}
        or_panic(star.complete());
        into.copy_sorted(&mut star.seen.ids);
        return;
    }
    let mut out = Visited::new();
    match kind {
        Kind::Vertices => {
            while let Some((t, i)) = star.next(view, |_| 0) {
                let base = first(t);
                for k in 1..4 {
                    out.add(view.v[(base + ((i + k) & 3)) as usize]);
                }
            }
        }
        Kind::Faces => {
            while let Some((t, i)) = star.next(view, |t| view.ahead_faces(t)) {
                for k in 1..4 {
                    // Each face once: from its canonical half-face.
                    let hf = first(t) + ((i + k) & 3);
                    if let Some(f) = view.face_if_canonical(hf) {
                        out.add(f);
                    }
                }
            }
        }
        Kind::Edges => {
            while let Some((t, i)) = star.next(view, |t| view.ahead_edges(t)) {
                for k in 1..4 {
                    // Each edge once: from its canonical slot.
                    let s = 6 * t as usize + edge_index(i, (i + k) & 3) as usize;
                    if let Some(e) = view.edge_if_canonical(s) {
                        out.add(e);
                    }
                }
            }
        }
        Kind::Tetrahedra => unreachable!(),
    }
    or_panic(star.complete().and(out.ids.complete()));
    into.copy_sorted(&mut out.ids);
}

impl Chf {
    fn vertex_ids(&self, v: u32, kind: Kind) -> VertexIds<'_> {
        let need = match kind {
            Kind::Faces => Need::FACES,
            Kind::Edges => Need::EDGES,
            Kind::Vertices | Kind::Tetrahedra => Need::NOTHING,
        };
        let mut it = VertexIds {
            ids: Ids::new(),
            pos: 0,
            _mesh: std::marker::PhantomData,
        };
        collect(&self.view(need), v, kind, &mut it.ids);
        it
    }

    /// VV: the vertices sharing an edge with `v`, each once, in increasing order. O(star)
    /// at level 2.
    pub fn vertex_vertices(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Vertices)
    }
    /// VE: the edges holding `v`, each once, in increasing order. O(star) at level 2.
    pub fn vertex_edges(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Edges)
    }
    /// VF: the faces holding `v`, each once, in increasing order. O(star) at level 2.
    pub fn vertex_faces(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Faces)
    }
    /// VT: the tetrahedra holding `v`, each once, in increasing order. O(star) at level 2.
    pub fn vertex_tetrahedra(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Tetrahedra)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visited_spills_and_keeps_order() {
        let mut seen = Visited::new();
        assert!(seen.add(5) && !seen.add(5) && seen.len() == 1);
        let mut seen = Visited::new();
        for t in 0..1000u32 {
            assert!(seen.add(t * 7919 % 1009));
            assert!(!seen.add(t * 7919 % 1009));
        }
        assert_eq!(seen.len(), 1000);
        for i in 0..1000 {
            assert_eq!(seen.get(i), i as u32 * 7919 % 1009);
        }
        let mut ids = seen.ids;
        ids.sort();
        assert!(ids.as_slice().windows(2).all(|w| w[0] < w[1]));
        let mut small = Visited::new();
        for t in [9, 3, 9, 12, 1, 3, NONE - 1] {
            small.add(t);
        }
        let mut ids = small.ids;
        ids.sort();
        assert_eq!(ids.as_slice(), &[1, 3, 9, 12, NONE - 1]);
    }
}
