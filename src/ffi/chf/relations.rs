//! The 16 relations, one element at a time (answers into caller buffers, see `ids!`).
//! Every relation works at every level with the same answer in the same order; below
//! level 2 a call computes the tables it needs (face and edge ranks, and `O` at level 0)
//! for itself, O(T) per call.

use super::ChfMesh;
use crate::ffi::declare::exports;

exports! { ChfMesh;
    /// VV: the vertices sharing an edge with `v`, each once, in increasing order (found by a
    /// walk over its star, the tetrahedra reached across the faces holding `v`; there is no
    /// rotation order around a vertex in 3D). Empty for an isolated vertex. O(star) at levels
    /// 2-3; O(T) time and memory at levels 0-1 (the start found by a scan of `V`, and the
    /// tables the level lacks, such as `O` at level 0 and the edge or face ranks, computed for
    /// the call).
    ids fn chf_vertex_vertices(v) { check_vertex(v) => |c| c.vertex_vertices(v) }
    /// VE: the edges holding `v`, each once, in increasing order. O(star) at levels 2-3; O(T)
    /// time and memory at levels 0-1, as `chf_vertex_vertices`.
    ids fn chf_vertex_edges(v) { check_vertex(v) => |c| c.vertex_edges(v) }
    /// VF: the faces holding `v`, each once, in increasing order. O(star) at levels 2-3; O(T)
    /// time and memory at levels 0-1, as `chf_vertex_vertices`.
    ids fn chf_vertex_faces(v) { check_vertex(v) => |c| c.vertex_faces(v) }
    /// VT: the tetrahedra holding `v`, each once, in increasing order (a walk over its star
    /// from the half-face `chf_vertex_half_face` gives). O(star) at levels 2-3; O(T) time and
    /// memory at levels 0-1, as `chf_vertex_vertices`.
    ids fn chf_vertex_tetrahedra(v) { check_vertex(v) => |c| c.vertex_tetrahedra(v) }
    /// EV: the 2 ends of edge `e`, in the direction of its canonical half-edge (where its
    /// rotation starts: on a boundary face for a boundary edge). O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_edge_vertices(e) { check_edge(e) => |c| c.edge_vertices(e) }
    /// EE: the edges sharing a face with `e`, each once: for each face of `chf_edge_faces`, in
    /// that order, its two other edges (next, then previous in the face's order). O(k) walks
    /// at levels 2-3 (k: tetrahedra around each edge); O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call), plus the walks.
    ids fn chf_edge_edges(e) { check_edge(e) => |c| c.edge_edges(e) }
    /// EF: the faces around edge `e` in rotation order; on a boundary edge from one boundary
    /// face to the other (one more face than tetrahedra). O(k) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_edge_faces(e) { check_edge(e) => |c| c.edge_faces(e) }
    /// ET: the tetrahedra around edge `e` in rotation order, from the boundary on a boundary
    /// edge. O(k) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_edge_tetrahedra(e) { check_edge(e) => |c| c.edge_tetrahedra(e) }
    /// FV: the 3 vertices of face `f` in the order of its canonical half-face (the boundary
    /// one on a boundary face, else the smaller of the two), outward for that half-face's
    /// tetrahedron. O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_face_vertices(f) { check_face(f) => |c| c.face_vertices(f) }
    /// FE: the 3 edges of face `f`; edge `j` runs from vertex `j` to vertex `j + 1` of
    /// `chf_face_vertices`. O(k) per edge at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_face_edges(f) { check_face(f) => |c| c.face_edges(f) }
    /// FF: the faces sharing a tetrahedron with `f` (hence an edge), each once: the other three
    /// faces of the canonical half-face's tetrahedron, then of its twin's (3 on a boundary
    /// face, 6 inside). O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_face_faces(f) { check_face(f) => |c| c.face_faces(f) }
    /// FT: the tetrahedra of face `f` (2 entries, 1 on a boundary face), the canonical
    /// half-face's first. O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_face_tetrahedra(f) { check_face(f) => |c| c.face_tetrahedra(f) }
    /// TV: the 4 vertices of tetrahedron `t` (`V[4t .. 4t + 4]`, positively oriented when
    /// built with positions and orientable). O(1) at every level.
    ids fn chf_tetrahedron_vertices(t) { check_tetrahedron(t) => |c| c.tetrahedron_vertices(t) }
    /// TE: the 6 edges of tetrahedron `t`, in local-pair order (0,1) (0,2) (0,3) (1,2) (1,3)
    /// (2,3). O(k) per edge at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_tetrahedron_edges(t) { check_tetrahedron(t) => |c| c.tetrahedron_edges(t) }
    /// TF: the 4 faces of tetrahedron `t`; face `i` (half-face `4t + i`) is opposite vertex
    /// `i`. O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    ids fn chf_tetrahedron_faces(t) { check_tetrahedron(t) => |c| c.tetrahedron_faces(t) }
    /// TT: always 4 entries, the tetrahedron across face `i` of `t`, or `TOPOMESH_NONE` on
    /// the boundary (also across the faces of a non-manifold face and orientation seams,
    /// which the structure keeps unpaired). O(1) at levels 1-3; O(T) at level 0 (a scan of
    /// `V` per face).
    ids fn chf_tetrahedron_tetrahedra(t) { check_tetrahedron(t) => |c| c.tetrahedron_tetrahedra(t) }
}
