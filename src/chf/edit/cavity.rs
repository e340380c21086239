//! The fast form of a plan that re-triangulates a cavity: the removed tetrahedra, and new
//! ones that fill the same region with the same boundary faces (the 1-4 split, the 2-3 and
//! 3-2 flips, the interior face and edge splits). Such a plan cannot change the topology of
//! any star outside the cavity, so it needs none of the star walks of the generic check
//! ([`Chf::verify`]): matching the new half-faces with the cavity's boundary and with one
//! another, and asking whether a new interior edge or face exists already elsewhere, is the
//! whole check. The writes then move each boundary face of the cavity to the new
//! half-face that takes its place, keeping its face id and its twin, and recompute a
//! canonical half-edge only where it lay in a removed tetrahedron: O(1) per operation,
//! plus one star walk for a new edge or face whose vertices all exist already.
//!
//! A plan of another shape (one that opens or closes the boundary, retires or strands a
//! vertex), or a mesh whose build flagged non-manifold faces, seams or edges with several
//! fans, goes to the generic check, which decides the same way (a test compares them).

use super::arrays;
use super::plan::{Plan, Shape, cycle, same_way, sorted3};
use super::refusal::refuse_as;
use super::state::{canonical_half_edge, for_each_fan_slot};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{
    EDGE, HalfEdge, NO_HALF_EDGE, face_cycle, first, he_face, slot_half_edges, tet,
};
use crate::chf::query::star::Star;
use crate::chf::query::view::{Need, View};
use crate::error::{ErrorKind, Result};

/// The largest cavity taken here (larger ones go to the generic check): every list of
/// the check and the writes then fits in a fixed array on the stack, so that an operation
/// allocates nothing but its result.
const MAX_REMOVE: usize = 8;
const MAX_ADD: usize = 16;

/// A list of at most `N` items, on the stack.
#[derive(Clone, Copy)]
pub(super) struct Small<T: Copy + Default, const N: usize> {
    items: [T; N],
    len: usize,
}

impl<T: Copy + Default, const N: usize> Small<T, N> {
    fn new() -> Self {
        Small {
            items: [T::default(); N],
            len: 0,
        }
    }
    fn push(&mut self, x: T) {
        self.items[self.len] = x;
        self.len += 1;
    }
    pub(super) fn as_slice(&self) -> &[T] {
        &self.items[..self.len]
    }
}

/// A checked cavity plan: where each new half-face goes.
pub(crate) struct Cavity {
    /// Per new half-face `4k + i`: the boundary half-face of the cavity it replaces
    /// (a half-face of a removed tetrahedron), or the new half-face it pairs with
    /// (post-edit id, at least `4 * bound`).
    link: Small<u32, { 4 * MAX_ADD }>,
}

/// A pair's edge id, and whether a new tetrahedron holds the pair.
pub(super) type EdgeIds = Small<((u32, u32), u32), { 6 * MAX_ADD }>;

