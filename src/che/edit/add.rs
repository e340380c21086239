//! Adding a vertex, and a triangle that pairs with the boundary half-edges it meets: on a
//! strict CHE refused where the surface would need a repair, on a non-strict one repaired
//! as the build repairs its input (`add_repair.rs`).

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
    /// boundary half-edge running the other way, if any, and returns its id. Refused, with
    /// the reason, for a removed or out-of-range vertex and a degenerate triangle (the
    /// build drops those).
    ///
    /// On a CHE built strict ([`Che::is_strict`]) it is also refused, naming the edge or
    /// the vertex, when it duplicates a triangle, when an edge already has a triangle on
    /// the same side (orientation), is not a boundary edge (it would become non-manifold)
    /// or is flagged non-manifold or seam, and when a corner would get a second fan (a
    /// non-manifold vertex).
    ///
    /// On a CHE built non-strict (the default) those cases are repaired by the build's
    /// rules, so that the result is the structure a fresh non-strict build of the live
    /// triangles gives, and counted in [`Che::report`]: a triangle against its
    /// neighbours' orientation is flipped; an edge that would carry three or more
    /// triangles is non-manifold, its half-edges unpaired and flagged, and a corner whose
    /// triangles then form several fans is split, each fan but the one of its smallest
    /// half-edge moving to a new vertex (so the returned triangle's corners may be new
    /// vertices, see [`Che::triangle_vertices`]); the half-edges the split leaves on one
    /// vertex pair are then paired again, as a rebuild pairs them; a duplicate is kept.
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
            if m.strict {
                m.add_strict(corners)
            } else {
                m.add_repaired(corners)
            }
        })
    }

    /// [`Che::add_triangle`] on a strict CHE, after the checks every CHE makes.
    fn add_strict(&mut self, corners: [u32; 3]) -> Result<u32> {
        let [a, b, c] = corners;
        if let Some(t) = self.triangle_on(a, b, c) {
            return refuse(format!("triangle ({a}, {b}, {c}) duplicates triangle {t}"));
        }
        let mut across = [NONE; 3];
        for i in 0..3 {
            across[i] = self.partner(corners[i], corners[(i + 1) % 3])?;
        }
        for i in 0..3 {
            let (x, incoming, outgoing) = (corners[i], across[(i + 2) % 3], across[i]);
            self.check_fan(x, incoming, outgoing)?;
        }
        self.make_room(1, 0, 3)?;
        let t = self.push_triangle(corners, NONE);
        for (i, &g) in across.iter().enumerate() {
            let h = first(t) + i as u32;
            let e = if g == NONE { NONE } else { self.edge_id(g) };
            self.link(h, g);
            self.name_edge(h, e);
        }
        for (i, &x) in corners.iter().enumerate() {
            self.fix_vh(x, first(t) + i as u32);
        }
        Ok(t)
    }

    /// A live triangle on the vertices `a`, `b`, `c` (either orientation), if any.
    pub(super) fn triangle_on(&self, a: u32, b: u32, c: u32) -> Option<u32> {
        let mut found = None;
        self.any_outgoing(a, |h| {
            let t = crate::che::ids::tri(h);
            let corners = self.triangle_vertices(t);
            let on = corners.contains(&b) && corners.contains(&c);
            if on {
                found = Some(t);
            }
            on
        });
        found
    }

    /// The boundary half-edge `b -> a` a new half-edge `a -> b` pairs with (`NONE`: none),
    /// or the refusal.
    fn partner(&self, a: u32, b: u32) -> Result<u32> {
        let mut found = NONE;
        let same_side = self.any_outgoing(a, |h| {
            if self.v[prev(h) as usize] == b {
                found = prev(h);
            }
            self.v[next(h) as usize] == b
        });
        if same_side {
            return refuse(format!(
                "edge {a}-{b} already has a triangle on this side (orientation)"
            ));
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
