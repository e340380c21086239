//! The CHE exports: the `che_mesh` handle (a [`Che`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod edit;
mod export;
mod info;
mod levelfile;
mod relations;
mod star;
#[cfg(test)]
mod tests;
mod views;
mod warnings;
mod write;

pub use {
    build::*, csr::*, edit::*, export::*, info::*, levelfile::*, relations::*, star::*, views::*,
    warnings::*, write::*,
};

use super::shapes::handle;
use crate::che::{BuildOptions, Che};
use std::sync::OnceLock;

/// Opaque handle to a CHE surface. Create with `che_mesh_from_triangles` or
/// `che_mesh_load`, free with `che_mesh_free`.
pub struct CheMesh {
    pub(crate) che: Che,
    vertex_origins: OnceLock<Box<[u32]>>,
    triangle_origins: OnceLock<Box<[u32]>>,
    /// The reader's warnings, `file:line: message` each (empty unless loaded from a file).
    warnings: Vec<String>,
}

handle!(CheMesh { che: Che, vertex_origins, triangle_origins, warnings }, CheBuildOptions => BuildOptions);

/// How to build a CHE.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheBuildOptions {
    /// The level, 0..3 (default 2).
    pub level: u32,
    /// Reject non-manifold edges, non-manifold vertices and duplicate triangles with
    /// `TOPOMESH_STATUS_NON_MANIFOLD` (detail: the offending ids) instead of repairing them
    /// (default 0). Any non-zero value is true. (A `uint8_t` rather than a `bool`, with the
    /// size and offset of the `bool` it was: a C `bool` field can hold other values, which
    /// Rust may not read as a `bool`.)
    pub strict: u8,
    /// Threads for the build: 0 (default) for as many as the machine runs at once, 1 for
    /// the calling thread alone; a larger number is capped at what the machine runs at once
    /// and at one thread per 8192 elements. The mesh is the same whatever the number.
    pub threads: u32,
    /// A memory budget for the build, in bytes (0, the default: none). The build
    /// estimates its peak from the input's sizes and, when the estimate exceeds the
    /// budget, returns `TOPOMESH_STATUS_OUT_OF_MEMORY` before allocating (detail: the
    /// estimate and the budget).
    pub memory_limit_bytes: u64,
    /// Weld before building: vertices at most this distance apart (on the positions, which
    /// it needs) become one, the smallest id of each cluster of close vertices winning;
    /// the others keep their ids but lose their elements. 0 (default) is off.
    pub weld_tolerance: f64,
}

/// The default build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn che_build_options_default() -> CheBuildOptions {
    CheBuildOptions::default()
}