/// A vertex pair, smaller id first.
fn pair(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The six vertex pairs of `q`.
pub(super) fn pairs(q: [u32; 4]) -> [(u32, u32); 6] {
    EDGE.map(|[p, r]| pair(q[p as usize], q[r as usize]))
}

/// The link of a 1-4 split of `t` ([`Shape::OneToFour`]), new tetrahedra from `bound` on:
/// face `k` of new tetrahedron `k` (opposite the new vertex) replaces face `k` of `t`,
/// and face `i` of it pairs with face `k` of new tetrahedron `i` (both hold the new vertex
/// and the two corners other than `i` and `k`). Nothing to search, and nothing inside the
/// cavity can exist already: every new edge and face holds the new vertex.
fn one_to_four_link(t: u32, bound: u32) -> Small<u32, { 4 * MAX_ADD }> {
    let mut link = Small::new();
    for k in 0..4 {
        for i in 0..4 {
            link.push(if i == k {
                first(t) + k
            } else {
                4 * (bound + i) + k
            });
        }
    }
    link
}

impl Chf {
    /// The cavity form of `plan`: `Ok(None)` when it is not one (the generic check
    /// decides), an error when it is one and is refused. Writes nothing.
    pub(crate) fn verify_cavity(&self, plan: &Plan) -> Result<Option<Cavity>> {
        let simple = self.non_manifold.is_empty() && self.seams.is_empty();
        if !simple || !self.multi_fan.is_empty() || !plan.retire.is_empty() {
            return Ok(None);
        }
        let sizes = 1..=MAX_REMOVE;
        if !sizes.contains(&plan.remove.len()) || plan.add.len() > MAX_ADD {
            return Ok(None);
        }
        self.verify_inputs(plan)?;
        if plan.shape == Shape::OneToFour {
            return Ok(Some(Cavity {
                link: one_to_four_link(plan.remove[0], self.num_tetrahedra() as u32),
            }));
        }
        let view = self.try_view(Need::NOTHING)?;
        let Some(link) = self.link_half_faces(plan, &view.o) else {
            return Ok(None);
        };
        let mut old = Small::<[u32; 4], MAX_REMOVE>::new();
        for &t in &plan.remove {
            old.push(self.tetrahedron_vertices(t));
        }
        let kept = |x: u32| plan.add.iter().any(|q| q.contains(&x));
        if !old.as_slice().iter().flatten().all(|&x| kept(x)) {
            return Ok(None);
        }
        self.check_new_interior(plan, old.as_slice(), &view)?;
        Ok(Some(Cavity { link }))
    }

    /// Matches every new half-face with the cavity boundary face it replaces (same
    /// vertices, same way) or with the one other new half-face on its vertices (the
    /// other way); `None` unless every boundary face is replaced exactly once.
    fn link_half_faces(&self, plan: &Plan, o: &[u32]) -> Option<Small<u32, { 4 * MAX_ADD }>> {
        let removed = |g: u32| g != NONE && plan.remove.contains(&tet(g));
        let mut outer = Small::<([u32; 3], u32), { 4 * MAX_REMOVE }>::new();
        for &t in &plan.remove {
            for hf in first(t)..first(t) + 4 {
                if !removed(o[hf as usize]) {
                    outer.push((sorted3(face_cycle(&self.v, hf)), hf));
                }
            }
        }
        let bound = 4 * self.num_tetrahedra() as u32;
        let outer = outer.as_slice();
        let mut used = [false; 4 * MAX_REMOVE];
        let n = 4 * plan.add.len();
        let mut link = Small::<u32, { 4 * MAX_ADD }>::new();
        let mut keys = [[0u32; 3]; 4 * MAX_ADD];
        for (h, key) in keys[..n].iter_mut().enumerate() {
            *key = sorted3(cycle(plan.add[h / 4], (h % 4) as u32));
        }
        for h in 0..n {
            let c = cycle(plan.add[h / 4], (h % 4) as u32);
            if let Some(k) = outer.iter().position(|(key, _)| *key == keys[h]) {
                let old = outer[k].1;
                if used[k] || !same_way(c, face_cycle(&self.v, old)) {
                    return None;
                }
                used[k] = true;
                link.push(old);
                continue;
            }
            let mut others = (0..n).filter(|&j| j != h && keys[j] == keys[h]);
            let j = others.next()?;
            let d = cycle(plan.add[j / 4], (j % 4) as u32);
            if others.next().is_some() || same_way(c, d) {
                return None;
            }
            link.push(bound + j as u32);
        }
        used[..outer.len()].iter().all(|&u| u).then_some(link)
    }

    /// Refuses a new interior edge or face that exists already outside the cavity (it
    /// would be held twice). One that holds the new vertex cannot exist. Each is looked
    /// for once, though several new tetrahedra hold it (the apexes' edge of a 2-3 flip is
    /// in all three): the search walks a star or a fan, the cost of the whole check.
    fn check_new_interior(&self, plan: &Plan, old: &[[u32; 4]], view: &View) -> Result<()> {
        let fresh = plan.new_vertex.map(|_| self.n_vertices as u32);
        let old_pair = |a: u32, b: u32| old.iter().any(|q| q.contains(&a) && q.contains(&b));
        let mut edges = Small::<(u32, u32), { 6 * MAX_ADD }>::new();
        let mut faces = Small::<[u32; 3], { 4 * MAX_ADD }>::new();
        for q in &plan.add {
            for (a, b) in pairs(*q) {
                let new_edge = Some(a) != fresh && Some(b) != fresh && !old_pair(a, b);
                if !new_edge || edges.as_slice().contains(&(a, b)) {
                    continue;
                }
                edges.push((a, b));
                if self.star_holds(view, plan, a, &[b])? {
                    return Err(refuse_as(
                        ErrorKind::NonManifold,
                        format_args!("edge ({a}, {b}) exists already"),
                    ));
                }
            }
            for i in 0..4 {
                let key = sorted3(cycle(*q, i));
                let new_pair = |a: u32, b: u32| !old_pair(a, b);
                let holds_old_face = old.iter().any(|o| key.iter().all(|x| o.contains(x)));
                if key.iter().any(|&x| Some(x) == fresh)
                    || holds_old_face
                    || new_pair(key[0], key[1])
                    || new_pair(key[0], key[2])
                    || new_pair(key[1], key[2])
                    || faces.as_slice().contains(&key)
                {
                    continue;
                }
                faces.push(key);
                if self.fan_holds(view, plan, old, key) {
                    return Err(refuse_as(
                        ErrorKind::NonManifold,
                        format_args!("face {key:?} would have three tetrahedra"),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Does a tetrahedron outside the cavity hold the triangle `key`, whose first pair is
    /// a pair of the removed tetrahedra `old`? It would lie in that pair's one fan.
    fn fan_holds(&self, view: &View, plan: &Plan, old: &[[u32; 4]], key: [u32; 3]) -> bool {
        let (k, q) = old
            .iter()
            .enumerate()
            .find(|(_, q)| q.contains(&key[0]) && q.contains(&key[1]))
            .expect("an old pair");
        let l = pairs(*q)
            .iter()
            .position(|&p| p == pair(key[0], key[1]))
            .expect("the pair's slot");
        let slot = 6 * plan.remove[k] as u64 + l as u64;
        let mut found = false;
        for_each_fan_slot(&self.v, &view.o, slot_half_edges(slot)[0], |s| {
            let t = (s / 6) as u32;
            found |= !plan.remove.contains(&t) && self.tetrahedron_vertices(t).contains(&key[2]);
        });
        found
    }

    /// Does a tetrahedron of the star of `x` outside the cavity hold every vertex of
    /// `others`?
    fn star_holds(&self, view: &View, plan: &Plan, x: u32, others: &[u32]) -> Result<bool> {
        let mut star = Star::new(x, view.start_half_face(x));
        while let Some((t, _)) = star.next(view, |_| 0) {
            let q = self.tetrahedron_vertices(t);
            if !plan.remove.contains(&t) && others.iter().all(|y| q.contains(y)) {
                return Ok(true);
            }
        }
        star.complete()?;
        Ok(false)
    }
}

impl Chf {
    /// Applies a checked cavity plan; returns the ids of the new tetrahedra. Allocation
    /// failures are reported before anything is written.
    pub(crate) fn commit_cavity(&mut self, plan: Plan, cavity: Cavity) -> Result<Vec<u32>> {
        let bound = self.num_tetrahedra() as u32;
        self.edit_state()?;
        self.reserve_for(&plan)?;
        if let Some(p) = plan.new_vertex {
            self.push_new_vertex(p)?;
        }
        self.touch_cavity(&plan.remove);
        let old_edges = self.old_edge_slots(&plan.remove);
        for &q in &plan.add {
            self.push_new_tetrahedron(q)?;
        }
        self.link_faces(bound, cavity.link.as_slice());
        self.retire_cavity(&plan.remove);
        self.number_cavity_edges(bound, &plan, old_edges);
        self.point_cavity_vertices(bound, &plan);
        let s = self.edit.as_ref().expect("edited");
        self.num_faces = s.face_hf.len();
        self.num_edges = s.edge_he.len();
        Ok((bound..bound + plan.add.len() as u32).collect())
    }

    /// Reads, at once, what the writes will read one after the other (the twins of the
    /// cavity, the half-faces of its vertices, the canonical elements of its faces and
    /// edges): scattered over a large mesh, each is a cache miss, and issued together the
    /// misses overlap instead of queueing behind one another.
    pub(super) fn touch_cavity(&self, remove: &[u32]) {
        let s = self.edit.as_ref().expect("edited");
        let mut sum = 0u32;
        for &t in remove {
            for hf in first(t)..first(t) + 4 {
                let g = self.o[hf as usize];
                sum ^= self.o.get(g as usize).copied().unwrap_or(0);
                sum ^= self.vh[self.v[hf as usize] as usize];
                sum ^= s.face_hf[s.hf_face[hf as usize] as usize];
            }
            for k in 0..6 {
                let e = s.slot_edge[6 * t as usize + k];
                sum ^= s.edge_he[e as usize] as u32;
            }
        }
        std::hint::black_box(sum);
    }

    /// Each removed pair with its edge id, read before the removal.
    pub(super) fn old_edge_slots(&self, remove: &[u32]) -> EdgeIds {
        let s = self.edit.as_ref().expect("edited");
        let mut out = EdgeIds::new();
        for &t in remove {
            for (k, p) in pairs(self.tetrahedron_vertices(t)).into_iter().enumerate() {
                if !out.as_slice().iter().any(|(q, _)| *q == p) {
                    out.push((p, s.slot_edge[6 * t as usize + k]));
                }
            }
        }
        out
    }

    /// `O` and the face ids of the new half-faces: a replaced boundary face keeps its id
    /// and its twin; each pair of new half-faces is a new face.
    fn link_faces(&mut self, bound: u32, link: &[u32]) {
        for (k, &g) in link.iter().enumerate() {
            let h = 4 * bound + k as u32;
            if g < 4 * bound {
                self.move_face(g, h);
            } else if h < g {
                self.pair_as_new_face(h, g);
            }
        }
    }

    /// Pairs half-faces `h < g` as a new face.
    pub(super) fn pair_as_new_face(&mut self, h: u32, g: u32) {
        arrays::set_opposite(self, h, g);
        arrays::set_opposite(self, g, h);
        let s = self.edit.as_mut().expect("edited");
        let f = s.face_hf.len() as u32;
        s.face_hf.push(h);
        s.hf_face[h as usize] = f;
        s.hf_face[g as usize] = f;
        s.live_faces += 1;
    }

    /// Half-face `new` takes the place of `old`: its twin, its face id.
    pub(super) fn move_face(&mut self, old: u32, new: u32) {
        let g = self.o[old as usize];
        arrays::set_opposite(self, new, g);
        if g == NONE {
            self.note_unpaired(new);
        } else {
            arrays::set_opposite(self, g, new);
        }
        let s = self.edit.as_mut().expect("edited");
        let f = s.hf_face[old as usize];
        s.hf_face[new as usize] = f;
        // The canonical half-face is the smaller of the two; `new` is larger than `old`,
        // so a twin smaller than `old` stays canonical and `face_hf` is not even read.
        if g == NONE || g > old {
            s.face_hf[f as usize] = if g != NONE && g < new { g } else { new };
        }
    }

    /// Marks the removed tetrahedra: their own twins, no ids; the faces inside the cavity
    /// are gone (the boundary ones moved on).
    fn retire_cavity(&mut self, remove: &[u32]) {
        for &t in remove {
            for hf in first(t)..first(t) + 4 {
                let g = self.o[hf as usize];
                let s = self.edit.as_mut().expect("edited");
                let f = std::mem::replace(&mut s.hf_face[hf as usize], NONE);
                let inside = g != NONE && remove.contains(&tet(g)) && g != hf;
                if inside && s.face_hf[f as usize] != NONE {
                    s.face_hf[f as usize] = NONE;
                    s.live_faces -= 1;
                }
                arrays::set_opposite(self, hf, hf);
            }
            let s = self.edit.as_mut().expect("edited");
            s.tet_removed.set(t as usize);
            s.live_tetrahedra -= 1;
            s.slot_edge[6 * t as usize..6 * t as usize + 6].fill(NONE);
        }
    }

    /// Edge ids of the new slots: a pair of the cavity keeps its id (its canonical
    /// half-edge found again when it lay in a removed tetrahedron), a new pair gets a new
    /// id, and a pair no new tetrahedron holds is gone.
    fn number_cavity_edges(&mut self, bound: u32, plan: &Plan, old: EdgeIds) {
        let old = old.as_slice();
        let mut fresh = EdgeIds::new();
        let mut seen = [false; 6 * MAX_REMOVE];
        for (k, &q) in plan.add.iter().enumerate() {
            for (l, p) in pairs(q).into_iter().enumerate() {
                let slot = 6 * (bound as u64 + k as u64) + l as u64;
                let id = match old.iter().position(|(o, _)| *o == p) {
                    Some(i) => {
                        seen[i] = true;
                        old[i].1
                    }
                    None => self.fresh_edge(&mut fresh, p),
                };
                self.edit.as_mut().expect("edited").slot_edge[slot as usize] = id;
            }
        }
        for (i, &(_, e)) in old.iter().enumerate() {
            let s = self.edit.as_mut().expect("edited");
            let he = s.edge_he[e as usize];
            if !seen[i] {
                s.edge_he[e as usize] = NO_HALF_EDGE;
                s.live_edges -= 1;
            } else if plan.remove.contains(&tet(he_face(he))) {
                let slot = self.slot_holding(bound, plan, old[i].0);
                self.set_canonical(e, slot);
            }
        }
        for &(p, e) in fresh.as_slice() {
            let slot = self.slot_holding(bound, plan, p);
            self.set_canonical(e, slot);
        }
    }

    /// The id of new pair `p`: the one given to it already, or a new one.
    fn fresh_edge(&mut self, fresh: &mut EdgeIds, p: (u32, u32)) -> u32 {
        if let Some(&(_, e)) = fresh.as_slice().iter().find(|(q, _)| *q == p) {
            return e;
        }
        let s = self.edit.as_mut().expect("edited");
        let e = s.edge_he.len() as u32;
        s.edge_he.push(NO_HALF_EDGE);
        s.live_edges += 1;
        fresh.push((p, e));
        e
    }

    /// A slot of the new tetrahedra on pair `p`.
    fn slot_holding(&self, bound: u32, plan: &Plan, p: (u32, u32)) -> u64 {
        for (k, &q) in plan.add.iter().enumerate() {
            if let Some(l) = pairs(q).iter().position(|&r| r == p) {
                return 6 * (bound as u64 + k as u64) + l as u64;
            }
        }
        unreachable!("the pair is held by a new tetrahedron")
    }

    /// Edge `e`'s canonical half-edge by the build's rule, found from its slot `slot`.
    pub(super) fn set_canonical(&mut self, e: u32, slot: u64) {
        let he: HalfEdge = canonical_half_edge(&self.v, &self.o, slot_half_edges(slot)[0]);
        self.edit.as_mut().expect("edited").edge_he[e as usize] = he;
    }

    /// `VH` of every vertex of the new tetrahedra whose half-face was removed (or that is
    /// new): a half-face of the new ones holding it, a boundary one if any (the cavity
    /// keeps its boundary faces, so a boundary vertex finds one there).
    fn point_cavity_vertices(&mut self, bound: u32, plan: &Plan) {
        for q in &plan.add {
            for &x in q {
                // `VH` never names a tetrahedron removed before this edit.
                let hf = self.vh[x as usize];
                if hf != NONE && !plan.remove.contains(&tet(hf)) {
                    continue;
                }
                let holding = (4 * bound..4 * (bound + plan.add.len() as u32)).filter(|&h| {
                    self.v[h as usize] != x && plan.add[(tet(h) - bound) as usize].contains(&x)
                });
                let mut best = NONE;
                for h in holding {
                    if self.o[h as usize] == NONE {
                        best = h;
                        break;
                    }
                    if best == NONE {
                        best = h;
                    }
                }
                arrays::set_vertex_half_face(self, x, best);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::NONE;
    use crate::chf::Chf;
    use crate::chf::edit::plan::Plan;
    use crate::chf::query::view::Need;
    use crate::error::Result;

    fn next(s: &mut u64) -> u64 {
        *s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = *s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A random operation's plan on live ids: a split of a tetrahedron, face or edge, or a
    /// flip.
    fn random_plan(chf: &Chf, rng: &mut u64) -> Result<Plan> {
        let live = |n: usize, dead: &dyn Fn(u32) -> bool, rng: &mut u64| loop {
            let x = (next(rng) % n as u64) as u32;
            if !dead(x) {
                break x;
            }
        };
        let t = live(
            chf.num_tetrahedra(),
            &|t| chf.is_tetrahedron_removed(t),
            rng,
        );
        let f = live(chf.num_faces(), &|f| chf.is_face_removed(f), rng);
        let e = live(chf.num_edges(), &|e| chf.is_edge_removed(e), rng);
        match next(rng) % 6 {
            0 => chf.plan_split_tetrahedron(t, None),
            1 => chf.plan_split_face(f, None),
            2 => chf.plan_split_edge(e, None),
            3 | 4 => chf.plan_flip_23(f),
            _ => chf.plan_flip_32(e),
        }
    }

    /// On random operations over a grid with and without positions, the cavity check
    /// accepts only what the generic check accepts and refuses only what it refuses; it
    /// takes most plans, and a boundary face of a cavity keeps its id and its vertices.
    #[test]
    fn the_cavity_check_agrees_with_the_generic_one() {
        let (mut taken, mut refused) = (0, 0);
        for positions in [true, false] {
            let mut chf = crate::chf::edit::test_grid(4, 2, positions);
            let mut rng = 7;
            for _ in 0..3000 {
                let Ok(plan) = random_plan(&chf, &mut rng) else {
                    continue;
                };
                let generic = chf.verify(plan.clone()).is_ok();
                let mut kept = Vec::new();
                match chf.verify_cavity(&plan) {
                    Ok(Some(_)) => {
                        assert!(generic, "the cavity check accepts {plan:?}");
                        taken += 1;
                        kept = boundary_faces(&chf, &plan);
                    }
                    Err(e) => {
                        assert!(!generic, "the cavity check refuses {plan:?}: {e}");
                        refused += 1;
                    }
                    Ok(None) => {}
                }
                if chf.run(plan).is_ok() {
                    for (f, tri) in kept {
                        assert!(!chf.is_face_removed(f));
                        let mut now = chf.face_vertices(f);
                        now.sort_unstable();
                        assert_eq!(now, tri, "face {f}");
                    }
                }
            }
            chf.validate().unwrap();
        }
        assert!(
            taken > 2000 && refused > 100,
            "{taken} taken, {refused} refused"
        );
    }

    /// The link a 1-4 split is given is the one the search finds, on a mesh with a
    /// boundary, with and without positions.
    #[test]
    fn a_one_to_four_link_is_the_searched_one() {
        for positions in [true, false] {
            let mut chf = crate::chf::edit::test_grid(3, 2, positions);
            let mut rng = 11;
            for _ in 0..300 {
                let t = (next(&mut rng) % chf.num_tetrahedra() as u64) as u32;
                if chf.is_tetrahedron_removed(t) {
                    continue;
                }
                let plan = chf.plan_split_tetrahedron(t, None).unwrap();
                let view = chf.try_view(Need::NOTHING).unwrap();
                let searched = chf.link_half_faces(&plan, &view.o).expect("a cavity");
                let known = super::one_to_four_link(t, chf.num_tetrahedra() as u32);
                assert_eq!(searched.as_slice(), known.as_slice(), "tetrahedron {t}");
                chf.split_tetrahedron(t, None).unwrap();
            }
            chf.validate().unwrap();
        }
    }

    /// The faces on the cavity's boundary, with their sorted vertices.
    fn boundary_faces(chf: &Chf, plan: &Plan) -> Vec<(u32, [u32; 3])> {
        let mut out = Vec::new();
        for &t in &plan.remove {
            for hf in 4 * t..4 * t + 4 {
                let g = chf.opposite(hf);
                if g == NONE || !plan.remove.contains(&(g / 4)) {
                    let mut tri = chf.half_face_vertices_of(hf);
                    tri.sort_unstable();
                    out.push((chf.face_of(hf), tri));
                }
            }
        }
        out
    }
}
