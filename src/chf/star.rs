//! The star of a vertex: its tetrahedra, breadth-first from the start half-face (`VH`),
//! crossing the three half-faces of each that hold the vertex. Every tetrahedron is met
//! three times or so, so the walk keeps a visited set: a small open-addressing table and
//! queue inline in the iterator (no global hash set, no allocation for stars of up to
//! [`INLINE`] tetrahedra). A larger star moves both to the heap once, doubling as it grows:
//! the one allocation a vertex query may make. (A star cannot be enumerated without
//! marks in general: its dual is the link of the vertex, an arbitrary surface.)

use super::Chf;
use super::ids::{edge_index, first, tet};
use super::view::{Need, View};
use crate::NONE;

/// Stars up to this many tetrahedra are walked without allocation.
pub const INLINE: usize = 64;

/// The tetrahedra met so far, in breadth-first order, and a hash set of them.
#[derive(Clone, Debug)]
struct Visited {
    items: [u32; INLINE],
    table: [u32; 2 * INLINE],
    len: usize,
    heap_items: Vec<u32>,
    heap_table: Vec<u32>,
}

#[inline]
fn probe_start(x: u32, cap: usize) -> usize {
    // Fibonacci hashing; `cap` is a power of two.
    (x.wrapping_mul(0x9E37_79B9) >> (32 - cap.trailing_zeros())) as usize
}

/// Inserts into an open-addressing table; false if already there.
#[inline]
fn insert(table: &mut [u32], x: u32) -> bool {
    let mask = table.len() - 1;
    let mut i = probe_start(x, table.len());
    loop {
        if table[i] == x {
            return false;
        }
        if table[i] == NONE {
            table[i] = x;
            return true;
        }
        i = (i + 1) & mask;
    }
}

impl Visited {
    fn new() -> Self {
        Visited {
            items: [NONE; INLINE],
            table: [NONE; 2 * INLINE],
            len: 0,
            heap_items: Vec::new(),
            heap_table: Vec::new(),
        }
    }

    #[inline]
    fn get(&self, i: usize) -> u32 {
        if self.heap_items.is_empty() {
            self.items[i]
        } else {
            self.heap_items[i]
        }
    }

    /// Adds `t` unless already there; false if it was.
    fn add(&mut self, t: u32) -> bool {
        if self.heap_items.is_empty() {
            if !insert(&mut self.table, t) {
                return false;
            }
            if self.len < INLINE {
                self.items[self.len] = t;
                self.len += 1;
                return true;
            }
            // Spill: the star is larger than the inline capacity.
            self.heap_items.reserve(4 * INLINE);
            self.heap_items.extend_from_slice(&self.items);
            self.heap_table = vec![NONE; 8 * INLINE];
            for &x in &self.heap_items {
                insert(&mut self.heap_table, x);
            }
            insert(&mut self.heap_table, t);
        } else if !insert(&mut self.heap_table, t) {
            return false;
        }
        self.heap_items.push(t);
        self.len += 1;
        if 2 * self.len > self.heap_table.len() {
            let cap = 2 * self.heap_table.len();
            self.heap_table.clear();
            self.heap_table.resize(cap, NONE);
            for &x in &self.heap_items {
                insert(&mut self.heap_table, x);
            }
        }
        true
    }
}

/// Breadth-first walk over the star of one vertex.
#[derive(Clone, Debug)]
pub(crate) struct Star {
    vertex: u32,
    seen: Visited,
    head: usize,
}

impl Star {
    pub(crate) fn new(vertex: u32, start_half_face: u32) -> Self {
        let mut seen = Visited::new();
        if start_half_face != NONE {
            seen.add(tet(start_half_face));
        }
        Star {
            vertex,
            seen,
            head: 0,
        }
    }

