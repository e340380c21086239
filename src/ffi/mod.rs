//! The C ABI. The header `include/topomesh.h` is generated from this module by cbindgen
//! (see `tests/header_drift.rs`); the C++ wrapper is `include/topomesh.hpp`.
//!
//! Layout (the pattern the CHF exports follow):
//! - `boundary`: the one helper every export runs behind (null checks, `catch_unwind`,
//!   error -> status + thread-local detail), caller-buffer and CSR sinks, handle boxing;
//! - `mesh_arrays`: the checked ids and positions of both build calls;
//! - `status`: `topomesh_status`, `topomesh_status_str`, `topomesh_last_error`,
//!   `topomesh_version`;
//! - `shapes`: the uniform bodies of the exports (count, value, ids into a caller buffer,
//!   CSR, zero-copy view, new handle, free) as macros, for CHE and CHF alike;
//! - `che/`: the `che_mesh` handle and build options (`mod.rs`); `build` (create, load,
//!   free, level, counts), `relations` (one element at a time), `star` (stack iterator;
//!   its step is inline in `topomesh_inline.h` from level 2), `csr` (bulk), `views`
//!   (zero-copy), `info` (summary, report, memory), `validate`. Each export is the guard,
//!   a conversion and one call into the core.
//! - `chf`: the `chf_mesh` handle and build options, the same shape: `chf_build`,
//!   `chf_relations` (the 16 relations), `chf_half_faces` (boundary tests, half-face
//!   helpers), `chf_csr`, `chf_views`, `chf_info`, `chf_surface` (the boundary surface as
//!   a new `che_mesh`, and the maps to it).
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
mod mesh_arrays;
mod shapes;
#[cfg(test)]
mod tests;

pub use che::{CheBuildOptions, CheMesh};
pub use che::{CheBuildReport, CheMemory, CheReportKind, CheStarIter, CheStarStep, CheSummary};
pub use chf::{ChfBuildOptions, ChfBuildReport, ChfMemory, ChfMesh, ChfReportKind, ChfSummary};
pub use status::Status;

/// `TOPOMESH_NONE` in C: no element (boundary, none, invalid).
pub const TOPOMESH_NONE: u32 = crate::NONE;
