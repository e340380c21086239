//! The CHF exports: the `chf_mesh` handle (a [`Chf`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod edit;
mod export;
mod half_faces;
mod info;
mod levelfile;
mod relations;
mod surface;
#[cfg(test)]
mod tests;
mod views;
mod warnings;
mod write;

pub use {
    build::*, csr::*, edit::*, export::*, half_faces::*, info::*, levelfile::*, relations::*,
    surface::*, views::*, warnings::*, write::*,
};

use super::shapes::handle;
use crate::chf::{BuildOptions, Chf};
use std::sync::OnceLock;

/// Opaque handle to a CHF tetrahedral mesh. Create with `chf_mesh_from_tetrahedra` or
/// `chf_mesh_load`, free with `chf_mesh_free`.
pub struct ChfMesh {
    pub(crate) chf: Chf,
    vertex_origins: OnceLock<Box<[u32]>>,
    tetrahedron_origins: OnceLock<Box<[u32]>>,
    /// The reader's warnings, `file:line: message` each (empty unless loaded from a file).
    warnings: Vec<String>,
}

handle!(ChfMesh { chf: Chf, vertex_origins, tetrahedron_origins, warnings }, ChfBuildOptions => BuildOptions);

/// How to build a CHF.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChfBuildOptions {
    /// The level, 0..3 (default 2).
    pub level: u32,
    /// Reject non-manifold faces (three or more tetrahedra on a face), non-manifold edges
    /// and vertices, and duplicate tetrahedra with `TOPOMESH_STATUS_NON_MANIFOLD` (detail:
    /// the offending ids) instead of keeping them (default 0). Any non-zero value is true.
    /// (A `uint8_t` rather than a `bool`, with the size and offset of the `bool` it was: a C
    /// `bool` field can hold other values, which Rust may not read as a `bool`.)
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

/// The default CHF build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn chf_build_options_default() -> ChfBuildOptions {
    ChfBuildOptions::default()
}
