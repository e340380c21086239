//! A star iterator that lives on the caller's stack and never allocates:
//!
//! ```c
//! che_star_iter it;
//! che_star_step s;
//! if (che_star_begin(m, v, &it) == TOPOMESH_STATUS_OK)
//!     while (che_star_next(&it, &s)) { ... s.vertex, s.edge, s.triangle ... }
//! ```
//!
//! `che_star_next` is `static inline` in `topomesh_inline.h`: from level 2 `che_star_begin`
//! leaves the zero-copy arrays (`V`, `O` and the edge-id directory) in the iterator and
//! each step is the header's arithmetic, with no call into the library; below level 2 (or
//! on an iterator the header cannot step) it calls `che_star_advance`, the library's step.
//! The two C structs are written by hand in `topomesh_inline.h` (it comes before the
//! generated declarations, and the inline step needs their layout); their Rust side and
//! the step are the core's `LentStar` and `LentStep`.

use super::CheMesh;
use crate::ffi::boundary::{guard, guard_or, handle, handle_mut, out_arg};
use crate::ffi::status::Status;

/// The state of a rotation around a vertex. Its fields are private: set them only with
/// `che_star_begin`. It borrows the mesh: do not free the mesh or change its level while
/// iterating.
///
/// cbindgen:no-export
#[repr(C)]
pub struct CheStarIter(crate::che::LentStar);

/// One step of a rotation around a vertex `v`, counter-clockwise seen from outside.
///
/// For each triangle around `v`: `half_edge` is its outgoing half-edge `v -> w`,
/// `vertex` is `w`, `edge` the edge of `v -> w`, `triangle` the triangle of `half_edge`.
/// On a boundary vertex the rotation starts at the outgoing boundary half-edge and ends
/// with one more step for the incoming boundary half-edge `u -> v`: `half_edge` is that
/// half-edge, `vertex` is `u`, `edge` its edge, and `triangle` is `TOPOMESH_NONE`. So the
/// steps give exactly `che_vertex_vertices` and `che_vertex_edges`, and the steps with a
/// triangle give `che_vertex_triangles`.
///
/// cbindgen:no-export
#[repr(C)]
#[derive(Default)]
pub struct CheStarStep(pub crate::che::LentStep);

/// Starts a rotation around vertex `v` in `*it` (an isolated vertex has no steps). From
/// level 2 the iterator holds the zero-copy arrays, so that `che_star_next` steps inline.
/// O(1) at levels 2-3; O(T) at level 1 (a scan of `V` for the start); O(T) time and
/// memory at level 0.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_star_begin(m: *const CheMesh, v: u32, it: *mut CheStarIter) -> Status {
    guard(|| {
        // SAFETY: caller contract: `m` NULL or live, `it` NULL or writable.
        let (mesh, it) = unsafe { (handle(m, "m")?, out_arg(it, "it")?) };
        it.set(CheStarIter(mesh.che.lent_star(v)?));
        Ok(())
    })
}

/// The library's step of `che_star_next` (which calls it when it cannot step inline):
/// writes the next step into `*step` and returns true, or returns false at the end (also
/// when `it` or `step` is NULL). O(1) per step at levels 2-3; O(1) per step at level 1
/// once the level-1 edge-id directory exists (the first request computes it, O(T), and
/// keeps it); O(T) time and memory per step at level 0 (the opposite and the edge id are
/// found by scans: O(d T) for a rotation, so at level 0 prefer `che_vertex_vertices`
/// and the other relations, O(T) each, or raise the level).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_star_advance(it: *mut CheStarIter, step: *mut CheStarStep) -> bool {
    guard_or(false, || {
        // SAFETY: caller contract: `it` NULL or set by `che_star_begin` on a live mesh,
        // `step` NULL or writable; the iterator borrows a live mesh.
        let (it, step) = unsafe { (handle_mut(it, "it")?, out_arg(step, "step")?) };
        let che = unsafe { handle(it.0.che, "it.mesh")? };
        Ok(it
            .0
            .advance(che)
            .map(|s| step.set(CheStarStep(s)))
            .is_some())
    })
}
