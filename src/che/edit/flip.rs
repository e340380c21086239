//! Flipping an interior edge: the diagonal of the quad of its two triangles turns.

use super::arrays::{replace_vh, set_v};
use super::checks::refuse;
use crate::che::ids::{next, prev};
use crate::che::{Che, Checked};
use crate::error::Result;
use crate::util::prefetch::prefetch;

impl Che {
    /// Flips edge `e` between triangles `(a, b, c)` and `(b, a, d)` into `c-d`; the edge
    /// keeps its id, the triangles theirs. Refused on a boundary (or non-manifold) edge,
    /// and when `c-d` is an edge already (or `c == d`).
    pub fn flip_edge(&mut self, e: u32) -> Result<()> {
        self.edit_with(|m| {
            let h = m.live_edge(e)?;
            // Right after `is_flip_ok(e)` said yes, nothing has changed since (every other
            // check and every edit clears the mark).
            let checked = m.checked == Checked::Flip(e);
            debug_assert!(!checked || m.flip_refusal(h).is_none());
            if !checked && let Some(why) = m.flip_refusal(h) {
                return refuse(format!("flip_edge: {}", why.words(e)));
            }
            m.flip_live(h);
            Ok(())
        })
    }

    /// Starts fetching what flipping the edge of `h` and `g` writes, besides the two
    /// triangles: `VH` of the four corners, `O` of the two outer neighbours it relinks and
    /// the edge ids of both triangles. Called by the check, whose walk around `c` takes a
    /// few memory latencies of its own: on a large mesh these lines are scattered, and a
    /// flip that follows its check (a storm, `is_flip_ok` then `flip_edge`) finds them in
    /// the cache rather than waiting for them after the walk.
    pub(super) fn touch_flip(&self, h: u32, g: u32) {
        let (v, o) = (&*self.v, &*self.o);
        for x in [h, next(h), prev(h), prev(g)] {
            prefetch(&self.vh, v[x as usize] as usize);
        }
        for x in [o[prev(h) as usize], o[prev(g) as usize]] {
            prefetch(o, x as usize);
        }
        if let Some(st) = self.edits() {
            prefetch(&st.edge_of, h as usize);
            prefetch(&st.edge_of, g as usize);
        }
    }

    /// Triangle `(a, b, c)` on slots `h, h1, h2` becomes `(d, b, c)`, `(b, a, d)` on
    /// `g, g1, g2` becomes `(c, a, d)`: the diagonal is `h2 <-> g2`, the outer half-edges
    /// `c -> a` and `d -> b` move to slots `g` and `h`.
    fn flip_live(&mut self, h: u32) {
        let g = self.o[h as usize];
        let (h1, h2, g1, g2) = (next(h), prev(h), next(g), prev(g));
        let (c, d) = (self.v[h2 as usize], self.v[g2 as usize]);
        let (oh2, og2) = (self.o[h2 as usize], self.o[g2 as usize]);
        let (e, e_ca, e_db) = (self.edge_id(h), self.edge_id(h2), self.edge_id(g2));
        self.move_flags(h2, g);
        self.move_flags(g2, h);
        set_v(self, h, d);
        set_v(self, g, c);
        self.link(g, oh2);
        self.link(h, og2);
        self.link(h2, g2);
        self.name_edge(g, e_ca);
        self.name_edge(h, e_db);
        self.name_edge(h2, e);
        // A flip changes no vertex's boundary: only a `VH` on a half-edge that left its
        // vertex (`a -> b`, `b -> a`) or on an outer one that moved (`c -> a`, `d -> b`)
        // changes, to one of the same kind, without walking the stars.
        let a = self.v[g1 as usize];
        let b = self.v[h1 as usize];
        for (x, was, now) in [(a, h, g1), (b, g, h1), (c, h2, g), (d, g2, h)] {
            replace_vh(self, x, was, now);
        }
    }
}
