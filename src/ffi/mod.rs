//! The C ABI. The header `include/topomesh.h` is generated from this module by cbindgen
//! (see `tests/header_drift.rs`); the C++ wrapper is `include/topomesh.hpp`.
//!
//! `che/` and `chf/` hold the exports, one file per kind of call (build, relations, csr,
//! views, info, ...); each export is the guard, a conversion and one call into the core:
//! the uniform shapes are entries of `declare::exports!`, the other bodies macros of
//! `shapes`, both made of the helpers of `boundary`.
//!
//! Safety contract of every export (written once here and in the header): each pointer
//! argument is NULL or valid for the access its documentation states (a handle from this
//! library that is not freed; a buffer of at least `cap` elements; a NUL-terminated path);
//! a `const che_mesh*` (`const chf_mesh*`) may be shared between threads, a `che_mesh*`
//! passed to `che_mesh_build_level` or `che_mesh_free` (and likewise for CHF) may not.
//! NULL where a value is required gives `TOPOMESH_STATUS_NULL_ARGUMENT`; nothing panics
//! or unwinds across the boundary.
#![allow(
    clippy::missing_safety_doc,
    reason = "every export has the same safety contract, documented once in the module docs and the header preamble"
)]

// The header lists items in this order: shared things first.
pub mod status;

pub(crate) mod boundary;
pub mod che;
pub mod chf;
mod declare;
mod matrix;
mod mesh_arrays;
mod shapes;
#[cfg(test)]
mod tests;
pub mod weld;

#[doc(hidden)]
pub use boundary::guarded_panic;
pub use che::{CheBuildOptions, CheMesh};
pub use che::{CheBuildReport, CheMemory, CheReportKind, CheStarIter, CheStarStep, CheSummary};
pub use chf::{ChfBuildOptions, ChfBuildReport, ChfMemory, ChfMesh, ChfReportKind, ChfSummary};
pub use status::Status;

/// `TOPOMESH_NONE` in C: no element (boundary, none, invalid).
pub const TOPOMESH_NONE: u32 = crate::NONE;
/// A `*_write` flag: PLY in binary little-endian instead of ASCII.
pub const TOPOMESH_WRITE_BINARY: u32 = 1;
/// A `*_write` flag: leave out the input vertex of each vertex, which is otherwise written
/// where the format has a vertex attribute (PLY, VTK, Medit, TetGen).
pub const TOPOMESH_WRITE_NO_ORIGIN: u32 = 2;
/// A `*_mesh_open` flag: check the checksums and the lengths but not the structure's
/// invariants (`*_mesh_validate`): for a file this program wrote.
pub const TOPOMESH_OPEN_CHECKSUMS_ONLY: u32 = 1;
/// A `*_mesh_open` flag: check neither the checksums nor the invariants, only the header
/// and the lengths (opening a damaged file never reads out of bounds, but its queries may
/// answer wrongly or return `TOPOMESH_STATUS_PANIC`): for a file this process just wrote.
/// Wins over `TOPOMESH_OPEN_CHECKSUMS_ONLY`.
pub const TOPOMESH_OPEN_TRUSTED: u32 = 2;
/// A `*_mesh_open` flag: map the file read-only instead of reading it (zero-copy: the big
/// arrays are the file's sections, paged in as queries touch them). Queries, CSR calls and
/// views answer from the mapping; raising the level or editing copies what it writes into
/// memory. The file must stay as it is while the handle lives: truncating it makes a later
/// access raise SIGBUS. With `TOPOMESH_OPEN_TRUSTED`, a query on a corrupt file may answer
/// wrongly or return `TOPOMESH_STATUS_PANIC`, but never reads outside the mapping.
pub const TOPOMESH_OPEN_MAPPED: u32 = 4;
