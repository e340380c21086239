//! The bounded relations (EV, FV, FE, FF, FT, TV, TE, TF, TT), boundary tests and the
//! half-face and half-edge accessors. Vertex-centred relations are in `star.rs`, the
//! rotation around an edge in `fan.rs`. Ids out of range panic; `check_*` first. A
//! removed face or edge (of an edited mesh) answers `NONE` or nothing, as its id does in
//! every relation of the live elements around it.

use crate::chf::Chf;
use crate::chf::ids::{
    self, HalfEdge, NO_HALF_EDGE, first, half_edge, he_face, he_origin, he_target, slot_half_edges,
    tet,
};
use crate::chf::query::view::Need;
use crate::{Ids, NONE};

impl Chf {
    /// The twin of half-face `hf`, `NONE` on the boundary; a half-face of a removed
    /// tetrahedron is its own twin until `garbage_collect`. O(1) from level 1, a scan at
    /// level 0.
    #[inline]
    pub fn opposite(&self, hf: u32) -> u32 {
        if self.level >= 1 || self.edit.is_some() {
            return self.o[hf as usize];
        }
        self.opposite_by_scan(hf)
    }

    /// Is half-face `hf` on the boundary? O(1) from level 1.
    pub fn is_boundary_half_face(&self, hf: u32) -> bool {
        self.opposite(hf) == NONE
    }

    /// The vertices of half-face `hf`, in its outward order.
    pub fn half_face_vertices_of(&self, hf: u32) -> [u32; 3] {
        ids::face_cycle(&self.v, hf)
    }

    /// The face id of half-face `hf`. O(1) at level 2, O(T) below.
    pub fn face_of(&self, hf: u32) -> u32 {
        self.view(Need::FACES).face_of(hf)
    }

    /// The canonical half-face of face `f` (the boundary one on a boundary face), `NONE`
    /// for a removed face. O(1) at level 2, O(T) below.
    pub fn face_half_face(&self, f: u32) -> u32 {
        self.view(Need::FACES).face_half_face(f)
    }

    /// The mate of half-edge `he`: the same edge on the other face of its tetrahedron.
    pub fn mate(&self, he: HalfEdge) -> HalfEdge {
        ids::mate(he)
    }

    /// The radial of half-edge `he`: the same edge on the twin half-face, or
    /// [`crate::chf::NO_HALF_EDGE`] on the boundary. O(1) from level 1.
    pub fn radial(&self, he: HalfEdge) -> HalfEdge {
        if self.level >= 1 || self.edit.is_some() {
            ids::radial(&self.v, &self.o, he)
        } else {
            ids::radial(&self.v, &self.view(Need::NOTHING).o, he)
        }
    }

    /// The ends of half-edge `he`.
    pub fn half_edge_vertices(&self, he: HalfEdge) -> [u32; 2] {
        [he_origin(&self.v, he), he_target(&self.v, he)]
    }

    /// The edge id of half-edge `he`. O(k) at level 2 (a walk around the edge to its
    /// canonical slot), O(T) below.
    pub fn edge_of(&self, he: HalfEdge) -> u32 {
        self.view(Need::EDGES).edge_of(he)
    }

    /// The canonical half-edge of edge `e`, where its rotation starts (on a boundary
    /// half-face for a boundary edge), [`crate::chf::NO_HALF_EDGE`] for a removed edge.
    /// O(1) at level 2, O(T) below.
    pub fn edge_half_edge(&self, e: u32) -> HalfEdge {
        self.view(Need::EDGES).edge_half_edge(e)
    }

    /// A half-face holding `v`, a boundary one when `v` is on the boundary; `NONE` for an
    /// isolated vertex. O(1) at level 2, a scan below.
    pub fn vertex_half_face(&self, v: u32) -> u32 {
        if self.level >= 2 || self.edit.is_some() {
            self.vh[v as usize]
        } else {
            self.view(Need::NOTHING).start_half_face(v)
        }
    }

    /// Is `v` on the boundary? O(1) at level 2. An isolated vertex is not.
    pub fn is_boundary_vertex(&self, v: u32) -> bool {
        let hf = self.vertex_half_face(v);
        hf != NONE && self.opposite(hf) == NONE
    }

    /// Is `v` in no tetrahedron?
    pub fn is_isolated_vertex(&self, v: u32) -> bool {
        self.vertex_half_face(v) == NONE
    }

