//! Bulk relations for all elements at once, in compressed sparse rows: row `i` is
//! `indices[offsets[i] .. offsets[i + 1]]`, so `offsets` has one entry per element plus one.
//!
//! Every call has the form `(m, offsets, offsets_cap, indices, indices_cap, *n_offsets,
//! *n_indices)`. Both buffers NULL (capacities 0) is a size query: OK, with both lengths
//! written. Exactly one NULL buffer gives NULL_ARGUMENT. A buffer too small gives
//! BUFFER_TOO_SMALL with both needed lengths written (the buffers then hold a prefix).
//! Rows are the answers of the one-element calls, in the same order. O(T) at every level,
//! without raising the level or copying the mesh: the rows around the vertices (VV, VE,
//! VF, VT, each row in increasing id order) come from counting passes over `V` and the
//! face and edge ranks, not from walks; ET and EF walk the rotations on one view; below
//! the level that stores them, the call computes the ranks (and `O` at level 0) once, in
//! temporary memory. A size query followed by the call does the work twice.

use super::ChfMesh;
use crate::ffi::shapes::csr;
use crate::ffi::status::Status;

/// VV for every vertex (rows as `chf_vertex_vertices`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_vertices_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| s.copy(&c.all_vertex_vertices()))
}

/// VE for every vertex (rows as `chf_vertex_edges`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_edges_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| s.copy(&c.all_vertex_edges()))
}

/// VF for every vertex (rows as `chf_vertex_faces`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_faces_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| s.copy(&c.all_vertex_faces()))
}

/// VT for every vertex (rows as `chf_vertex_tetrahedra`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| s.copy(&c.all_vertex_tetrahedra()))
}

/// EF for every edge (rows as `chf_edge_faces`, in rotation order).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_edge_faces_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| c.for_each_edge_faces(|_, row| s.stream(row)))
}

/// ET for every edge (rows as `chf_edge_tetrahedra`, in rotation order).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_edge_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| c.for_each_edge_tetrahedra(|_, row| s.stream(row)))
}

/// TT for every tetrahedron: 4 entries per row (so `offsets[t] == 4 t`), the
/// tetrahedron across face `i`, `TOPOMESH_NONE` on the boundary, as
/// `chf_tetrahedron_tetrahedra`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_tetrahedron_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => |c, s| c.for_each_tetrahedron_tetrahedra(|row| s.stream(row)))
}
