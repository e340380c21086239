//! Bulk relations for all elements at once, in compressed sparse rows (see `CsrSink`),
//! rows in the order of the one-element calls. O(T) at every level: the core's bulk sweep
//! streams the rows into the caller's buffers.

use super::CheMesh;
use crate::ffi::shapes::csr;
use crate::ffi::status::Status;

/// VV for every vertex (rows as `che_vertex_vertices`). O(T) at every level
/// (O(T) memory at level 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_vertices_csr(
    m: *const CheMesh, offsets: *mut u32, offsets_cap: usize, indices: *mut u32,
    indices_cap: usize, n_offsets: *mut usize, n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => vertex_vertices_rows)
}

/// VE for every vertex (rows as `che_vertex_edges`). O(T) at every level
/// (O(T) memory at level 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_edges_csr(
    m: *const CheMesh, offsets: *mut u32, offsets_cap: usize, indices: *mut u32,
    indices_cap: usize, n_offsets: *mut usize, n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => vertex_edges_rows)
}

/// VF for every vertex (rows as `che_vertex_triangles`). O(T) at every level
/// (O(T) memory at level 0).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_triangles_csr(
    m: *const CheMesh, offsets: *mut u32, offsets_cap: usize, indices: *mut u32,
    indices_cap: usize, n_offsets: *mut usize, n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => vertex_triangles_rows)
}

/// FF for every triangle: 3 entries per row (so `offsets[t] == 3 t`), `TOPOMESH_NONE`
/// across boundary edges, as `che_triangle_triangles`. O(T) at every level.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_triangle_triangles_csr(
    m: *const CheMesh, offsets: *mut u32, offsets_cap: usize, indices: *mut u32,
    indices_cap: usize, n_offsets: *mut usize, n_indices: *mut usize,
) -> Status {
    csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices
        => triangle_triangles_rows)
}
