//! Edge collapse: the origin of a half-edge merges into its target, under the link
//! condition (with the boundary closed by a virtual vertex, so that it also holds there).

use super::plan::{Plan, replaced};
use super::refusal::{Named, context, yes_or_no};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::HalfEdge;
use crate::chf::query::star::star_tetrahedra;
use crate::chf::query::view::{Need, View};
use crate::error::{Error, Result};
use crate::util::alloc::{try_push, try_with_capacity};

/// The virtual vertex that cones the boundary off.
const INF: u32 = NONE - 1;

/// A simplex of a link: up to three sorted vertex ids, `NONE` padding.
type Simplex = [u32; 3];

/// What the link's simplices are called when they do not fit in memory.
const LINK: &str = "the link of a collapse";

/// Every face of each simplex of `tops` (the simplices themselves included), sorted, once.
fn closure(tops: &[Simplex]) -> Result<Vec<Simplex>> {
    // A simplex of at most three vertices has at most seven faces.
    let mut out = try_with_capacity(7 * tops.len(), LINK)?;
    for s in tops {
        let n = s.iter().take_while(|&&x| x != NONE).count();
        for mask in 1u32..(1 << n) {
            let mut x = [NONE; 3];
            let mut k = 0;
            for (i, &v) in s[..n].iter().enumerate() {
                if mask & (1 << i) != 0 {
                    x[k] = v;
                    k += 1;
                }
            }
            x[..k].sort_unstable();
            out.push(x);
        }
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}

/// The vertices of `q` not in `keep`, `NONE` padded, and `extra` after them if given.
fn rest(q: &[u32], keep: &[u32], extra: Option<u32>) -> Simplex {
    let mut out = [NONE; 3];
    let kept = q.iter().copied().filter(|x| !keep.contains(x)).chain(extra);
    for (slot, x) in out.iter_mut().zip(kept) {
        *slot = x;
    }
    out
}

impl Chf {
    /// The link of the simplex `keep` (one or two vertices): the rest of each tetrahedron
    /// holding it, and the rest of each boundary face holding it coned to [`INF`].
    fn link(&self, view: &View, keep: &[u32]) -> Result<Vec<Simplex>> {
        let mut tops: Vec<Simplex> = Vec::new();
        for t in star_tetrahedra(view, keep[0])? {
            let q = self.tetrahedron_vertices(t);
            if keep.iter().all(|x| q.contains(x)) {
                try_push(&mut tops, rest(&q, keep, None), LINK)?;
                for i in 0..4 {
                    let hf = 4 * t + i;
                    let tri = self.half_face_vertices_of(hf);
                    if view.o[hf as usize] == NONE && keep.iter().all(|x| tri.contains(x)) {
                        try_push(&mut tops, rest(&tri, keep, Some(INF)), LINK)?;
                    }
                }
            }
        }
        closure(&tops)
    }

    fn plan_collapse_edge(&self, he: HalfEdge) -> Result<Plan> {
        self.check_live_half_edge(he)?;
        let [a, b] = self.half_edge_vertices(he);
        // One view for the three links and the plan (below level 1 on a mesh never
        // edited, it computes `O`).
        let view = self.try_view(Need::NOTHING)?;
        let (la, lb) = (self.link(&view, &[a])?, self.link(&view, &[b])?);
        let lab = self.link(&view, &[a, b])?;
        let mut common = la.iter().filter(|s| lb.binary_search(s).is_ok());
        if let Some(s) = common.find(|s| lab.binary_search(s).is_err()) {
            let named: Vec<String> = s
                .iter()
                .filter(|&&x| x != NONE)
                .map(|&x| {
                    if x == INF {
                        "the boundary".into()
                    } else {
                        x.to_string()
                    }
                })
                .collect();
            return Err(Error::non_manifold(format!(
                "refused: the link condition fails: ({}) is in the links of {a} and {b} but not of the edge",
                named.join(", ")
            )));
        }
        let mut plan = Plan {
            retire: vec![a],
            ..Plan::default()
        };
        for t in star_tetrahedra(&view, a)? {
            let q = self.tetrahedron_vertices(t);
            try_push(&mut plan.remove, t, "a collapse's tetrahedra")?;
            if !q.contains(&b) {
                try_push(&mut plan.add, replaced(q, a, b), "a collapse's tetrahedra")?;
            }
        }
        Ok(plan)
    }

    /// Collapses half-edge `he`: its origin merges into its target (returned), which
    /// keeps its position; the tetrahedra around the edge go. Refused when the link
    /// condition fails (with the simplex that breaks it), or, with positions, when a
    /// tetrahedron would invert. O(the stars of both ends).
    pub fn collapse_edge(&mut self, he: HalfEdge) -> Result<u32> {
        let what = Named("half-edge", he);
        let plan = self
            .plan_collapse_edge(he)
            .map_err(context("collapse_edge", what))?;
        let b = self.half_edge_vertices(he)[1];
        self.run(plan).map_err(context("collapse_edge", what))?;
        Ok(b)
    }

    /// Can half-edge `he` be collapsed? [`Chf::check_collapse_edge`] without the reason,
    /// as [`crate::Che::is_collapse_ok`]: `Ok(false)` for a refusal, `Err` for a bad or
    /// removed id. Changes nothing.
    pub fn is_collapse_ok(&self, he: HalfEdge) -> Result<bool> {
        yes_or_no(|| self.check_collapse_edge(he))
    }

    /// Would [`Chf::collapse_edge`] succeed? Changes nothing.
    pub fn check_collapse_edge(&self, he: HalfEdge) -> Result<()> {
        self.check_op("collapse_edge", Named("half-edge", he), |c| {
            c.plan_collapse_edge(he)
        })
    }
}
