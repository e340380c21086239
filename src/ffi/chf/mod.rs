//! The CHF exports: the `chf_mesh` handle (a [`Chf`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod half_faces;
mod info;
mod levelfile;
mod relations;
mod surface;
#[cfg(test)]
mod tests;
mod views;
mod write;

pub use {
    build::*, csr::*, half_faces::*, info::*, levelfile::*, relations::*, surface::*, views::*,
    write::*,
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
}

handle!(ChfMesh { chf: Chf, vertex_origins, tetrahedron_origins }, ChfBuildOptions => BuildOptions);

/// How to build a CHF.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChfBuildOptions {
    /// The level, 0..3 (default 2).
    pub level: u32,
    /// Reject non-manifold faces (three or more tetrahedra on a face), non-manifold edges
    /// and vertices, and duplicate tetrahedra with `TOPOMESH_STATUS_NON_MANIFOLD` (detail:
    /// the offending ids) instead of keeping them (default false).
    pub strict: bool,
    /// Threads for the build: 0 (default) for as many as the machine runs at once, 1 for
    /// the calling thread alone. The mesh is the same whatever the number.
    pub threads: u32,
}

/// The default CHF build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn chf_build_options_default() -> ChfBuildOptions {
    ChfBuildOptions::default()
}
