//! The `chf_mesh` handle: a boxed [`Chf`] plus the identity origin maps, materialised on
//! the first request for a zero-copy view (the core stores none when they are the identity).

mod build;
mod csr;
mod half_faces;
mod info;
mod relations;
mod surface;
#[cfg(test)]
mod tests;
mod views;

pub use build::*;
pub use csr::*;
pub use half_faces::*;
pub use info::*;
pub use relations::*;
pub use surface::*;
pub use views::*;

use super::boundary::Handle;
use crate::chf::{BuildOptions as CoreOptions, Chf};
use crate::error::Result;
use crate::ffi::che::level_arg;
use std::sync::OnceLock;

/// Opaque handle to a CHF tetrahedral mesh. Create with `chf_mesh_from_tetrahedra` or
/// `chf_mesh_load`, free with `chf_mesh_free`.
pub struct ChfMesh {
    pub(crate) chf: Chf,
    vertex_origins: OnceLock<Box<[u32]>>,
    tetrahedron_origins: OnceLock<Box<[u32]>>,
}

impl ChfMesh {
    pub(crate) fn new(chf: Chf) -> Self {
        ChfMesh {
            chf,
            vertex_origins: OnceLock::new(),
            tetrahedron_origins: OnceLock::new(),
        }
    }

    /// Structure vertex -> input vertex, identity included (origins do not depend on the level).
    pub(crate) fn vertex_origins(&self) -> &[u32] {
        match self.chf.vertex_origins() {
            Some(map) => map,
            None => self
                .vertex_origins
                .get_or_init(|| (0..self.chf.num_vertices() as u32).collect()),
        }
    }

    /// Structure tetrahedron -> input tetrahedron, identity included.
    pub(crate) fn tetrahedron_origins(&self) -> &[u32] {
        match self.chf.tetrahedron_origins() {
            Some(map) => map,
            None => self
                .tetrahedron_origins
                .get_or_init(|| (0..self.chf.num_tetrahedra() as u32).collect()),
        }
    }
}

impl Handle for ChfMesh {
    type Core = Chf;
    #[inline(always)]
    fn core(&self) -> &Chf {
        &self.chf
    }
}

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

impl Default for ChfBuildOptions {
    fn default() -> Self {
        let d = CoreOptions::default();
        ChfBuildOptions {
            level: d.level as u32,
            strict: d.strict,
            threads: d.threads as u32,
        }
    }
}

impl ChfBuildOptions {
    /// The defaults at `level`.
    pub(crate) fn at(level: u32) -> Self {
        ChfBuildOptions {
            level,
            ..Self::default()
        }
    }

    pub(crate) fn to_core(self) -> Result<CoreOptions> {
        Ok(CoreOptions {
            level: level_arg(self.level)?,
            strict: self.strict,
            threads: self.threads as usize,
        })
    }
}

/// The default CHF build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn chf_build_options_default() -> ChfBuildOptions {
    ChfBuildOptions::default()
}
