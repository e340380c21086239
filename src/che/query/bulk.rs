//! Whole relations at once, as rows (CSR: offsets + indices), in O(T) at every level:
//! below level 2 the missing `O`, `VH` or edge ids are computed once for the sweep instead
//! of once per element. The rows go to a [`Rows`] receiver: a [`Csr`] here, the caller's
//! buffers in the C API.

use super::star::{StarStep, for_each_step, vf_item, vv_item};
use crate::NONE;
use crate::che::Che;
use crate::che::ids::tri;
use crate::che::tables::{edge_ids, vertex_half_edges};
use std::borrow::Cow;

/// A relation for every element: element `i` has `indices[offsets[i]..offsets[i + 1]]`.
pub type Csr = crate::util::csr::Csr<usize>;

impl Csr {
    /// Row `i` (the name before [`Csr::row`]).
    pub fn get(&self, i: usize) -> &[u32] {
        self.row(i)
    }

    fn with_capacity(rows: usize, indices: usize) -> Self {
        Csr {
            offsets: Vec::with_capacity(rows + 1),
            indices: Vec::with_capacity(indices),
        }
    }

    /// Closes the last row.
    fn finish(mut self) -> Self {
        self.offsets.push(self.indices.len());
        self
    }
}

/// Where a one-element walk writes its entries (the C API's caller buffers).
pub(crate) trait Push {
    fn push(&mut self, x: u32);
}

/// Where a bulk sweep writes: `row()` before each element's entries, `push` for each entry.
pub(crate) trait Rows: Push {
    fn row(&mut self);
}

impl Push for Csr {
    #[inline]
    fn push(&mut self, x: u32) {
        self.indices.push(x);
    }
}

impl Rows for Csr {
    #[inline]
    fn row(&mut self) {
        self.offsets.push(self.indices.len());
    }
}

/// The tables a sweep needs, borrowed or computed once.
struct Tables<'a> {
    o: Cow<'a, [u32]>,
    vh: Cow<'a, [u32]>,
}

impl Che {
    fn sweep_tables(&self) -> Tables<'_> {
        let o = self.opposites_or_computed();
        let vh = match self.vertex_half_edges() {
            Some(vh) => Cow::Borrowed(vh),
            None => Cow::Owned(vertex_half_edges(self.n_vertices, &self.v, &o)),
        };
        Tables { o, vh }
    }

    /// One row per vertex: `item` of each step of its rotation.
    fn star_rows(
        &self, t: &Tables, out: &mut impl Rows, mut item: impl FnMut(StarStep) -> Option<u32>,
    ) {
        for &start in t.vh.iter() {
            out.row();
            for_each_step(&t.o, start, |s| {
                if let Some(x) = item(s) {
                    out.push(x);
                }
            });
        }
    }

    fn star_csr(&self, fill: impl FnOnce(&Self, &mut Csr)) -> Csr {
        let mut csr = Csr::with_capacity(self.n_vertices, self.v.len() + self.v.len() / 8);
        fill(self, &mut csr);
        csr.finish()
    }

    /// One star, over `O` stored (level 1 on) or computed once (level 0).
    #[inline(always)]
    fn star_into(&self, v: u32, out: &mut impl Push, item: impl Fn(StarStep) -> Option<u32>) {
        let each = |s| {
            if let Some(x) = item(s) {
                out.push(x);
            }
        };
        match self.opposites() {
            Some(o) => for_each_step(o, self.vertex_half_edge(v), each),
            None => {
                let o = self.opposites_or_computed();
                for_each_step(&o, self.vertex_half_edge_in(&o, v), each);
            }
        }
    }

    /// VV of `v` into `out`, as [`Che::vertex_vertices`] (without the iterator's state).
    pub(crate) fn vertex_vertices_into(&self, v: u32, out: &mut impl Push) {
        let vs = &self.v[..];
        self.star_into(v, out, |s| Some(vv_item(vs, s)));
    }

    /// VE of `v` into `out`, as [`Che::vertex_edges`].
    pub(crate) fn vertex_edges_into(&self, v: u32, out: &mut impl Push) {
        if self.level >= 2 {
            return self.star_into(v, out, |s| Some(self.ve_item(s)));
        }
        let names = self.edge_names();
        self.star_into(v, out, |s| Some(names.of(s.half_edge())));
    }

    /// VF of `v` into `out`, as [`Che::vertex_triangles`].
    pub(crate) fn vertex_triangles_into(&self, v: u32, out: &mut impl Push) {
        self.star_into(v, out, vf_item);
    }

    /// VV rows, in the order of [`Che::vertex_vertices`].
    pub(crate) fn vertex_vertices_rows(&self, out: &mut impl Rows) {
        let t = self.sweep_tables();
        let vs = &self.v[..];
        self.star_rows(&t, out, |s| Some(vv_item(vs, s)));
    }

    /// VE rows, in the order of [`Che::vertex_edges`].
    pub(crate) fn vertex_edges_rows(&self, out: &mut impl Rows) {
        let t = self.sweep_tables();
        if self.level >= 2 {
            return self.star_rows(&t, out, |s| Some(self.ve_item(s)));
        }
        let ids = edge_ids(&t.o);
        self.star_rows(&t, out, |s| match s {
            StarStep::Out(h) | StarStep::LastIn(h) => Some(ids[h as usize]),
        });
    }

    /// VF rows, in the order of [`Che::vertex_triangles`].
    pub(crate) fn vertex_triangles_rows(&self, out: &mut impl Rows) {
        let t = self.sweep_tables();
        self.star_rows(&t, out, vf_item);
    }

    /// FF rows: 3 entries per triangle, `NONE` across boundary edges.
    pub(crate) fn triangle_triangles_rows(&self, out: &mut impl Rows) {
        let o = self.opposites_or_computed();
        for (h, &g) in o.iter().enumerate() {
            if h % 3 == 0 {
                out.row();
            }
            out.push(if g == NONE { NONE } else { tri(g) });
        }
    }

    /// VV for every vertex, in the order of [`Che::vertex_vertices`].
    pub fn all_vertex_vertices(&self) -> Csr {
        self.star_csr(|c, csr| c.vertex_vertices_rows(csr))
    }

    /// VE for every vertex, in the order of [`Che::vertex_edges`].
    pub fn all_vertex_edges(&self) -> Csr {
        self.star_csr(|c, csr| c.vertex_edges_rows(csr))
    }

    /// VF for every vertex, in the order of [`Che::vertex_triangles`].
    pub fn all_vertex_triangles(&self) -> Csr {
        self.star_csr(|c, csr| c.vertex_triangles_rows(csr))
    }

    /// FF for every triangle: 3 entries each, `NONE` across boundary edges.
    pub fn all_triangle_triangles(&self) -> Vec<u32> {
        let o = self.opposites_or_computed();
        o.iter()
            .map(|&g| if g == NONE { NONE } else { tri(g) })
            .collect()
    }

    /// FE for every triangle: 3 edge ids each.
    pub fn all_triangle_edges(&self) -> Vec<u32> {
        if self.level >= 2 {
            return (0..self.v.len() as u32).map(|h| self.edge_of(h)).collect();
        }
        edge_ids(&self.opposites_or_computed())
    }
}
