//! Half-edge (DCEL) arrays, as OpenMesh, CGAL's `Surface_mesh` or a textbook DCEL hold them.

use crate::NONE;
use crate::che::Che;
use crate::che::Push;
use crate::che::ids::{next, prev, tri};
use crate::che::tables::vertex_half_edges;
use crate::error::Result;
use crate::util::alloc::{try_collect, try_to_vec};
use crate::util::sparse::{filled, reserve};
use std::borrow::Cow;

/// How boundary half-edges appear in [`HalfEdgeArrays`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HalfEdgeOptions {
    /// `false` (default): the `3T` half-edges of the triangles only, a boundary half-edge
    /// marked by `twin == NONE`. `true` (OpenMesh style): one extra half-edge per boundary
    /// half-edge, numbered from `3T` in the order of the boundary half-edges they twin,
    /// with `face == NONE`, linked by `next` into loops around each hole.
    pub explicit_boundary: bool,
}

/// Half-edge arrays. Half-edges `0..3T` are CHE's: `3t, 3t + 1, 3t + 2` go round
/// triangle `t` counter-clockwise.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct HalfEdgeArrays {
    /// The next half-edge round the same face (or the same hole).
    pub next: Vec<u32>,
    /// The previous half-edge round the same face (or hole).
    pub prev: Vec<u32>,
    /// The opposite half-edge: `NONE` on the boundary unless explicit.
    pub twin: Vec<u32>,
    /// The tail (origin) of each half-edge, as CHE's `V`; the head is `vertex[next[h]]`.
    pub vertex: Vec<u32>,
    /// The triangle of each half-edge, `NONE` for an explicit boundary half-edge.
    pub face: Vec<u32>,
    /// The edge of each half-edge (the ids of `Che::edge_of`).
    pub edge: Vec<u32>,
    /// One outgoing half-edge per vertex, `NONE` for an isolated vertex. On a boundary
    /// vertex the boundary one: the triangle's when marked, the hole's when explicit (as
    /// OpenMesh keeps it).
    pub vertex_half_edge: Vec<u32>,
    /// One half-edge per triangle: `3t`.
    pub face_half_edge: Vec<u32>,
}

/// Which array `che_mesh_export_half_edges` writes (one entry per half-edge unless
/// stated).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HalfEdgeArray {
    /// The next half-edge round the same triangle (or hole).
    Next = 0,
    /// The previous half-edge round the same triangle (or hole).
    Prev = 1,
    /// The opposite half-edge (TOPOMESH_NONE on a marked boundary).
    Twin = 2,
    /// The tail (origin) of the half-edge, CHE's V; the head is `vertex[next[h]]`.
    Vertex = 3,
    /// The triangle (TOPOMESH_NONE for an explicit boundary half-edge).
    Face = 4,
    /// The edge id.
    Edge = 5,
    /// One entry per vertex: an outgoing half-edge, the boundary one on the boundary (the
    /// hole's when explicit), TOPOMESH_NONE when isolated.
    VertexHalfEdge = 6,
    /// One entry per triangle t: 3t.
    FaceHalfEdge = 7,
}

// cbindgen reads this file for the C enum (`tests/header_drift.rs`); the list is Rust's.
/// cbindgen:ignore
impl HalfEdgeArray {
    pub const ALL: [HalfEdgeArray; 8] = [
        HalfEdgeArray::Next,
        HalfEdgeArray::Prev,
        HalfEdgeArray::Twin,
        HalfEdgeArray::Vertex,
        HalfEdgeArray::Face,
        HalfEdgeArray::Edge,
        HalfEdgeArray::VertexHalfEdge,
        HalfEdgeArray::FaceHalfEdge,
    ];
}

/// What every array reads: `O`, and with an explicit boundary the boundary half-edges in
/// order (the `k`-th is twinned by `3T + k`).
struct Layout<'a> {
    o: Cow<'a, [u32]>,
    boundary: Vec<u32>,
}

impl Che {
    /// The half-edge arrays; see [`HalfEdgeArrays`] for the layout.
    pub fn half_edge_arrays(&self, options: HalfEdgeOptions) -> Result<HalfEdgeArrays> {
        self.check_collected("the half-edge export")?;
        let l = self.half_edge_layout(options)?;
        let array = |which| self.half_edge_array_in(&l, which);
        Ok(HalfEdgeArrays {
            next: array(HalfEdgeArray::Next)?,
            prev: array(HalfEdgeArray::Prev)?,
            twin: array(HalfEdgeArray::Twin)?,
            vertex: array(HalfEdgeArray::Vertex)?,
            face: array(HalfEdgeArray::Face)?,
            edge: array(HalfEdgeArray::Edge)?,
            vertex_half_edge: array(HalfEdgeArray::VertexHalfEdge)?,
            face_half_edge: array(HalfEdgeArray::FaceHalfEdge)?,
        })
    }

    /// Array `which` of [`Che::half_edge_arrays`], computed alone: one pass over the
    /// half-edges (and the vertices for the per-vertex arrays).
    pub fn half_edge_array(
        &self, options: HalfEdgeOptions, which: HalfEdgeArray,
    ) -> Result<Vec<u32>> {
        self.check_collected("the half-edge export")?;
        self.half_edge_array_in(&self.half_edge_layout(options)?, which)
    }

