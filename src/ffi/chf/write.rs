//! Writing a `chf_mesh`, or its boundary surface, to a file.

use super::ChfMesh;
use crate::ffi::shapes::save;
use crate::ffi::status::Status;
use std::ffi::c_char;

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
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_write(
    m: *const ChfMesh, path: *const c_char, flags: u32,
) -> Status {
    save!(m, path, flags => |c, path, options| c.write_with(path, &options))
}

/// Writes the boundary surface (`chf_mesh_boundary`, built at any level) to `path` as a
/// surface file, as `che_mesh_write` does; the origin of each of its vertices is the input
/// vertex of the volume mesh it lies on. The same flags and statuses as `che_mesh_write`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_write_boundary(
    m: *const ChfMesh, path: *const c_char, flags: u32,
) -> Status {
    save!(m, path, flags => |c, path, options| c.write_boundary_with(path, &options))
}
