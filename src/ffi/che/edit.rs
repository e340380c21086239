//! Editing a surface in place: the exports of `che/edit/`. Each call needs exclusive
//! access to the mesh; a refused or failed call leaves it unchanged and names the reason
//! in `topomesh_last_error`. Views and arrays obtained before an edit (V, O, VH, EH, CH,
//! the origin maps, the positions) are invalid after it, whatever its outcome; ids stay
//! valid until `che_mesh_garbage_collect`.

use super::CheMesh;
use crate::che::GarbageMapsOut;
use crate::ffi::boundary::{collect_garbage, null_argument, position_arg};
use crate::ffi::declare::exports;
use crate::ffi::status::Status;

exports! { CheMesh;
    /// Adds an isolated vertex. `position` (3 doubles) is required when the mesh has
    /// positions and must be NULL when it has none. Its id goes to `out` (NULL: not wanted).
    ///
    /// Editing (this call and every `che_mesh_*` edit after it: add, remove, flip, split,
    /// collapse, set_position, the checks, garbage_collect) needs exclusive access. Every
    /// zero-copy view (`che_mesh_half_edge_vertices`, `_opposites`, `_vertex_half_edges`,
    /// `_edge_half_edges`, `_curve_half_edges`, `_edge_ranks`, the origins and positions) and
    /// every `che_star_iter` obtained before an edit is invalid after it, whatever its
    /// outcome: fetch them again. Removed elements keep their ids (`V = NONE` for a removed
    /// triangle's half-edges) until `che_mesh_garbage_collect`; until then `che_mesh_num_*`
    /// are the id bounds, `che_mesh_num_live_*` the counts, the edge-rank view is NULL (edge
    /// ids are not ranks), and exports and writers expect a collected mesh.
    edit fn che_mesh_add_vertex(position_xyz: *const f64) -> out: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.add_vertex(unsafe { position_arg(position_xyz) }?)
    }
    /// Adds triangle (a, b, c) into `out`, paired with the boundary half-edges it meets.
    /// Refused (INVALID_INPUT) for a degenerate triangle, OUT_OF_RANGE for a bad vertex id.
    /// On a mesh built strict (`che_build_options.strict`, kept by level files) also refused
    /// (INVALID_INPUT, the detail naming the edge or vertex) when an edge already has a
    /// triangle on that side, would become non-manifold, or a corner would get a second fan,
    /// and for a duplicate. On a mesh built non-strict (the default) those are repaired by
    /// the build's rules and counted in `che_mesh_report` (status OK): an edge that would
    /// carry a third triangle counts as non-manifold and the corners on it are split (the
    /// new triangle's corners may then be new vertices: read them back with
    /// `che_triangle_vertices`), a triangle against its neighbours' orientation is flipped
    /// (`flipped_triangles`), a duplicate is kept; the mesh is then the one a fresh non-strict build of its live
    /// triangles gives.
    edit fn che_mesh_add_triangle(a, b, c) -> out: u32 { |che| che.add_triangle(a, b, c) }
    /// Removes triangle `t` (marked: its id and the others stay until garbage collection).
    edit fn che_mesh_remove_triangle(t) { |c| c.remove_triangle(t) }
    /// Removes vertex `v` and its star.
    edit fn che_mesh_remove_vertex(v) { |c| c.remove_vertex(v) }
    /// Flips interior edge `e` (it keeps its id). Refused on a boundary edge or when the
    /// flipped edge exists.
    edit fn che_mesh_flip_edge(e) { |c| c.flip_edge(e) }
    /// Splits edge `e` at a new vertex (into `out`; position: `position_xyz`, or NULL for the
    /// midpoint when the mesh has positions).
    edit fn che_mesh_split_edge(e, position_xyz: *const f64) -> out: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.split_edge(e, unsafe { position_arg(position_xyz) }?)
    }
    /// Collapses half-edge `h`: its target merges into its origin (the kept vertex goes to
    /// `out`). Refused, with the reason, when the link condition fails.
    edit fn che_mesh_collapse_edge(h) -> out: u32 { |c| c.collapse_edge(h) }
    /// Splits triangle `t` into 3 at a new vertex (into `out`; NULL position: the centroid).
    edit fn che_mesh_split_triangle(t, position_xyz: *const f64) -> out: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.split_triangle(t, unsafe { position_arg(position_xyz) }?)
    }
    /// Moves vertex `v` to `position_xyz` (3 doubles); refused on a mesh without positions.
    edit fn che_mesh_set_position(v, position_xyz: *const f64) {
        |c| {
            // SAFETY: the export's contract: NULL or three readable doubles.
            let p = unsafe { position_arg(position_xyz) }?;
            c.set_position(v, p.ok_or_else(|| null_argument("position_xyz"))?)
        }
    }
    /// Would `che_mesh_flip_edge(m, e)` succeed? Never modifies the mesh: every view stays
    /// valid.
    ask fn che_mesh_is_flip_ok(e) -> bool { |c| c.is_flip_ok(e) }
    /// Would `che_mesh_collapse_edge(m, h)` succeed? Never modifies the mesh: every view
    /// stays valid.
    ask fn che_mesh_is_collapse_ok(h) -> bool { |c| c.is_collapse_ok(h) }
}

/// Compacts the removed elements away (ids become `h = 3t + i` without holes, edge ids
/// ranks again) and writes the old -> new maps (`UINT32_MAX` for a removed element) into
/// the buffers given (NULL: not wanted), sized by the counts before the call
/// (`che_mesh_num_vertices`, `_num_triangles`, `_num_edges`). A buffer too small is
/// BUFFER_TOO_SMALL, and buffers that overlap INVALID_INPUT, before anything changes.
/// Every id and view from before is invalid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_garbage_collect(
    m: *mut CheMesh, vertex_map: *mut u32, vertex_cap: usize, triangle_map: *mut u32,
    triangle_cap: usize, edge_map: *mut u32, edge_cap: usize,
) -> Status {
    let maps = [
        (vertex_map, vertex_cap, "vertex_map"),
        (triangle_map, triangle_cap, "triangle_map"),
        (edge_map, edge_cap, "edge_map"),
    ];
    // SAFETY: forwarded caller contract.
    unsafe {
        collect_garbage(
            m,
            maps,
            |c| [c.num_vertices(), c.num_triangles(), c.num_edges()],
            |c, [vertices, triangles, edges]| {
                c.garbage_collect_into(GarbageMapsOut {
                    vertices,
                    triangles,
                    edges,
                })
            },
        )
    }
}

exports! { CheMesh;
    /// Is vertex `v` removed (until garbage collection)?
    value fn che_vertex_is_removed(v) -> bool { check_vertex(v) => |c| c.is_vertex_removed(v) }
    /// Is triangle `t` removed?
    value fn che_triangle_is_removed(t) -> bool {
        check_triangle(t) => |c| c.is_triangle_removed(t)
    }
    /// Is edge `e` removed? (Below level 2 edge ids are the ranks of the live edges: never.)
    value fn che_edge_is_removed(e) -> bool { check_edge(e) => |c| c.is_edge_removed(e) }
    /// Live vertices (`che_mesh_num_vertices` stays the id bound until garbage collection).
    count fn che_mesh_num_live_vertices() -> usize { |c| c.num_live_vertices() }
    /// Live triangles.
    count fn che_mesh_num_live_triangles() -> usize { |c| c.num_live_triangles() }
    /// Live edges.
    count fn che_mesh_num_live_edges() -> usize { |c| c.num_live_edges() }
}
