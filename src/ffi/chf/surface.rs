//! The boundary surface of a volume mesh as a CHE, and the maps between its triangles and
//! the boundary half-faces and faces.
//!
//! Triangle `k` of the boundary surface is the `k`-th unpaired half-face in increasing
//! order (boundary faces, and also the half-faces of non-manifold faces and orientation
//! seams, which the structure keeps unpaired), its corners in the half-face's outward
//! order. Its vertices are the boundary vertices only, with compact ids: boundary vertex
//! `b` is the `b`-th volume vertex on an unpaired half-face, in increasing id order, so the
//! surface's `che_summary` (Euler characteristic, isolated vertices) is the boundary's.
//! Vertices the CHE itself splits (a boundary pinched at a vertex) come after those, see
//! its `che_mesh_vertex_origins`; `chf_boundary_vertex_vertex` maps any of them back to the
//! volume. Every call works at every level: O(1) per element at level 3, which stores the
//! surface and the maps; O(T) per call below.

use super::ChfMesh;
use crate::ffi::boundary::handle;
use crate::ffi::che::CheMesh;
use crate::ffi::declare::exports;
use crate::ffi::shapes::make;
use crate::ffi::status::Status;

/// The boundary surface as a new CHE at level 3 into `*out`, which the caller frees with
/// `che_mesh_free` (it does not borrow the volume mesh). A copy of the stored surface at
/// level 3; built, O(T), below. A closed volume gives a closed surface (no boundary
/// curves); a mesh without tetrahedra an empty one. `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_boundary(m: *const ChfMesh, out: *mut *mut CheMesh) -> Status {
    make!(out, handle(m, "m")?.chf.boundary_surface())
}

exports! { ChfMesh;
    /// Boundary faces: faces with exactly one tetrahedron (as `boundary_faces` in
    /// `chf_summary`). The half-faces of faces shared by 3+ tetrahedra
    /// (`chf_mesh_num_non_manifold_half_faces`) and of orientation seams
    /// (`chf_mesh_num_seam_half_faces`) are unpaired too but are not boundary faces; all three
    /// together are the triangles of `chf_mesh_boundary`'s surface
    /// (`chf_mesh_num_boundary_triangles`). O(1) at level 3, O(T) below; 0 for NULL.
    count fn chf_mesh_num_boundary_faces() -> usize { |c| c.num_boundary_faces() }
    /// Unpaired half-faces: the triangles of `chf_mesh_boundary`'s surface, that is
    /// `chf_mesh_num_boundary_faces + chf_mesh_num_non_manifold_half_faces +
    /// chf_mesh_num_seam_half_faces`. O(1) at level 3, O(T) below; 0 for NULL.
    count fn chf_mesh_num_boundary_triangles() -> usize { |c| c.num_boundary_triangles() }
    /// Half-faces of non-manifold faces (faces shared by 3+ tetrahedra: one per tetrahedron,
    /// each unpaired). O(1); 0 for NULL.
    count fn chf_mesh_num_non_manifold_half_faces() -> usize { |c| c.num_non_manifold_half_faces() }
    /// Half-faces on orientation seams (a face of two tetrahedra whose orientations disagree,
    /// in a non-orientable component: both unpaired). O(1); 0 for NULL.
    count fn chf_mesh_num_seam_half_faces() -> usize { |c| c.num_seam_half_faces() }
    /// Boundary vertices: the vertices of the unpaired half-faces, the vertices of
    /// `chf_mesh_boundary`'s surface before its own split. O(1) at level 3, O(T) below; 0 for
    /// NULL.
    count fn chf_mesh_num_boundary_vertices() -> usize { |c| c.num_boundary_vertices() }
    /// The boundary-surface vertex of volume vertex `v` into `*out`, `TOPOMESH_NONE` off the
    /// boundary. O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call).
    value fn chf_vertex_boundary_vertex(v) -> u32 { check_vertex(v) => |c| c.boundary_vertex(v) }
    /// The volume vertex of vertex `b` of `chf_mesh_boundary`'s surface into `*out` (copies
    /// the surface split map to the vertex they come from); `b` out of range gives
    /// OUT_OF_RANGE. O(1) at level 3; O(T) time and memory below (the boundary surface built
    /// for the call).
    value fn chf_boundary_vertex_vertex(b) -> u32 { |c| c.checked_boundary_vertex_volume_vertex(b) }
    /// Boundary components of the structure (after the vertex split): components of the
    /// boundary faces joined through shared vertices. O(1) at level 3, O(T) below; 0 for NULL.
    count fn chf_mesh_num_boundary_components() -> usize { |c| c.try_num_boundary_components()? }
    /// The boundary triangle of half-face `hf` into `*out`, `TOPOMESH_NONE` when `hf` is
    /// paired (interior). O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call).
    value fn chf_half_face_boundary_triangle(hf) -> u32 {
        check_half_face(hf) => |c| c.boundary_triangle(hf)
    }
    /// The half-face of boundary triangle `k` into `*out`; `k` out of range (see
    /// `chf_mesh_num_boundary_triangles`) gives OUT_OF_RANGE. O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call).
    value fn chf_boundary_triangle_half_face(k) -> u32 {
        |c| c.checked_boundary_triangle_half_face(k)
    }
    /// The boundary triangle of face `f` into `*out`, `TOPOMESH_NONE` for an interior face.
    /// O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call)
    value fn chf_face_boundary_triangle(f) -> u32 {
        check_face(f) => |c| c.face_boundary_triangle(f)
    }
    /// The face of boundary triangle `k` into `*out`; `k` out of range gives OUT_OF_RANGE.
    /// O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call)
    value fn chf_boundary_triangle_face(k) -> u32 { |c| c.checked_boundary_triangle_face(k) }
    /// The boundary component of vertex `v` into `*out` (`TOPOMESH_NONE` off the boundary;
    /// see `chf_mesh_boundary_vertex_components` for the array at level 3). O(1) at level 3; O(T) time and memory below (the boundary's tables computed for the
    /// call).
    value fn chf_vertex_boundary_component(v) -> u32 {
        |c| c.check_vertex(v).and_then(|_| c.try_boundary_component(v))
    }
}
