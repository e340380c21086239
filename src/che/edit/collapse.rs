//! Collapsing an edge: its target merges into its origin, its one or two triangles go.

use super::arrays::{positions_mut, set_o, set_v, vh_mut};
use super::checks::refuse;
use crate::NONE;
use crate::che::ids::{next, prev, tri};
use crate::che::{Che, Checked};
use crate::error::Result;
use crate::util::small_ids::Ids;
use glam::DVec3;

impl Che {
    /// Collapses half-edge `h = a -> b`: `b` merges into `a` (returned; `b` is removed and
    /// `a` keeps its position), the triangles of the edge are removed, and the two other
    /// edges of each become one (keeping the id of the edge at `a`). Refused, with the
    /// reason, when the link condition fails (see [`Che::is_collapse_ok`]).
    pub fn collapse_edge(&mut self, h: u32) -> Result<u32> {
        self.edit_with(|m| {
            m.live_half_edge(h)?;
            // Right after `is_collapse_ok(h)` said yes, nothing has changed since (as for
            // `flip_edge`): the link condition is not walked again. (Asked again, it may
            // run out of memory at a hub, but never refuse.)
            let checked = m.checked == Checked::Collapse(h);
            debug_assert!(!checked || !matches!(m.collapse_refusal(h), Ok(Some(_))));
            if !checked && let Some(why) = m.collapse_refusal(h)? {
                return refuse(format!("collapse_edge: {why}"));
            }
            Ok(m.collapse_live(h))
        })
    }

    /// The ends `a -> b` of half-edge `h` and the wings a collapse of `h` removes: `h`, and
    /// its opposite when it has one.
    pub(super) fn collapse_wings(&self, h: u32) -> (u32, u32, Ids<2>) {
        let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
        (a, b, Ids::both_sides(h, self.o[h as usize], |w| w))
    }

    fn collapse_live(&mut self, h: u32) -> u32 {
        let (a, b, wings) = self.collapse_wings(h);
        // Whether a vertex is interior, read before the collapse: one the checks allow keeps
        // an interior third vertex interior, and `a` interior when both ends were, so
        // those take their new `VH` without the walk to a boundary half-edge.
        let interior = |c: &Self, x: u32| c.o[c.vh[x as usize] as usize] != NONE;
        let ends_interior = interior(self, a) && interior(self, b);
        // Per wing w: its third vertex z, and the outer half-edges across its edge at `b`
        // (whose id goes) and at `a` (whose id stays).
        let mut outer = [(NONE, NONE, NONE); 2];
        let mut z_interior = [false; 2];
        for (k, &w) in wings.iter().enumerate() {
            let (at_b, at_a) = if w == h {
                (next(w), prev(w))
            } else {
                (prev(w), next(w))
            };
            let z = self.v[prev(w) as usize];
            outer[k] = (z, self.o[at_b as usize], self.o[at_a as usize]);
            z_interior[k] = interior(self, z);
        }
        let start = self.vh[b as usize];
        let mut x = start;
        while x != NONE {
            let following = self.next_outgoing(start, x);
            if !wings.contains(&x) && !wings.contains(&prev(x)) {
                set_v(self, x, a);
            }
            x = following;
        }
        for &w in wings.iter() {
            self.unlink_triangle(tri(w));
        }
        // Half-edges leaving z or a around each merged edge: `s` and `next(s)` per side.
        let mut near = [NONE; 8];
        for (k, &(z, gone, keep)) in outer[..wings.len()].iter().enumerate() {
            self.merge(gone, keep);
            for (i, s) in [gone, keep].into_iter().enumerate() {
                if s != NONE {
                    near[4 * k + 2 * i..4 * k + 2 * i + 2].copy_from_slice(&[s, next(s)]);
                }
            }
            let out_z = self.leaving(&near[4 * k..4 * k + 4], z);
            self.set_vh(z, out_z, z_interior[k]);
        }
        let out_a = self.leaving(&near, a);
        self.set_vh(a, out_a, ends_interior);
        vh_mut(self)[b as usize] = NONE;
        let st = self.st_mut();
        st.removed_vertex.set(b as usize);
        st.live_vertices -= 1;
        a
    }

    /// The first of `candidates` (`NONE` entries skipped) leaving vertex `x`, else `NONE`.
    fn leaving(&self, candidates: &[u32], x: u32) -> u32 {
        let leaves = |&s: &u32| s != NONE && self.v[s as usize] == x;
        candidates.iter().copied().find(leaves).unwrap_or(NONE)
    }

    /// Pairs `p` and `q`, left unpaired by their removed triangle, into one edge (`q`'s id).
    fn merge(&mut self, p: u32, q: u32) {
        if p == NONE || q == NONE {
            return;
        }
        let (keep, gone) = (self.edge_id(q), self.edge_id(p));
        set_o(self, p, q);
        set_o(self, q, p);
        self.drop_edge(gone);
        self.name_edge(q, keep);
    }

    /// Moves vertex `x` to `p`.
    pub fn set_position(&mut self, x: u32, p: DVec3) -> Result<()> {
        self.check_vertex(x)?;
        if self.positions.is_empty() {
            return refuse("set_position: the mesh has no positions".into());
        }
        positions_mut(self)[x as usize] = p;
        Ok(())
    }
}
