//! Bulk relations for all elements at once, in compressed sparse rows: row `i` is
//! `indices[offsets[i] .. offsets[i + 1]]`, so `offsets` has one entry per element plus one.
//!
//! Every call has the form `(m, offsets, offsets_cap, indices, indices_cap, *n_offsets,
//! *n_indices)`. Both buffers NULL (capacities 0) is a size query: OK, with both lengths
//! written. Exactly one NULL buffer gives NULL_ARGUMENT. A buffer too small gives
//! BUFFER_TOO_SMALL with both needed lengths written (the buffers then hold a prefix).
//! Rows are in the order of the one-element calls. O(T) at every level: from level 2 the
//! rows stream from the structure; at level 1 VV and VF stream the same walk over a
//! starting half-edge per vertex found in one pass (4 bytes per vertex of temporary
//! memory); otherwise the core's bulk sweep computes the missing tables once (O(T)
//! temporary memory).

use super::boundary::{CsrSink, csr_answer};
use super::che::CheMesh;
use super::che_walk::{Walk, vertex_half_edges};
use super::status::Status;
use crate::NONE;
use crate::che::{Che, Csr, tri};
use crate::error::Result;

/// Streams one row per vertex from level 2; below, copies the core's bulk answer.
fn vertex_rows(
    che: &Che,
    s: &mut CsrSink<'_>,
    row: impl Fn(&Che, u32, &mut CsrSink<'_>),
    bulk: impl Fn(&Che) -> Csr,
) {
    if che.level() >= 2 {
        for v in 0..che.num_vertices() as u32 {
            s.row();
            row(che, v, s);
        }
    } else {
        let csr = bulk(che);
        for v in 0..csr.len() {
            s.row();
            csr.get(v).iter().for_each(|&x| s.push(x));
        }
    }
}

/// VV or VF rows: `row` walks each star (from level 1), else the core's bulk answer is copied.
fn star_rows(
    che: &Che,
    s: &mut CsrSink<'_>,
    row: impl Fn(&Walk<'_>, u32, &mut CsrSink<'_>),
    bulk: impl Fn(&Che) -> Csr,
) {
    let found;
    let walk = match (Walk::of(che), che.opposites()) {
        (Some(w), _) => w,
        (None, Some(o)) => {
            let v = che.half_edge_vertices();
            found = vertex_half_edges(che.num_vertices(), v, o);
            Walk { v, o, vh: &found }
        }
        (None, None) => return vertex_rows(che, s, |_, _, _| {}, bulk),
    };
    for v in 0..che.num_vertices() as u32 {
        s.row();
        row(&walk, v, s);
    }
}

/// The CSR calls' shared body on a `CheMesh` (see `boundary::csr_answer`).
///
/// # Safety
/// As `boundary::csr_answer`.
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
    // SAFETY: forwarded contract.
    unsafe {
        csr_answer(
            m,
            offsets,
            offsets_cap,
            indices,
            indices_cap,
            n_offsets,
            n_indices,
            |m: &CheMesh, s| fill(&m.che, s),
        )
    }
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
                star_rows(
                    che,
                    s,
                    |w, v, s| w.vertex_vertices(v, &mut |x| s.push(x)),
                    Che::all_vertex_vertices,
                );
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
                vertex_rows(
                    che,
                    s,
                    |che, v, s| che.vertex_edges(v).for_each(|x| s.push(x)),
                    Che::all_vertex_edges,
                );
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
                star_rows(
                    che,
                    s,
                    |w, v, s| w.vertex_triangles(v, &mut |x| s.push(x)),
                    Che::all_vertex_triangles,
                );
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
