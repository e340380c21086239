//! The reader's warnings of a mesh loaded from a file: what the reader read past or found
//! odd (data after the declared elements, elements not stored, non-finite coordinates, ...),
//! one `file:line: message` text each.

use super::CheMesh;
use crate::ffi::shapes::warnings;
use crate::ffi::status::Status;
use std::ffi::c_char;

/// How many warnings the reader gave for the file `m` was loaded from (0 for a mesh built
/// from arrays, and for NULL). O(1).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_num_warnings(m: *const CheMesh) -> usize {
    warnings!(m)
}

/// Warning `i` ("file:line: message"), NUL-terminated, into `buf`, with the buffer rules of
/// `topomesh_last_error`: `*out_len` receives the capacity needed, NUL included;
/// `buf == NULL` with `cap == 0` is a size query; a short `buf` receives a truncated text
/// and the call returns `TOPOMESH_STATUS_BUFFER_TOO_SMALL`. `i` out of range gives
/// `TOPOMESH_STATUS_OUT_OF_RANGE`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_warning(
    m: *const CheMesh, i: usize, buf: *mut c_char, cap: usize, out_len: *mut usize,
) -> Status {
    warnings!(m, i, buf, cap, out_len)
}
