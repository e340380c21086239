//! The `che_mesh` handle: a boxed [`Che`] plus the identity origin maps, materialised on
//! the first request for a zero-copy view (the core stores none when they are the identity).

use crate::che::{BuildOptions, Che, edge_directory};
use crate::error::{Error, Result};
use crate::util::rank_directory::RankDirectory;
use std::sync::OnceLock;

/// Opaque handle to a CHE surface. Create with `che_mesh_from_triangles` or
/// `che_mesh_load`, free with `che_mesh_free`.
pub struct CheMesh {
    pub(crate) che: Che,
    vertex_origins: OnceLock<Box<[u32]>>,
    triangle_origins: OnceLock<Box<[u32]>>,
    /// The edge-id directory at level 1, computed from `O` on first use (the core stores
    /// one from level 2); reset when the level changes.
    edge_ranks: OnceLock<Option<RankDirectory>>,
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

    /// The edge-id directory (see `che_mesh_edge_ranks`): the core's from level 2, computed
    /// from `O` on first use at level 1; `None` at level 0.
    pub(crate) fn edge_ranks(&self) -> Option<&[u64]> {
        if let Some(entries) = self.che.edge_rank_directory() {
            return Some(entries);
        }
        self.edge_ranks
            .get_or_init(|| self.che.opposites().map(edge_directory))
            .as_ref()
            .map(RankDirectory::entries)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NONE;

    /// The arithmetic of `che_edge_of` (topomesh_inline.h) on the lent directory gives the
    /// core's edge ids, at level 1 (computed here) and from level 2 (the core's own).
    #[test]
    fn edge_directory_gives_the_core_edge_ids() {
        // A strip of 40 triangles (120 half-edges: boundary and interior edges).
        let mut tris = Vec::new();
        for i in 0..40u32 {
            if i % 2 == 0 {
                tris.extend([i, i + 1, i + 2]);
            } else {
                tris.extend([i, i + 2, i + 1]);
            }
        }
        for level in 1..=3 {
            let mesh =
                CheMesh::new(Che::from_flat(&tris, 42, &[], BuildOptions::level(level)).unwrap());
            let o = mesh.che.opposites().unwrap();
            let d = mesh.edge_ranks().unwrap();
            assert_eq!(d.len(), o.len().div_ceil(32));
            for h in 0..o.len() as u32 {
                let g = o[h as usize];
                let c = if g != NONE && g < h { g } else { h } as usize;
                let entry = d[c / 32];
                let edge =
                    (entry >> 32) as u32 + (entry as u32 & ((1u32 << (c % 32)) - 1)).count_ones();
                assert_eq!(edge, mesh.che.edge_of(h), "level {level} h {h}");
            }
        }
        let level0 = CheMesh::new(Che::from_flat(&tris, 42, &[], BuildOptions::level(0)).unwrap());
        assert!(level0.edge_ranks().is_none());
    }
}
