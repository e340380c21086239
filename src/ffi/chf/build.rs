//! Making, freeing and re-levelling `chf_mesh` handles, and their counts.

use super::{ChfBuildOptions, ChfMesh};
use crate::chf::{BuildOptions as CoreOptions, Chf, MAX_TETRAHEDRA};
use crate::error::Result;
use crate::ffi::boundary::{guard, handle, handle_mut, options_arg, path_arg};
use crate::ffi::che::level_arg;
use crate::ffi::mesh_arrays::{Cells, mesh_arrays};
use crate::ffi::shapes::{count, free, make};
use crate::ffi::status::Status;
use std::ffi::c_char;

/// Builds from C arrays (sizes checked before any slice is made).
///
/// # Safety
/// `tets` is NULL or holds `4 * n_tets` ids; `positions` is NULL or holds `3 * n_vertices`
/// doubles.
unsafe fn build(
    tets: *const u32,
    n_tets: usize,
    n_vertices: usize,
    positions: *const f64,
    options: CoreOptions,
) -> Result<ChfMesh> {
    let kind = Cells {
        per: 4,
        max_cells: MAX_TETRAHEDRA,
        cells: "tetrahedra",
        part: "half-face",
    };
    // SAFETY: forwarded contract.
    let (flat, points) = unsafe { mesh_arrays(kind, tets, n_tets, n_vertices, positions)? };
    Ok(ChfMesh::new(Chf::from_flat(
        flat, n_vertices, points, options,
    )?))
}

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
/// more than 2^32 - 2 vertices or 1073741823 tetrahedra `TOPOMESH_STATUS_TOO_LARGE`.
/// `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_from_tetrahedra(
    tetrahedra: *const u32,
    n_tets: usize,
    n_vertices: usize,
    positions: *const f64,
    level: u32,
    out: *mut *mut ChfMesh,
) -> Status {
    // SAFETY: the same contract as the `_ex` variant; the options are a local.
    let options = ChfBuildOptions::at(level);
    unsafe { chf_mesh_from_tetrahedra_ex(tetrahedra, n_tets, n_vertices, positions, &options, out) }
}

/// `chf_mesh_from_tetrahedra` with options (NULL: `chf_build_options_default()`). With
/// `strict`, non-manifold input fails with `TOPOMESH_STATUS_NON_MANIFOLD`, the detail
/// naming the offending face and tetrahedra, edge, or vertex.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_from_tetrahedra_ex(
    tetrahedra: *const u32,
    n_tets: usize,
    n_vertices: usize,
    positions: *const f64,
    options: *const ChfBuildOptions,
    out: *mut *mut ChfMesh,
) -> Status {
    // SAFETY: caller contract: `options` NULL or readable, the arrays NULL or of the
    // stated sizes.
    make!(out, unsafe {
        let options = options_arg(options).to_core()?;
        build(tetrahedra, n_tets, n_vertices, positions, options)
    })
}

/// Reads a volume file (the format from the extension: .mesh (Medit), .msh (Gmsh), .vtk,
/// .node/.ele (TetGen)) and builds its tetrahedra at `level` (triangles the file also
/// holds, such as its boundary, are ignored). A missing or unreadable file gives
/// `TOPOMESH_STATUS_IO`, a malformed one `TOPOMESH_STATUS_PARSE` (the detail names the
/// file and line), a file without tetrahedra (a surface) `TOPOMESH_STATUS_INVALID_INPUT`.
/// `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_load(
    path: *const c_char,
    level: u32,
    out: *mut *mut ChfMesh,
) -> Status {
    // SAFETY: the same contract as the `_ex` variant; the options are a local.
    unsafe { chf_mesh_load_ex(path, &ChfBuildOptions::at(level), out) }
}

/// `chf_mesh_load` with options (NULL: `chf_build_options_default()`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_load_ex(
    path: *const c_char,
    options: *const ChfBuildOptions,
    out: *mut *mut ChfMesh,
) -> Status {
    // SAFETY: caller contract: `options` NULL or readable, `path` NULL or NUL-terminated.
    let (options, path) = unsafe { (options_arg(options), path_arg(path, "path")) };
    make!(out, Chf::load(path?, options.to_core()?).map(ChfMesh::new))
}

/// Frees a mesh; NULL is a no-op. Needs exclusive access.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_free(m: *mut ChfMesh) {
    free!(m)
}

/// Raises or lowers the level (0..3) in place. Ids never change with the level; views
/// obtained before are invalid afterwards. Needs exclusive access. Runs on every thread of
/// the machine (large meshes).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_build_level(m: *mut ChfMesh, level: u32) -> Status {
    guard(|| {
        // SAFETY: caller contract: NULL or a live handle, not shared during the call.
        let m = unsafe { handle_mut(m, "m")? };
        m.chf.build_level(level_arg(level)?)
    })
}

/// Checks every invariant of the mesh at its level: `TOPOMESH_STATUS_OK`, or
/// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (the element and what is
/// wrong) in `topomesh_last_error`. O(T); the mesh is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_validate(m: *const ChfMesh) -> Status {
    // SAFETY: caller contract: NULL or a live handle.
    guard(|| unsafe { handle(m, "m")? }.chf.validate())
}

/// The current level (0..3); 0 for NULL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_level(m: *const ChfMesh) -> u32 {
    count!(m, 0, |c| c.level() as u32)
}

/// Vertices of the structure: the input vertices, then the copies made by splitting
/// non-manifold vertices. 0 for NULL (and likewise for the other counts).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_vertices(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_vertices())
}

/// Vertices given as input (ids `0..n` of the structure are the same vertices).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_input_vertices(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_input_vertices())
}

/// Tetrahedra kept (degenerate input tetrahedra are dropped).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_tetrahedra(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_tetrahedra())
}

/// Faces of the structure: paired half-faces count once, unpaired ones (boundary, and the
/// half-faces of a non-manifold face, which stay unpaired) once each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_faces(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_faces())
}

/// Edges of the structure: one per fan of tetrahedra around a vertex pair (a non-manifold
/// edge whose fans the vertex split did not separate counts once per fan).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_edges(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_edges())
}

/// Half-faces: 4 per tetrahedron (half-face `4t + i` is the face opposite local vertex `i`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_half_faces(m: *const ChfMesh) -> usize {
    count!(m, 0, |c| c.num_half_faces())
}
