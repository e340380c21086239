//! The rotation around a vertex as plain C data, for the C API's star iterator
//! (`che_star_iter`, `che_star_step`, which `topomesh_inline.h` writes out by hand: keep
//! the fields of [`LentStar`] and [`LentStep`] in its order). From level 2 the state lends
//! the zero-copy arrays (`V`, `O` and the edge-id directory), so that the header steps
//! inline; below, or on a state the header cannot step, each step is [`LentStar::advance`],
//! the core's [`StarCursor`].

use super::star::{StarCursor, StarStep};
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{prev, tri};
use crate::error::Result;
use core::mem::{offset_of, size_of};
use std::ptr;

/// The state of a rotation around a vertex. It borrows the structure by pointer: the
/// caller keeps it alive and at its level while stepping.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct LentStar {
    /// The structure stepped, for [`LentStar::advance`] (opaque to the header).
    pub che: *const Che,
    /// `V`, `O` and the edge-id directory when the header may step inline (from level 2);
    /// all NULL otherwise.
    v: *const u32,
    o: *const u32,
    edge_ranks: *const u64,
    cursor: StarCursor,
    /// `O[cur]` (when `cur` is not NONE): the previous step's `prev(h)`, so that the inline
    /// step finds the edge of `cur` without loading it.
    cur_opposite: u32,
}

/// One step of a rotation around `v`: the outgoing half-edge `v -> w`, `w`, its edge and
/// triangle; on a boundary vertex a last step for the incoming boundary half-edge `u -> v`
/// with `u` and its edge and triangle `NONE`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LentStep {
    pub half_edge: u32,
    pub vertex: u32,
    pub edge: u32,
    pub triangle: u32,
}

// The layout `topomesh_inline.h` mirrors by hand (its `_Static_assert`s check the same).
const _: () = {
    assert!(size_of::<LentStar>() == 48);
    assert!(offset_of!(LentStar, che) == 0);
    assert!(offset_of!(LentStar, v) == 8);
    assert!(offset_of!(LentStar, o) == 16);
    assert!(offset_of!(LentStar, edge_ranks) == 24);
    assert!(offset_of!(LentStar, cursor) + offset_of!(StarCursor, start) == 32);
    assert!(offset_of!(LentStar, cursor) + offset_of!(StarCursor, cur) == 36);
    assert!(offset_of!(LentStar, cursor) + offset_of!(StarCursor, tail) == 40);
    assert!(offset_of!(LentStar, cur_opposite) == 44);
    assert!(size_of::<LentStep>() == 16);
    assert!(offset_of!(LentStep, half_edge) == 0);
    assert!(offset_of!(LentStep, vertex) == 4);
    assert!(offset_of!(LentStep, edge) == 8);
    assert!(offset_of!(LentStep, triangle) == 12);
};

impl Che {
    /// The lent rotation around `v` (checked).
    pub fn lent_star(&self, v: u32) -> Result<LentStar> {
        self.check_vertex(v)?;
        let start = self.vertex_half_edge(v);
        // The arrays are lent to the inline step from level 2 only, and not on an edited
        // mesh before garbage collection: its edge ids are not ranks then.
        let inline = self.level() >= 2 && self.edge_ranks().is_some();
        fn lent<T>(a: Option<&[T]>, inline: bool) -> *const T {
            a.filter(|_| inline).map_or(ptr::null(), <[T]>::as_ptr)
        }
        let cur_opposite = if start == NONE {
            NONE
        } else {
            self.opposite(start)
        };
        Ok(LentStar {
            che: self,
            v: lent(Some(self.half_edge_vertices()), inline),
            o: lent(self.opposites(), inline),
            edge_ranks: lent(self.edge_ranks(), inline),
            cursor: StarCursor::new(start),
            cur_opposite,
        })
    }
}

impl LentStar {
    /// One step of the core's rotation over `che` (the structure it was begun on).
    pub fn advance(&mut self, che: &Che) -> Option<LentStep> {
        let step = self.cursor.step(|p| che.opposite(p))?;
        let (half_edge, edge) = (step.half_edge(), che.edge_of(step.half_edge()));
        Some(match step {
            StarStep::Out(h) => {
                if self.cursor.cur != NONE {
                    self.cur_opposite = prev(h);
                }
                let (vertex, triangle) = (che.target(h), tri(h));
                LentStep {
                    half_edge,
                    vertex,
                    edge,
                    triangle,
                }
            }
            StarStep::LastIn(h) => {
                let vertex = che.origin(h);
                LentStep {
                    half_edge,
                    vertex,
                    edge,
                    triangle: NONE,
                }
            }
        })
    }
}
