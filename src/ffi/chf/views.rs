//! Zero-copy views of the containers (see `view!`), valid until the mesh is freed or its
//! level changes.

use super::ChfMesh;
use crate::ffi::boundary::origins;
use crate::ffi::mesh_arrays::coordinates;
use crate::ffi::shapes::view;
use std::borrow::Cow;

/// A map stored at this level (borrowed), else `None` (computed for the call: no view).
fn stored(map: Cow<'_, [u32]>) -> Option<&[u32]> {
    match map {
        Cow::Borrowed(s) => Some(s),
        Cow::Owned(_) => None,
    }
}

/// `V`: vertex `i` of tetrahedron `t` at `V[4t + i]` (`4 * num_tetrahedra` entries); also
/// the vertex each half-face `4t + i` is opposite. The vertices of half-face `hf` in its
/// outward order are `V[chf_face_corner(hf, j)]`, j = 0, 1, 2. All levels.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_half_face_vertices(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| Some(m.chf.half_face_vertices()))
}

/// `O`: the twin of every half-face (`TOPOMESH_NONE` on the boundary). NULL below level 1.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_opposites(m: *const ChfMesh, len: *mut usize) -> *const u32 {
    view!(m, len, |m| m.chf.opposites())
}

/// `VH`: one half-face holding each vertex, a boundary one on a boundary vertex,
/// `TOPOMESH_NONE` for an isolated vertex (`num_vertices` entries). NULL below level 2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_half_faces(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| m.chf.vertex_half_faces())
}

/// `FH`: the canonical half-face of every face (`num_faces` entries, increasing; the
/// boundary one on a boundary face). NULL below level 2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_face_half_faces(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| m.chf.face_half_faces())
}

/// The boundary half-faces in increasing order: triangle `k` of `chf_mesh_boundary`'s
/// surface is the `k`-th. NULL below level 3 (then use `chf_boundary_triangle_half_face`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_boundary_half_faces(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| stored(m.chf.boundary_half_faces()))
}

/// The boundary vertices in increasing order (`chf_mesh_num_boundary_vertices` entries):
/// vertex `b` of `chf_mesh_boundary`'s surface is volume vertex `[b]` (copies the surface
/// splits come after, see `chf_boundary_vertex_vertex`). NULL below level 3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_boundary_vertices(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| stored(m.chf.boundary_vertices()))
}

/// The boundary component of every boundary vertex (indexed like
/// `chf_mesh_boundary_vertices`): components of the boundary triangles joined through
/// shared vertices, numbered in order of their first boundary half-face. NULL below level
/// 3 (then use `chf_vertex_boundary_component`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_boundary_vertex_components(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| m.chf.boundary_vertex_components())
}

/// Positions: x, y, z per structure vertex (copies repeat their origin's position);
/// `*len` is the number of doubles, `3 * num_vertices`. NULL when built without positions.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_positions(m: *const ChfMesh, len: *mut usize) -> *const f64 {
    view!(m, len, |m| Some(m.chf.positions())
        .filter(|p| !p.is_empty())
        .map(coordinates))
}

/// Structure vertex -> input vertex (`num_vertices` entries; the identity on the input
/// vertices, then the origin of each split copy). Materialised on first use when it is the
/// identity; then kept with the mesh.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_origins(m: *const ChfMesh, len: *mut usize) -> *const u32 {
    view!(m, len, |m| Some(origins(
        m.chf.vertex_origins(),
        &m.vertex_origins,
        m.chf.num_vertices()
    )))
}

/// Structure tetrahedron -> input tetrahedron (`num_tetrahedra` entries; increasing, with
/// gaps where degenerate tetrahedra were dropped). Materialised on first use when it is
/// the identity.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_tetrahedron_origins(
    m: *const ChfMesh, len: *mut usize,
) -> *const u32 {
    view!(m, len, |m| Some(origins(
        m.chf.tetrahedron_origins(),
        &m.tetrahedron_origins,
        m.chf.num_tetrahedra()
    )))
}
