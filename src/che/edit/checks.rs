//! Checks before an edit writes anything: ids live and in range, and the conditions of
//! the Euler operators ([`Che::is_flip_ok`], [`Che::is_collapse_ok`]), which never modify.

use crate::NONE;
use crate::che::ids::{first, next, prev, tri};
use crate::che::{Che, Checked};
use crate::error::{Error, Result};
use crate::util::alloc::try_push;
use crate::util::small_ids::Ids;

/// A refused operation: an invalid-input error with the reason.
pub(super) fn refuse<T>(what: String) -> Result<T> {
    Err(Error::invalid(what))
}

/// Why a flip is refused; worded only when it is reported (a check drops it, and the
/// checks of a flip storm run millions of times).
pub(super) enum FlipRefusal {
    /// The edge is on the boundary (or non-manifold).
    Boundary,
    /// Both triangles have this third vertex.
    SameThird(u32),
    /// The flipped edge, between these vertices, exists already.
    Exists(u32, u32),
}

impl FlipRefusal {
    /// The reason, for edge `e`.
    pub(super) fn words(&self, e: u32) -> String {
        match *self {
            FlipRefusal::Boundary => format!("edge {e} is on the boundary (or non-manifold)"),
            FlipRefusal::SameThird(c) => {
                format!("edge {e}: both triangles have the same third vertex {c}")
            }
            FlipRefusal::Exists(c, d) => {
                format!("edge {e}: the flipped edge {c}-{d} exists already")
            }
        }
    }
}

/// What the link condition of a collapse of `a -> b` reads of the stars of `a` and `b`.
struct Links {
    /// A neighbour of both other than `a` and the thirds (the first met around `b`).
    shared: Option<u32>,
    /// Both stars hold a triangle on the two thirds `c, d` (edge `c-d` is in both links).
    /// Read to the end of `b`'s star only when `shared` is `None`.
    both_on_thirds: bool,
}

impl Che {
    /// Is vertex `x` removed (until [`Che::garbage_collect`])? `false` out of range.
    pub fn is_vertex_removed(&self, x: u32) -> bool {
        self.edits()
            .and_then(|s| s.removed_vertex.get(x as usize))
            .unwrap_or(false)
    }
    /// Is triangle `t` removed? `false` out of range.
    pub fn is_triangle_removed(&self, t: u32) -> bool {
        self.v.get(first(t) as usize).is_some_and(|&x| x == NONE)
    }
    /// Is half-edge `h` removed (its triangle is)? `false` out of range.
    pub fn is_half_edge_removed(&self, h: u32) -> bool {
        self.is_triangle_removed(tri(h))
    }
    /// Is edge `e` removed? From level 2 only (below, edge ids are the ranks of the live
    /// edges, so every id below the count is live). `false` out of range.
    pub fn is_edge_removed(&self, e: u32) -> bool {
        self.level >= 2 && self.eh.get(e as usize).is_some_and(|&h| h == NONE)
    }

