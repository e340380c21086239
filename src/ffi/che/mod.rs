//! The CHE exports: the `che_mesh` handle (a boxed [`Che`] plus the identity origin maps,
//! materialised on the first request for a zero-copy view, as the core stores none when
//! they are the identity) and its build options; `build` (create, load, free, level,
//! counts), `relations` (one element at a time), `star` (the stack iterator; its step is
//! inline in `topomesh_inline.h` from level 2), `csr` (bulk), `views` (zero-copy), `info`
//! (summary, report, memory), `validate`.

mod build;
mod csr;
mod info;
mod relations;
mod star;
#[cfg(test)]
mod tests;
mod validate;
mod views;

pub use build::*;
pub use csr::*;
pub use info::*;
pub use relations::*;
pub use star::*;
pub use validate::*;
pub use views::*;

use super::boundary::{CsrSink, Handle, Sink};
use crate::che::{BuildOptions, Che, Push, Rows};
use crate::error::{Error, Result};
use std::sync::OnceLock;

/// Opaque handle to a CHE surface. Create with `che_mesh_from_triangles` or
/// `che_mesh_load`, free with `che_mesh_free`.
pub struct CheMesh {
    pub(crate) che: Che,
    vertex_origins: OnceLock<Box<[u32]>>,
    triangle_origins: OnceLock<Box<[u32]>>,
}

impl Handle for CheMesh {
    type Core = Che;
    #[inline(always)]
    fn core(&self) -> &Che {
        &self.che
    }
}

impl CheMesh {
    pub(crate) fn new(che: Che) -> Self {
        CheMesh {
            che,
            vertex_origins: OnceLock::new(),
            triangle_origins: OnceLock::new(),
        }
    }

    /// Structure vertex -> input vertex, identity included (origins do not depend on the level).
    pub(crate) fn vertex_origins(&self) -> &[u32] {
        match self.che.vertex_origins() {
            Some(map) => map,
            None => self
                .vertex_origins
                .get_or_init(|| (0..self.che.num_vertices() as u32).collect()),
        }
    }

    /// Structure triangle -> input triangle, identity included.
    pub(crate) fn triangle_origins(&self) -> &[u32] {
        match self.che.triangle_origins() {
            Some(map) => map,
            None => self
                .triangle_origins
                .get_or_init(|| (0..self.che.num_triangles() as u32).collect()),
        }
    }
}

// The core's walks write straight into the caller's buffers.
impl Push for Sink<'_, u32> {
    #[inline(always)]
    fn push(&mut self, x: u32) {
        Sink::push(self, x);
    }
}

impl Push for CsrSink<'_> {
    #[inline(always)]
    fn push(&mut self, x: u32) {
        CsrSink::push(self, x);
    }
}

impl Rows for CsrSink<'_> {
    #[inline(always)]
    fn row(&mut self) {
        CsrSink::row(self);
    }
}

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

impl Default for CheBuildOptions {
    fn default() -> Self {
        let d = BuildOptions::default();
        CheBuildOptions {
            level: d.level as u32,
            strict: d.strict,
            threads: d.threads as u32,
        }
    }
}

/// A C level as the core's, or OUT_OF_RANGE.
pub(crate) fn level_arg(level: u32) -> Result<u8> {
    if level <= 3 {
        Ok(level as u8)
    } else {
        Err(Error::out_of_range(format!("level {level} is not in 0..3")))
    }
}

impl CheBuildOptions {
    /// The defaults at `level`.
    pub(crate) fn at(level: u32) -> Self {
        CheBuildOptions {
            level,
            ..Self::default()
        }
    }

    pub(crate) fn to_core(self) -> Result<BuildOptions> {
        Ok(BuildOptions {
            level: level_arg(self.level)?,
            strict: self.strict,
            threads: self.threads as usize,
        })
    }
}

/// The default build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn che_build_options_default() -> CheBuildOptions {
    CheBuildOptions::default()
}
