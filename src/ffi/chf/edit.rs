//! Editing a mesh in place: inserting and removing tetrahedra and vertices, splits, flips
//! and edge collapse, their checks, the removed marks and the compaction. Every call needs
//! exclusive access; views obtained before an edit are invalid afterwards. A refused
//! operation returns `TOPOMESH_STATUS_INVALID_INPUT` (or `NON_MANIFOLD` for a face that
//! would have three tetrahedra, a broken link condition or a pinch) with a detail naming
//! the element and the reason, and changes nothing; a removed, out-of-range or
//! `TOPOMESH_NONE` id gives `TOPOMESH_STATUS_OUT_OF_RANGE`.
//!
//! Vertex and tetrahedron ids never move until `chf_mesh_garbage_collect`; neither do
//! face and edge ids. Positions: a `const double[3]` or NULL (the operation's default:
//! the centroid of what is split); a mesh without positions takes NULL only.

use super::ChfMesh;
use crate::ffi::boundary::{collect_garbage, copy_maps, ids_arg, position_arg};
use crate::ffi::declare::exports;
use crate::ffi::status::Status;
use crate::util::structure::check_id;

exports! { ChfMesh;
    /// Adds an isolated vertex at `position` (required when the mesh has positions, NULL when
    /// it has none); its id into `*out_v` (may be NULL).
    edit fn chf_mesh_add_vertex(position: *const f64) -> out_v: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.add_vertex(unsafe { position_arg(position) }?)
    }
    /// Adds the tetrahedron of the four vertices `vertices[4]` (any order: oriented by the
    /// determinant with positions, else by the faces it pairs with); its id into `*out_t`.
    edit fn chf_mesh_add_tetrahedron(vertices: *const u32) -> out_t: u32 {
        // SAFETY: the export's contract: NULL or four readable ids.
        |c| c.add_tetrahedron(unsafe { ids_arg(vertices, "vertices") }?)
    }
    /// Would `chf_mesh_add_tetrahedron` succeed? Changes nothing.
    check fn chf_mesh_check_add_tetrahedron(vertices: *const u32) {
        // SAFETY: the export's contract: NULL or four readable ids.
        |c| c.check_add_tetrahedron(unsafe { ids_arg(vertices, "vertices") }?)
    }
    /// Removes tetrahedron `t` (refused when that pinches a vertex or an edge).
    edit fn chf_mesh_remove_tetrahedron(t) { |c| c.remove_tetrahedron(t) }
    /// Would `chf_mesh_remove_tetrahedron` succeed? Changes nothing.
    check fn chf_mesh_check_remove_tetrahedron(t) { |c| c.check_remove_tetrahedron(t) }
    /// Removes vertex `v` with every tetrahedron around it.
    edit fn chf_mesh_remove_vertex(v) { |c| c.remove_vertex(v) }
    /// Would `chf_mesh_remove_vertex` succeed? Changes nothing.
    check fn chf_mesh_check_remove_vertex(v) { |c| c.check_remove_vertex(v) }
    /// Splits tetrahedron `t` in four (1-4) at a new vertex (id into `*out_v`), at `position`
    /// or the centroid; refused unless the position is strictly inside. `t` keeps its id,
    /// its vertex 0 replaced by the new one; the pieces with vertex 1, 2 and 3 replaced
    /// are appended, in that order.
    edit fn chf_mesh_split_tetrahedron(t, position: *const f64) -> out_v: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.split_tetrahedron(t, unsafe { position_arg(position) }?)
    }
    /// Would `chf_mesh_split_tetrahedron` succeed? Changes nothing.
    check fn chf_mesh_check_split_tetrahedron(t, position: *const f64) {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.check_split_tetrahedron(t, unsafe { position_arg(position) }?)
    }
    /// Splits face `f` (2-6, or 1-3 on the boundary) at a new vertex (id into `*out_v`).
    edit fn chf_mesh_split_face(f, position: *const f64) -> out_v: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.split_face(f, unsafe { position_arg(position) }?)
    }
    /// Would `chf_mesh_split_face` succeed? Changes nothing.
    check fn chf_mesh_check_split_face(f, position: *const f64) {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.check_split_face(f, unsafe { position_arg(position) }?)
    }
    /// Splits edge `e` at a new vertex (id into `*out_v`): each tetrahedron around it in two.
    edit fn chf_mesh_split_edge(e, position: *const f64) -> out_v: u32 {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.split_edge(e, unsafe { position_arg(position) }?)
    }
    /// Would `chf_mesh_split_edge` succeed? Changes nothing.
    check fn chf_mesh_check_split_edge(e, position: *const f64) {
        // SAFETY: the export's contract: NULL or three readable doubles.
        |c| c.check_split_edge(e, unsafe { position_arg(position) }?)
    }
    /// Flips interior face `f` (2-3); the three new tetrahedra into `out_tets[3]` (may be
    /// NULL). Refused on the boundary, when the apexes share an edge already, or (with
    /// positions) when the union is not strictly convex.
    edit fn chf_mesh_flip_23(f) -> out_tets: u32 as [u32; 3] { |c| c.flip_23(f) }
    /// Would `chf_mesh_flip_23` succeed? Changes nothing.
    check fn chf_mesh_check_flip_23(f) { |c| c.check_flip_23(f) }
    /// Can face `f` be flipped (2-3)? `*out` true or false, as `che_mesh_is_flip_ok`: a
    /// refusal is `false` with `TOPOMESH_STATUS_OK` (and no detail to word, so cheaper than
    /// `chf_mesh_check_flip_23`); a bad or removed id is an error. Changes nothing.
    value fn chf_mesh_is_flip_23_ok(f) -> bool { |c| c.is_flip_23_ok(f) }
    /// Flips interior edge `e` with three tetrahedra around it (3-2); the two new tetrahedra
    /// into `out_tets[2]` (may be NULL).
    edit fn chf_mesh_flip_32(e) -> out_tets: u32 as [u32; 2] { |c| c.flip_32(e) }
    /// Would `chf_mesh_flip_32` succeed? Changes nothing.
    check fn chf_mesh_check_flip_32(e) { |c| c.check_flip_32(e) }
    /// Can edge `e` be flipped (3-2)? As `chf_mesh_is_flip_23_ok`.
    value fn chf_mesh_is_flip_32_ok(e) -> bool { |c| c.is_flip_32_ok(e) }
    /// Collapses half-edge `he` (`3 * hf + j`): its origin merges into its target (id into
    /// `*out_v`). Refused when the link condition fails or a tetrahedron would invert.
    edit fn chf_mesh_collapse_edge(he: u64) -> out_v: u32 { |c| c.collapse_edge(he) }
    /// Would `chf_mesh_collapse_edge` succeed? Changes nothing.
    check fn chf_mesh_check_collapse_edge(he: u64) { |c| c.check_collapse_edge(he) }
    /// Can half-edge `he` be collapsed? As `chf_mesh_is_flip_23_ok`.
    value fn chf_mesh_is_collapse_ok(he: u64) -> bool { |c| c.is_collapse_ok(he) }
    /// Is tetrahedron `t` removed (by an edit, until `chf_mesh_garbage_collect`)?
    value fn chf_tetrahedron_is_removed(t) -> bool {
        |c| check_id(t, c.num_tetrahedra(), "tetrahedron", "tetrahedra")
            .map(|_| c.is_tetrahedron_removed(t))
    }
    /// Is vertex `v` removed?
    value fn chf_vertex_is_removed(v) -> bool { check_vertex(v) => |c| c.is_vertex_removed(v) }
    /// Is face `f` removed?
    value fn chf_face_is_removed(f) -> bool {
        |c| check_id(f, c.num_faces(), "face", "faces").map(|_| c.is_face_removed(f))
    }
    /// Is edge `e` removed?
    value fn chf_edge_is_removed(e) -> bool { check_edge(e) => |c| c.is_edge_removed(e) }
    /// Live tetrahedra (the `chf_mesh_num_*` counts are id bounds, removed ids included).
    count fn chf_mesh_num_live_tetrahedra() -> usize { |c| c.num_live_tetrahedra() }
    /// Live vertices.
    count fn chf_mesh_num_live_vertices() -> usize { |c| c.num_live_vertices() }
    /// Live faces.
    count fn chf_mesh_num_live_faces() -> usize { |c| c.num_live_faces() }
    /// Live edges.
    count fn chf_mesh_num_live_edges() -> usize { |c| c.num_live_edges() }
}

