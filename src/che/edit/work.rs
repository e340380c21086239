//! The steps every operation is made of, on the working tables (`V`, `O`, `VH` at every
//! level during an edit; edge ids from level 2): pairing, naming edges, finding and
//! settling the star of a vertex, making room before the first write.

use super::arrays::{
    eh_mut, non_manifold_mut, o_mut, positions_mut, seams_mut, set_o, set_v, touch_edge_ranks,
    triangle_origin_mut, v_mut, vertex_origin_mut, vh_mut,
};
use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev};
use crate::error::Result;
use crate::util::alloc::{try_grow, try_push};
use glam::DVec3;

impl Che {
    /// Pairs `h` with `g` (`g == NONE`: `h` becomes a boundary half-edge).
    pub(super) fn link(&mut self, h: u32, g: u32) {
        set_o(self, h, g);
        if g != NONE {
            set_o(self, g, h);
        } else {
            self.note_unpaired(h);
        }
    }

    /// `old`'s place goes to `new`: its opposite, edge id and flags.
    pub(super) fn hand_over(&mut self, old: u32, new: u32) {
        let (o, e) = (self.o[old as usize], self.edge_id(old));
        self.move_flags(old, new);
        self.link(new, o);
        self.name_edge(new, e);
    }

    /// Links `h` and `g` across a new edge.
    pub(super) fn link_new(&mut self, h: u32, g: u32) {
        self.link(h, g);
        self.name_edge(h, NONE);
    }

    /// The edge id of live `h` from level 2. Below, ids are ranks and an edit names no
    /// edge: any id but `NONE` (which [`Che::name_edge`] reads as a new edge).
    pub(super) fn edge_id(&self, h: u32) -> u32 {
        if self.level >= 2 {
            self.st().edge_of[h as usize]
        } else {
            0
        }
    }

    /// Names `h` and its opposite edge `e` (`NONE`: a new edge), keeping `EH` canonical.
    pub(super) fn name_edge(&mut self, h: u32, e: u32) {
        if e == NONE {
            self.st_mut().live_edges += 1;
        }
        if self.level < 2 {
            return;
        }
        let g = self.o[h as usize];
        let e = if e == NONE {
            eh_mut(self).push(NONE);
            (self.eh.len() - 1) as u32
        } else {
            e
        };
        let canonical = crate::che::tables::canonical_half_edge(&self.o, h);
        let st = self.st_mut();
        st.edge_of[h as usize] = e;
        if g != NONE {
            st.edge_of[g as usize] = e;
        }
        eh_mut(self)[e as usize] = canonical;
    }

    /// Edge `e` is gone.
    pub(super) fn drop_edge(&mut self, e: u32) {
        self.st_mut().live_edges -= 1;
        if self.level >= 2 {
            eh_mut(self)[e as usize] = NONE;
        }
    }

    /// The outgoing half-edges of `x` in rotation order (from `VH`), appended to `out`.
    pub(super) fn outgoing_into(&self, x: u32, out: &mut Vec<u32>) -> Result<()> {
        let mut grown = Ok(());
        self.any_outgoing(x, |h| {
            grown = try_push(out, h, "the star of a vertex");
            grown.is_err()
        });
        grown
    }

    /// The outgoing half-edges of `x` in rotation order (from `VH`).
    pub(super) fn outgoing(&self, x: u32) -> Result<Vec<u32>> {
        let mut out = Vec::new();
        self.outgoing_into(x, &mut out)?;
        Ok(out)
    }

    /// The outgoing half-edge after `h` in the rotation that starts at `start` (`VH`), or
    /// `NONE` at its end: what `any_outgoing` steps by, for a walk that edits as it goes.
    pub(super) fn next_outgoing(&self, start: u32, h: u32) -> u32 {
        let g = self.o[prev(h) as usize];
        if g == start { NONE } else { g }
    }

    /// Walks the outgoing half-edges of `x` in rotation order (from `VH`) until `stop` says
    /// so, without allocating (the checks run once per flip or collapse); true if it did.
    pub(super) fn any_outgoing(&self, x: u32, mut stop: impl FnMut(u32) -> bool) -> bool {
        let start = self.vh[x as usize];
        let mut h = start;
        while h != NONE {
            if stop(h) {
                return true;
            }
            h = self.next_outgoing(start, h);
        }
        false
    }

    /// Sets `VH[x]` from `out`, a live outgoing half-edge of `x` (`NONE`: isolated): the
    /// boundary one reached clockwise, else `out`.
    pub(super) fn fix_vh(&mut self, x: u32, out: u32) {
        let mut h = out;
        if h != NONE {
            loop {
                let g = self.o[h as usize];
                if g == NONE || next(g) == out {
                    break;
                }
                h = next(g);
            }
        }
        vh_mut(self)[x as usize] = h;
    }

    /// `fix_vh` for a vertex known to be interior or not: an interior one takes `out` as it
    /// is, without the walk.
    pub(super) fn set_vh(&mut self, x: u32, out: u32, interior: bool) {
        if interior {
            vh_mut(self)[x as usize] = out;
        } else {
            self.fix_vh(x, out);
        }
    }

