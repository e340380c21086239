//! Whole relations at once, as rows (CSR: offsets + indices), in O(T) at every level:
//! below level 2 the missing `O`, `VH` or edge ids are computed once for the sweep instead
//! of once per element. The rows go to a [`Rows`] receiver: a [`Csr`] here, the caller's
//! buffers in the C API.

use super::star::{StarStep, for_each_step, vf_item, vv_item};
use crate::NONE;
use crate::che::Che;
use crate::che::ids::tri;
use crate::che::tables::{edge_ids, vertex_half_edges};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_push, try_with_capacity};
use std::borrow::Cow;

/// A relation for every element: element `i` has `indices[offsets[i]..offsets[i + 1]]`.
pub type Csr = crate::util::csr::Csr<usize>;

impl Csr {
    /// Row `i` (the name before [`Csr::row`]).
    pub fn get(&self, i: usize) -> &[u32] {
        self.row(i)
    }
}

/// A [`Csr`] being filled by a sweep: its growth past the first room is fallible, and the
/// first failure is kept (a [`Rows`] receiver has no error to return) and ends the fill.
struct Filling {
    csr: Csr,
    failed: Option<Error>,
}

impl Filling {
    fn with_capacity(rows: usize, indices: usize) -> Result<Self> {
        let csr = Csr {
            offsets: try_with_capacity(rows + 1, "the CSR offsets")?,
            indices: try_with_capacity(indices, "the CSR indices")?,
        };
        Ok(Filling { csr, failed: None })
    }

    fn keep(&mut self, r: Result<()>) {
        if let (Err(e), None) = (r, &self.failed) {
            self.failed = Some(e);
        }
    }

    /// Closes the last row.
    fn finish(mut self) -> Result<Csr> {
        let end = self.csr.indices.len();
        let r = try_push(&mut self.csr.offsets, end, "the CSR offsets");
        self.keep(r);
        match self.failed {
            Some(e) => Err(e),
            None => Ok(self.csr),
        }
    }
}

/// Where a one-element walk writes its entries (the C API's caller buffers).
pub(crate) trait Push {
    fn push(&mut self, x: u32);

    /// Every entry of `xs`, in order.
    #[inline]
    fn push_all(&mut self, xs: impl IntoIterator<Item = u32>)
    where
        Self: Sized,
    {
        xs.into_iter().for_each(|x| self.push(x));
    }
}

/// A vector the caller reserved for the whole answer, so `push` does not allocate.
impl Push for Vec<u32> {
    #[inline(always)]
    fn push(&mut self, x: u32) {
        Vec::push(self, x);
    }
}

/// Where a bulk sweep writes: `row()` before each element's entries, `push` for each entry.
pub(crate) trait Rows: Push {
    fn row(&mut self);
}

impl Push for Filling {
    #[inline]
    fn push(&mut self, x: u32) {
        if self.failed.is_none() {
            let r = try_push(&mut self.csr.indices, x, "the CSR indices");
            self.keep(r);
        }
    }
}

impl Rows for Filling {
    #[inline]
    fn row(&mut self) {
        if self.failed.is_none() {
            let end = self.csr.indices.len();
            let r = try_push(&mut self.csr.offsets, end, "the CSR offsets");
            self.keep(r);
        }
    }
}

/// The tables a sweep needs, borrowed or computed once.
struct Tables<'a> {
    o: Cow<'a, [u32]>,
    vh: Cow<'a, [u32]>,
}

impl Che {
    fn sweep_tables(&self) -> Result<Tables<'_>> {
        let o = self.try_opposites_or_computed()?;
        let vh = match self.vertex_half_edges().or(self.kept_vertex_half_edges()) {
            Some(vh) => Cow::Borrowed(vh),
            None if self.edits().is_some() => Cow::Owned(self.live_vertex_half_edges(&o)?),
            None => Cow::Owned(vertex_half_edges(self.n_vertices, &self.v, &o)?),
        };
        Ok(Tables { o, vh })
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

