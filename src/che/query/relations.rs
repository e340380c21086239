//! Queries at every level. Level 0 answers by scanning `V`; level 1 reads `O`; level 2
//! reads `VH` and the edge ranks; level 3 the curves. Ids are the same at every level.

use super::star::{Rotation, vf_item, vv_item};
use crate::che::ids::{first, next, prev, tri};
use crate::che::tables::canonical_half_edge;
use crate::che::{Che, edge_directory, pairs};
use crate::error::Result;
use crate::util::alloc::or_panic;
use crate::util::live_ranks::{BLOCK, LiveRanks};
use crate::util::rank_directory::RankDirectory;
use crate::{Ids, NONE};
use std::borrow::Cow;

impl Che {
    /// Origin of half-edge `h`.
    #[inline]
    pub fn origin(&self, h: u32) -> u32 {
        self.v[h as usize]
    }

    /// Target of half-edge `h`.
    #[inline]
    pub fn target(&self, h: u32) -> u32 {
        self.v[next(h) as usize]
    }

    /// The opposite half-edge, `NONE` on the boundary. O(1) from level 1, a scan at level 0
    /// (O(1) there too once edited: the `O` the edits keep).
    #[inline]
    pub fn opposite(&self, h: u32) -> u32 {
        if self.level >= 1 {
            return self.o[h as usize];
        }
        if let Some(o) = self.kept_opposites() {
            return o[h as usize];
        }
        self.opposite_by_scan(h)
    }

    /// The level-0 rule (the same that level 1 stores): `h` and `g` are opposite when they
    /// are the only two half-edges on their vertex pair, run opposite ways, and are not on
    /// a non-manifold edge.
    fn opposite_by_scan(&self, h: u32) -> u32 {
        if self.non_manifold.binary_search(&h).is_ok() {
            return NONE;
        }
        let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
        let mut found = NONE;
        let mut others = 0;
        for t in 0..self.num_triangles() as u32 {
            let [x, y, z] = [0, 1, 2].map(|i| self.v[(3 * t + i) as usize]);
            for (g, (p, q)) in [(x, y), (y, z), (z, x)].into_iter().enumerate() {
                let g = 3 * t + g as u32;
                if g == h {
                    continue;
                }
                if p == b && q == a {
                    found = g;
                    others += 1;
                } else if p == a && q == b {
                    others += 1;
                }
            }
        }
        if others == 1 { found } else { NONE }
    }