    /// The vertices not removed, in increasing id order (every id of a mesh never edited):
    /// what OpenMesh's and CGAL's `vertices()` iterate. Likewise [`Che::live_triangles`]
    /// and [`Che::live_edges`].
    pub fn live_vertices(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.n_vertices as u32).filter(|&x| !self.is_vertex_removed(x))
    }
    pub fn live_triangles(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.num_triangles() as u32).filter(|&t| !self.is_triangle_removed(t))
    }
    pub fn live_edges(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.num_edges as u32).filter(|&e| !self.is_edge_removed(e))
    }

    /// Live counts: the `num_*` counts are the id bounds until garbage collection.
    pub fn num_live_vertices(&self) -> usize {
        self.edits().map_or(self.n_vertices, |s| s.live_vertices)
    }
    pub fn num_live_triangles(&self) -> usize {
        self.edits()
            .map_or(self.num_triangles(), |s| s.live_triangles)
    }
    pub fn num_live_edges(&self) -> usize {
        self.edits().map_or(self.num_edges, |s| s.live_edges)
    }

    /// Refuses `what` while removed elements wait for [`Self::garbage_collect`]: exports,
    /// writers and level files lay ids out without holes, so they run on a collected mesh.
    pub(crate) fn check_collected(&self, what: &str) -> Result<()> {
        let holes = self.num_live_vertices() != self.n_vertices
            || self.num_live_triangles() != self.num_triangles()
            || self.num_live_edges() != self.num_edges;
        crate::util::structure::refuse_holes(holes, what)
    }

    /// Refuses a mesh changed since its last garbage collection: its arrays are right,
    /// but a level file holds the tables the build's rules define, which only
    /// `garbage_collect` restores.
    pub(crate) fn check_unchanged(&self, what: &str) -> Result<()> {
        crate::util::structure::refuse_edited(self.edits().is_some_and(|s| s.changed), what)
    }

    pub(super) fn live_vertex(&self, x: u32) -> Result<()> {
        self.check_vertex(x)?;
        if self.is_vertex_removed(x) {
            return refuse(format!("vertex {x} is removed"));
        }
        Ok(())
    }
    pub(super) fn live_triangle(&self, t: u32) -> Result<()> {
        self.check_triangle(t)?;
        if self.is_triangle_removed(t) {
            return refuse(format!("triangle {t} is removed"));
        }
        Ok(())
    }
    pub(super) fn live_half_edge(&self, h: u32) -> Result<()> {
        self.check_half_edge(h)?;
        if self.is_half_edge_removed(h) {
            return refuse(format!("half-edge {h} is removed (triangle {})", tri(h)));
        }
        Ok(())
    }

    /// The canonical half-edge of live edge `e`, on the working tables.
    pub(super) fn live_edge(&self, e: u32) -> Result<u32> {
        if self.level >= 2 {
            self.check_edge(e)?;
            return match self.eh[e as usize] {
                NONE => refuse(format!("edge {e} is removed")),
                h => Ok(h),
            };
        }
        crate::util::structure::check_id(e, self.num_live_edges(), "edge", "edges")?;
        Ok(self.nth_live_canonical(&self.o, e))
    }

    /// Is there a half-edge from `a`, the origin of `out` (live), to `b` or from `b` to
    /// `a`? O(degree of `a`). The rotation is walked from `out` both ways at once, a step
    /// each in turn: two chains of loads, each half as long, whose cache misses overlap.
    pub(super) fn adjacent(&self, out: u32, b: u32) -> bool {
        let (v, o) = (&*self.v, &*self.o);
        let hit = |h: u32| v[next(h) as usize] == b || v[prev(h) as usize] == b;
        if hit(out) {
            return true;
        }
        // Counter-clockwise `h -> O[prev(h)]`, clockwise `h -> next(O[h])`; `NONE` once a
        // side has reached the boundary. They stop where they meet.
        let (mut ccw, mut cw) = (out, out);
        while ccw != NONE || cw != NONE {
            if ccw != NONE {
                ccw = o[prev(ccw) as usize];
                if ccw != NONE && (ccw == cw || hit(ccw)) {
                    return ccw != cw;
                }
            }
            if cw != NONE {
                cw = match o[cw as usize] {
                    NONE => NONE,
                    g => next(g),
                };
                if cw != NONE && (cw == ccw || hit(cw)) {
                    return cw != ccw;
                }
            }
        }
        false
    }

    /// Why flipping the edge of half-edge `h` is refused, if it is.
    pub(super) fn flip_refusal(&self, h: u32) -> Option<FlipRefusal> {
        let (v, o) = (&*self.v, &*self.o);
        let g = o[h as usize];
        if g == NONE {
            return Some(FlipRefusal::Boundary);
        }
        let (c, d) = (v[prev(h) as usize], v[prev(g) as usize]);
        if c == d {
            return Some(FlipRefusal::SameThird(c));
        }
        self.touch_flip(h, g);
        // From `c -> a`, in the triangle just read, rather than from `VH[c]`: a cache miss
        // less on the walk that is most of a flip's cost.
        if self.adjacent(prev(h), d) {
            return Some(FlipRefusal::Exists(c, d));
        }
        None
    }

    /// Why collapsing half-edge `h` (its target into its origin) is refused, if it is:
    /// the link condition (the common neighbours of the two ends are the third vertices of
    /// its triangles, and no edge between them is in both links), no edge between two
    /// boundary vertices unless on the boundary, no triangle left with two boundary edges.
    pub(super) fn collapse_refusal(&self, h: u32) -> Result<Option<String>> {
        let (a, b, wings) = self.collapse_wings(h);
        let interior = wings.len() == 2;
        for &w in wings.iter() {
            if [w, next(w), prev(w)].iter().any(|&x| self.is_flagged(x)) {
                return Ok(Some(format!(
                    "half-edge {h}: triangle {} is on a non-manifold edge or seam",
                    tri(w)
                )));
            }
            let (p, q) = (self.o[next(w) as usize], self.o[prev(w) as usize]);
            if p == NONE && q == NONE {
                return Ok(Some(format!(
                    "half-edge {h}: triangle {} would fold onto its boundary",
                    tri(w)
                )));
            }
        }
        let boundary = |x: u32| self.o[self.vh[x as usize] as usize] == NONE;
        if interior && boundary(a) && boundary(b) {
            return Ok(Some(format!(
                "half-edge {h}: interior edge {a}-{b} joins two boundary vertices"
            )));
        }
        let mut thirds = Ids::<2>::new();
        wings
            .iter()
            .for_each(|&w| thirds.push(self.v[prev(w) as usize]));
        if let [c, d] = thirds[..]
            && c == d
        {
            return Ok(Some(format!(
                "half-edge {h}: both triangles have the same third vertex {c}"
            )));
        }
        let links = self.links(a, b, &thirds)?;
        if let Some(y) = links.shared {
            return Ok(Some(format!(
                "half-edge {h}: the link condition fails ({a} and {b} share neighbour {y})"
            )));
        }
        if let [c, d] = thirds[..]
            && links.both_on_thirds
        {
            return Ok(Some(format!(
                "half-edge {h}: the link condition fails (edge {c}-{d} is in both links)"
            )));
        }
        Ok(None)
    }

    /// What the link condition of a collapse of `a -> b` reads of the two stars, in one
    /// walk of each. The ring of `a` is gathered on the stack when it is small, as it
    /// nearly always is.
    fn links(&self, a: u32, b: u32, thirds: &[u32]) -> Result<Links> {
        self.links_in::<32>(a, b, thirds)
    }

    /// `links` with a stack ring of `SMALL` vertices.
    fn links_in<const SMALL: usize>(&self, a: u32, b: u32, thirds: &[u32]) -> Result<Links> {
        // A triangle of the star on the two thirds `c, d`: `c-d` is in that vertex's link.
        let on_thirds =
            |p: u32, q: u32| matches!(thirds, &[c, d] if (p, q) == (c, d) || (p, q) == (d, c));
        let (mut ring, mut n, mut a_on) = ([NONE; SMALL], 0, false);
        let fits = !self.any_neighbour(a, |y, q| {
            a_on |= on_thirds(y, q);
            if n == SMALL {
                return true;
            }
            ring[n] = y;
            n += 1;
            false
        });
        // Past `SMALL` neighbours (a rare hub), the ring goes to a sorted vector instead.
        let mut large = Vec::new();
        if !fits {
            let mut grown = Ok(());
            self.any_neighbour(a, |y, q| {
                a_on |= on_thirds(y, q);
                grown = try_push(&mut large, y, "the ring of a collapsed edge's end");
                grown.is_err()
            });
            grown?;
            large.sort_unstable();
        }
        let around_a = |y: u32| {
            if fits {
                ring[..n].contains(&y)
            } else {
                large.binary_search(&y).is_ok()
            }
        };
        let (mut shared, mut b_on) = (None, false);
        self.any_neighbour(b, |y, q| {
            b_on |= on_thirds(y, q);
            let found = y != a && !thirds.contains(&y) && around_a(y);
            shared = found.then_some(y);
            found
        });
        Ok(Links {
            shared,
            both_on_thirds: a_on && b_on,
        })
    }

    /// Calls `f(y, q)` on the vertices `y` around `x` (each once, in rotation order), with
    /// `q` the third vertex of the triangle `(x, y, q)` of the outgoing half-edge `x -> y`
    /// (`NONE` for the tail of a boundary vertex's incoming boundary half-edge), until it
    /// returns true; true if it did. Allocation-free: the checks run once per flip or
    /// collapse.
    fn any_neighbour(&self, x: u32, mut f: impl FnMut(u32, u32) -> bool) -> bool {
        let mut last = NONE;
        let stopped = self.any_outgoing(x, |h| {
            last = h;
            f(self.v[next(h) as usize], self.v[prev(h) as usize])
        });
        if stopped || last == NONE {
            return stopped;
        }
        // On the boundary the rotation ends at the last outgoing half-edge; the vertex
        // behind it (the tail of the incoming boundary half-edge) is a neighbour too.
        let p = prev(last);
        self.o[p as usize] == NONE && f(self.v[p as usize], NONE)
    }

    /// Can edge `e` be flipped? Never modifies. `Err` for a bad or removed id, `Ok(false)`
    /// when the flip would be refused (see [`Che::flip_edge`]).
    pub fn is_flip_ok(&mut self, e: u32) -> Result<bool> {
        let ok = self.check_with(|c| {
            let h = c.live_edge(e)?;
            Ok(c.flip_refusal(h).is_none())
        });
        self.mark_if_allowed(ok, Checked::Flip(e))
    }

    /// Can half-edge `h` be collapsed? Never modifies; see [`Che::collapse_edge`].
    pub fn is_collapse_ok(&mut self, h: u32) -> Result<bool> {
        let ok = self.check_with(|c| {
            c.live_half_edge(h)?;
            Ok(c.collapse_refusal(h)?.is_none())
        });
        self.mark_if_allowed(ok, Checked::Collapse(h))
    }

    /// A check's answer, with `mark` kept as [`Che::checked`] when it is yes (and no mark
    /// otherwise): the edit that follows may then skip the check.
    fn mark_if_allowed(&mut self, ok: Result<bool>, mark: Checked) -> Result<bool> {
        self.checked = if matches!(ok, Ok(true)) {
            mark
        } else {
            Checked::Nothing
        };
        ok
    }
}

