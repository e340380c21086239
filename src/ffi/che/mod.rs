//! The CHE exports: the `che_mesh` handle (a [`Che`] plus the identity origin maps,
//! materialised on the first request for a view, as the core stores none) and its options.

mod build;
mod csr;
mod edit;
mod export;
mod files;
mod info;
mod relations;
mod star;
#[cfg(test)]
mod tests;
mod views;

pub use {
    build::*, csr::*, edit::*, export::*, files::*, info::*, relations::*, star::*, views::*,
};

use super::shapes::{build_options, handle};
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

handle!(CheMesh { che: Che, vertex_origins: num_vertices, triangle_origins: num_triangles }, CheBuildOptions => BuildOptions);

build_options! {
    /// How to build a CHE.
    CheBuildOptions {
        /// Reject non-manifold edges, non-manifold vertices and duplicate triangles with
        /// `TOPOMESH_STATUS_NON_MANIFOLD` (detail: the offending ids) instead of repairing them
        /// (default 0).
        strict
    }
}

/// The default build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn che_build_options_default() -> CheBuildOptions {
    CheBuildOptions::default()
}
