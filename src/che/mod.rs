//! CHE, the Compact Half-Edge for triangle surfaces, in levels:
//! - 0: `V[3T]`, the (oriented, manifold-split) triangle soup;
//! - 1: `O[3T]`, opposite half-edges (`NONE` on the boundary);
//! - 2: `VH[V]` (a boundary vertex stores its outgoing boundary half-edge), edge ids;
//! - 3: boundary curves.
//!
//! Every query works at every level; a higher level only answers faster. The build always
//! canonicalises the input (degenerate triangles dropped, components oriented, non-manifold
//! vertices split) so that the half-edge and edge ids are the same at every level.

pub(crate) mod build;
mod edit;
pub mod export;
pub mod ids;
mod pairs;
pub(crate) mod query;
pub(crate) mod tables;

pub use crate::Ids;
pub use crate::util::sparse::{Assembled, CsrSlices, SparseMatrix, Storage};
pub use build::{
    BuildOptions, BuildReport, MAX_TRIANGLES, MAX_UNUSED_VERTICES, SweepLimits, check_counts,
    estimated_build_bytes,
};
pub use edit::{GarbageMaps, GarbageMapsOut};
pub use export::{
    CornerTable, HalfEdgeArray, HalfEdgeArrays, HalfEdgeOptions, MatrixKind, Strips, WingedEdges,
};
pub use ids::{first, next, prev, tri};
pub(crate) use query::for_each_step;
pub use query::{
    BoundaryWalk, Csr, LentStar, LentStep, Memory, Rotation, StarCursor, StarStep, Summary,
};
pub(crate) use query::{Push, Rows};
pub(crate) use tables::edge_directory;

use crate::NONE;
use crate::error::Result;
use crate::util::input::Input;
use crate::util::origin::OriginMap;
use crate::util::progress::BuildProgress;
use crate::util::rank::RankBits;
use crate::util::rank_directory::RankDirectory;
use crate::util::store::Store;
use crate::util::structure::{as_elements, check_id};
use glam::DVec3;
use std::sync::OnceLock;

/// A triangle surface in the Compact Half-Edge structure.
#[derive(Clone, Debug)]
pub struct Che {
    pub(crate) level: u8,
    pub(crate) n_input_vertices: usize,
    pub(crate) n_vertices: usize,
    /// `V[h]`: origin of half-edge `h`.
    pub(crate) v: Store<u32>,
    /// Level 1: `O[h]`.
    pub(crate) o: Store<u32>,
    /// Level 2: one outgoing half-edge per vertex, the boundary one on the boundary.
    pub(crate) vh: Store<u32>,
    /// Level 2: bit `h` set when `h` is the canonical half-edge of its edge
    /// (`O[h] == NONE || h < O[h]`); the edge id is the rank.
    pub(crate) edge_bits: RankDirectory,
    /// Level 2: the canonical half-edge of each edge.
    pub(crate) eh: Store<u32>,
    /// Level 1 only: the edge-id directory computed from `O` on first request (see
    /// [`Che::edge_ranks`]); emptied when the level changes.
    pub(crate) lazy_edge_bits: OnceLock<RankDirectory>,
    /// Level 3: one boundary half-edge per boundary curve.
    pub(crate) ch: Store<u32>,
    /// Level 3: bit `h` set when `O[h] == NONE`; rank indexes `curve_of`.
    pub(crate) boundary_bits: RankBits,
    /// Level 3: the curve of each boundary half-edge, in half-edge order.
    pub(crate) curve_of: Store<u32>,
    /// Edge count, the same at every level.
    pub(crate) num_edges: usize,
    pub(crate) positions: Store<DVec3>,
    /// Structure vertex -> input vertex; empty when the identity.
    pub(crate) vertex_origin: OriginMap,
    /// Structure triangle -> input triangle; empty when the identity.
    pub(crate) triangle_origin: OriginMap,
    /// Sorted half-edges of non-manifold edges (3+ triangles), kept unpaired.
    pub(crate) non_manifold: Vec<u32>,
    /// Sorted half-edges on the seams of non-orientable components, kept unpaired.
    pub(crate) seams: Vec<u32>,
    pub(crate) report: BuildReport,
    /// Built with `BuildOptions::strict`: an edit that would make the surface
    /// non-manifold or reverse an orientation is refused instead of repaired.
    pub(crate) strict: bool,
    /// What the first edit materialises (see `edit/`); `None` on a CHE never edited.
    pub(crate) edit: Option<Box<edit::EditState>>,
    /// What a check (`is_flip_ok`, `is_collapse_ok`) last said yes to, until the next
    /// check, edit, change of level or collection: the edit that usually follows its check
    /// skips repeating it.
    pub(crate) checked: Checked,
}

/// The element a check last allowed an edit of (see [`Che::checked`]); none would be
/// refused now, since nothing has changed the mesh since.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Checked {
    #[default]
    Nothing,
    /// `is_flip_ok(e)` said yes.
    Flip(u32),
    /// `is_collapse_ok(h)` said yes.
    Collapse(u32),
}

