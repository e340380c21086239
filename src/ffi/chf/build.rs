//! Making, freeing and re-levelling `chf_mesh` handles, and their counts; the reader's
//! warnings of a mesh loaded from a file: what the reader read past or found
//! odd (data after the declared elements, elements not stored, non-finite coordinates, ...),
//! one `file:line: message` text each.

use super::{ChfBuildOptions, ChfMesh};
use crate::chf::Chf;
use crate::ffi::boundary::level_arg;
use crate::ffi::declare::exports;
use crate::ffi::mesh_arrays::TETRAHEDRA;
use crate::ffi::shapes::{build, load};
use crate::ffi::status::Status;
use std::ffi::c_char;

/// Builds a CHF at `level` (0..3) from `n_tets` tetrahedra (4 vertex ids each, over
/// vertices `0..n_vertices`). `positions` may be NULL; otherwise it holds 3 doubles (x, y,
/// z) per input vertex (they only orient each component, positive volume where possible,
/// and count zero-volume and inverted tetrahedra in the report). `tetrahedra` may be NULL
/// when `n_tets == 0`.
///
/// Input vertex ids are kept; copies made by splitting non-manifold vertices are appended
/// after them (see `chf_mesh_vertex_origins`). Input tetrahedron order is kept; degenerate
/// tetrahedra (a repeated id) are dropped (see `chf_mesh_tetrahedron_origins`). Every
/// component is oriented consistently (local vertices 1 and 2 swapped where needed);
/// `chf_mesh_report` says what was changed. Non-manifold input is kept (faces of three or
/// more tetrahedra stay unpaired; see `chf_mesh_from_tetrahedra_ex` for strict mode).
/// A tetrahedron naming a vertex `>= n_vertices` gives `TOPOMESH_STATUS_OUT_OF_RANGE`;
/// more than 2^32 - 2 vertices, more than 1073741823 tetrahedra, or more than 2^26
/// vertices beyond the `4 * n_tets` the tetrahedra can name `TOPOMESH_STATUS_TOO_LARGE`,
/// before anything is allocated or read. `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_from_tetrahedra(
    tetrahedra: *const u32, n_tets: usize, n_vertices: usize, positions: *const f64, level: u32,
    out: *mut *mut ChfMesh,
) -> Status {
    build!(out, &ChfBuildOptions::at(level) => Chf(TETRAHEDRA, tetrahedra, n_tets, n_vertices, positions))
}

/// `chf_mesh_from_tetrahedra` with options (NULL: `chf_build_options_default()`). With
/// `strict`, non-manifold input fails with `TOPOMESH_STATUS_NON_MANIFOLD`, the detail
/// naming the offending face and tetrahedra, edge, or vertex.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_from_tetrahedra_ex(
    tetrahedra: *const u32, n_tets: usize, n_vertices: usize, positions: *const f64,
    options: *const ChfBuildOptions, out: *mut *mut ChfMesh,
) -> Status {
    build!(out, options => Chf(TETRAHEDRA, tetrahedra, n_tets, n_vertices, positions))
}

/// Reads a volume file (the format from the extension: .mesh (Medit), .msh (Gmsh), .vtk,
/// .node/.ele (TetGen)) and builds its tetrahedra at `level` (triangles the file also
/// holds, such as its boundary, are ignored). A missing or unreadable file gives
/// `TOPOMESH_STATUS_IO`, a malformed one `TOPOMESH_STATUS_PARSE` (the detail names the
/// file and line), a file without tetrahedra (a surface) `TOPOMESH_STATUS_INVALID_INPUT`.
/// `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_load(
    path: *const c_char, level: u32, out: *mut *mut ChfMesh,
) -> Status {
    load!(out, path, &ChfBuildOptions::at(level) => crate::io::load::chf_loaded)
}

/// `chf_mesh_load` with options (NULL: `chf_build_options_default()`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_load_ex(
    path: *const c_char, options: *const ChfBuildOptions, out: *mut *mut ChfMesh,
) -> Status {
    load!(out, path, options => crate::io::load::chf_loaded)
}

exports! { ChfMesh;
    free fn chf_mesh_free();
    /// Raises or lowers the level (0..3) in place. Ids never change with the level; views
    /// obtained before are invalid afterwards. Needs exclusive access. Runs on every thread of
    /// the machine (large meshes).
    edit fn chf_mesh_build_level(level) { |c| c.build_level(level_arg(level)?) }
    /// The current level (0..3); 0 for NULL.
    count fn chf_mesh_level() -> u32 { |c| c.level() as u32 }
    /// Vertices of the structure: the input vertices, then the copies made by splitting
    /// non-manifold vertices. 0 for NULL (and likewise for the other counts).
    count fn chf_mesh_num_vertices() -> usize { |c| c.num_vertices() }
    /// Vertices given as input (ids `0..n` of the structure are the same vertices).
    count fn chf_mesh_num_input_vertices() -> usize { |c| c.num_input_vertices() }
    /// Tetrahedra kept (degenerate input tetrahedra are dropped).
    count fn chf_mesh_num_tetrahedra() -> usize { |c| c.num_tetrahedra() }
    /// Faces of the structure: paired half-faces count once, unpaired ones (boundary, and the
    /// half-faces of a non-manifold face, which stay unpaired) once each.
    count fn chf_mesh_num_faces() -> usize { |c| c.num_faces() }
    /// Edges of the structure: one per fan of tetrahedra around a vertex pair (a non-manifold
    /// edge whose fans the vertex split did not separate counts once per fan).
    count fn chf_mesh_num_edges() -> usize { |c| c.num_edges() }
    /// Half-faces: 4 per tetrahedron (half-face `4t + i` is the face opposite local vertex `i`).
    count fn chf_mesh_num_half_faces() -> usize { |c| c.num_half_faces() }
    warnings fn chf_mesh_num_warnings(), chf_mesh_warning();
}