/// Compacts the mesh: removed elements go, the others take the ids a fresh build of the
/// live tetrahedra gives, each component kept on its side (a build from scratch may turn a
/// folded one over to agree with most of its determinants). Each map (NULL: not wanted) receives old id -> new id
/// (`TOPOMESH_NONE` for removed ones) and needs room for the count before the call
/// (`chf_mesh_num_vertices`, `_tetrahedra`, `_faces`, `_edges`); too little room gives
/// `TOPOMESH_STATUS_BUFFER_TOO_SMALL`, and maps that overlap
/// `TOPOMESH_STATUS_INVALID_INPUT`, before anything changes. O(T log T).
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn chf_mesh_garbage_collect(
    m: *mut ChfMesh, vertex_map: *mut u32, vertex_cap: usize, tetrahedron_map: *mut u32,
    tetrahedron_cap: usize, face_map: *mut u32, face_cap: usize, edge_map: *mut u32,
    edge_cap: usize,
) -> Status {
    let maps = [
        (vertex_map, vertex_cap, "vertex_map"),
        (tetrahedron_map, tetrahedron_cap, "tetrahedron_map"),
        (face_map, face_cap, "face_map"),
        (edge_map, edge_cap, "edge_map"),
    ];
    let counts = |c: &crate::Chf| {
        [
            c.num_vertices(),
            c.num_tetrahedra(),
            c.num_faces(),
            c.num_edges(),
        ]
    };
    // SAFETY: forwarded caller contract.
    unsafe {
        collect_garbage(m, maps, counts, |c, out| {
            let g = c.garbage_collect()?;
            copy_maps([g.vertices, g.tetrahedra, g.faces, g.edges], out)
        })
    }
}