    /// Opposites: borrowed from level 1 on, and at level 0 from the tables the last edit
    /// kept; else computed (O(T) time and memory).
    pub(crate) fn try_opposites_or_computed(&self) -> Result<Cow<'_, [u32]>> {
        Ok(if self.level >= 1 {
            Cow::Borrowed(&self.o)
        } else if let Some(o) = self.kept_opposites() {
            Cow::Borrowed(o)
        } else if self.edits().is_some() {
            Cow::Owned(self.live_opposites()?)
        } else {
            Cow::Owned(pairs::opposites_by_rule(
                &self.v,
                self.n_vertices,
                &self.non_manifold,
            )?)
        })
    }

    /// [`Che::try_opposites_or_computed`] for the queries without an error to return.
    pub(crate) fn opposites_or_computed(&self) -> Cow<'_, [u32]> {
        crate::util::alloc::or_panic(self.try_opposites_or_computed())
    }

    /// An edited CHE's edge ids from level 2 (`None`: the ranks are the ids).
    #[inline]
    pub(crate) fn edited_edge_ids(&self) -> Option<&[u32]> {
        self.edits()
            .map(|s| &s.edge_of[..])
            .filter(|ids| !ids.is_empty())
    }

    /// Is `h` on the boundary (no opposite)?
    pub fn is_boundary_half_edge(&self, h: u32) -> bool {
        self.opposite(h) == NONE
    }

    /// The outgoing half-edge a rotation around `v` starts at: the boundary one on a
    /// boundary vertex, `NONE` for an isolated vertex. O(1) at level 2, O(T) at level 1 (a
    /// scan of `V`), O(T) time and memory at level 0 (`O` computed, then the scan); O(1)
    /// at every level once edited (the `VH` the edits keep).
    #[inline]
    pub fn vertex_half_edge(&self, v: u32) -> u32 {
        if self.level >= 2 {
            return self.vh[v as usize];
        }
        // Once edited, `O` is the kept one and `vertex_half_edge_in` reads the kept `VH`.
        self.vertex_half_edge_in(&self.opposites_or_computed(), v)
    }

    /// [`Che::vertex_half_edge`] with `O` at hand (`o`: the stored or computed opposites):
    /// below level 2, the kept `VH`'s once edited, else the first boundary half-edge from
    /// `v`, else the first.
    pub(crate) fn vertex_half_edge_in(&self, o: &[u32], v: u32) -> u32 {
        if self.level >= 2 {
            return self.vh[v as usize];
        }
        if let Some(vh) = self.kept_vertex_half_edges() {
            return vh[v as usize];
        }
        let mut any = NONE;
        for (h, &x) in self.v.iter().enumerate() {
            if x == v {
                if o[h] == NONE {
                    return h as u32;
                }
                if any == NONE {
                    any = h as u32;
                }
            }
        }
        any
    }

    /// Is `v` on the boundary? O(1) at level 2, O(T) below (see
    /// [`Che::vertex_half_edge`]). An isolated vertex is not.
    pub fn is_boundary_vertex(&self, v: u32) -> bool {
        let h = self.vertex_half_edge(v);
        h != NONE && self.opposite(h) == NONE
    }

    /// Is `v` referenced by no triangle?
    pub fn is_isolated_vertex(&self, v: u32) -> bool {
        self.vertex_half_edge(v) == NONE
    }

    /// The star of `v` in rotation order; see [`StarStep`](crate::che::StarStep). O(d) at
    /// level 2, O(T) at level 1 (finding the start), O(T) time and memory at level 0 (`O`
    /// computed once for the rotation); O(d) at every level once edited.
    pub fn vertex_star(&self, v: u32) -> Rotation<'_> {
        let o = self.opposites_or_computed();
        let start = self.vertex_half_edge_in(&o, v);
        Rotation::new(o, start)
    }

    /// VV: the vertices around `v`, counter-clockwise, from the boundary on a boundary vertex.
    pub fn vertex_vertices(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.vertex_star(v).map(|s| vv_item(&self.v, s))
    }

    /// VE: the edges around `v`, in the order of [`Che::vertex_vertices`]. The cost of
    /// [`Che::vertex_star`], plus at level 0 the edge ids (O(T) time and memory).
    pub fn vertex_edges(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        let names = self.edge_names();
        self.vertex_star(v).map(move |s| names.of(s.half_edge()))
    }

    /// VF: the triangles around `v`, counter-clockwise.
    pub fn vertex_triangles(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.vertex_star(v).filter_map(vf_item)
    }

    /// The edge id of half-edge `h`. O(1) at level 2; O(1) at level 1 once the level-1
    /// edge-id directory is there (the first request computes it, O(T), and keeps it: see
    /// [`Che::edge_ranks`]); O(T) time and memory at level 0; O(log T) below level 2 once
    /// edited (the live edges' block counts the edits keep). `NONE` for a removed
    /// half-edge.
    pub fn edge_of(&self, h: u32) -> u32 {
        if self.level >= 2 {
            if let Some(ids) = self.edited_edge_ids() {
                return ids[h as usize];
            }
            return self
                .edge_bits
                .rank(canonical_half_edge(&self.o, h) as usize) as u32;
        }
        // Below level 2 an id is a rank among the live half-edges, which a removed one
        // (no vertex) is not.
        if self.v[h as usize] == NONE {
            return NONE;
        }
        self.edge_names().of(h)
    }

    /// What naming edges takes, borrowed from level 1 (`O` and the edge-id directory, the
    /// level-1 one computed on the first request) and computed at level 0, once for a
    /// query that names several edges.
    pub(crate) fn try_edge_names(&self) -> Result<EdgeNames<'_>> {
        let o = self.try_opposites_or_computed()?;
        let naming = match (self.level, self.live_edge_ranks(), self.edited_edge_ids()) {
            (2.., _, Some(ids)) => Naming::Ids(ids),
            (_, Some(live), _) => Naming::Live(live, self),
            (0, ..) if self.edits().is_some() => {
                Naming::Ranks(Cow::Owned(self.live_edge_directory(&o)?))
            }
            (0, ..) => Naming::Ranks(Cow::Owned(edge_directory(&o)?)),
            (1, ..) => Naming::Ranks(Cow::Borrowed(self.try_level1_edge_bits()?)),
            _ => Naming::Ranks(Cow::Borrowed(&self.edge_bits)),
        };
        Ok(EdgeNames { o, naming })
    }

    /// Below level 2 on an edited CHE, the live edges' block counts the edits keep.
    fn live_edge_ranks(&self) -> Option<&LiveRanks> {
        let st = self.edits().filter(|_| self.level < 2)?;
        st.edge_ranks.as_ref()
    }

    /// Below level 2, the `e`-th live canonical half-edge over `o` (`NONE` past the last):
    /// an edited CHE's block counts find its block, else the half-edges are counted from
    /// the first.
    pub(crate) fn nth_live_canonical(&self, o: &[u32], e: u32) -> u32 {
        let (hs, nth) = match self.live_edge_ranks() {
            Some(ranks) => match ranks.select(e) {
                Some((k, before)) => (k * BLOCK..(k * BLOCK + BLOCK).min(o.len()), before),
                None => return NONE,
            },
            None => (0..o.len(), e),
        };
        hs.filter(|&h| self.is_live_canonical(o, h))
            .nth(nth as usize)
            .map_or(NONE, |h| h as u32)
    }

    /// [`Che::try_edge_names`] for the queries without an error to return.
    pub(crate) fn edge_names(&self) -> EdgeNames<'_> {
        or_panic(self.try_edge_names())
    }

    /// The canonical half-edge of edge `e` (the boundary one on a boundary edge), `NONE`
    /// for a removed edge. O(1) at level 2; O(T) at level 1 (a count of the canonical
    /// half-edges), and O(T) memory at level 0; O(log T) below level 2 once edited.
    pub fn edge_half_edge(&self, e: u32) -> u32 {
        if self.level >= 2 {
            return self.eh[e as usize];
        }
        self.nth_live_canonical(&self.opposites_or_computed(), e)
    }

    /// EV: the two ends of edge `e`, in the direction of its canonical half-edge.
    pub fn edge_vertices(&self, e: u32) -> [u32; 2] {
        match self.edge_half_edge(e) {
            NONE => [NONE; 2],
            h => [self.v[h as usize], self.v[next(h) as usize]],
        }
    }

    /// Is edge `e` on the boundary (one triangle)?
    pub fn is_boundary_edge(&self, e: u32) -> bool {
        let h = self.edge_half_edge(e);
        h != NONE && self.opposite(h) == NONE
    }

    /// EF: the one or two triangles of edge `e`, the canonical half-edge's first.
    pub fn edge_triangles(&self, e: u32) -> Ids<2> {
        match self.edge_half_edge(e) {
            NONE => Ids::new(),
            h => Ids::both_sides(h, self.opposite(h), tri),
        }
    }

    /// EE: the wings of edge `e`, the other edges of its triangles: next and previous in the
    /// canonical half-edge's triangle, then in the opposite one.
    pub fn edge_edges(&self, e: u32) -> Ids<4> {
        let h = self.edge_half_edge(e);
        let mut out = Ids::new();
        if h == NONE {
            return out;
        }
        let names = self.edge_names();
        out.push(names.of(next(h)));
        out.push(names.of(prev(h)));
        let o = names.o[h as usize];
        if o != NONE {
            out.push(names.of(next(o)));
            out.push(names.of(prev(o)));
        }
        out
    }

    /// FV: the corners of triangle `t`, counter-clockwise.
    pub fn triangle_vertices(&self, t: u32) -> [u32; 3] {
        let h = first(t) as usize;
        [self.v[h], self.v[h + 1], self.v[h + 2]]
    }

    /// FE: the edges of triangle `t`; edge `i` runs from corner `i` to corner `i + 1`.
    pub fn triangle_edges(&self, t: u32) -> [u32; 3] {
        if self.level >= 2 || self.v[first(t) as usize] == NONE {
            return [0, 1, 2].map(|i| self.edge_of(first(t) + i));
        }
        let names = self.edge_names();
        [0, 1, 2].map(|i| names.of(first(t) + i))
    }

    /// FF: the triangle across each edge of `t` (`NONE` on the boundary).
    pub fn triangle_triangles(&self, t: u32) -> [u32; 3] {
        let across = |o: u32| if o == NONE { NONE } else { tri(o) };
        let h = first(t) as usize;
        // From level 1 one slice of `O`: a single bounds check and no level test per corner.
        match self.opposites().and_then(|o| o.get(h..h + 3)) {
            Some(o) => [across(o[0]), across(o[1]), across(o[2])],
            None => [0, 1, 2].map(|i| across(self.opposite(first(t) + i))),
        }
    }
}

/// The tables that name edges (see [`Che::edge_names`]).
pub(crate) struct EdgeNames<'a> {
    o: Cow<'a, [u32]>,
    naming: Naming<'a>,
}

/// Where an edge id comes from.
enum Naming<'a> {
    /// The rank of the canonical half-edge in the edge-id directory.
    Ranks(Cow<'a, RankDirectory>),
    /// An edited CHE's edge ids, from level 2, by half-edge.
    Ids(&'a [u32]),
    /// Below level 2 on an edited CHE: the rank of the canonical half-edge among the live
    /// ones, counted over the edits' block counts.
    Live(&'a LiveRanks, &'a Che),
}

impl EdgeNames<'_> {
    /// The edge id of half-edge `h`: the rank of its canonical half-edge.
    #[inline]
    pub(crate) fn of(&self, h: u32) -> u32 {
        match &self.naming {
            Naming::Ids(ids) => ids[h as usize],
            Naming::Live(live, che) => {
                let c = canonical_half_edge(&self.o, h) as usize;
                live.rank(c, |g| che.is_live_canonical(&self.o, g))
            }
            Naming::Ranks(ranks) => ranks.rank(canonical_half_edge(&self.o, h) as usize) as u32,
        }
    }
}
