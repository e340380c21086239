//! The CHE exports: the `che_mesh` handle (a [`Che`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod info;
mod levelfile;
mod relations;
mod star;
#[cfg(test)]
mod tests;
mod views;
mod write;

pub use {build::*, csr::*, info::*, levelfile::*, relations::*, star::*, views::*, write::*};

use super::shapes::handle;
use crate::che::{BuildOptions, Che};
use std::sync::OnceLock;

/// Opaque handle to a CHE surface. Create with `che_mesh_from_triangles` or
/// `che_mesh_load`, free with `che_mesh_free`.
pub struct CheMesh {
    pub(crate) che: Che,
    vertex_origins: OnceLock<Box<[u32]>>,
    triangle_origins: OnceLock<Box<[u32]>>,
}

handle!(CheMesh { che: Che, vertex_origins, triangle_origins }, CheBuildOptions => BuildOptions);

/// How to build a CHE.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheBuildOptions {
    /// The level, 0..3 (default 2).
    pub level: u32,
    /// Reject non-manifold edges, non-manifold vertices and duplicate triangles with
    /// `TOPOMESH_STATUS_NON_MANIFOLD` (detail: the offending ids) instead of repairing them
    /// (default false).
    pub strict: bool,
    /// Threads for the build: 0 (default) for as many as the machine runs at once, 1 for
    /// the calling thread alone. The mesh is the same whatever the number.
    pub threads: u32,
}

/// The default build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn che_build_options_default() -> CheBuildOptions {
    CheBuildOptions::default()
}
