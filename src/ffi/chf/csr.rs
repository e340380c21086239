//! Bulk relations for all elements at once, in compressed sparse rows (see `CsrSink`),
//! rows as the one-element calls give them. O(T) at every level, without raising the
//! level: below the level that stores them, the call computes the ranks (and `O` at level
//! 0) once, in temporary memory. A size query followed by the call does the work twice.

use super::ChfMesh;
use crate::ffi::declare::exports;

exports! { ChfMesh;
    /// VV for every vertex (rows as `chf_vertex_vertices`). O(T) at every level.
    csr fn chf_mesh_vertex_vertices_csr() { |c, s| s.copy(&c.all_vertex_vertices()?) }
    /// VE for every vertex (rows as `chf_vertex_edges`). O(T) at every level.
    csr fn chf_mesh_vertex_edges_csr() { |c, s| s.copy(&c.all_vertex_edges()?) }
    /// VF for every vertex (rows as `chf_vertex_faces`). O(T) at every level.
    csr fn chf_mesh_vertex_faces_csr() { |c, s| s.copy(&c.all_vertex_faces()?) }
    /// VT for every vertex (rows as `chf_vertex_tetrahedra`). O(T) at every level.
    csr fn chf_mesh_vertex_tetrahedra_csr() { |c, s| s.copy(&c.all_vertex_tetrahedra()?) }
    /// EF for every edge (rows as `chf_edge_faces`, in rotation order). O(T) at every level.
    csr fn chf_mesh_edge_faces_csr() { |c, s| c.for_each_edge_faces(|_, row| s.stream(row)) }
    /// ET for every edge (rows as `chf_edge_tetrahedra`, in rotation order). O(T) at every level.
    csr fn chf_mesh_edge_tetrahedra_csr() {
        |c, s| c.for_each_edge_tetrahedra(|_, row| s.stream(row))
    }
    /// TT for every tetrahedron: 4 entries per row (so `offsets[t] == 4 t`), the
    /// tetrahedron across face `i`, `TOPOMESH_NONE` on the boundary, as
    /// `chf_tetrahedron_tetrahedra`. O(T) at every level.
    csr fn chf_mesh_tetrahedron_tetrahedra_csr() {
        |c, s| c.for_each_tetrahedron_tetrahedra(|row| s.stream(row))
    }
}
