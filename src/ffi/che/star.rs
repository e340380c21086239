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

use super::CheMesh;
use crate::NONE;
use crate::che::{Che, StarCursor, StarStep, prev, tri};
use crate::ffi::boundary::{guard, guard_or, handle, handle_mut, out_arg};
use crate::ffi::status::Status;
use core::mem::{offset_of, size_of};
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
    /// The core's rotation state: `start`, `cur`, `tail` (three `uint32_t` in C).
    cursor: StarCursor,
    /// `O[cur]` (when `cur` is not NONE): the previous step's `prev(h)`, so that the inline
    /// step finds the edge of `cur` without loading it.
    cur_opposite: u32,
}

// The layout `topomesh_inline.h` mirrors by hand (its `_Static_assert`s check the same).
const _: () = {
    assert!(size_of::<CheStarIter>() == 48);
    assert!(offset_of!(CheStarIter, mesh) == 0);
    assert!(offset_of!(CheStarIter, v) == 8);
    assert!(offset_of!(CheStarIter, o) == 16);
    assert!(offset_of!(CheStarIter, edge_ranks) == 24);
    assert!(offset_of!(CheStarIter, cursor) + offset_of!(StarCursor, start) == 32);
    assert!(offset_of!(CheStarIter, cursor) + offset_of!(StarCursor, cur) == 36);
    assert!(offset_of!(CheStarIter, cursor) + offset_of!(StarCursor, tail) == 40);
    assert!(offset_of!(CheStarIter, cur_opposite) == 44);
    assert!(size_of::<CheStarStep>() == 16);
    assert!(offset_of!(CheStarStep, half_edge) == 0);
    assert!(offset_of!(CheStarStep, vertex) == 4);
    assert!(offset_of!(CheStarStep, edge) == 8);
    assert!(offset_of!(CheStarStep, triangle) == 12);
};

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

impl CheStarIter {
    /// The iterator of the rotation around `v` (checked) on the mesh `m`; from level 2
    /// it holds the zero-copy arrays.
    fn begin(m: *const CheMesh, che: &Che, v: u32) -> crate::error::Result<Self> {
        che.check_vertex(v)?;
        let start = che.vertex_half_edge(v);
        // The arrays are lent to the inline step from level 2 only.
        // (Not on an edited mesh before garbage collection: its edge ids are not ranks.)
        let inline = che.level() >= 2 && che.edge_ranks().is_some();
        fn lent<T>(a: Option<&[T]>, inline: bool) -> *const T {
            a.filter(|_| inline).map_or(ptr::null(), <[T]>::as_ptr)
        }
        Ok(CheStarIter {
            mesh: m,
            v: lent(Some(che.half_edge_vertices()), inline),
            o: lent(che.opposites(), inline),
            edge_ranks: lent(che.edge_ranks(), inline),
            cursor: StarCursor::new(start),
            cur_opposite: if start == NONE {
                NONE
            } else {
                che.opposite(start)
            },
        })
    }

    /// One step of the core's rotation, as the C step.
    fn advance(&mut self, che: &Che) -> Option<CheStarStep> {
        let step = self.cursor.step(|p| che.opposite(p))?;
        Some(match step {
            StarStep::Out(h) => {
                if self.cursor.cur != NONE {
                    self.cur_opposite = prev(h);
                }
                CheStarStep {
                    half_edge: h,
                    vertex: che.target(h),
                    edge: che.edge_of(h),
                    triangle: tri(h),
                }
            }
            StarStep::LastIn(h) => CheStarStep {
                half_edge: h,
                vertex: che.origin(h),
                edge: che.edge_of(h),
                triangle: NONE,
            },
        })
    }
}

/// Starts a rotation around vertex `v` in `*it` (an isolated vertex has no steps). From
/// level 2 the iterator holds the zero-copy arrays, so that `che_star_next` steps inline.
/// O(1) at levels 2-3; O(T) at level 1 (a scan of `V` for the start); O(T) time and
/// memory at level 0.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_star_begin(m: *const CheMesh, v: u32, it: *mut CheStarIter) -> Status {
    guard(|| {
        // SAFETY: caller contract: `m` NULL or live, `it` NULL or writable.
        let (mesh, it) = unsafe { (handle(m, "m")?, out_arg(it, "it")?) };
        it.set(CheStarIter::begin(m, &mesh.che, v)?);
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
        let m = unsafe { handle(it.mesh, "it.mesh")? };
        Ok(it.advance(&m.che).map(|s| step.set(s)).is_some())
    })
}