    /// After triangles around `x` were removed: `outs` held its outgoing half-edges before.
    /// Each fan but the first moves to a new copy of `x` (the build splits a vertex whose
    /// triangles form several fans the same way), so every vertex keeps one rotation.
    pub(super) fn settle(&mut self, x: u32, outs: &[u32]) {
        // A fan starts at an unpaired outgoing half-edge (the rotation's first). Moving
        // one fan rewrites the vertex of its own half-edges only, none of them a start.
        let is_start = |c: &Che, h: u32| c.v[h as usize] == x && c.o[h as usize] == NONE;
        if outs.iter().filter(|&&h| is_start(self, h)).count() <= 1 {
            let live = outs.iter().copied().find(|&h| self.v[h as usize] == x);
            self.fix_vh(x, live.unwrap_or(NONE));
            return;
        }
        let mut first = true;
        for &h in outs {
            if !is_start(self, h) {
                continue;
            }
            if first {
                vh_mut(self)[x as usize] = h;
                first = false;
            } else {
                self.move_fan(x, h);
            }
        }
    }

    /// Moves the boundary fan of `x` that starts at `s` to a new copy of `x` (room made
    /// for it), as the build splits a vertex whose triangles form several fans.
    pub(super) fn move_fan(&mut self, x: u32, s: u32) {
        let copy = self.push_vertex(self.position_of(x), self.vertex_origin.get(x));
        let mut h = s;
        loop {
            set_v(self, h, copy);
            let g = self.o[prev(h) as usize];
            if g == NONE {
                break;
            }
            h = g;
        }
        vh_mut(self)[copy as usize] = s;
    }

    pub(super) fn position_of(&self, x: u32) -> Option<DVec3> {
        self.positions.get(x as usize).copied()
    }

    /// Room for `t` triangles, `n` vertices and `e` edges more, so that the writes after
    /// it cannot fail half-way; grown by amortised steps, since an edit appends a few
    /// elements at a time and exact growth would move every array on every edit.
    pub(super) fn make_room(&mut self, t: usize, n: usize, e: usize) -> Result<()> {
        let h = 3 * t;
        let (nv, nt) = (self.n_vertices, self.num_triangles());
        try_grow(v_mut(self), h, "the half-edge vertices V")?;
        try_grow(o_mut(self), h, "the opposites O")?;
        try_grow(vh_mut(self), n, "the vertex half-edges VH")?;
        let total = self.v.len() + h;
        let st = self.st_mut();
        if let Some(ranks) = st.edge_ranks.as_mut() {
            ranks.reserve(total)?;
        }
        st.removed_vertex.try_grow(n, "the removed-vertex flags")?;
        if self.level >= 2 {
            try_grow(&mut self.st_mut().edge_of, h, "the edge ids")?;
            try_grow(eh_mut(self), e, "the edge half-edges EH")?;
        }
        if !self.positions.is_empty() {
            try_grow(positions_mut(self), n, "the positions")?;
        }
        if n > 0 {
            try_grow(
                vertex_origin_mut(self).written_out(nv)?,
                n,
                "the vertex origins",
            )?;
        }
        if t > 0 {
            let map = triangle_origin_mut(self).written_out(nt)?;
            try_grow(map, t, "the triangle origins")?;
        }
        Ok(())
    }

    /// A new vertex (room made first); its position is `p` when the mesh has positions.
    pub(super) fn push_vertex(&mut self, p: Option<DVec3>, origin: u32) -> u32 {
        let x = self.n_vertices as u32;
        self.n_vertices += 1;
        vh_mut(self).push(NONE);
        let st = self.st_mut();
        st.removed_vertex.push(false);
        st.live_vertices += 1;
        if !self.positions.is_empty() {
            positions_mut(self).push(p.unwrap_or_default());
        }
        let n = self.n_vertices - 1;
        vertex_origin_mut(self)
            .written_out(n)
            .expect("room made")
            .push(origin);
        x
    }

    /// A new triangle `(a, b, c)`, unpaired, with the input origin `origin` (room made first).
    pub(super) fn push_triangle(&mut self, corners: [u32; 3], origin: u32) -> u32 {
        let t = self.num_triangles() as u32;
        v_mut(self).extend_from_slice(&corners);
        o_mut(self).extend_from_slice(&[NONE; 3]);
        for h in 3 * t..3 * t + 3 {
            self.note_unpaired(h);
            touch_edge_ranks(self, h);
        }
        if self.level >= 2 {
            self.st_mut().edge_of.extend_from_slice(&[NONE; 3]);
        }
        let n = t as usize;
        let map = triangle_origin_mut(self).written_out(n).expect("room made");
        map.push(origin);
        self.st_mut().live_triangles += 1;
        t
    }

    /// Half-edge `from`'s flags (non-manifold, seam) now belong to `to`.
    pub(super) fn move_flags(&mut self, from: u32, to: u32) {
        move_in(non_manifold_mut(self), from, to);
        move_in(seams_mut(self), from, to);
    }

    /// Is `h` flagged non-manifold or seam?
    pub(super) fn is_flagged(&self, h: u32) -> bool {
        self.non_manifold.binary_search(&h).is_ok() || self.seams.binary_search(&h).is_ok()
    }

    /// Half-edge `h` is gone: unflagged.
    pub(super) fn unflag(&mut self, h: u32) {
        move_in(non_manifold_mut(self), h, NONE);
        move_in(seams_mut(self), h, NONE);
    }
}

/// Replaces `from` by `to` in the sorted `list` (`to == NONE`: removes it).
fn move_in(list: &mut Vec<u32>, from: u32, to: u32) {
    if let Ok(i) = list.binary_search(&from) {
        list.remove(i);
        if to != NONE {
            let j = list.binary_search(&to).unwrap_or_else(|j| j);
            list.insert(j, to);
        }
    }
}
