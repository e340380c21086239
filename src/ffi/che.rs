//! The `che_mesh` handle: a boxed [`Che`] plus the identity origin maps, materialised on
//! the first request for a zero-copy view (the core stores none when they are the identity).

use super::che_edge_ranks::EdgeRanks;
use crate::che::{BuildOptions, Che};
use crate::error::{Error, Result};
use std::sync::OnceLock;

/// Opaque handle to a CHE surface. Create with `che_mesh_from_triangles` or
/// `che_mesh_load`, free with `che_mesh_free`.
pub struct CheMesh {
    pub(crate) che: Che,
    vertex_origins: OnceLock<Box<[u32]>>,
    triangle_origins: OnceLock<Box<[u32]>>,
    /// The edge-id directory of the current level (see `che_edge_ranks`); reset when the
    /// level changes.
    edge_ranks: OnceLock<Option<EdgeRanks>>,
}

impl CheMesh {
    pub(crate) fn new(che: Che) -> Self {
        CheMesh {
            che,
            vertex_origins: OnceLock::new(),
            triangle_origins: OnceLock::new(),
            edge_ranks: OnceLock::new(),
        }
    }

    /// The edge-id rank directory, computed from `O` on first use; `None` below level 1.
    pub(crate) fn edge_ranks(&self) -> Option<&EdgeRanks> {
        self.edge_ranks
            .get_or_init(|| self.che.opposites().and_then(EdgeRanks::from_opposites))
            .as_ref()
    }

    /// Changes the level; views (the edge-id directory too) are invalid afterwards.
    pub(crate) fn build_level(&mut self, level: u8) -> Result<()> {
        self.edge_ranks = OnceLock::new();
        self.che.build_level(level)
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
}

impl Default for CheBuildOptions {
    fn default() -> Self {
        let d = BuildOptions::default();
        CheBuildOptions {
            level: d.level as u32,
            strict: d.strict,
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
    pub(crate) fn to_core(self) -> Result<BuildOptions> {
        Ok(BuildOptions {
            level: level_arg(self.level)?,
            strict: self.strict,
        })
    }
}

/// The default build options: level 2, not strict.
#[unsafe(no_mangle)]
pub extern "C" fn che_build_options_default() -> CheBuildOptions {
    CheBuildOptions::default()
}