#[cfg(test)]
mod tests {
    use crate::generate::{grid, sphere, torus};
    use crate::{BuildOptions, Che};

    /// The walk both ways from any outgoing half-edge finds exactly the vertices that share
    /// a triangle with its origin, inside and on the boundary, before and after flips.
    #[test]
    fn adjacency_from_any_half_edge_is_brute_force() {
        for s in [grid(4, 3), torus(6, 5), sphere(5, 4), grid(1, 1)] {
            let n = s.positions.len();
            let mut che =
                Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(2)).unwrap();
            for round in 0..3u32 {
                let v = che.half_edge_vertices().to_vec();
                for h in 0..v.len() as u32 {
                    let a = v[h as usize];
                    for b in 0..n as u32 {
                        let brute =
                            b != a && v.chunks_exact(3).any(|t| t.contains(&a) && t.contains(&b));
                        assert_eq!(che.adjacent(h, b), brute, "half-edge {h}, {a} -> {b}");
                    }
                }
                // Some flips, so that degrees vary.
                for e in (round..che.num_edges() as u32).step_by(5) {
                    if che.is_flip_ok(e).unwrap() {
                        che.flip_edge(e).unwrap();
                    }
                }
            }
        }
    }

    /// The shared neighbour found through the stack ring and through the sorted vector of
    /// a hub is the same, for every half-edge of meshes with vertices of degree 3 to 40;
    /// whether both stars hold a triangle on the thirds is what a scan of every triangle
    /// says (where no shared neighbour stopped the walk of `b`).
    #[test]
    fn links_on_the_stack_or_in_a_vector_agree_with_a_scan() {
        // The surface of a tetrahedron: every edge's thirds span a triangle on both ends.
        let tetrahedron = crate::generate::Surface {
            positions: vec![glam::DVec3::ZERO; 4],
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        };
        let build = |s: crate::generate::Surface| {
            let n = s.positions.len();
            Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(2)).unwrap()
        };
        // A triangle split: its new vertex has degree 3, its corners more.
        let mut split = build(torus(6, 5));
        split.split_triangle(0, None).unwrap();
        let meshes = [
            sphere(40, 4),
            torus(6, 5),
            grid(4, 3),
            sphere(5, 4),
            tetrahedron,
        ];
        let mut both = 0;
        for che in meshes.into_iter().map(build).chain([split]) {
            let v = che.half_edge_vertices();
            let on = |x: u32, c: u32, d: u32| {
                che.live_triangles().any(|t| {
                    let q = che.triangle_vertices(t);
                    [x, c, d].iter().all(|y| q.contains(y))
                })
            };
            for h in (0..v.len() as u32).filter(|&h| !che.is_half_edge_removed(h)) {
                let (a, b) = (v[h as usize], v[crate::che::ids::next(h) as usize]);
                let (c, g) = (v[crate::che::ids::prev(h) as usize], che.opposite(h));
                let mut thirds = vec![c];
                if g != crate::NONE {
                    thirds.push(v[crate::che::ids::prev(g) as usize]);
                }
                let stack = che.links_in::<64>(a, b, &thirds).unwrap();
                let heap = che.links_in::<1>(a, b, &thirds).unwrap();
                let chosen = che.links(a, b, &thirds).unwrap();
                for l in [&heap, &chosen] {
                    assert_eq!(l.shared, stack.shared, "half-edge {h}");
                    assert_eq!(l.both_on_thirds, stack.both_on_thirds, "half-edge {h}");
                }
                if let (&[c, d], None) = (&thirds[..], stack.shared) {
                    assert_eq!(
                        stack.both_on_thirds,
                        on(a, c, d) && on(b, c, d),
                        "half-edge {h}"
                    );
                    both += stack.both_on_thirds as usize;
                }
            }
        }
        // The tetrahedron says yes for each of its 12 half-edges: the comparison can fail.
        assert!(both >= 12, "{both}");
    }
}
