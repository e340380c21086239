//! The 1-4 split: a new vertex inside a tetrahedron, joined to its four faces.
//!
//! The split tetrahedron keeps its id, as a split triangle of a CHE and a cell of CGAL's
//! `insert_in_cell` do: `t = (q0, q1, q2, q3)` becomes `(x, q1, q2, q3)`, and
//! `(q0, x, q2, q3)`, `(q0, q1, x, q3)`, `(q0, q1, q2, x)` are appended in that order.
//! Written in place, the split touches only what changes: face 0 of `t` stays as it is,
//! faces 1-3 move to the new tetrahedra that hold them, and an edge of `t` keeps its
//! canonical half-edge unless that lay where the edge no longer is, so the fan walks
//! that find a canonical half-edge again are the exception.

use super::arrays;
use super::cavity::pairs;
use super::plan::{Plan, Shape, replaced};
use super::refusal::{Named, context};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{EDGE, edge_index, first, he_face, local, slot_half_edges, tet};
use crate::error::Result;
use glam::DVec3;

/// The id of piece `k` of a split of `t` (the one holding the new vertex in place of
/// corner `k`), the new tetrahedra starting at `bound`.
fn piece(t: u32, bound: u32, k: u32) -> u32 {
    if k == 0 { t } else { bound + k - 1 }
}

impl Chf {
    pub(super) fn plan_split_tetrahedron(&self, t: u32, position: Option<DVec3>) -> Result<Plan> {
        self.check_tetrahedron(t)?;
        let q = self.tetrahedron_vertices(t);
        let (mut plan, x) = self.split_plan(position, &q)?;
        plan.remove.push(t);
        plan.add.extend(q.map(|c| replaced(q, c, x)));
        plan.shape = Shape::OneToFour;
        Ok(plan)
    }

    /// Splits tetrahedron `t` in four at a new vertex (returned), at `position` or the
    /// centroid; refused when the position is not strictly inside. `t` keeps its id and
    /// becomes the piece without its vertex 0; the other three pieces are appended (see
    /// the module doc). O(1) stars.
    pub fn split_tetrahedron(&mut self, t: u32, position: Option<DVec3>) -> Result<u32> {
        self.touch_split(t);
        let plan = self.plan_split_tetrahedron(t, position)?;
        self.check_plan(&plan).map_err(context(
            "split_tetrahedron",
            Named("tetrahedron", u64::from(t)),
        ))?;
        self.split_in_place(t, &plan)
    }

    /// Would [`Chf::split_tetrahedron`] succeed? Changes nothing.
    pub fn check_split_tetrahedron(&self, t: u32, position: Option<DVec3>) -> Result<()> {
        let plan = self.plan_split_tetrahedron(t, position)?;
        self.check_plan(&plan).map_err(context(
            "split_tetrahedron",
            Named("tetrahedron", u64::from(t)),
        ))
    }

    /// Reads at once, before the check, what the check and the writes will read one
    /// after the other (`t`'s mark, corners and positions, and what
    /// `touch_cavity` reads), so that the cache misses overlap. Only on an edited
    /// mesh: the first edit makes the state that the writes read.
    fn touch_split(&self, t: u32) {
        let Some(s) = self.edit.as_deref() else {
            return;
        };
        // The check refuses a removed tetrahedron, whose ids are gone.
        if s.tet_removed.get(t as usize).is_none_or(|removed| removed) {
            return;
        }
        let mut sum = 0;
        for x in self.tetrahedron_vertices(t) {
            sum ^= self.positions.get(x as usize).map_or(0, |p| p.x.to_bits());
        }
        std::hint::black_box(sum);
        self.touch_cavity(&[t]);
    }

    /// Writes the checked 1-4 split `plan` of `t`; the new vertex. Allocation failures
    /// are reported before anything is written.
    fn split_in_place(&mut self, t: u32, plan: &Plan) -> Result<u32> {
        self.reserve_for(plan)?;
        let x = self.n_vertices as u32;
        self.push_new_vertex(plan.new_vertex.expect("a split adds a vertex"))?;
        let q = self.tetrahedron_vertices(t);
        let open = [0, 1, 2, 3].map(|i| self.o[(first(t) + i) as usize] == NONE);
        let old_edges = self.old_edge_slots(&[t]);
        let bound = self.num_tetrahedra() as u32;
        let piece = |k: u32| piece(t, bound, k);
        for k in 1..4 {
            self.push_new_tetrahedron(replaced(q, q[k], x))?;
        }
        for k in 1..4 {
            self.move_face(first(t) + k, first(piece(k)) + k);
        }
        arrays::set_corner(self, first(t), x);
        for i in 0..4 {
            for k in i + 1..4 {
                self.pair_as_new_face(first(piece(i)) + k, first(piece(k)) + i);
            }
        }
        self.number_split_edges(t, bound, q, old_edges.as_slice(), open);
        self.point_split_vertices(t, bound, q, x);
        let s = self.edit.as_ref().expect("edited");
        self.num_faces = s.face_hf.len();
        self.num_edges = s.edge_he.len();
        Ok(x)
    }

