//! Bulk relations for all elements at once, in compressed sparse rows: row `i` is
//! `indices[offsets[i] .. offsets[i + 1]]`, so `offsets` has one entry per element plus one.
//!
//! Every call has the form `(m, offsets, offsets_cap, indices, indices_cap, *n_offsets,
//! *n_indices)`. Both buffers NULL (capacities 0) is a size query: OK, with both lengths
//! written. Exactly one NULL buffer gives NULL_ARGUMENT. A buffer too small gives
//! BUFFER_TOO_SMALL with both needed lengths written (the buffers then hold a prefix).
//! Rows are the answers of the one-element calls, in the same order. O(T) at every level:
//! from the level the rows need (2, or 1 for TT) they stream from the structure; below,
//! the call builds a temporary copy of the structure at that level (O(T) time and
//! temporary memory) and leaves the mesh at its level. A size query followed by the call
//! does the work twice: callers that care raise the level first.

use super::boundary::{CsrSink, guard, handle};
use super::chf::ChfMesh;
use super::status::Status;
use crate::NONE;
use crate::chf::Chf;
use crate::error::Result;
use std::borrow::Cow;

/// The structure at `level` or above: borrowed, or a temporary raised copy.
fn at_least(chf: &Chf, level: u8) -> Result<Cow<'_, Chf>> {
    if chf.level() >= level {
        return Ok(Cow::Borrowed(chf));
    }
    let mut copy = chf.clone();
    copy.build_level(level)?;
    Ok(Cow::Owned(copy))
}

/// One row per element `0..n`, each the ids `row` yields.
fn rows<I: IntoIterator<Item = u32>>(s: &mut CsrSink<'_>, n: usize, mut row: impl FnMut(u32) -> I) {
    for x in 0..n as u32 {
        s.row();
        for y in row(x) {
            s.push(y);
        }
    }
}

/// Shared body of the CSR calls.
///
/// # Safety
/// `m` NULL or a live handle; each buffer NULL or valid for its capacity; each length
/// pointer NULL or valid for one write.
#[allow(clippy::too_many_arguments)]
unsafe fn csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
    fill: impl FnOnce(&Chf, &mut CsrSink<'_>) -> Result<()>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (m, mut sink) = unsafe {
            (
                handle(m, "m")?,
                CsrSink::new(
                    offsets,
                    offsets_cap,
                    indices,
                    indices_cap,
                    n_offsets,
                    n_indices,
                )?,
            )
        };
        fill(&m.chf, &mut sink)?;
        sink.finish()
    })
}

/// VV for every vertex (rows as `chf_vertex_vertices`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_vertices_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_vertices(), |x| chf.vertex_vertices(x));
                Ok(())
            },
        )
    }
}

/// VE for every vertex (rows as `chf_vertex_edges`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_edges_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_vertices(), |x| chf.vertex_edges(x));
                Ok(())
            },
        )
    }
}

/// VF for every vertex (rows as `chf_vertex_faces`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_faces_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_vertices(), |x| chf.vertex_faces(x));
                Ok(())
            },
        )
    }
}

/// VT for every vertex (rows as `chf_vertex_tetrahedra`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_vertex_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_vertices(), |x| chf.vertex_tetrahedra(x));
                Ok(())
            },
        )
    }
}

/// EF for every edge (rows as `chf_edge_faces`, in rotation order).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_edge_faces_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_edges(), |x| chf.edge_faces(x));
                Ok(())
            },
        )
    }
}

/// ET for every edge (rows as `chf_edge_tetrahedra`, in rotation order).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_edge_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 2)?;
                rows(s, chf.num_edges(), |x| chf.edge_tetrahedra(x));
                Ok(())
            },
        )
    }
}

/// TT for every tetrahedron: 4 entries per row (so `offsets[t] == 4 t`), the
/// tetrahedron across face `i`, `TOPOMESH_NONE` on the boundary, as
/// `chf_tetrahedron_tetrahedra`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_tetrahedron_tetrahedra_csr(
    m: *const ChfMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
) -> Status {
    // SAFETY: caller contract.
    unsafe {
        csr(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |chf, s| {
                let chf = at_least(chf, 1)?;
                let o = chf.opposites().unwrap_or_default();
                rows(s, chf.num_tetrahedra(), |t| {
                    o[4 * t as usize..4 * t as usize + 4]
                        .iter()
                        .map(|&g| if g == NONE { NONE } else { g >> 2 })
                });
                Ok(())
            },
        )
    }
}
