//! Classic representations of a CHE into caller buffers: half-edge (DCEL) arrays, the
//! winged-edge table, the corner table, edge and face lists, sparse matrices, Betti
//! numbers and triangle strips. Each is a size query first (`buf == NULL`, `cap == 0`)
//! and then a fill, as the CSR calls; the layouts are stated on each call and in the
//! core (`crate::che::export`).
//!
//! The docs are the C header's, for C readers: `buf[h]` is an index, not a link.
#![allow(rustdoc::broken_intra_doc_links)]

use super::CheMesh;
use crate::che::{HalfEdgeArray, HalfEdgeOptions, MatrixKind, Strips, WingedEdges};
use crate::error::Result;
use crate::ffi::boundary::{options_arg, report_kind};
use crate::ffi::declare::exports;

/// How `che_mesh_export_half_edges` shows the boundary.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheHalfEdgeOptions {
    /// false (default): only the 3T half-edges of the triangles, a boundary half-edge
    /// marked by twin == TOPOMESH_NONE. true (OpenMesh style): one extra half-edge per
    /// boundary half-edge, numbered from 3T in the order of the half-edges they twin, with
    /// face TOPOMESH_NONE, linked by next and prev into a loop round each hole.
    pub explicit_boundary: bool,
}

/// Which array `che_mesh_export_winged_edges` writes.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheWingedArray {
    /// 2 per edge: its ends, in the direction of its canonical half-edge.
    Vertices = 0,
    /// 2 per edge: the left triangle (which runs along that direction), then the right
    /// one (TOPOMESH_NONE on the boundary).
    Faces = 1,
    /// 4 per edge: the edges before and after it counter-clockwise round the left
    /// triangle, then round the right one (TOPOMESH_NONE twice on the boundary).
    Wings = 2,
    /// 1 per vertex: an edge at it (TOPOMESH_NONE when isolated).
    VertexEdge = 3,
    /// 1 per triangle t: the edge of half-edge 3t.
    FaceEdge = 4,
}

/// Which list `che_mesh_export_strips` writes.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheStripList {
    /// The strips one after another, separated by TOPOMESH_NONE (primitive restart).
    Restarts = 0,
    /// One strip, the strips joined by degenerate triangles (repeated vertices).
    Joined = 1,
}

/// Betti numbers over Z/2.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheBetti {
    pub b0: u64,
    pub b1: u64,
    pub b2: u64,
}

fn winged_array(w: WingedEdges, which: u32) -> Result<Vec<u32>> {
    let all = [w.vertices, w.faces, w.wings, w.vertex_edge, w.face_edge];
    report_kind(all, which, "che_winged_array")
}

/// The options of `che_mesh_export_half_edges` (NULL: the defaults), read under the
/// export's contract.
fn half_edge_options(p: *const CheHalfEdgeOptions) -> HalfEdgeOptions {
    // SAFETY: the export's contract: NULL or a valid options struct.
    let o = unsafe { options_arg(p) };
    HalfEdgeOptions {
        explicit_boundary: o.explicit_boundary,
    }
}

exports! { CheMesh;
    /// Half-edge (DCEL) array `which` (a `che_half_edge_array`) with `options` (NULL: marked
    /// boundary). Half-edges 0..3T are CHE's own: 3t, 3t+1, 3t+2 go round triangle t
    /// counter-clockwise, half-edge h from vertex[h] (its tail) to vertex[next[h]]. O(T) at
    /// every level. Without explicit boundary, `vertex` and `twin` are the structure's own
    /// arrays, lent without a copy by `che_mesh_half_edge_vertices` and (from level 1)
    /// `che_mesh_opposites`.
    ids fn che_mesh_export_half_edges(options: *const CheHalfEdgeOptions, which) {
        |c, s| {
            let which = report_kind(HalfEdgeArray::ALL, which, "che_half_edge_array")?;
            c.half_edge_array_into(half_edge_options(options), which, s)?
        }
    }
    /// Winged-edge array `which` (a `che_winged_array`) over the edge ids of `che_half_edge_edge`.
    /// O(T) at every level.
    ids fn che_mesh_export_winged_edges(which) {
        try |c| c.winged_edges().and_then(|w| winged_array(w, which))
    }
    /// The corner table's opposite corners, 3T entries. Corner c is half-edge c: the corner of
    /// triangle c / 3 at vertex V[c] (so the table's V is `che_mesh_half_edge_vertices`); the
    /// opposite corner of c faces the same edge (half-edge next(c)) from the other triangle:
    /// prev(O[next(c)]), TOPOMESH_NONE on the boundary. O(T) at every level.
    ids fn che_mesh_export_corner_opposites() { try |c| c.corner_table().map(|t| t.o) }
    /// The edge list, 2E entries: edge e from [2e] to [2e + 1], in the direction of its
    /// canonical half-edge. O(T) at every level.
    ids fn che_mesh_export_edge_list() { try |c| c.edge_list() }
    /// The face list with edge ids, 3T entries: entry 3t + i is the edge of half-edge 3t + i
    /// (from corner i to corner i + 1 of triangle t). O(T) at every level.
    ids fn che_mesh_export_triangle_edges() { try |c| c.all_triangle_edges() }
    /// Triangle strips covering every triangle once in its orientation (greedy, from the
    /// dual graph), as list `which` (a `che_strip_list`). A strip s stands for the triangles
    /// (s[i], s[i+1], s[i+2]) for even i and (s[i+1], s[i], s[i+2]) for odd i. O(T) at every
    /// level.
    ids fn che_mesh_export_strips(which) {
        try |c| {
            let list = [Strips::with_restarts, Strips::joined];
            let list = report_kind(list, which, "che_strip_list")?;
            list(&c.triangle_strips()?)
        }
    }
    /// Betti numbers over Z/2 of the surface as given (seams and split vertices joined again,
    /// isolated vertices counted) into `*out`; b0 - b1 + b2 is the Euler characteristic of
    /// `che_mesh_summary`. Near-linear at every level.
    value fn che_mesh_betti_numbers() -> CheBetti {
        |c| c.betti_numbers().map(|[b0, b1, b2]| CheBetti { b0, b1, b2 })
    }
}

exports! { CheMesh;
    /// Sparse matrix `kind` (a `che_matrix_kind`) in CSR, ready for Eigen (`Map<SparseMatrix<
    /// double, RowMajor, int64_t>>` after a cast of the columns) or SciPy (`csr_matrix((values,
    /// columns, offsets))`): row r holds `columns[offsets[r] .. offsets[r + 1]]` (sorted) with
    /// `values` at the same places; `*n_offsets` is rows + 1, `*n_entries` the entries. All
    /// three buffers NULL (capacities 0) is a size query; some NULL and not all is an error; a
    /// short buffer gives BUFFER_TOO_SMALL with both lengths written. O(T + entries) at every
    /// level.
    matrix fn che_mesh_export_matrix(kind) {
        |c, offer| c.matrix_into(report_kind(MatrixKind::ALL, kind, "che_matrix_kind")?, offer)
    }
}