    /// Edge ids of the four pieces: the six pairs of `t` keep theirs (`old`, by slot of
    /// `t`), the four pairs of the new vertex get new ones. A kept pair finds its
    /// canonical half-edge again only where it lay in `t` and no longer does: on a pair
    /// `t` lost, or on a face of `t` that moved to a piece and was on the boundary (`open`).
    fn number_split_edges(
        &mut self, t: u32, bound: u32, q: [u32; 4], old: &[((u32, u32), u32)], open: [bool; 4],
    ) {
        let piece = |k: u32| piece(t, bound, k);
        let s = self.edit.as_mut().expect("edited");
        let fresh = s.edge_he.len() as u32;
        // Edge `fresh + j` joins `q[j]` to the new vertex. Its fan is closed and made of
        // pieces: the canonical half-edge is the smaller one of its slot in the first
        // piece holding it (piece 1 for `q[0]`, `t` for the others).
        s.edge_he
            .push(slot_half_edges(6 * bound as u64 + edge_index(0, 1) as u64)[0]);
        for j in 1..4 {
            s.edge_he
                .push(slot_half_edges(6 * t as u64 + edge_index(0, j) as u64)[0]);
        }
        s.live_edges += 4;
        for k in 0..4 {
            let p = piece(k);
            let pairs = pairs(self.tetrahedron_vertices(p));
            let s = self.edit.as_mut().expect("edited");
            for (l, pair) in pairs.into_iter().enumerate() {
                let id = match old.iter().find(|(o, _)| *o == pair) {
                    Some(&(_, e)) => e,
                    // The new vertex has the largest id: `pair.0` is the corner.
                    None => fresh + q.iter().position(|&c| c == pair.0).expect("a corner") as u32,
                };
                s.slot_edge[6 * p as usize + l] = id;
            }
        }
        for (l, &(_, e)) in old.iter().enumerate() {
            let he = self.edit.as_ref().expect("edited").edge_he[e as usize];
            let [a, b] = EDGE[l];
            if tet(he_face(he)) != t {
                continue;
            }
            if a == 0 {
                // The pair left `t`; a piece holding it has it in the same slot.
                let m = (1..4).find(|&m| m != b).expect("a third corner");
                self.set_canonical(e, 6 * piece(m) as u64 + l as u64);
            } else if open[local(he_face(he)) as usize] && local(he_face(he)) != 0 {
                self.set_canonical(e, 6 * t as u64 + l as u64);
            }
        }
    }

    /// `VH` of the corners whose half-face moved, and of the new vertex.
    fn point_split_vertices(&mut self, t: u32, bound: u32, q: [u32; 4], x: u32) {
        for c in q {
            let hf = self.vh[c as usize];
            let k = local(hf);
            if tet(hf) == t && k != 0 {
                // Face k of `t` is face k of piece k now (a boundary one stays one).
                arrays::set_vertex_half_face(self, c, first(piece(t, bound, k)) + k);
            }
        }
        arrays::set_vertex_half_face(self, x, first(t) + 1);
    }
}

#[cfg(test)]
mod tests {
    use crate::chf::Chf;

    /// The live tetrahedra as sorted vertex quadruples, sorted.
    fn quads(chf: &Chf) -> Vec<[u32; 4]> {
        let mut out: Vec<[u32; 4]> = (0..chf.num_tetrahedra() as u32)
            .filter(|&t| !chf.is_tetrahedron_removed(t))
            .map(|t| {
                let mut q = chf.tetrahedron_vertices(t);
                q.sort_unstable();
                q
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// Splits written in place leave the tetrahedra that the same splits run as plans
    /// (remove one, append four) leave, and a valid mesh after each, at every level, on
    /// a grid with a boundary, with and without positions.
    #[test]
    fn a_split_in_place_is_the_planned_split() {
        for (level, positions) in (0..=3).flat_map(|l| [(l, true), (l, false)]) {
            let build = || crate::chf::edit::test_grid(2, level, positions);
            let (mut fast, mut planned) = (build(), build());
            let mut rng = 5u64;
            for step in 0..80 {
                rng = rng
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let live = quads(&fast);
                let q = live[(rng >> 33) as usize % live.len()];
                let find = |chf: &Chf| {
                    (0..chf.num_tetrahedra() as u32)
                        .find(|&t| {
                            let mut r = chf.tetrahedron_vertices(t);
                            r.sort_unstable();
                            !chf.is_tetrahedron_removed(t) && r == q
                        })
                        .expect("the same tetrahedron")
                };
                let (t, s) = (find(&fast), find(&planned));
                let x = fast.split_tetrahedron(t, None).unwrap();
                let plan = planned.plan_split_tetrahedron(s, None).unwrap();
                planned.run(plan).unwrap();
                assert_eq!(x as usize, planned.num_vertices() - 1);
                fast.validate().unwrap();
                assert_eq!(quads(&fast), quads(&planned), "level {level}, step {step}");
                assert_eq!(
                    fast.summary(),
                    planned.summary(),
                    "level {level}, step {step}"
                );
            }
            fast.garbage_collect().unwrap();
            fast.validate().unwrap();
            assert_eq!(quads(&fast), quads(&planned), "level {level}");
        }
    }
}
