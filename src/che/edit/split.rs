//! Splitting an edge (2 triangles into 4, or 1 into 2 on the boundary) and a triangle
//! (1 into 3) at a new vertex.

use super::arrays::{replace_vh, set_v, vh_mut};
use super::checks::refuse;
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{first, next, prev, tri};
use crate::error::{Error, Result};
use glam::DVec3;

impl Che {
    /// Splits edge `e` at a new vertex `m` (returned): `position`, or the midpoint when
    /// the mesh has positions. Its half `a-m` keeps the id `e`; the triangles keep theirs
    /// as `(a, m, c)` and `(m, a, d)`, the new ones `(m, b, c)` and `(b, m, d)` take the
    /// origins of the triangles they come from. Refused on a non-manifold or seam edge.
    pub fn split_edge(&mut self, e: u32, position: Option<DVec3>) -> Result<u32> {
        self.edit_with(|m| {
            let h = m.live_edge(e)?;
            if m.is_flagged(h) {
                return refuse(format!("split_edge: edge {e} is non-manifold or a seam"));
            }
            let g = m.o[h as usize];
            if g != NONE && m.v[prev(h) as usize] == m.v[prev(g) as usize] {
                return refuse(format!(
                    "split_edge: both triangles of edge {e} have the same third vertex"
                ));
            }
            m.room_for_split()?;
            let p = position.or_else(|| {
                let [a, b] = [m.v[h as usize], m.v[next(h) as usize]];
                Some((m.position_of(a)? + m.position_of(b)?) / 2.0)
            });
            Ok(m.split_live(h, p))
        })
    }

    fn room_for_split(&mut self) -> Result<()> {
        if (self.num_triangles() + 2) * 3 >= NONE as usize || self.n_vertices + 1 >= NONE as usize {
            return Err(Error::too_large("split: no id left"));
        }
        self.make_room(2, 1, 3)
    }

    /// [`Che::split_edge`] after the checks (room made).
    fn split_live(&mut self, h: u32, p: Option<DVec3>) -> u32 {
        let g = self.o[h as usize];
        let (h1, h2) = (next(h), prev(h));
        let (b, c) = (self.v[h1 as usize], self.v[h2 as usize]);
        let m = self.push_vertex(p, NONE);
        let t3 = first(self.push_triangle([m, b, c], self.triangle_origin.get(tri(h))));
        self.hand_over(h1, t3 + 1);
        set_v(self, h1, m);
        self.link_new(h1, t3 + 2);
        // No old vertex changes its boundary, so a `VH` changes only where its half-edge
        // changed: `b -> c` and `b -> a` now leave `m`, and `d -> b` now ends at `m`; each
        // is replaced by the new half-edge that took its place. `m` leaves by `m -> b` on
        // the boundary.
        replace_vh(self, b, h1, t3 + 1);
        let mut m_out = h1;
        if g == NONE {
            self.name_edge(t3, NONE);
            m_out = t3;
        } else {
            let g2 = prev(g);
            let d = self.v[g2 as usize];
            let t4 = first(self.push_triangle([b, m, d], self.triangle_origin.get(tri(g))));
            self.hand_over(g2, t4 + 2);
            set_v(self, g, m);
            self.link_new(g2, t4 + 1);
            self.link_new(t3, t4);
            replace_vh(self, b, g, t4);
            replace_vh(self, d, g2, t4 + 2);
        }
        vh_mut(self)[m as usize] = m_out;
        m
    }

    /// Splits triangle `t` at a new vertex `m` (returned; `position`, or the centroid when
    /// the mesh has positions) into `(a, b, m)` (keeping the id `t`), `(b, c, m)` and
    /// `(c, a, m)` (new ids, the origin of `t`).
    pub fn split_triangle(&mut self, t: u32, position: Option<DVec3>) -> Result<u32> {
        self.edit_with(|m| {
            m.live_triangle(t)?;
            m.room_for_split()?;
            let p = position.or_else(|| {
                let [a, b, c] = m.triangle_vertices(t).map(|x| m.position_of(x));
                Some((a? + b? + c?) / 3.0)
            });
            Ok(m.split_triangle_live(t, p))
        })
    }

    fn split_triangle_live(&mut self, t: u32, p: Option<DVec3>) -> u32 {
        let (h0, h1, h2) = (first(t), first(t) + 1, first(t) + 2);
        let [a, b, c] = self.triangle_vertices(t);
        let x = self.push_vertex(p, NONE);
        let origin = self.triangle_origin.get(t);
        let p0 = first(self.push_triangle([b, c, x], origin));
        let q0 = first(self.push_triangle([c, a, x], origin));
        self.hand_over(h1, p0);
        self.hand_over(h2, q0);
        set_v(self, h2, x);
        for (u, w) in [(h1, p0 + 2), (h2, q0 + 1), (p0 + 1, q0 + 2)] {
            self.link_new(u, w);
        }
        for (y, out) in [(a, h0), (b, p0), (c, q0), (x, h2)] {
            self.fix_vh(y, out);
        }
        x
    }
}
