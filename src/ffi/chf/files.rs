//! Files: writing a `chf_mesh` in a mesh format, and saving it as a level file and
//! opening it again.

use super::ChfMesh;
use crate::Chf;
use crate::ffi::declare::exports;
use crate::ffi::shapes::open;
use crate::ffi::status::Status;
use std::ffi::c_char;

exports! { ChfMesh;
    /// Writes the built volume to `path`, the format from its extension: .mesh .msh (4.1)
    /// .vtk, or .node/.ele (TetGen: both files, beside each other, whichever is named). What is
    /// written is the structure: the oriented tetrahedra (degenerate ones dropped) over its
    /// vertices, the copies made by splitting non-manifold vertices as vertices of their own;
    /// where the format has a vertex attribute (VTK `POINT_DATA origin`, the Medit vertex
    /// reference, a TetGen point attribute) the input vertex each comes from, unless
    /// `TOPOMESH_WRITE_NO_ORIGIN`. `flags` is 0 or `TOPOMESH_WRITE_NO_ORIGIN`
    /// (`TOPOMESH_WRITE_BINARY` is refused: no volume format here is binary); another bit gives
    /// `TOPOMESH_STATUS_INVALID_INPUT`. Written whole or not at all; a failure to write gives
    /// `TOPOMESH_STATUS_IO` naming the path, a mesh built without positions, an unknown
    /// extension or a surface format `TOPOMESH_STATUS_INVALID_INPUT`.
    save fn chf_mesh_write(flags) { |c, path, options| c.write_with(path, &options) }
    /// Writes the boundary surface (`chf_mesh_boundary`, built at any level) to `path` as a
    /// surface file, as `che_mesh_write` does; the origin of each of its vertices is the input
    /// vertex of the volume mesh it lies on. The same flags and statuses as `che_mesh_write`.
    save fn chf_mesh_write_boundary(flags) { |c, path, options| c.write_boundary_with(path, &options) }
    /// Saves the built volume at its level to `path` as a level file (`.chf` by convention;
    /// the layout is in `docs/level-files.md`), whole or not at all; `chf_mesh_open` reads it
    /// back. A failure to write gives `TOPOMESH_STATUS_IO` naming the path; a mesh edited since
    /// its last `chf_mesh_garbage_collect` gives `TOPOMESH_STATUS_INVALID_INPUT`.
    save fn chf_mesh_save() { |c, path| c.save(path) }
}

/// Opens a level file written by `chf_mesh_save`, with no parsing and no build. `flags`
/// is 0 (check everything: the header, every length, every checksum and the structure's
/// invariants), `TOPOMESH_OPEN_CHECKSUMS_ONLY` or `TOPOMESH_OPEN_TRUSTED`; another bit gives
/// `TOPOMESH_STATUS_INVALID_INPUT`. A missing file gives `TOPOMESH_STATUS_IO`, a damaged
/// one `TOPOMESH_STATUS_PARSE` (the detail names the section and the byte) or
/// `TOPOMESH_STATUS_INVALID_INPUT` (an invariant broken). `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_open(
    path: *const c_char, flags: u32, out: *mut *mut ChfMesh,
) -> Status {
    open!(out, path, flags => Chf::open)
}
