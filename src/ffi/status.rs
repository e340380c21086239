//! Status codes, the thread-local last-error detail and the library version.

use super::boundary;
use std::ffi::c_char;

/// What a call did. `TOPOMESH_STATUS_OK` (0) is success; every other value is an error
/// whose detail (file, line, element id, sizes) `topomesh_last_error` gives.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// Success.
    Ok = 0,
    /// A required pointer argument was NULL.
    NullArgument = 1,
    /// An id (vertex, edge, triangle, half-edge, curve) or a level was out of range.
    OutOfRange = 2,
    /// The input is not acceptable (unknown file format, a volume file where a surface was
    /// expected, positions not matching the vertices, ...).
    InvalidInput = 3,
    /// Strict mode: the input has a non-manifold edge or vertex, or duplicate triangles.
    NonManifold = 4,
    /// A caller buffer is too small; the needed length was written to `*out_len`.
    BufferTooSmall = 5,
    /// A file could not be opened or read.
    Io = 6,
    /// A file could not be parsed.
    Parse = 7,
    /// The input does not fit 32-bit ids.
    TooLarge = 8,
    /// An internal error (a Rust panic) was caught at the boundary. Please report it.
    Panic = 9,
    /// Memory ran out: an allocation failed, or a build's estimate exceeded
    /// `memory_limit_bytes`. The detail names the bytes and what they were for; the
    /// process and every other handle are unharmed.
    OutOfMemory = 10,
}

/// Every status in order with its description (`STATUSES[s as usize].0 == s`; the error
/// kinds map one to one onto the statuses after `Ok`).
pub(crate) const STATUSES: [(Status, &std::ffi::CStr); 11] = [
    (Status::Ok, c"ok"),
    (Status::NullArgument, c"null argument"),
    (Status::OutOfRange, c"out of range"),
    (Status::InvalidInput, c"invalid input"),
    (Status::NonManifold, c"non-manifold input (strict mode)"),
    (Status::BufferTooSmall, c"buffer too small"),
    (Status::Io, c"input/output error"),
    (Status::Parse, c"parse error"),
    (Status::TooLarge, c"too large for 32-bit ids"),
    (Status::Panic, c"internal error (panic caught)"),
    (Status::OutOfMemory, c"out of memory"),
];

/// A static, NUL-terminated English description of `s`, a `topomesh_status` value (never
/// NULL): "unknown status" for any other value. The parameter is a plain `uint32_t` so
/// that any value a C caller passes is defined behaviour.
#[unsafe(no_mangle)]
pub extern "C" fn topomesh_status_str(s: u32) -> *const c_char {
    let known = STATUSES.get(s as usize).map(|(_, text)| *text);
    known.unwrap_or(c"unknown status").as_ptr()
}

/// The detail of the last failed call on this thread (for example
/// "vertex 12 out of range (the mesh has 8 vertices)"), NUL-terminated, into `buf`.
///
/// `*out_len` receives the needed capacity in bytes, terminating NUL included (1 when no
/// call has failed yet on this thread). `buf == NULL` with `cap == 0` is a size query
/// (returns OK). A `buf` shorter than needed receives a truncated, NUL-terminated message
/// and the call returns `TOPOMESH_STATUS_BUFFER_TOO_SMALL`. Successful calls do not clear
/// the detail; this function never changes it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn topomesh_last_error(
    buf: *mut c_char, cap: usize, out_len: *mut usize,
) -> Status {
    // Not behind `boundary::guard`: reading the detail must not overwrite it.
    let run = || {
        // SAFETY: caller contract: NULL or valid pointers of the stated sizes.
        let copied =
            boundary::with_last_error(|msg| unsafe { boundary::text_out(msg, buf, cap, out_len) });
        copied.map_or_else(|e| boundary::status_of(e.kind), |()| Status::Ok)
    };
    boundary::catch(run).unwrap_or(Status::Panic)
}

/// The library version, "MAJOR.MINOR.PATCH" (static, NUL-terminated).
#[unsafe(no_mangle)]
pub extern "C" fn topomesh_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}
