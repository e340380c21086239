//! Zero-copy views of the containers (`view` entries of `exports!`), valid until the mesh
//! is freed or its level changes.

use super::CheMesh;
use crate::che::Che;
use crate::ffi::boundary::origins;
use crate::ffi::declare::exports;
use crate::ffi::mesh_arrays::coordinates;
use std::ptr::null;

/// The arrays an inline walk reads and the counts that bound its ids, in one call: what
/// `che_mesh_half_edge_vertices`, `che_mesh_opposites`, `che_mesh_vertex_half_edges`,
/// `che_mesh_edge_half_edges`, `che_mesh_positions` and `che_mesh_num_*` give one at a
/// time, for a wrapper that fetches them again after every edit. NULL where the level
/// stores none; `positions` NULL unless every vertex has one. Valid as the views are.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct CheViews {
    /// `V`, `3 * num_triangles` entries.
    pub half_edge_vertices: *const u32,
    /// `O`, `3 * num_triangles` entries, from level 1.
    pub opposites: *const u32,
    /// `VH`, `num_vertices` entries, from level 2.
    pub vertex_half_edges: *const u32,
    /// `EH`, `num_edges` entries, from level 2.
    pub edge_half_edges: *const u32,
    /// x, y, z per vertex.
    pub positions: *const f64,
    pub num_vertices: usize,
    pub num_triangles: usize,
    pub num_edges: usize,
}

fn views_of(c: &Che) -> CheViews {
    let ptr = |s: Option<&[u32]>| s.map_or(null(), <[u32]>::as_ptr);
    let p = c.positions();
    CheViews {
        half_edge_vertices: c.half_edge_vertices().as_ptr(),
        opposites: ptr(c.opposites()),
        vertex_half_edges: ptr(c.vertex_half_edges()),
        edge_half_edges: ptr(c.edge_half_edges()),
        positions: if p.len() < c.num_vertices() || p.is_empty() {
            null()
        } else {
            coordinates(p).as_ptr()
        },
        num_vertices: c.num_vertices(),
        num_triangles: c.num_triangles(),
        num_edges: c.num_edges(),
    }
}

exports! { CheMesh;
    /// The views and counts into `*out` (see `che_views`), all at once. O(1).
    value fn che_mesh_views() -> CheViews { |c| Ok(views_of(c)) }
    /// `V`: the origin vertex of every half-edge (`3 * num_triangles` entries); triangle t is
    /// `V[3t], V[3t+1], V[3t+2]`, counter-clockwise. All levels.
    view fn che_mesh_half_edge_vertices() -> u32 { |m| Some(m.che.half_edge_vertices()) }
    /// `O`: the opposite of every half-edge (`TOPOMESH_NONE` on the boundary). NULL below
    /// level 1.
    view fn che_mesh_opposites() -> u32 { |m| m.che.opposites() }
    /// `VH`: one outgoing half-edge per vertex, the boundary one on a boundary vertex,
    /// `TOPOMESH_NONE` for an isolated vertex. NULL below level 2.
    view fn che_mesh_vertex_half_edges() -> u32 { |m| m.che.vertex_half_edges() }
    /// `EH`: the canonical half-edge of every edge (the boundary one on a boundary edge).
    /// NULL below level 2.
    view fn che_mesh_edge_half_edges() -> u32 { |m| m.che.edge_half_edges() }
    /// `CH`: one boundary half-edge per boundary curve (its smallest). NULL below level 3.
    view fn che_mesh_curve_half_edges() -> u32 { |m| m.che.curve_half_edges() }
    /// Positions: x, y, z per structure vertex (copies repeat their origin's position);
    /// `*len` is the number of doubles, `3 * num_vertices`. NULL when built without positions.
    view fn che_mesh_positions() -> f64 {
        |m| { let p = m.che.positions(); (!p.is_empty()).then(|| coordinates(p)) }
    }
    /// Structure vertex -> input vertex (`num_vertices` entries; the identity on the input
    /// vertices, then the origin of each split copy). Materialised on first use when it is the
    /// identity, then kept with the mesh; NULL when that runs out of memory
    /// (`TOPOMESH_STATUS_OUT_OF_MEMORY` in `topomesh_last_error`), as for the next one.
    view fn che_mesh_vertex_origins() -> u32 {
        |m| Some(origins(m.che.vertex_origins(), &m.vertex_origins, m.che.num_vertices())?)
    }
    /// Structure triangle -> input triangle (`num_triangles` entries; increasing, with gaps
    /// where degenerate triangles were dropped).
    view fn che_mesh_triangle_origins() -> u32 {
        |m| Some(origins(m.che.triangle_origins(), &m.triangle_origins, m.che.num_triangles())?)
    }
    /// The edge-id directory: one entry per 32 half-edges (`*len` entries, `ceil(3T / 32)`);
    /// the low 32 bits of entry k flag the canonical half-edges among `32k .. 32k + 31`
    /// (`O[h] == TOPOMESH_NONE || h < O[h]`, bit `h % 32`), the high 32 bits count the canonical
    /// half-edges before `32k`. With `O` it gives the edge of any half-edge in O(1) without a
    /// call: `che_edge_of` in `topomesh_inline.h`. From level 2 this is the structure's own
    /// directory (counted in `che_mesh_memory`'s `edges`); at level 1 it is computed from `O`
    /// on the first request (2 bits per half-edge, kept with the mesh until its level
    /// changes). NULL below level 1.
    view fn che_mesh_edge_ranks() -> u64 { |m| m.che.edge_ranks() }
}
