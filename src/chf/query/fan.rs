//! The rotation around an edge: from its canonical half-edge (on a boundary half-face for
//! a boundary edge, so one way round sweeps the whole fan), alternately `mate` (the other
//! face of the same tetrahedron) and `radial` (the twin face, into the next tetrahedron).
//! No allocation; O(k) for k tetrahedra, plus, for EE, the walk that names each edge.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{HalfEdge, NO_HALF_EDGE, he_face, he_next, mate, radial, tet};
use crate::chf::query::view::{Need, View};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Edges,
    Faces,
    Tetrahedra,
}

/// The edges, faces or tetrahedra around an edge, in rotation order, each once:
/// - ET: the tetrahedra in rotation order, from the boundary on a boundary edge;
/// - EF: the faces crossed in the same order (one more than the tetrahedra on a boundary
///   edge, starting and ending on the boundary);
/// - EE: for each face in EF order, its two other edges (next, then previous in the face's
///   order); an edge is listed once even when the first and last faces of a boundary fan
///   share it.
#[derive(Clone, Debug)]
pub struct EdgeIds<'a> {
    view: View<'a>,
    kind: Kind,
    /// The canonical half-edge, where the rotation starts and (closed fans) ends.
    start: HalfEdge,
    /// Entry half-edge of the current tetrahedron; `NO_HALF_EDGE` when done.
    cur: HalfEdge,
    /// Faces: the first face (the start's) is still to come.
    first_pending: bool,
    /// EE: the edges of the first face, and the ones waiting to be returned.
    first_edges: [u32; 2],
    pending: [u32; 2],
    len: u8,
    pos: u8,
}

impl<'a> EdgeIds<'a> {
    fn with_kind(view: View<'a>, e: u32, kind: Kind) -> Self {
        let start = view.edge_half_edge(e);
        EdgeIds {
            view,
            kind,
            start,
            cur: start,
            // A removed edge (no canonical half-edge) has nothing around it.
            first_pending: kind != Kind::Tetrahedra && start != NO_HALF_EDGE,
            first_edges: [NONE; 2],
            pending: [NONE; 2],
            len: 0,
            pos: 0,
        }
    }

    /// ET (or EF with `faces`) of edge `e` on a view with the edge ranks (and the face
    /// ranks for EF), for the bulk calls.
    pub(crate) fn on(view: View<'a>, e: u32, faces: bool) -> Self {
        let kind = if faces { Kind::Faces } else { Kind::Tetrahedra };
        Self::with_kind(view, e, kind)
    }

    /// The next half-edge of the rotation lying on a new face; `true` with the last face
    /// of an open fan.
    fn next_face(&mut self) -> Option<(HalfEdge, bool)> {
        if self.first_pending {
            self.first_pending = false;
            return Some((self.start, false));
        }
        if self.cur == NO_HALF_EDGE {
            return None;
        }
        let m = mate(self.cur);
        let n = radial(self.view.v, &self.view.o, m);
        if n == self.start {
            self.cur = NO_HALF_EDGE;
            return None;
        }
        self.cur = n;
        Some((m, n == NO_HALF_EDGE))
    }
}

impl Iterator for EdgeIds<'_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
        match self.kind {
            Kind::Tetrahedra => {
                let g = self.cur;
                if g == NO_HALF_EDGE {
                    return None;
                }
                let n = radial(self.view.v, &self.view.o, mate(g));
                self.cur = if n == self.start { NO_HALF_EDGE } else { n };
                Some(tet(he_face(g)))
            }
            Kind::Faces => {
                let (he, _) = self.next_face()?;
                Some(self.view.face_of(he_face(he)))
            }
            Kind::Edges => loop {
                if self.pos < self.len {
                    self.pos += 1;
                    return Some(self.pending[self.pos as usize - 1]);
                }
                let first = self.first_pending;
                let (he, last) = self.next_face()?;
                let a = self.view.edge_of(he_next(he));
                let b = self.view.edge_of(he_next(he_next(he)));
                self.pos = 0;
                self.len = 0;
                if first {
                    self.first_edges = [a, b];
                }
                for id in [a, b] {
                    // Only the two ends of an open fan can share a third vertex.
                    if !(last && self.first_edges.contains(&id)) {
                        self.pending[self.len as usize] = id;
                        self.len += 1;
                    }
                }
            },
        }
    }
}

impl std::iter::FusedIterator for EdgeIds<'_> {}

impl Chf {
    fn edge_ids(&self, e: u32, kind: Kind) -> EdgeIds<'_> {
        let need = match kind {
            Kind::Faces => Need {
                faces: true,
                edges: true,
            },
            Kind::Edges | Kind::Tetrahedra => Need::EDGES,
        };
        EdgeIds::with_kind(self.view(need), e, kind)
    }
    /// EE: the edges sharing a face with `e`, each once, in rotation order. O(k) walks of
    /// the neighbouring edges' fans at level 2.
    pub fn edge_edges(&self, e: u32) -> EdgeIds<'_> {
        self.edge_ids(e, Kind::Edges)
    }
    /// EF: the faces around `e`, in rotation order, from the boundary on a boundary edge.
    /// O(k) at level 2.
    pub fn edge_faces(&self, e: u32) -> EdgeIds<'_> {
        self.edge_ids(e, Kind::Faces)
    }
    /// ET: the tetrahedra around `e`, in rotation order, from the boundary on a boundary
    /// edge. O(k) at level 2.
    pub fn edge_tetrahedra(&self, e: u32) -> EdgeIds<'_> {
        self.edge_ids(e, Kind::Tetrahedra)
    }
}
