//! Bulk relations for all elements at once, in compressed sparse rows: row `i` is
//! `indices[offsets[i] .. offsets[i + 1]]`, so `offsets` has one entry per element plus one.
//!
//! Every call has the form `(m, offsets, offsets_cap, indices, indices_cap, *n_offsets,
//! *n_indices)`. Both buffers NULL (capacities 0) is a size query: OK, with both lengths
//! written. Exactly one NULL buffer gives NULL_ARGUMENT. A buffer too small gives
//! BUFFER_TOO_SMALL with both needed lengths written (the buffers then hold a prefix).
//! Rows are in the order of the one-element calls. O(T) from level 2; below level 2 the
//! vertex-centred calls first build a temporary level-2 copy (O(T) time and memory).

use super::boundary::{CsrSink, guard, handle};
use super::che::CheMesh;
use super::status::Status;
use crate::NONE;
use crate::che::{Che, tri};
use crate::error::Result;
use std::borrow::Cow;

/// `che` itself from level 2, else a level-2 copy.
fn at_level_2(che: &Che) -> Result<Cow<'_, Che>> {
    if che.level() >= 2 {
        return Ok(Cow::Borrowed(che));
    }
    let mut copy = che.clone();
    copy.build_level(2)?;
    Ok(Cow::Owned(copy))
}

/// Shared body of the CSR calls.
///
/// # Safety
/// `m` NULL or a live handle; each buffer NULL or valid for its capacity; each length
/// pointer NULL or valid for one write.
#[allow(clippy::too_many_arguments)]
unsafe fn csr(
    m: *const CheMesh,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
    fill: impl FnOnce(&Che, &mut CsrSink<'_>) -> Result<()>,
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
        fill(&m.che, &mut sink)?;
        sink.finish()
    })
}

/// VV for every vertex (rows as `che_vertex_vertices`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_vertices_csr(
    m: *const CheMesh,
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
            |che, s| {
                let che = at_level_2(che)?;
                for v in 0..che.num_vertices() as u32 {
                    s.row();
                    che.vertex_vertices(v).for_each(|w| s.push(w));
                }
                Ok(())
            },
        )
    }
}

/// VE for every vertex (rows as `che_vertex_edges`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_edges_csr(
    m: *const CheMesh,
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
            |che, s| {
                let che = at_level_2(che)?;
                for v in 0..che.num_vertices() as u32 {
                    s.row();
                    che.vertex_edges(v).for_each(|e| s.push(e));
                }
                Ok(())
            },
        )
    }
}

/// VF for every vertex (rows as `che_vertex_triangles`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_vertex_triangles_csr(
    m: *const CheMesh,
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
            |che, s| {
                let che = at_level_2(che)?;
                for v in 0..che.num_vertices() as u32 {
                    s.row();
                    che.vertex_triangles(v).for_each(|t| s.push(t));
                }
                Ok(())
            },
        )
    }
}

/// FF for every triangle: 3 entries per row (so `offsets[t] == 3 t`), `TOPOMESH_NONE`
/// across boundary edges, as `che_triangle_triangles`. O(T) at every level.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_triangle_triangles_csr(
    m: *const CheMesh,
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
            |che, s| {
                let o = che.opposites_or_computed();
                for (h, &g) in o.iter().enumerate() {
                    if h % 3 == 0 {
                        s.row();
                    }
                    s.push(if g == NONE { NONE } else { tri(g) });
                }
                Ok(())
            },
        )
    }
}
