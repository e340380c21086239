//! Arrays crossing the boundary: the ids and positions of a build call
//! (`che_mesh_from_triangles`, `chf_mesh_from_tetrahedra`), checked before any slice is
//! made, and positions handed back as plain doubles.

use super::boundary::slice_arg;
use crate::error::Result;
use glam::DVec3;

// Positions arrive as `3 * n` doubles and are viewed as `n` `DVec3` without a copy.
const _: () = {
    assert!(std::mem::size_of::<DVec3>() == 3 * std::mem::size_of::<f64>());
    assert!(std::mem::align_of::<DVec3>() == std::mem::align_of::<f64>());
};

/// Points as their coordinates (`3 n` doubles).
pub(crate) fn coordinates(points: &[DVec3]) -> &[f64] {
    // SAFETY: `DVec3` is `repr(C)` with three `f64` fields and no padding (asserted above),
    // so `n` points are `3 n` contiguous, aligned doubles borrowed for the same lifetime.
    unsafe { std::slice::from_raw_parts(points.as_ptr().cast::<f64>(), 3 * points.len()) }
}

/// What one build call takes: `(per, check, cells)`, `per` vertex ids per cell, `check`
/// the core's check of the counts (`che::check_counts`, `chf::check_counts`), `cells`
/// the name of the cells.
pub(crate) type Cells = (usize, fn(usize, usize) -> Result<()>, &'static str);
pub(crate) const TRIANGLES: Cells = (3, crate::che::check_counts, "triangles");
pub(crate) const TETRAHEDRA: Cells = (4, crate::chf::check_counts, "tetrahedra");

/// The ids (`per * n_cells`) and positions (empty, or `n_vertices`) of a build call, once
/// the core has checked the counts.
///
/// # Safety
/// `ids` is NULL or holds `per * n_cells` ids; `positions` is NULL or holds
/// `3 * n_vertices` doubles; both stay alive and unchanged during `'a`.
pub(crate) unsafe fn mesh_arrays<'a>(
    kind: Cells, ids: *const u32, n_cells: usize, n_vertices: usize, positions: *const f64,
) -> Result<(&'a [u32], &'a [DVec3])> {
    let (per, check_counts, cells) = kind;
    check_counts(n_cells, n_vertices)?;
    // SAFETY: sizes bounded above (far below isize::MAX bytes); the caller contract covers
    // the pointers. `DVec3` is `repr(C)` with three `f64` (asserted above).
    unsafe {
        let flat = slice_arg(ids, per * n_cells, cells)?;
        let points: &[DVec3] = if positions.is_null() {
            &[]
        } else {
            slice_arg(positions.cast::<DVec3>(), n_vertices, "positions")?
        };
        Ok((flat, points))
    }
}
