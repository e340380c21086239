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
//! generated declarations, and the inline step needs their layout): keep them and these in
//! the same order.

use super::boundary::{guard, guard_or, handle, handle_mut, out_arg};
use super::che::CheMesh;
use super::status::Status;
use crate::NONE;
use crate::che::{prev, tri};
use std::ptr;

/// The state of a rotation around a vertex. Its fields are private: set them only with
/// `che_star_begin`. It borrows the mesh: do not free the mesh or change its level while
/// iterating.
///
/// cbindgen:no-export
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct CheStarIter {
    mesh: *const CheMesh,
    /// `V`, `O` and the edge-id directory when the header may step inline (from level 2);
    /// all NULL otherwise.
    v: *const u32,
    o: *const u32,
    edge_ranks: *const u64,
    start: u32,
    cur: u32,
    tail: u32,
    /// `O[cur]` (when `cur` is not NONE): the previous step's `prev(h)`, so that the inline
    /// step finds the edge of `cur` without loading it.
    cur_opposite: u32,
}

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
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheStarStep {
    pub half_edge: u32,
    pub vertex: u32,
    pub edge: u32,
    pub triangle: u32,
}

/// Starts a rotation around vertex `v` in `*it` (an isolated vertex has no steps). From
/// level 2 the iterator holds the zero-copy arrays, so that `che_star_next` steps inline.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_star_begin(m: *const CheMesh, v: u32, it: *mut CheStarIter) -> Status {
    guard(|| {
        // SAFETY: caller contract: `m` NULL or live, `it` NULL or writable.
        let (mesh, it) = unsafe { (handle(m, "m")?, out_arg(it, "it")?) };
        mesh.che.check_vertex(v)?;
        let start = mesh.che.vertex_half_edge(v);
        let inline = match (mesh.che.vertex_half_edges(), mesh.che.opposites()) {
            (Some(_), Some(o)) => mesh.edge_ranks().map(|r| (o, r)),
            _ => None,
        };
        let (o, edge_ranks) = inline.map_or((ptr::null(), ptr::null()), |(o, r)| {
            (o.as_ptr(), r.as_ptr())
        });
        it.set(CheStarIter {
            mesh: m,
            v: if o.is_null() {
                ptr::null()
            } else {
                mesh.che.half_edge_vertices().as_ptr()
            },
            o,
            edge_ranks,
            start,
            cur: start,
            tail: NONE,
            cur_opposite: if start == NONE {
                NONE
            } else {
                mesh.che.opposite(start)
            },
        });
        Ok(())
    })
}

/// The library's step of `che_star_next` (which calls it when it cannot step inline):
/// writes the next step into `*step` and returns true, or returns false at the end (also
/// when `it` or `step` is NULL). O(1) per step from level 2 (edge ids are O(T) below).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_star_advance(it: *mut CheStarIter, step: *mut CheStarStep) -> bool {
    guard_or(false, || {
        // SAFETY: caller contract: `it` NULL or set by `che_star_begin` on a live mesh,
        // `step` NULL or writable.
        let (it, step) = unsafe { (handle_mut(it, "it")?, out_arg(step, "step")?) };
        // SAFETY: the iterator borrows a live mesh (contract).
        let m = unsafe { handle(it.mesh, "it.mesh")? };
        let che = &m.che;
        // The rotation of `crate::che::star`: h, then O[prev(h)], until the boundary or back.
        if it.cur != NONE {
            let h = it.cur;
            let p = prev(h);
            let around = che.opposite(p);
            if around == NONE {
                it.cur = NONE;
                it.tail = p;
            } else if around == it.start {
                it.cur = NONE;
            } else {
                it.cur = around;
                it.cur_opposite = p;
            }
            step.set(CheStarStep {
                half_edge: h,
                vertex: che.target(h),
                edge: che.edge_of(h),
                triangle: tri(h),
            });
            return Ok(true);
        }
        if it.tail != NONE {
            let h = it.tail;
            it.tail = NONE;
            step.set(CheStarStep {
                half_edge: h,
                vertex: che.origin(h),
                edge: che.edge_of(h),
                triangle: NONE,
            });
            return Ok(true);
        }
        Ok(false)
    })
}
