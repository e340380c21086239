//! Saving a `chf_mesh` as a level file and opening it again.

use super::ChfMesh;
use crate::Chf;
use crate::ffi::shapes::{open, save};
use crate::ffi::status::Status;
use std::ffi::c_char;

/// Saves the built volume at its level to `path` as a level file (`.chf` by convention;
/// the layout is in `docs/level-files.md`), whole or not at all; `chf_mesh_open` reads it
/// back. A failure to write gives `TOPOMESH_STATUS_IO` naming the path; a mesh edited since
/// its last `chf_mesh_garbage_collect` gives `TOPOMESH_STATUS_INVALID_INPUT`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_save(m: *const ChfMesh, path: *const c_char) -> Status {
    save!(m, path => |c, path| c.save(path))
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
