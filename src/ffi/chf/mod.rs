//! The CHF exports: the `chf_mesh` handle (a [`Chf`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod edit;
mod export;
mod files;
mod half_faces;
mod info;
mod relations;
mod surface;
#[cfg(test)]
mod tests;
mod views;

pub use {
    build::*, csr::*, edit::*, export::*, files::*, half_faces::*, info::*, relations::*,
    surface::*, views::*,
};

use super::shapes::{build_options, handle};
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

handle!(ChfMesh { chf: Chf, vertex_origins: num_vertices, tetrahedron_origins: num_tetrahedra }, ChfBuildOptions => BuildOptions);

build_options! {
    /// How to build a CHF.
    ChfBuildOptions {
        /// Reject non-manifold faces (three or more tetrahedra on a face), non-manifold edges
        /// and vertices, and duplicate tetrahedra with `TOPOMESH_STATUS_NON_MANIFOLD` (detail:
        /// the offending ids) instead of keeping them (default 0).
        strict
    }
}

/// The default CHF build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn chf_build_options_default() -> ChfBuildOptions {
    ChfBuildOptions::default()
}
