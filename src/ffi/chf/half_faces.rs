//! Boundary tests and the half-face helpers, one value into `*out` per call. An id out of
//! range gives `TOPOMESH_STATUS_OUT_OF_RANGE` (the detail names it) and writes nothing.
//!
//! Half-face `hf = 4t + i` is the face of tetrahedron `t` opposite its local vertex `i`
//! (see `chf_tet`, `chf_next` and `chf_face_corner` in the inline header).

use super::ChfMesh;
use crate::ffi::declare::exports;

exports! { ChfMesh;
    /// Is vertex `v` on the boundary? (`false` for an isolated vertex.) O(1) at levels 2-3;
    /// O(T) at level 1 (a scan of `V`); O(T) time and memory at level 0 (`O` computed).
    value fn chf_vertex_is_boundary(v) -> bool { check_vertex(v) => |c| c.is_boundary_vertex(v) }
    /// Is edge `e` on the boundary (on a boundary face)? O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    value fn chf_edge_is_boundary(e) -> bool { check_edge(e) => |c| c.is_boundary_edge(e) }
    /// Is face `f` on the boundary (one tetrahedron)? O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    value fn chf_face_is_boundary(f) -> bool { check_face(f) => |c| c.is_boundary_face(f) }
    /// The twin of half-face `hf` (the same face seen from the neighbouring tetrahedron) into
    /// `*out`, `TOPOMESH_NONE` on the boundary. O(1) at levels 1-3; O(T) at level 0 (a scan
    /// of `V`).
    value fn chf_half_face_opposite(hf) -> u32 { check_half_face(hf) => |c| c.opposite(hf) }
    /// The face of half-face `hf` into `*out`. O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    value fn chf_half_face_face(hf) -> u32 { check_half_face(hf) => |c| c.face_of(hf) }
    /// The canonical half-face of face `f` into `*out`: the boundary one on a boundary face,
    /// else the smaller of the two. O(1) at levels 2-3; O(T) time and memory at levels 0-1 (the tables the level lacks, such as `O` at level 0
    /// and the face or edge ranks, computed for the call).
    value fn chf_face_half_face(f) -> u32 { check_face(f) => |c| c.face_half_face(f) }
    /// A half-face holding vertex `v` into `*out`, where its star starts: a boundary one on a
    /// boundary vertex, `TOPOMESH_NONE` for an isolated vertex (`VH[v]`). O(1) at levels 2-3;
    /// O(T) at level 1 (a scan of `V`); O(T) time and memory at level 0 (`O` computed).
    value fn chf_vertex_half_face(v) -> u32 { check_vertex(v) => |c| c.vertex_half_face(v) }
}
