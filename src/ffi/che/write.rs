//! Writing a `che_mesh` to a file.

use super::CheMesh;
use crate::ffi::shapes::save;
use crate::ffi::status::Status;
use std::ffi::c_char;

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
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_write(
    m: *const CheMesh, path: *const c_char, flags: u32,
) -> Status {
    save!(m, path, flags => |c, path, options| c.write_with(path, &options))
}
