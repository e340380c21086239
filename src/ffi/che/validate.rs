//! The invariant check of a mesh.

use super::CheMesh;
use crate::ffi::shapes::status;
use crate::ffi::status::Status;

/// Checks every invariant of the mesh at its level (ids in range, `O` an involution on
/// matching vertex pairs, the rules of `VH`, the edge directory and `EH`, the boundary
/// curves). `TOPOMESH_STATUS_OK` when they all hold; otherwise
/// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (element and what is wrong) in
/// `topomesh_last_error`. O(T).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_validate(m: *const CheMesh) -> Status {
    status!(m, |c| c.validate())
}
