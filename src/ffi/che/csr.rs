//! Bulk relations for all elements at once, in compressed sparse rows (see `CsrSink`),
//! rows in the order of the one-element calls. O(T) at every level: the core's bulk sweep
//! streams the rows into the caller's buffers.

use super::CheMesh;
use crate::ffi::declare::exports;

exports! { CheMesh;
    /// VV for every vertex (rows as `che_vertex_vertices`). O(T) at every level
    /// (O(T) memory at level 0).
    csr fn che_mesh_vertex_vertices_csr() { |c, s| c.vertex_vertices_rows(s) }
    /// VE for every vertex (rows as `che_vertex_edges`). O(T) at every level
    /// (O(T) memory at level 0).
    csr fn che_mesh_vertex_edges_csr() { |c, s| c.vertex_edges_rows(s) }
    /// VF for every vertex (rows as `che_vertex_triangles`). O(T) at every level
    /// (O(T) memory at level 0).
    csr fn che_mesh_vertex_triangles_csr() { |c, s| c.vertex_triangles_rows(s) }
    /// FF for every triangle: 3 entries per row (so `offsets[t] == 3 t`), `TOPOMESH_NONE`
    /// across boundary edges, as `che_triangle_triangles`. O(T) at every level.
    csr fn che_mesh_triangle_triangles_csr() { |c, s| c.triangle_triangles_rows(s) }
}