    /// The next tetrahedron and the local index of the vertex in it.
    pub(crate) fn next(&mut self, view: &View) -> Option<(u32, u32)> {
        if self.head == self.seen.len {
            return None;
        }
        let t = self.seen.get(self.head);
        self.head += 1;
        let base = first(t);
        let i = (0..4)
            .find(|&i| view.v[(base + i) as usize] == self.vertex)
            .expect("a star tetrahedron holds its vertex");
        for hf in base..base + 4 {
            let g = view.o[hf as usize];
            if hf != base + i && g != NONE {
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

/// The vertices, edges, faces or tetrahedra around a vertex, each once, in the
/// breadth-first order of its star (there is no rotation order around a vertex in 3D).
/// Allocation-free at level 2 and up for stars of up to [`super::STAR_INLINE`] tetrahedra.
#[derive(Clone, Debug)]
pub struct VertexIds<'a> {
    view: View<'a>,
    star: Star,
    kind: Kind,
    pending: [u32; 3],
    len: u8,
    pos: u8,
}

impl Iterator for VertexIds<'_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
        loop {
            if self.pos < self.len {
                self.pos += 1;
                return Some(self.pending[self.pos as usize - 1]);
            }
            let (t, i) = self.star.next(&self.view)?;
            self.pos = 0;
            self.len = 0;
            if self.kind == Kind::Tetrahedra {
                self.pending[0] = t;
                self.len = 1;
                continue;
            }
            let x = self.star.vertex;
            let view = &self.view;
            for j in (0..4).filter(|&j| j != i) {
                let id = match self.kind {
                    Kind::Faces => {
                        // Each face once: from its canonical half-face.
                        let hf = first(t) + j;
                        (view.canonical_half_face(hf) == hf)
                            .then(|| view.faces.rank(hf as usize) as u32)
                    }
                    Kind::Edges | Kind::Vertices => {
                        // Each edge once: from its canonical slot.
                        let s = 6 * t as u64 + edge_index(i, j) as u64;
                        if !view.edges.get(s as usize) {
                            None
                        } else if self.kind == Kind::Edges {
                            Some(view.edges.rank(s as usize) as u32)
                        } else {
                            let w = view.v[(first(t) + j) as usize];
                            first_fan(view, x, w, s).then_some(w)
                        }
                    }
                    Kind::Tetrahedra => unreachable!(),
                };
                if let Some(id) = id {
                    self.pending[self.len as usize] = id;
                    self.len += 1;
                }
            }
        }
    }
}

impl std::iter::FusedIterator for VertexIds<'_> {}

/// Is canonical slot `s` of pair `{x, w}` the one VV reports `w` from? Yes unless the pair
/// carries several fans and `s` is not the first.
#[inline]
fn first_fan(view: &View, x: u32, w: u32, s: u64) -> bool {
    if view.multi_fan.is_empty() {
        return true;
    }
    let (a, b) = (x.min(w), x.max(w));
    match view.multi_fan.binary_search_by(|m| (m.a, m.b).cmp(&(a, b))) {
        Ok(k) => view.multi_fan[k].first_slot == s,
        Err(_) => true,
    }
}

impl Chf {
    fn vertex_ids(&self, v: u32, kind: Kind) -> VertexIds<'_> {
        let need = match kind {
            Kind::Faces => Need::FACES,
            Kind::Edges | Kind::Vertices => Need::EDGES,
            Kind::Tetrahedra => Need::NOTHING,
        };
        let view = self.view(need);
        let star = Star::new(v, view.start_half_face(v));
        VertexIds {
            view,
            star,
            kind,
            pending: [NONE; 3],
            len: 0,
            pos: 0,
        }
    }

    /// VV: the vertices sharing an edge with `v`, each once. O(star) at level 2.
    pub fn vertex_vertices(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Vertices)
    }
    /// VE: the edges holding `v`, each once. O(star) at level 2.
    pub fn vertex_edges(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Edges)
    }
    /// VF: the faces holding `v`, each once. O(star) at level 2.
    pub fn vertex_faces(&self, v: u32) -> VertexIds<'_> {
        self.vertex_ids(v, Kind::Faces)
    }
    /// VT: the tetrahedra holding `v`, each once. O(star) at level 2.
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
        for t in 0..1000u32 {
            assert!(seen.add(t * 7919 % 1009));
            assert!(!seen.add(t * 7919 % 1009));
        }
        assert_eq!(seen.len, 1000);
        for i in 0..1000 {
            assert_eq!(seen.get(i), i as u32 * 7919 % 1009);
        }
    }
}
