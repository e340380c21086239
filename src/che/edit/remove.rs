//! Removing a triangle, and a vertex with its star. The ids are marked, not reused.

use super::arrays::{set_o, set_v, vh_mut};
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{first, next, prev};
use crate::error::Result;
use crate::util::alloc::try_with_capacity;

impl Che {
    /// Removes triangle `t`: its half-edges get `V = O = NONE`, its edges that no other
    /// triangle holds are removed, its corners keep their other triangles. A corner whose
    /// triangles fall into two fans is split (the second fan moves to a new vertex, as the
    /// build splits such a vertex); a corner left without triangles stays, isolated.
    pub fn remove_triangle(&mut self, t: u32) -> Result<()> {
        self.edit_with(|c| {
            c.live_triangle(t)?;
            c.make_room(0, 3, 0)?;
            c.remove_live_triangle(t);
            Ok(())
        })
    }

    /// Removes vertex `x` and every triangle around it; its neighbours stay (split as in
    /// [`Che::remove_triangle`] where needed).
    pub fn remove_vertex(&mut self, x: u32) -> Result<()> {
        self.edit_with(|c| {
            c.live_vertex(x)?;
            let outs = c.outgoing(x)?;
            c.make_room(0, outs.len() + 1, 0)?;
            // All the star goes first, then each neighbour settles once: removing the
            // triangles one at a time could split a neighbour into a copy left isolated.
            let ring = c.ring(&outs)?;
            // The neighbours' outgoing half-edges before, one list after another.
            let (mut ring_outs, mut ends) =
                (Vec::new(), try_with_capacity(ring.len(), "the ring")?);
            for &y in &ring {
                c.outgoing_into(y, &mut ring_outs)?;
                ends.push(ring_outs.len());
            }
            for &h in &outs {
                c.unlink_triangle(crate::che::ids::tri(h));
            }
            let mut from = 0;
            for (&y, &end) in ring.iter().zip(&ends) {
                c.settle(y, &ring_outs[from..end]);
                from = end;
            }
            vh_mut(c)[x as usize] = NONE;
            let st = c.st_mut();
            st.removed_vertex.set(x as usize);
            st.live_vertices -= 1;
            Ok(())
        })
    }

    /// The other vertices of the triangles of the outgoing half-edges `outs` of a vertex,
    /// increasing.
    fn ring(&self, outs: &[u32]) -> Result<Vec<u32>> {
        let mut ring = try_with_capacity(outs.len() + 1, "the ring")?;
        ring.extend(outs.iter().map(|&h| self.v[next(h) as usize]));
        ring.extend(outs.last().map(|&last| self.v[prev(last) as usize]));
        ring.sort_unstable();
        ring.dedup();
        Ok(ring)
    }

    /// [`Che::remove_triangle`] after the checks, room made for 3 vertex copies.
    pub(super) fn remove_live_triangle(&mut self, t: u32) {
        let corners: [Corner; 3] = std::array::from_fn(|i| self.corner(first(t) + i as u32));
        self.unlink_triangle(t);
        for c in corners {
            self.settle_corner(c);
        }
    }

    /// Where the outgoing half-edge `h` lies in its vertex's rotation.
    fn corner(&self, h: u32) -> Corner {
        let x = self.v[h as usize];
        let start = self.vh[x as usize];
        Corner {
            x,
            h,
            start,
            after: self.o[prev(h) as usize],
            on_boundary: self.o[start as usize] == NONE,
        }
    }

    /// `VH` of corner `c` once its triangle is gone, from where the triangle lay in the
    /// rotation, without walking it: the half-edge after the triangle (when there is
    /// one) now starts a fan, and the old start still starts one when it was on the
    /// boundary and not the triangle's. Two fans (the triangle lay inside a boundary fan):
    /// the second moves to a copy of the vertex, as `settle` does.
    fn settle_corner(&mut self, c: Corner) {
        let old_start_kept = c.on_boundary && c.start != c.h;
        match (old_start_kept, c.after) {
            (false, after) => vh_mut(self)[c.x as usize] = after,
            (true, NONE) => {}
            (true, after) => self.move_fan(c.x, after),
        }
    }
    /// Marks triangle `t` removed: its edges stay with the opposite half-edges, or go.
    pub(super) fn unlink_triangle(&mut self, t: u32) {
        for h in first(t)..first(t) + 3 {
            let g = self.o[h as usize];
            let e = self.edge_id(h);
            if g == NONE {
                self.drop_edge(e);
            } else {
                set_o(self, g, NONE);
                self.note_unpaired(g);
                self.name_edge(g, e);
            }
            set_o(self, h, NONE);
            self.unflag(h);
        }
        for h in first(t)..first(t) + 3 {
            set_v(self, h, NONE);
            if self.level >= 2 {
                self.st_mut().edge_of[h as usize] = NONE;
            }
        }
        self.st_mut().live_triangles -= 1;
    }
}

/// An outgoing half-edge of a triangle about to be removed, and its place in the rotation
/// of its vertex `x`: the rotation's start (`VH[x]`), whether `x` is on the boundary, and
/// the outgoing half-edge after `h` (`O[prev(h)]`, `NONE` at the end of a boundary fan).
#[derive(Clone, Copy)]
struct Corner {
    x: u32,
    h: u32,
    start: u32,
    after: u32,
    on_boundary: bool,
}