    /// [`Che::half_edge_array`] written entry by entry into `out` (the C API's caller
    /// buffer), so a caller that owns the storage pays for no array in between.
    pub(crate) fn half_edge_array_into(
        &self, options: HalfEdgeOptions, which: HalfEdgeArray, out: &mut impl Push,
    ) -> Result<()> {
        self.check_collected("the half-edge export")?;
        self.write_half_edge_array(&self.half_edge_layout(options)?, which, out)
    }

    fn half_edge_layout(&self, options: HalfEdgeOptions) -> Result<Layout<'_>> {
        let o = self.try_opposites_or_computed()?;
        // One pass: the boundary is a small part of the half-edges, so growing beats a
        // counting pass over all of them.
        let boundary = match options.explicit_boundary {
            true => {
                let open = (0..o.len() as u32).filter(|&h| o[h as usize] == NONE);
                try_collect(open, "boundary half-edges")?
            }
            false => Vec::new(),
        };
        Ok(Layout { o, boundary })
    }

    fn half_edge_array_in(&self, l: &Layout<'_>, which: HalfEdgeArray) -> Result<Vec<u32>> {
        let len = match which {
            HalfEdgeArray::VertexHalfEdge => self.n_vertices,
            HalfEdgeArray::FaceHalfEdge => self.num_triangles(),
            _ => self.v.len() + l.boundary.len(),
        };
        let mut out = Vec::new();
        reserve(&mut out, len, "a half-edge array")?;
        self.write_half_edge_array(l, which, &mut out)?;
        Ok(out)
    }

    fn write_half_edge_array(
        &self, l: &Layout<'_>, which: HalfEdgeArray, out: &mut impl Push,
    ) -> Result<()> {
        let b = &l.boundary;
        let base = self.v.len() as u32;
        match which {
            HalfEdgeArray::Next => {
                out.push_all((0..base).map(next));
                let after = self.explicit_by_vertex(b, |h| self.v[next(h) as usize])?;
                out.push_all(b.iter().map(|&h| after[self.v[h as usize] as usize]));
            }
            HalfEdgeArray::Prev => {
                out.push_all((0..base).map(prev));
                let before = self.explicit_by_vertex(b, |h| self.v[h as usize])?;
                out.push_all(b.iter().map(|&h| before[self.v[next(h) as usize] as usize]));
            }
            HalfEdgeArray::Twin => {
                let mut k = base;
                out.push_all(l.o.iter().map(|&g| {
                    if g != NONE || b.is_empty() {
                        return g;
                    }
                    k += 1;
                    k - 1
                }));
                out.push_all(b.iter().copied());
            }
            HalfEdgeArray::Vertex => {
                out.push_all(self.v.iter().copied());
                out.push_all(b.iter().map(|&h| self.v[next(h) as usize]));
            }
            HalfEdgeArray::Face => {
                out.push_all((0..base).map(tri));
                out.push_all(b.iter().map(|_| NONE));
            }
            HalfEdgeArray::Edge => {
                let names = self.try_edge_names()?;
                out.push_all((0..base).map(|h| names.of(h)));
                out.push_all(b.iter().map(|&h| names.of(h)));
            }
            HalfEdgeArray::VertexHalfEdge => {
                let vh = self.vertex_half_edge_array(l)?;
                out.push_all(vh.iter().copied());
            }
            HalfEdgeArray::FaceHalfEdge => {
                out.push_all((0..self.num_triangles() as u32).map(|t| 3 * t))
            }
        }
        Ok(())
    }

    /// Per vertex, the explicit boundary half-edge `3T + k` whose tail it is: `tail(h)`
    /// is that tail for the `k`-th boundary half-edge `h` (its twin runs head to tail).
    /// Each vertex of a built CHE is one fan, so it has at most one.
    fn explicit_by_vertex(&self, boundary: &[u32], tail: impl Fn(u32) -> u32) -> Result<Vec<u32>> {
        if boundary.is_empty() {
            return Ok(Vec::new());
        }
        let mut by = filled(self.n_vertices, NONE, "boundary half-edges")?;
        let n = self.v.len() as u32;
        for (k, &h) in boundary.iter().enumerate() {
            by[tail(h) as usize] = n + k as u32;
        }
        Ok(by)
    }

    /// One outgoing half-edge per vertex: the stored or computed `VH`, where an explicit
    /// boundary replaces the boundary one by the hole's (as OpenMesh keeps it).
    fn vertex_half_edge_array(&self, l: &Layout<'_>) -> Result<Cow<'_, [u32]>> {
        let mut out = match self.vertex_half_edges() {
            Some(vh) => Cow::Borrowed(vh),
            None => Cow::Owned(vertex_half_edges(self.n_vertices, &self.v, &l.o)?),
        };
        if l.boundary.is_empty() {
            return Ok(out);
        }
        // The explicit twin `3T + k` of boundary half-edge `h = (u -> w)` leaves `w`.
        let n = self.v.len() as u32;
        if let Cow::Borrowed(vh) = out {
            out = Cow::Owned(try_to_vec(vh, "the vertex half-edges")?);
        }
        let out_mut = out.to_mut();
        for (k, &h) in l.boundary.iter().enumerate() {
            out_mut[self.v[next(h) as usize] as usize] = n + k as u32;
        }
        Ok(out)
    }
}
