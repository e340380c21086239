//! Zero-copy views of the containers (`view` entries of `exports!`), valid until the mesh
//! is freed or its level changes.

use super::ChfMesh;
use crate::ffi::boundary::origins;
use crate::ffi::declare::exports;
use crate::ffi::mesh_arrays::coordinates;
use std::borrow::Cow;

/// A map stored at this level (borrowed), else `None` (computed for the call: no view).
fn stored(map: Cow<'_, [u32]>) -> Option<&[u32]> {
    match map {
        Cow::Borrowed(s) => Some(s),
        Cow::Owned(_) => None,
    }
}

exports! { ChfMesh;
    /// `V`: vertex `i` of tetrahedron `t` at `V[4t + i]` (`4 * num_tetrahedra` entries); also
    /// the vertex each half-face `4t + i` is opposite. The vertices of half-face `hf` in its
    /// outward order are `V[chf_face_corner(hf, j)]`, j = 0, 1, 2. All levels.
    view fn chf_mesh_half_face_vertices() -> u32 { |m| Some(m.chf.half_face_vertices()) }
    /// `O`: the twin of every half-face (`TOPOMESH_NONE` on the boundary). NULL below level 1.
    view fn chf_mesh_opposites() -> u32 { |m| m.chf.opposites() }
    /// `VH`: one half-face holding each vertex, a boundary one on a boundary vertex,
    /// `TOPOMESH_NONE` for an isolated vertex (`num_vertices` entries). NULL below level 2.
    view fn chf_mesh_vertex_half_faces() -> u32 { |m| m.chf.vertex_half_faces() }
    /// `FH`: the canonical half-face of every face (`num_faces` entries, increasing; the
    /// boundary one on a boundary face). NULL below level 2.
    view fn chf_mesh_face_half_faces() -> u32 { |m| m.chf.face_half_faces() }
    /// The boundary half-faces in increasing order: triangle `k` of `chf_mesh_boundary`'s
    /// surface is the `k`-th. NULL below level 3 (then use `chf_boundary_triangle_half_face`).
    view fn chf_mesh_boundary_half_faces() -> u32 { |m| stored(m.chf.boundary_half_faces()) }
    /// The boundary vertices in increasing order (`chf_mesh_num_boundary_vertices` entries):
    /// vertex `b` of `chf_mesh_boundary`'s surface is volume vertex `[b]` (copies the surface
    /// splits come after, see `chf_boundary_vertex_vertex`). NULL below level 3.
    view fn chf_mesh_boundary_vertices() -> u32 { |m| stored(m.chf.boundary_vertices()) }
    /// The boundary component of every boundary vertex (indexed like
    /// `chf_mesh_boundary_vertices`): components of the boundary triangles joined through
    /// shared vertices, numbered in order of their first boundary half-face. NULL below level
    /// 3 (then use `chf_vertex_boundary_component`).
    view fn chf_mesh_boundary_vertex_components() -> u32 { |m| m.chf.boundary_vertex_components() }
    /// Positions: x, y, z per structure vertex (copies repeat their origin's position);
    /// `*len` is the number of doubles, `3 * num_vertices`. NULL when built without positions.
    view fn chf_mesh_positions() -> f64 {
        |m| Some(m.chf.positions()).filter(|p| !p.is_empty()).map(coordinates)
    }
    /// Structure vertex -> input vertex (`num_vertices` entries; the identity on the input
    /// vertices, then the origin of each split copy). Materialised on first use when it is the
    /// identity, then kept with the mesh; NULL when that runs out of memory
    /// (`TOPOMESH_STATUS_OUT_OF_MEMORY` in `topomesh_last_error`), as for the next one.
    view fn chf_mesh_vertex_origins() -> u32 {
        |m| Some(origins(m.chf.vertex_origins(), &m.vertex_origins, m.chf.num_vertices())?)
    }
    /// Structure tetrahedron -> input tetrahedron (`num_tetrahedra` entries; increasing, with
    /// gaps where degenerate tetrahedra were dropped). Materialised on first use when it is
    /// the identity.
    view fn chf_mesh_tetrahedron_origins() -> u32 {
        |m| Some(origins(m.chf.tetrahedron_origins(), &m.tetrahedron_origins, m.chf.num_tetrahedra())?)
    }
}