impl Che {
    crate::util::structure::build_constructors!(
        Che,
        3,
        from_triangles,
        from_triangles_with_progress,
        "triangles",
        "triangle"
    );

    crate::util::structure::structure_accessors!(BuildReport);

    /// Was the CHE built with `BuildOptions::strict`? A strict CHE refuses an
    /// [`Che::add_triangle`] that would make an edge non-manifold or reverse an
    /// orientation; a non-strict one repairs it as its build would, and reports it.
    pub fn is_strict(&self) -> bool {
        self.strict
    }

    /// Raises (or lowers) the level in place. Ids do not change.
    pub fn build_level(&mut self, level: u8) -> Result<()> {
        self.checked = Checked::Nothing;
        if self.edit.is_some() {
            return self.change_edited_level(level);
        }
        build::change_level(self, level)
    }

    pub fn num_triangles(&self) -> usize {
        self.v.len() / 3
    }
    pub fn num_half_edges(&self) -> usize {
        self.v.len()
    }

    /// `V`: the origin of every half-edge.
    pub fn half_edge_vertices(&self) -> &[u32] {
        &self.v
    }
    /// `VH`, from level 2.
    pub fn vertex_half_edges(&self) -> Option<&[u32]> {
        (self.level >= 2).then_some(&self.vh[..])
    }
    /// The edge-id directory, from level 2: one entry per 32 half-edges, the canonical
    /// flags in its low half and the canonical half-edges before them in its high half
    /// (the edge of a canonical half-edge `c` is its rank; see `rank_directory.rs`).
    /// `None` on an edited CHE until [`Che::garbage_collect`] (the ids are then not ranks).
    pub fn edge_rank_directory(&self) -> Option<&[u64]> {
        if self.edits().is_some_and(|s| !s.edge_of.is_empty()) {
            return None;
        }
        (self.level >= 2).then_some(self.edge_bits.entries())
    }
    /// The edge-id directory from level 1: the structure's own from level 2 (as
    /// [`Che::edge_rank_directory`], so `None` on an edited CHE until garbage collection); at level 1 computed from `O` on the first request and
    /// kept until the level changes. `None` at level 0.
    pub fn edge_ranks(&self) -> Option<&[u64]> {
        match self.level {
            0 => None,
            1 => Some(self.level1_edge_bits().entries()),
            _ => self.edge_rank_directory(),
        }
    }
    /// `EH`: the canonical half-edge of every edge, from level 2.
    pub fn edge_half_edges(&self) -> Option<&[u32]> {
        (self.level >= 2).then_some(&self.eh[..])
    }
    /// The level-1 edge-id directory, computed on the first request (over the live
    /// half-edges on an edited CHE).
    pub(crate) fn try_level1_edge_bits(&self) -> Result<&RankDirectory> {
        if let Some(bits) = self.lazy_edge_bits.get() {
            return Ok(bits);
        }
        let bits = match self.edits() {
            Some(_) => self.live_edge_directory(&self.o)?,
            None => edge_directory(&self.o)?,
        };
        Ok(self.lazy_edge_bits.get_or_init(|| bits))
    }

    /// [`Che::try_level1_edge_bits`] for the queries without an error to return.
    pub(crate) fn level1_edge_bits(&self) -> &RankDirectory {
        crate::util::alloc::or_panic(self.try_level1_edge_bits())
    }
    /// `CH`: one boundary half-edge per curve, at level 3 (on an edited CHE, computed at
    /// the first request after an edit).
    pub fn curve_half_edges(&self) -> Option<&[u32]> {
        if self.level >= 3 && self.edits().is_some() {
            return Some(&self.edited_curves().ch);
        }
        (self.level >= 3).then_some(&self.ch[..])
    }

    /// The input triangle a structure triangle comes from.
    pub fn triangle_origin(&self, t: u32) -> u32 {
        self.triangle_origin.get(t)
    }
    /// The triangle origin map, or `None` when it is the identity.
    pub fn triangle_origins(&self) -> Option<&[u32]> {
        self.triangle_origin.explicit()
    }

    /// Half-edges of non-manifold edges (sorted); they are unpaired at every level.
    pub fn non_manifold_half_edges(&self) -> &[u32] {
        &self.non_manifold
    }
    /// Half-edges on non-orientable seams (sorted); they are unpaired at every level.
    pub fn seam_half_edges(&self) -> &[u32] {
        &self.seams
    }

    #[inline]
    pub fn check_triangle(&self, t: u32) -> Result<()> {
        check_id(t, self.num_triangles(), "triangle", "triangles")
    }
    #[inline]
    pub fn check_half_edge(&self, h: u32) -> Result<()> {
        check_id(h, self.v.len(), "half-edge", "half-edges")
    }
}

const _: () = {
    // Queries are `&self` and lock-free: the structure is plain data.
    const fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<Che>();
    assert!(NONE == u32::MAX);
};
