//! Collapsing an edge: its target merges into its origin, its one or two triangles go.

use super::arrays::{o_mut, positions_mut, v_mut, vh_mut};
use super::checks::refuse;
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev, tri};
use crate::error::Result;
use glam::DVec3;

impl Che {
    /// Collapses half-edge `h = a -> b`: `b` merges into `a` (returned; `b` is removed and
    /// `a` keeps its position), the triangles of the edge are removed, and the two other
    /// edges of each become one (keeping the id of the edge at `a`). Refused, with the
    /// reason, when the link condition fails (see [`Che::is_collapse_ok`]).
    pub fn collapse_edge(&mut self, h: u32) -> Result<u32> {
        self.edit_with(|m| {
            m.live_half_edge(h)?;
            if let Some(why) = m.collapse_refusal(h) {
                return refuse(format!("collapse_edge: {why}"));
            }
            Ok(m.collapse_live(h))
        })
    }

    /// The ends `a -> b` of half-edge `h` and the wings a collapse of `h` removes: `h`, and
    /// its opposite when it has one.
    pub(super) fn collapse_wings(&self, h: u32) -> (u32, u32, Vec<u32>) {
        let (a, b, g) = (
            self.v[h as usize],
            self.v[next(h) as usize],
            self.o[h as usize],
        );
        let mut wings = vec![h];
        if g != NONE {
            wings.push(g);
        }
        (a, b, wings)
    }

    fn collapse_live(&mut self, h: u32) -> u32 {
        let (a, b, wings) = self.collapse_wings(h);
        // Per wing w: its third vertex z, and the outer half-edges across its edge at `b`
        // (whose id goes) and at `a` (whose id stays).
        let outer: Vec<(u32, u32, u32)> = wings
            .iter()
            .map(|&w| {
                let (at_b, at_a) = if w == h {
                    (next(w), prev(w))
                } else {
                    (prev(w), next(w))
                };
                let z = self.v[prev(w) as usize];
                (z, self.o[at_b as usize], self.o[at_a as usize])
            })
            .collect();
        for x in self.outgoing(b) {
            if !wings.contains(&x) && !wings.contains(&prev(x)) {
                v_mut(self)[x as usize] = a;
            }
        }
        for &w in &wings {
            self.unlink_triangle(tri(w));
        }
        let mut candidates = Vec::new();
        for &(z, gone, keep) in &outer {
            self.merge(gone, keep);
            // Half-edges leaving z or a around the merged edge.
            let near: Vec<u32> = [gone, keep]
                .into_iter()
                .filter(|&s| s != NONE)
                .flat_map(|s| [s, next(s)])
                .collect();
            let out_z = near.iter().copied().find(|&s| self.v[s as usize] == z);
            self.fix_vh(z, out_z.unwrap_or(NONE));
            candidates.extend(near);
        }
        let out_a = candidates
            .into_iter()
            .find(|&s| s != NONE && self.v[s as usize] == a);
        self.fix_vh(a, out_a.unwrap_or(NONE));
        vh_mut(self)[b as usize] = NONE;
        let st = self.st_mut();
        st.removed_vertex[b as usize] = true;
        st.live_vertices -= 1;
        a
    }

    /// Pairs `p` and `q`, left unpaired by their removed triangle, into one edge (`q`'s id).
    fn merge(&mut self, p: u32, q: u32) {
        if p == NONE || q == NONE {
            return;
        }
        let (keep, gone) = (self.edge_id(q), self.edge_id(p));
        o_mut(self)[p as usize] = q;
        o_mut(self)[q as usize] = p;
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
