//! Making, freeing and re-levelling `che_mesh` handles, and their counts; the reader's
//! warnings of a mesh loaded from a file: what the reader read past or found
//! odd (data after the declared elements, elements not stored, non-finite coordinates, ...),
//! one `file:line: message` text each.

use super::{CheBuildOptions, CheMesh};
use crate::che::Che;
use crate::ffi::boundary::level_arg;
use crate::ffi::declare::exports;
use crate::ffi::mesh_arrays::TRIANGLES;
use crate::ffi::shapes::{build, load};
use crate::ffi::status::Status;
use std::ffi::c_char;

/// Builds a CHE at `level` (0..3) from `n_triangles` triangles (3 vertex ids each, over
/// vertices `0..n_vertices`). `positions` may be NULL; otherwise it holds 3 doubles (x, y,
/// z) per input vertex. `triangles` may be NULL when `n_triangles == 0`.
///
/// Input vertex ids are kept; copies made by splitting non-manifold vertices are appended
/// after them (see `che_mesh_vertex_origins`). Input triangle order is kept; degenerate
/// triangles (a repeated id) are dropped (see `che_mesh_triangle_origins`). Every
/// component is oriented consistently; `che_mesh_report` says what was changed.
/// Non-manifold input is repaired (see `che_mesh_from_triangles_ex` for strict mode).
/// A triangle naming a vertex `>= n_vertices` gives `TOPOMESH_STATUS_OUT_OF_RANGE`; more
/// than 2^32 - 2 vertices, more than 1431655765 triangles, or more than 2^26 vertices
/// beyond the `3 * n_triangles` the triangles can name `TOPOMESH_STATUS_TOO_LARGE`, before
/// anything is allocated or read. `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_from_triangles(
    triangles: *const u32, n_triangles: usize, n_vertices: usize, positions: *const f64,
    level: u32, out: *mut *mut CheMesh,
) -> Status {
    build!(out, &CheBuildOptions::at(level) => Che(TRIANGLES, triangles, n_triangles, n_vertices, positions))
}

/// `che_mesh_from_triangles` with options (NULL: `che_build_options_default()`). With
/// `strict`, non-manifold input fails with `TOPOMESH_STATUS_NON_MANIFOLD`, the detail
/// naming the offending edge and triangles, or vertex.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_from_triangles_ex(
    triangles: *const u32, n_triangles: usize, n_vertices: usize, positions: *const f64,
    options: *const CheBuildOptions, out: *mut *mut CheMesh,
) -> Status {
    build!(out, options => Che(TRIANGLES, triangles, n_triangles, n_vertices, positions))
}

/// Reads a surface file (the format from the extension: .off .obj .ply .stl; also .mesh
/// .msh .vtk when they hold triangles only) and builds it at `level`. A missing or
/// unreadable file gives `TOPOMESH_STATUS_IO`, a malformed one `TOPOMESH_STATUS_PARSE`
/// (the detail names the file and line), a file holding tetrahedra
/// `TOPOMESH_STATUS_INVALID_INPUT`. `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_load(
    path: *const c_char, level: u32, out: *mut *mut CheMesh,
) -> Status {
    load!(out, path, &CheBuildOptions::at(level) => crate::io::load::che_loaded)
}

/// `che_mesh_load` with options (NULL: `che_build_options_default()`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_load_ex(
    path: *const c_char, options: *const CheBuildOptions, out: *mut *mut CheMesh,
) -> Status {
    load!(out, path, options => crate::io::load::che_loaded)
}

exports! { CheMesh;
    free fn che_mesh_free();
    /// Raises or lowers the level (0..3) in place. Ids never change with the level; views
    /// obtained before are invalid afterwards. Needs exclusive access.
    edit fn che_mesh_build_level(level) { |c| c.build_level(level_arg(level)?) }
    /// The current level (0..3); 0 for NULL.
    count fn che_mesh_level() -> u32 { |c| c.level() as u32 }
    /// Vertices of the structure: the input vertices, then the copies made by splitting
    /// non-manifold vertices. 0 for NULL (and likewise for the other counts).
    count fn che_mesh_num_vertices() -> usize { |c| c.num_vertices() }
    /// Vertices given as input (ids `0..n` of the structure are the same vertices).
    count fn che_mesh_num_input_vertices() -> usize { |c| c.num_input_vertices() }
    /// Triangles kept (degenerate input triangles are dropped).
    count fn che_mesh_num_triangles() -> usize { |c| c.num_triangles() }
    /// Edges of the structure (the edges of a non-manifold edge count once per triangle).
    count fn che_mesh_num_edges() -> usize { |c| c.num_edges() }
    /// Half-edges: 3 per triangle.
    count fn che_mesh_num_half_edges() -> usize { |c| c.num_half_edges() }
    /// Boundary curves of the structure: O(1) at level 3, O(T) at levels 1-2, O(T) time and
    /// memory at level 0.
    count fn che_mesh_num_boundary_curves() -> usize { |c| c.num_boundary_curves() }
    warnings fn che_mesh_num_warnings(), che_mesh_warning();
}
