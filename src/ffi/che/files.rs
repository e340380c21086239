//! Files: writing a `che_mesh` in a mesh format, and saving it as a level file and
//! opening it again.

use super::CheMesh;
use crate::Che;
use crate::ffi::declare::exports;
use crate::ffi::shapes::open;
use crate::ffi::status::Status;
use std::ffi::c_char;

exports! { CheMesh;
    /// Writes the built surface to `path`, the format from its extension: .off .obj .ply
    /// .stl (binary, `float` positions) .vtk .mesh .msh (4.1). What is written is the structure:
    /// the oriented triangles (degenerate ones dropped) over its vertices, the copies made by
    /// splitting non-manifold vertices as vertices of their own; where the format has a vertex
    /// attribute (PLY `origin`, VTK `POINT_DATA origin`, the Medit vertex reference) the input
    /// vertex each comes from, unless `TOPOMESH_WRITE_NO_ORIGIN`. `flags` is 0 or an OR of
    /// `TOPOMESH_WRITE_BINARY` (binary PLY) and `TOPOMESH_WRITE_NO_ORIGIN`; another bit gives
    /// `TOPOMESH_STATUS_INVALID_INPUT`. The file is written whole or not at all (a temporary
    /// file renamed over it); a failure to write gives `TOPOMESH_STATUS_IO` naming the path,
    /// a mesh built without positions, an unknown extension or a format that cannot hold a
    /// surface (.node) `TOPOMESH_STATUS_INVALID_INPUT`.
    save fn che_mesh_write(flags) { |c, path, options| c.write_with(path, &options) }
    /// Saves the built surface at its level to `path` as a level file (`.che` by convention;
    /// the layout is in `docs/level-files.md`), whole or not at all; `che_mesh_open` reads it
    /// back. A failure to write gives `TOPOMESH_STATUS_IO` naming the path; a mesh edited since
    /// its last `che_mesh_garbage_collect` gives `TOPOMESH_STATUS_INVALID_INPUT`.
    save fn che_mesh_save() { |c, path| c.save(path) }
}

/// Opens a level file written by `che_mesh_save`, with no parsing and no build. `flags`
/// is 0 (check everything: the header, every length, every checksum and the structure's
/// invariants), `TOPOMESH_OPEN_CHECKSUMS_ONLY` or `TOPOMESH_OPEN_TRUSTED`; another bit gives
/// `TOPOMESH_STATUS_INVALID_INPUT`. A missing file gives `TOPOMESH_STATUS_IO`, a damaged
/// one `TOPOMESH_STATUS_PARSE` (the detail names the section and the byte) or
/// `TOPOMESH_STATUS_INVALID_INPUT` (an invariant broken). `*out` is NULL on failure.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_open(
    path: *const c_char, flags: u32, out: *mut *mut CheMesh,
) -> Status {
    open!(out, path, flags => Che::open)
}
