//! The weld alone, for a C host that wants the map the builds apply with `weld_tolerance`.

use super::boundary::{guard, null_argument, sink};
use super::mesh_arrays::{TRIANGLES, mesh_arrays};
use super::status::Status;

/// The weld of `n_vertices` positions (`3 * n_vertices` doubles) at `tolerance`, as the
/// builds do it with `weld_tolerance`: into `buf`, for each vertex, the smallest id of its
/// cluster of vertices at most `tolerance` apart (single linkage), itself when it welds to
/// none; `*out_len` receives `n_vertices`. A tolerance that is not finite and positive, or
/// a position that is not finite, is `TOPOMESH_STATUS_INVALID_INPUT`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn topomesh_weld_representatives(
    positions: *const f64, n_vertices: usize, tolerance: f64, buf: *mut u32, cap: usize,
    out_len: *mut usize,
) -> Status {
    guard(|| {
        // SAFETY: the caller contract (positions: 3 * n_vertices doubles; buf: cap writes).
        let (_, points) =
            unsafe { mesh_arrays(TRIANGLES, std::ptr::null(), 0, n_vertices, positions)? };
        if points.is_empty() && n_vertices != 0 {
            return Err(null_argument("positions"));
        }
        // SAFETY: forwarded contract.
        let mut sink = unsafe { sink(buf, cap, out_len, "buf")? };
        sink.extend(crate::util::weld::representatives(points, tolerance)?);
        sink.finish()
    })
}
