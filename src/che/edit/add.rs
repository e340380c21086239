//! Adding a vertex, and a triangle that pairs with the boundary half-edges it meets.

use super::checks::refuse;
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{first, next, prev};
use crate::error::{Error, Result};
use glam::DVec3;

impl Che {
    /// A new isolated vertex. `position` is required when the mesh has positions and
    /// refused when it has none.
    pub fn add_vertex(&mut self, position: Option<DVec3>) -> Result<u32> {
        match (self.positions.is_empty(), position) {
            (false, None) => return refuse("add_vertex: the mesh has positions, give one".into()),
            (true, Some(_)) => {
                return refuse("add_vertex: the mesh has no positions, give none".into());
            }
            _ => {}
        }
        if self.n_vertices >= NONE as usize - 1 {
            return Err(Error::too_large("add_vertex: no vertex id left"));
        }
        self.edit_with(|c| {
            c.make_room(0, 1, 0)?;
            Ok(c.push_vertex(position, NONE))
        })
    }

    /// Adds triangle `(a, b, c)` (counter-clockwise) and pairs each of its edges with the
    /// boundary half-edge running the other way, if any. Refused, naming the edge or the
    /// vertex, when an edge already has a triangle on the same side (orientation), is not a
    /// boundary edge (it would become non-manifold), or is flagged non-manifold or seam,
    /// and when a corner would get a second fan (a non-manifold vertex).
    pub fn add_triangle(&mut self, a: u32, b: u32, c: u32) -> Result<u32> {
        self.edit_with(|m| {
            let corners = [a, b, c];
            for x in corners {
                m.live_vertex(x)?;
            }
            if a == b || b == c || a == c {
                return refuse(format!("triangle ({a}, {b}, {c}) is degenerate"));
            }
            if (m.num_triangles() + 1) * 3 >= NONE as usize {
                return Err(Error::too_large("add_triangle: no half-edge id left"));
            }
            if let Some(t) = m.triangle_on(a, b, c) {
                return refuse(format!("triangle ({a}, {b}, {c}) duplicates triangle {t}"));
            }
            let mut across = [NONE; 3];
            for i in 0..3 {
                across[i] = m.partner(corners[i], corners[(i + 1) % 3])?;
            }
            for i in 0..3 {
                let (x, incoming, outgoing) = (corners[i], across[(i + 2) % 3], across[i]);
                m.check_fan(x, incoming, outgoing)?;
            }
            m.make_room(1, 0, 3)?;
            let t = m.push_triangle(corners, NONE);
            for (i, &g) in across.iter().enumerate() {
                let h = first(t) + i as u32;
                let e = if g == NONE { NONE } else { m.edge_id(g) };
                m.link(h, g);
                m.name_edge(h, e);
            }
            for (i, &x) in corners.iter().enumerate() {
                m.fix_vh(x, first(t) + i as u32);
            }
            Ok(t)
        })
    }

    /// A live triangle on the vertices `a`, `b`, `c` (either orientation), if any.
    fn triangle_on(&self, a: u32, b: u32, c: u32) -> Option<u32> {
        self.outgoing(a)
            .into_iter()
            .map(crate::che::ids::tri)
            .find(|&t| {
                let [x, y, z] = self.triangle_vertices(t);
                [x, y, z].contains(&b) && [x, y, z].contains(&c)
            })
    }

    /// The boundary half-edge `b -> a` a new half-edge `a -> b` pairs with (`NONE`: none),
    /// or the refusal.
    fn partner(&self, a: u32, b: u32) -> Result<u32> {
        let mut found = NONE;
        for h in self.outgoing(a) {
            if self.v[next(h) as usize] == b {
                return refuse(format!(
                    "edge {a}-{b} already has a triangle on this side (orientation)"
                ));
            }
            let p = prev(h);
            if self.v[p as usize] == b {
                found = p;
            }
        }
        if found != NONE && (self.o[found as usize] != NONE || self.is_flagged(found)) {
            return refuse(format!("edge {a}-{b} would become non-manifold"));
        }
        Ok(found)
    }

    /// A new triangle at `x` must extend the one fan of `x` (or start it, on an isolated
    /// vertex): `incoming`, the half-edge its incoming edge pairs with, must leave `x` at
    /// the fan's start, or `outgoing`'s partner end there at its end.
    fn check_fan(&self, x: u32, incoming: u32, outgoing: u32) -> Result<()> {
        let s = self.vh[x as usize];
        if s == NONE || incoming != NONE || outgoing != NONE {
            return Ok(());
        }
        refuse(format!(
            "vertex {x} would become non-manifold (a second fan)"
        ))
    }
}