    /// Is edge `e` on the boundary (on a boundary face)? O(1) at level 2.
    pub fn is_boundary_edge(&self, e: u32) -> bool {
        let view = self.view(Need::EDGES);
        let he = view.edge_half_edge(e);
        he != NO_HALF_EDGE && view.is_boundary_half_edge(he)
    }

    /// Is face `f` on the boundary (one tetrahedron)? O(1) at level 2; O(1) from level 1
    /// on half-faces ([`Chf::is_boundary_half_face`]).
    pub fn is_boundary_face(&self, f: u32) -> bool {
        let view = self.view(Need::FACES);
        let hf = view.face_half_face(f);
        hf != NONE && view.opposite(hf) == NONE
    }

    /// EV: the ends of edge `e`, in the direction of its canonical half-edge.
    pub fn edge_vertices(&self, e: u32) -> [u32; 2] {
        match self.edge_half_edge(e) {
            NO_HALF_EDGE => [NONE; 2],
            he => self.half_edge_vertices(he),
        }
    }

    /// FV: the vertices of face `f` in the order of its canonical half-face (outward for
    /// the tetrahedron that half-face belongs to).
    pub fn face_vertices(&self, f: u32) -> [u32; 3] {
        match self.face_half_face(f) {
            NONE => [NONE; 3],
            hf => ids::face_cycle(&self.v, hf),
        }
    }

    /// FE: the edges of face `f`; edge `j` runs from vertex `j` to vertex `j + 1` of FV.
    pub fn face_edges(&self, f: u32) -> [u32; 3] {
        let view = self.view(Need {
            faces: true,
            edges: true,
        });
        let hf = view.face_half_face(f);
        if hf == NONE {
            return [NONE; 3];
        }
        [0, 1, 2].map(|j| view.edge_of(half_edge(hf, j)))
    }

    /// FF: the faces sharing a tetrahedron (hence an edge) with `f`, each once: the other
    /// three faces of the tetrahedron of `f`'s canonical half-face, then of its twin's.
    pub fn face_faces(&self, f: u32) -> Ids<6> {
        let view = self.view(Need::FACES);
        let hf = view.face_half_face(f);
        let mut out = Ids::new();
        if hf == NONE {
            return out;
        }
        for side in [hf, view.opposite(hf)] {
            if side == NONE {
                continue;
            }
            for k in 1..4 {
                let g = view.face_of(ids::next(side, k));
                // Two tetrahedra share two faces only when they have the same vertices.
                if !out.contains(&g) {
                    out.push(g);
                }
            }
        }
        out
    }

    /// FT: the one or two tetrahedra of face `f`, the canonical half-face's first.
    pub fn face_tetrahedra(&self, f: u32) -> Ids<2> {
        let view = self.view(Need::FACES);
        match view.face_half_face(f) {
            NONE => Ids::new(),
            hf => Ids::both_sides(hf, view.opposite(hf), tet),
        }
    }

    /// TV: the four vertices of tetrahedron `t` (a removed one keeps its corners until
    /// `garbage_collect`; `check_tetrahedron` tells it is removed).
    pub fn tetrahedron_vertices(&self, t: u32) -> [u32; 4] {
        let b = first(t) as usize;
        [self.v[b], self.v[b + 1], self.v[b + 2], self.v[b + 3]]
    }

    /// TE: the six edges of `t`, in local-pair order (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
    pub fn tetrahedron_edges(&self, t: u32) -> [u32; 6] {
        let view = self.view(Need::EDGES);
        [0, 1, 2, 3, 4, 5].map(|k| view.edge_of(slot_half_edges(6 * t as u64 + k)[0]))
    }

    /// TF: the four faces of `t`; face `i` is opposite vertex `i`.
    pub fn tetrahedron_faces(&self, t: u32) -> [u32; 4] {
        let view = self.view(Need::FACES);
        [0, 1, 2, 3].map(|i| view.face_of(first(t) + i))
    }

    /// TT: the tetrahedron across each face of `t` (`NONE` on the boundary, and for a
    /// removed `t`). O(1) from level 1.
    pub fn tetrahedron_tetrahedra(&self, t: u32) -> [u32; 4] {
        [0, 1, 2, 3].map(|i| {
            let hf = first(t) + i;
            // A removed tetrahedron's half-faces are their own twins.
            match self.opposite(hf) {
                o if o == NONE || o == hf => NONE,
                o => tet(o),
            }
        })
    }

    /// The face of half-edge `he`'s half-face, for callers walking half-edges.
    pub fn half_edge_face(&self, he: HalfEdge) -> u32 {
        self.face_of(he_face(he))
    }
}
