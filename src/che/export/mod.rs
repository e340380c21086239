//! Classic representations of a built CHE, for code written against another structure:
//! half-edge (DCEL) arrays, the winged-edge table, the corner table and directed edges,
//! edge and face lists, sparse matrices (adjacency, incidence, Laplacian, dual graph),
//! Betti numbers over Z/2 and triangle strips.
//!
//! Exports are queries: they work at every level, read what the level stores and compute
//! the rest once for the whole export (as the bulk relations do), and never run a build
//! pass. Every id is the structure's: half-edge `h` of triangle `t = h / 3` runs from
//! `V[h]` (its tail, the origin) to `V[next(h)]`; edge ids are those of [`Che::edge_of`].

mod betti;
mod corner;
mod halfedge;
mod lists;
mod matrices;
mod strips;
mod winged;

pub use corner::CornerTable;
pub use halfedge::{HalfEdgeArray, HalfEdgeArrays, HalfEdgeOptions};
pub use matrices::MatrixKind;
pub use strips::Strips;
pub use winged::WingedEdges;

use crate::NONE;
use crate::che::Che;
use crate::che::tables::{edge_ids, vertex_half_edges};
use crate::error::Result;
use crate::util::alloc::try_collect;
use crate::util::sparse::filled;
use std::borrow::Cow;

/// What every export reads: `O`, the edge of every half-edge, the canonical half-edge of
/// every edge and the starting half-edge of every vertex, borrowed where the level stores
/// them and computed once otherwise.
pub(crate) struct ExportTables<'a> {
    pub o: Cow<'a, [u32]>,
    pub edge: Vec<u32>,
    pub eh: Cow<'a, [u32]>,
    pub vh: Cow<'a, [u32]>,
}

impl Che {
    pub(crate) fn export_tables(&self) -> Result<ExportTables<'_>> {
        let o = self.try_opposites_or_computed()?;
        let edge = if self.level >= 2 {
            let edges = (0..self.v.len() as u32).map(|h| self.edge_of(h));
            try_collect(edges, "the edge of each half-edge")?
        } else {
            edge_ids(&o)?
        };
        let eh = match self.edge_half_edges() {
            Some(eh) => Cow::Borrowed(eh),
            None => {
                let mut eh = filled(self.num_edges, NONE, "edge half-edges")?;
                for (h, &e) in edge.iter().enumerate() {
                    if eh[e as usize] == NONE {
                        eh[e as usize] = h as u32;
                    }
                }
                Cow::Owned(eh)
            }
        };
        let vh = match self.vertex_half_edges() {
            Some(vh) => Cow::Borrowed(vh),
            None => Cow::Owned(vertex_half_edges(self.n_vertices, &self.v, &o)?),
        };
        Ok(ExportTables { o, edge, eh, vh })
    }
}
