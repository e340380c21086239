//! Edge collapse: the origin of a half-edge merges into its target, under the link
//! condition (with the boundary closed by a virtual vertex, so that it also holds there).

use super::plan::{Plan, replaced};
use super::refusal::{Named, context, yes_or_no};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::HalfEdge;
use crate::error::{Error, Result};

/// The virtual vertex that cones the boundary off.
const INF: u32 = NONE - 1;

/// A simplex of a link: up to three sorted vertex ids, `NONE` padding.
type Simplex = [u32; 3];

/// Every face of each simplex of `tops` (the simplices themselves included), sorted, once.
fn closure(tops: &[Vec<u32>]) -> Vec<Simplex> {
    let mut out = Vec::new();
    for s in tops {
        let n = s.len();
        for mask in 1u32..(1 << n) {
            let mut x = [NONE; 3];
            let mut k = 0;
            for (i, &v) in s.iter().enumerate() {
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
    out
}

impl Chf {
    /// The link of the simplex `keep` (one or two vertices): the rest of each tetrahedron
    /// holding it, and the rest of each boundary face holding it coned to [`INF`].
    fn link(&self, keep: &[u32]) -> Vec<Simplex> {
        let mut tops: Vec<Vec<u32>> = Vec::new();
        for t in self.vertex_tetrahedra(keep[0]) {
            let q = self.tetrahedron_vertices(t);
            if keep.iter().all(|x| q.contains(x)) {
                tops.push(q.iter().copied().filter(|x| !keep.contains(x)).collect());
                for i in 0..4 {
                    let hf = 4 * t + i;
                    let tri = self.half_face_vertices_of(hf);
                    if self.opposite(hf) == NONE && keep.iter().all(|x| tri.contains(x)) {
                        let mut rest: Vec<u32> =
                            tri.iter().copied().filter(|x| !keep.contains(x)).collect();
                        rest.push(INF);
                        tops.push(rest);
                    }
                }
            }
        }
        closure(&tops)
    }

    fn plan_collapse_edge(&self, he: HalfEdge) -> Result<Plan> {
        self.check_live_half_edge(he)?;
        let [a, b] = self.half_edge_vertices(he);
        let (la, lb) = (self.link(&[a]), self.link(&[b]));
        let lab = self.link(&[a, b]);
        let common: Vec<Simplex> = la
            .iter()
            .copied()
            .filter(|s| lb.binary_search(s).is_ok())
            .collect();
        if let Some(s) = common.iter().find(|s| lab.binary_search(s).is_err()) {
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
        for t in self.vertex_tetrahedra(a) {
            let q = self.tetrahedron_vertices(t);
            plan.remove.push(t);
            if !q.contains(&b) {
                plan.add.push(replaced(q, a, b));
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