    fn star_csr(&self, fill: impl FnOnce(&Self, &mut Filling) -> Result<()>) -> Result<Csr> {
        let mut csr = Filling::with_capacity(self.n_vertices, self.v.len() + self.v.len() / 8)?;
        fill(self, &mut csr)?;
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
    pub(crate) fn vertex_vertices_rows(&self, out: &mut impl Rows) -> Result<()> {
        let t = self.sweep_tables()?;
        let vs = &self.v[..];
        self.star_rows(&t, out, |s| Some(vv_item(vs, s)));
        Ok(())
    }

    /// VE rows, in the order of [`Che::vertex_edges`].
    pub(crate) fn vertex_edges_rows(&self, out: &mut impl Rows) -> Result<()> {
        let t = self.sweep_tables()?;
        if self.level >= 2 {
            self.star_rows(&t, out, |s| Some(self.ve_item(s)));
            return Ok(());
        }
        let ids = self.edge_ids_below_2(&t.o)?;
        self.star_rows(&t, out, |s| match s {
            StarStep::Out(h) | StarStep::LastIn(h) => Some(ids[h as usize]),
        });
        Ok(())
    }

    /// VF rows, in the order of [`Che::vertex_triangles`].
    pub(crate) fn vertex_triangles_rows(&self, out: &mut impl Rows) -> Result<()> {
        let t = self.sweep_tables()?;
        self.star_rows(&t, out, vf_item);
        Ok(())
    }

    /// FF rows: 3 entries per triangle, `NONE` across boundary edges.
    pub(crate) fn triangle_triangles_rows(&self, out: &mut impl Rows) -> Result<()> {
        let o = self.try_opposites_or_computed()?;
        for (h, &g) in o.iter().enumerate() {
            if h % 3 == 0 {
                out.row();
            }
            out.push(if g == NONE { NONE } else { tri(g) });
        }
        Ok(())
    }

    /// VV for every vertex, in the order of [`Che::vertex_vertices`].
    ///
    /// An [`ErrorKind::OutOfMemory`](crate::ErrorKind::OutOfMemory) error when the rows
    /// (or, below level 2, the tables computed for the sweep) do not fit in memory; the
    /// same for every bulk relation.
    pub fn all_vertex_vertices(&self) -> Result<Csr> {
        self.star_csr(|c, csr| c.vertex_vertices_rows(csr))
    }

    /// VE for every vertex, in the order of [`Che::vertex_edges`].
    pub fn all_vertex_edges(&self) -> Result<Csr> {
        self.star_csr(|c, csr| c.vertex_edges_rows(csr))
    }

    /// VF for every vertex, in the order of [`Che::vertex_triangles`].
    pub fn all_vertex_triangles(&self) -> Result<Csr> {
        self.star_csr(|c, csr| c.vertex_triangles_rows(csr))
    }

    /// FF for every triangle: 3 entries each, `NONE` across boundary edges.
    pub fn all_triangle_triangles(&self) -> Result<Vec<u32>> {
        let o = self.try_opposites_or_computed()?;
        let ff = o.iter().map(|&g| if g == NONE { NONE } else { tri(g) });
        try_collect(ff, "the triangle neighbours")
    }

    /// FE for every triangle: 3 edge ids each.
    pub fn all_triangle_edges(&self) -> Result<Vec<u32>> {
        if self.level >= 2 {
            let fe = (0..self.v.len() as u32).map(|h| self.edge_of(h));
            return try_collect(fe, "the triangle edges");
        }
        self.edge_ids_below_2(&self.try_opposites_or_computed()?)
    }

    /// The edge id of every half-edge below level 2 (over the live ones when edited).
    fn edge_ids_below_2(&self, o: &[u32]) -> Result<Vec<u32>> {
        match self.edits() {
            Some(_) => self.live_edge_ids(o),
            None => edge_ids(o),
        }
    }
}
