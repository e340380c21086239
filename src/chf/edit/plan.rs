//! An edit as a transaction: tetrahedra to remove, tetrahedra to add (new ones take the
//! ids after the last), maybe a vertex to create first and vertices to retire after.
//! [`Chf::verify`] checks it without writing anything; [`Chf::commit`] applies a verified
//! plan by local updates.

use super::arrays;
use super::refusal::{Corners, context, refuse, refuse_as};
use super::state::canonical_half_edge;
use crate::NONE;
use crate::chf::Chf;
use crate::chf::geometry::orient_of;
use crate::chf::ids::{EDGE, FACE, edge_index, first, slot_half_edges, tet};
use crate::chf::query::star::Star;
use crate::chf::query::view::{Need, View};
use crate::error::{Error, ErrorKind, Result};
use crate::util::alloc::{try_collect, try_extend, try_push, try_vec, try_with_capacity};
use glam::DVec3;

/// What an operation does, before it is checked.
#[derive(Clone, Debug, Default)]
pub(crate) struct Plan {
    pub remove: Vec<u32>,
    pub add: Vec<[u32; 4]>,
    /// A vertex to create first (id `n_vertices`), with its position when the mesh has
    /// positions.
    pub new_vertex: Option<Option<DVec3>>,
    /// Vertices to retire afterwards (they end with no tetrahedron).
    pub retire: Vec<u32>,
    /// What the plan is known to be, when that spares the check a search.
    pub shape: Shape,
}

/// A plan's known shape.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum Shape {
    /// Anything: the checks find out.
    #[default]
    Any,
    /// A 1-4 split: removes one tetrahedron `q` and adds, as its `k`-th new one, `q` with
    /// vertex `k` replaced by the new vertex.
    OneToFour,
}

/// A checked plan: the twins of the new half-faces and the stars after the edit.
pub(crate) struct Verified {
    plan: Plan,
    /// Twin of each new half-face (`4k + i` for new tetrahedron `k`), by post-edit id.
    new_o: Vec<u32>,
    /// Each touched vertex and its tetrahedra after the edit (post-edit ids).
    stars: Stars,
}

/// Touched vertices, each with its tetrahedra after an edit.
type Stars = Vec<(u32, Vec<u32>)>;

/// Each touched vertex pair with its edge id before the edit (`NONE`: a new pair).
type EdgeIdsBefore = Vec<((u32, u32), u32)>;

/// What a plan's check and commit call their working lists when they do not fit in memory.
const STAR: &str = "the stars an edit touches";

/// The mesh as the plan would leave it, read without writing.
struct After<'a> {
    chf: &'a Chf,
    plan: &'a Plan,
    /// The first new tetrahedron id.
    bound: u32,
    view: View<'a>,
}

impl After<'_> {
    fn verts(&self, t: u32) -> [u32; 4] {
        if t >= self.bound {
            self.plan.add[(t - self.bound) as usize]
        } else {
            self.chf.tetrahedron_vertices(t)
        }
    }

    /// The tetrahedra around `x` after the edit.
    fn star(&self, x: u32) -> Result<Vec<u32>> {
        let mut out = Vec::new();
        if (x as usize) < self.chf.n_vertices {
            let mut star = Star::new(x, self.view.start_half_face(x));
            while let Some((t, _)) = star.next(&self.view, |_| 0) {
                if !self.plan.remove.contains(&t) {
                    try_push(&mut out, t, STAR)?;
                }
            }
            star.complete()?;
        }
        for (k, q) in self.plan.add.iter().enumerate() {
            if q.contains(&x) {
                try_push(&mut out, self.bound + k as u32, STAR)?;
            }
        }
        Ok(out)
    }

    /// The tetrahedra other than `t` holding every vertex of `key` after the edit.
    fn holders(&self, t: u32, key: [u32; 3]) -> Result<Vec<u32>> {
        let star = self.star(key[0])?.into_iter();
        let holders = star.filter(|&s| s != t && key.iter().all(|x| self.verts(s).contains(x)));
        try_collect(holders, STAR)
    }
}

/// The local index of the vertex of `q` not in `key`.
fn fourth(q: [u32; 4], key: [u32; 3]) -> u32 {
    (0..4)
        .find(|&j| !key.contains(&q[j as usize]))
        .expect("a fourth vertex")
}

/// The vertex triple of face `i` of `q`, in its outward order.
pub(super) fn cycle(q: [u32; 4], i: u32) -> [u32; 3] {
    FACE[i as usize].map(|l| q[l as usize])
}

/// Do two cycles on the same triple run the same way?
pub(super) fn same_way(a: [u32; 3], b: [u32; 3]) -> bool {
    let k = b.iter().position(|&x| x == a[0]).expect("same triple");
    b[(k + 1) % 3] == a[1]
}

pub(super) fn sorted3(mut t: [u32; 3]) -> [u32; 3] {
    t.sort_unstable();
    t
}

impl Chf {
    /// Checks `plan` against the mesh; nothing is written.
    pub(crate) fn verify(&self, plan: Plan) -> Result<Verified> {
        let (new_o, stars) = self.verify_ref(&plan)?;
        Ok(Verified { plan, new_o, stars })
    }

    /// [`Chf::verify`] of a plan the caller keeps: the twins of the new half-faces and the
    /// stars after the edit.
    fn verify_ref(&self, plan: &Plan) -> Result<(Vec<u32>, Stars)> {
        self.verify_inputs(plan)?;
        let after = After {
            chf: self,
            plan,
            bound: self.num_tetrahedra() as u32,
            view: self.try_view(Need::NOTHING)?,
        };
        let new_o = self.pair_new_faces(&after)?;
        let removed = plan
            .remove
            .iter()
            .flat_map(|&t| self.tetrahedron_vertices(t));
        let mut touched = try_collect(removed, STAR)?;
        try_extend(&mut touched, plan.add.iter().flatten().copied(), STAR)?;
        touched.sort_unstable();
        touched.dedup();
        let mut stars = try_with_capacity(touched.len(), STAR)?;
        for &x in &touched {
            let star = after.star(x)?;
            self.one_piece(&after, &new_o, &star, &[x], || {
                format!("vertex {x} would be non-manifold (its star in pieces)")
            })?;
            stars.push((x, star));
        }
        self.check_fans(&after, &new_o, &stars)?;
        for &x in &plan.retire {
            if stars.iter().any(|(y, s)| *y == x && !s.is_empty()) {
                return Err(refuse(format_args!("vertex {x} would keep tetrahedra")));
            }
        }
        Ok((new_o, stars))
    }

    /// Live ids, distinct vertices, no flagged face removed, positive volumes.
    pub(super) fn verify_inputs(&self, plan: &Plan) -> Result<()> {
        let n = self.n_vertices as u32 + plan.new_vertex.is_some() as u32;
        for &t in &plan.remove {
            self.check_tetrahedron(t)?;
            for hf in first(t)..first(t) + 4 {
                if self.non_manifold.binary_search(&hf).is_ok()
                    || self.seams.binary_search(&hf).is_ok()
                {
                    return Err(refuse(format_args!(
                        "tetrahedron {t} has a non-manifold or seam face"
                    )));
                }
            }
        }
        let positions = !self.positions.is_empty();
        let at = |x: u32| match plan.new_vertex {
            Some(Some(p)) if x as usize == self.n_vertices => p,
            _ => self.positions[x as usize],
        };
        for q in &plan.add {
            for (i, &x) in q.iter().enumerate() {
                // The vertex the plan creates is the one id past the mesh's.
                if plan.new_vertex.is_none() || x != n - 1 {
                    self.check_live_vertex(x)?;
                }
                if q[..i].contains(&x) {
                    return Err(refuse(format_args!(
                        "tetrahedron {} repeats vertex {x}",
                        Corners(*q)
                    )));
                }
            }
            if positions && orient_of(*q, at) <= 0.0 {
                return Err(refuse(format_args!(
                    "tetrahedron {} would be inverted or flat",
                    Corners(*q)
                )));
            }
        }
        Ok(())
    }

    /// The twin of every new half-face: the one other tetrahedron holding its triple after
    /// the edit, running the other way.
    fn pair_new_faces(&self, after: &After) -> Result<Vec<u32>> {
        let mut new_o = try_vec(4 * after.plan.add.len(), NONE, STAR)?;
        for (k, &q) in after.plan.add.iter().enumerate() {
            let t = after.bound + k as u32;
            for i in 0..4 {
                let c = cycle(q, i);
                let key = sorted3(c);
                let holders = after.holders(t, key)?;
                if holders.len() > 1 {
                    return Err(refuse_as(
                        ErrorKind::NonManifold,
                        format_args!("face {key:?} would have three tetrahedra"),
                    ));
                }
                let Some(&s) = holders.first() else { continue };
                let sv = after.verts(s);
                if key.iter().chain([&q[i as usize]]).all(|x| sv.contains(x)) {
                    return Err(refuse(format_args!(
                        "tetrahedron {} already exists",
                        Corners(q)
                    )));
                }
                let j = fourth(sv, key);
                let g = 4 * s + j;
                if s < after.bound
                    && (self.non_manifold.binary_search(&g).is_ok()
                        || self.seams.binary_search(&g).is_ok())
                {
                    return Err(refuse(format_args!(
                        "face {key:?} is non-manifold or a seam"
                    )));
                }
                if same_way(c, cycle(sv, j)) {
                    return Err(refuse(format_args!(
                        "face {key:?} would be held by two tetrahedra running the same way"
                    )));
                }
                new_o[4 * k + i as usize] = g;
            }
        }
        Ok(new_o)
    }

    /// Does a face of the new tetrahedron `q` (live, distinct vertices) meet the one
    /// tetrahedron holding it running the same way, so that `q` could pair only turned
    /// over? The orientation decision of an added tetrahedron without positions.
    pub(crate) fn meets_a_face_the_same_way(&self, q: [u32; 4]) -> Result<bool> {
        let plan = Plan {
            add: vec![q],
            ..Plan::default()
        };
        let after = After {
            chf: self,
            plan: &plan,
            bound: self.num_tetrahedra() as u32,
            view: self.try_view(Need::NOTHING)?,
        };
        for i in 0..4 {
            let c = cycle(q, i);
            let key = sorted3(c);
            if let [s] = after.holders(after.bound, key)?[..] {
                let sv = after.verts(s);
                if same_way(c, cycle(sv, fourth(sv, key))) {
                    return Ok(true);
                }
            }
        }
        Ok(false)
    }

    /// Twin of half-face `hf` (post-edit id) after the edit.
    fn twin_after(&self, after: &After, new_o: &[u32], hf: u32) -> u32 {
        let t = tet(hf);
        if t >= after.bound {
            return new_o[(hf - 4 * after.bound) as usize];
        }
        if let Some(k) = new_o.iter().position(|&g| g == hf) {
            return 4 * after.bound + k as u32;
        }
        let g = after.view.o[hf as usize];
        if g == NONE || after.plan.remove.contains(&tet(g)) {
            NONE
        } else {
            g
        }
    }

    /// The tetrahedra in `set` holding every vertex of `keep`, joined through their
    /// faces that hold `keep`: one piece, or an error from `what`.
    fn one_piece(
        &self, after: &After, new_o: &[u32], set: &[u32], keep: &[u32],
        what: impl FnOnce() -> String,
    ) -> Result<()> {
        if set.len() <= 1 {
            return Ok(());
        }
        let mut reached = try_vec(set.len(), false, STAR)?;
        // Each member is pushed once at most: the stack never outgrows `set`.
        let mut stack = try_with_capacity(set.len(), STAR)?;
        stack.push(0usize);
        reached[0] = true;
        while let Some(i) = stack.pop() {
            let q = after.verts(set[i]);
            for (j, x) in q.iter().enumerate() {
                if keep.contains(x) {
                    continue;
                }
                let g = self.twin_after(after, new_o, 4 * set[i] + j as u32);
                if g == NONE {
                    continue;
                }
                if let Some(k) = set.iter().position(|&s| s == tet(g))
                    && !reached[k]
                {
                    reached[k] = true;
                    stack.push(k);
                }
            }
        }
        if reached.iter().all(|&r| r) {
            Ok(())
        } else {
            Err(Error::non_manifold(format!("refused: {}", what())))
        }
    }

    /// Every touched vertex pair is one fan after the edit, and none carries several now.
    fn check_fans(&self, after: &After, new_o: &[u32], stars: &[(u32, Vec<u32>)]) -> Result<()> {
        for (a, b) in touched_pairs(self, after.plan)? {
            if self.multi_fan.iter().any(|m| (m.a, m.b) == (a, b)) {
                return Err(refuse(format_args!("edge ({a}, {b}) carries several fans")));
            }
            let fan = try_collect(fan_of(stars, a, b, |t| after.verts(t)), STAR)?;
            self.one_piece(after, new_o, &fan, &[a, b], || {
                format!("edge ({a}, {b}) would be non-manifold (several fans)")
            })?;
        }
        Ok(())
    }
}

/// The tetrahedra of the pair `(a, b)`: those of the star of `a` among the touched `stars`
/// whose vertices (`verts`) hold `b`.
fn fan_of<'a>(
    stars: &'a [(u32, Vec<u32>)], a: u32, b: u32, verts: impl Fn(u32) -> [u32; 4] + 'a,
) -> impl Iterator<Item = u32> + 'a {
    star_of(stars, a)
        .iter()
        .copied()
        .filter(move |&t| verts(t).contains(&b))
}

/// The tetrahedra of touched vertex `a` after the edit.
fn star_of(stars: &[(u32, Vec<u32>)], a: u32) -> &[u32] {
    &stars.iter().find(|(x, _)| *x == a).expect("touched").1
}

/// The vertex pairs of the removed and added tetrahedra, each once.
fn touched_pairs(chf: &Chf, plan: &Plan) -> Result<Vec<(u32, u32)>> {
    let quads = plan
        .remove
        .iter()
        .map(|&t| chf.tetrahedron_vertices(t))
        .chain(plan.add.iter().copied());
    let pairs = quads.flat_map(|q| {
        EDGE.map(|[p, r]| {
            (
                q[p as usize].min(q[r as usize]),
                q[p as usize].max(q[r as usize]),
            )
        })
    });
    let mut pairs = try_collect(pairs, STAR)?;
    pairs.sort_unstable();
    pairs.dedup();
    Ok(pairs)
}

impl Chf {
    /// Applies a verified plan; returns the ids of the new tetrahedra. Allocation failures
    /// are reported before anything is written.
    pub(crate) fn commit(&mut self, verified: Verified) -> Result<Vec<u32>> {
        let Verified { plan, new_o, stars } = verified;
        let bound = self.num_tetrahedra() as u32;
        self.reserve_for(&plan)?;
        // Every list the writes fill, made first: nothing below allocates.
        let new_ids = try_collect(bound..bound + plan.add.len() as u32, STAR)?;
        let mut rep_faces = try_with_capacity(4 * (plan.remove.len() + plan.add.len()), STAR)?;
        let old_ids = self.old_edge_ids(&plan, &stars)?;
        if let Some(p) = plan.new_vertex {
            self.push_new_vertex(p)?;
        }
        self.detach(&plan.remove, &mut rep_faces);
        for &q in &plan.add {
            self.push_new_tetrahedron(q)?;
        }
        for (k, &g) in new_o.iter().enumerate() {
            if g != NONE {
                arrays::set_opposite(self, 4 * bound + k as u32, g);
                arrays::set_opposite(self, g, 4 * bound + k as u32);
            } else {
                self.note_unpaired(4 * bound + k as u32);
            }
        }
        self.renumber_faces(bound, plan.add.len(), rep_faces);
        self.renumber_edges(old_ids, &stars);
        for (x, star) in &stars {
            let hf = self.star_half_face(*x, star);
            arrays::set_vertex_half_face(self, *x, hf);
        }
        for &x in &plan.retire {
            let s = self.edit.as_mut().expect("edited");
            if !s.vertex_removed[x as usize] {
                s.vertex_removed.set(x as usize);
                s.live_vertices -= 1;
            }
            arrays::set_vertex_half_face(self, x, NONE);
        }
        self.num_faces = self.edit.as_ref().expect("edited").face_hf.len();
        self.num_edges = self.edit.as_ref().expect("edited").edge_he.len();
        Ok(new_ids)
    }

    /// Appends a vertex (live, no half-face yet).
    pub(super) fn push_new_vertex(&mut self, p: Option<DVec3>) -> Result<()> {
        arrays::push_vertex(self, p)?;
        let s = self.edit_state()?;
        s.vertex_removed.push(false);
        s.live_vertices += 1;
        Ok(())
    }

    /// Appends tetrahedron `q` (live, unpaired, no ids yet).
    pub(super) fn push_new_tetrahedron(&mut self, q: [u32; 4]) -> Result<()> {
        arrays::push_tetrahedron(self, q)?;
        let s = self.edit_state()?;
        s.tet_removed.push(false);
        s.hf_face.extend_from_slice(&[NONE; 4]);
        s.slot_edge.extend_from_slice(&[NONE; 6]);
        s.live_tetrahedra += 1;
        Ok(())
    }

    /// Room for everything the plan appends, so that the writes cannot fail halfway.
    pub(super) fn reserve_for(&mut self, plan: &Plan) -> Result<()> {
        use crate::util::alloc::try_grow;
        let n = plan.add.len();
        try_grow(
            self.v.to_mut("the tetrahedra V")?,
            4 * n,
            "the tetrahedra V",
        )?;
        try_grow(self.o.to_mut("the opposites O")?, 4 * n, "the opposites O")?;
        self.edit_state()?;
        // After the edit state, which writes the identity map of a CHF that has none.
        self.tet_origin.reserve(n, "the tetrahedron origins")?;
        let s = self.edit.as_mut().expect("made above");
        s.tet_removed.try_grow(n, "the tetrahedron marks")?;
        try_grow(&mut s.hf_face, 4 * n, "the face ids")?;
        try_grow(&mut s.slot_edge, 6 * n, "the edge ids")?;
        try_grow(&mut s.face_hf, 4 * n, "the face half-faces")?;
        try_grow(&mut s.edge_he, 6 * n, "the edge half-edges")?;
        s.vertex_removed.try_grow(1, "the vertex marks")?;
        if self.level >= 3 {
            let s = self.edit.as_mut().expect("edited");
            s.boundary.settle(&self.o)?;
            s.boundary.reserve(4 * (plan.remove.len() + n))?;
        }
        Ok(())
    }

    /// Half-face `hf` may have become unpaired: the level-3 boundary rebuild looks at it.
    pub(super) fn note_unpaired(&mut self, hf: u32) {
        if self.level >= 3 {
            self.edit.as_mut().expect("edited").boundary.note(hf);
        }
    }

    /// Marks `remove` removed and unpairs their neighbours; adds to `reps` (room made for
    /// four per tetrahedron) the faces that live on through a surviving twin, with that
    /// twin.
    fn detach(&mut self, remove: &[u32], reps: &mut Vec<(u32, u32)>) {
        let s = self.edit.as_mut().expect("edited");
        for &t in remove {
            s.tet_removed.set(t as usize);
        }
        for &t in remove {
            for hf in first(t)..first(t) + 4 {
                let g = self.o[hf as usize];
                let s = self.edit.as_mut().expect("edited");
                let f = s.hf_face[hf as usize];
                s.hf_face[hf as usize] = NONE;
                if g != NONE && g != hf && !s.tet_removed[tet(g) as usize] {
                    reps.push((f, g));
                    arrays::set_opposite(self, g, NONE);
                    self.note_unpaired(g);
                } else if s.face_hf[f as usize] != NONE {
                    s.face_hf[f as usize] = NONE;
                    s.live_faces -= 1;
                }
                arrays::set_opposite(self, hf, hf);
            }
            let s = self.edit.as_mut().expect("edited");
            s.live_tetrahedra -= 1;
            for k in 0..6 {
                s.slot_edge[6 * t as usize + k] = NONE;
            }
        }
    }

    /// Face ids of the new half-faces (inherited through an old twin, else new) and the
    /// canonical half-face of every touched face.
    fn renumber_faces(&mut self, bound: u32, n_new: usize, mut reps: Vec<(u32, u32)>) {
        let s = self.edit.as_mut().expect("edited");
        for h in 4 * bound..4 * (bound + n_new as u32) {
            let g = self.o[h as usize];
            if g != NONE && g < 4 * bound {
                s.hf_face[h as usize] = s.hf_face[g as usize];
            } else if g == NONE || g > h {
                s.hf_face[h as usize] = s.face_hf.len() as u32;
                if g != NONE {
                    s.hf_face[g as usize] = s.face_hf.len() as u32;
                }
                s.face_hf.push(h);
                s.live_faces += 1;
            }
            reps.push((s.hf_face[h as usize], h));
        }
        for (f, hf) in reps {
            let g = self.o[hf as usize];
            s.face_hf[f as usize] = if g != NONE && g < hf { g } else { hf };
        }
    }

    /// Edge ids of the touched vertex pairs: kept while the pair has tetrahedra, new for a
    /// new pair; the canonical half-edge of each by the build's rule.
    fn renumber_edges(&mut self, old_ids: EdgeIdsBefore, stars: &[(u32, Vec<u32>)]) {
        for ((a, b), old) in old_ids {
            // The fan is read from the star as it is walked: the commit allocates nothing.
            let holds_b = |c: &Chf, t: u32| c.tetrahedron_vertices(t).contains(&b);
            let t0 = star_of(stars, a)
                .iter()
                .copied()
                .find(|&t| holds_b(self, t));
            let s = self.edit.as_mut().expect("edited");
            let Some(t0) = t0 else {
                if old != NONE && s.edge_he[old as usize] != crate::chf::NO_HALF_EDGE {
                    s.edge_he[old as usize] = crate::chf::NO_HALF_EDGE;
                    s.live_edges -= 1;
                }
                continue;
            };
            let id = if old != NONE {
                old
            } else {
                s.edge_he.push(0);
                s.live_edges += 1;
                s.edge_he.len() as u32 - 1
            };
            for &t in star_of(stars, a) {
                if !holds_b(self, t) {
                    continue;
                }
                let slot = self.pair_slot(t, a, b);
                self.edit.as_mut().expect("edited").slot_edge[slot as usize] = id;
            }
            let he = slot_half_edges(self.pair_slot(t0, a, b))[0];
            let canonical = canonical_half_edge(&self.v, &self.o, he);
            self.edit.as_mut().expect("edited").edge_he[id as usize] = canonical;
        }
    }

    /// The slot of the pair `(a, b)` in tetrahedron `t`.
    fn pair_slot(&self, t: u32, a: u32, b: u32) -> u64 {
        let q = self.tetrahedron_vertices(t);
        let la = q.iter().position(|&x| x == a).expect("a in t") as u32;
        let lb = q.iter().position(|&x| x == b).expect("b in t") as u32;
        6 * t as u64 + edge_index(la, lb) as u64
    }

    /// Each touched pair with its edge id before the edit (from a removed tetrahedron or
    /// a surviving one holding the pair), `NONE` for a new pair. Read before `detach`.
    fn old_edge_ids(&self, plan: &Plan, stars: &[(u32, Vec<u32>)]) -> Result<EdgeIdsBefore> {
        let s = self.edit.as_ref().expect("edited");
        let bound = self.num_tetrahedra() as u32;
        let id_in = |t: u32, a: u32, b: u32| s.slot_edge[self.pair_slot(t, a, b) as usize];
        let pairs = touched_pairs(self, plan)?;
        let mut out = try_with_capacity(pairs.len(), STAR)?;
        for (a, b) in pairs {
            let star = star_of(stars, a);
            let holds = |t: &u32| {
                self.tetrahedron_vertices(*t).contains(&a)
                    && self.tetrahedron_vertices(*t).contains(&b)
            };
            let old = plan
                .remove
                .iter()
                .chain(star.iter().filter(|&&t| t < bound))
                .find(|t| holds(t))
                .map_or(NONE, |&t| id_in(t, a, b));
            out.push(((a, b), old));
        }
        Ok(out)
    }

    /// A half-face of `star` holding `x`, a boundary one if any; `NONE` for no star.
    fn star_half_face(&self, x: u32, star: &[u32]) -> u32 {
        let mut any = NONE;
        for &t in star {
            let q = self.tetrahedron_vertices(t);
            for i in 0..4u32 {
                if q[i as usize] == x {
                    continue;
                }
                let hf = first(t) + i;
                if self.o[hf as usize] == NONE {
                    return hf;
                }
                if any == NONE {
                    any = hf;
                }
            }
        }
        any
    }
}

impl Chf {
    /// Would `plan` be accepted? Writes nothing.
    pub(crate) fn check_plan(&self, plan: &Plan) -> Result<()> {
        match self.verify_cavity(plan)? {
            Some(_) => Ok(()),
            None => self.verify_ref(plan).map(|_| ()),
        }
    }

    /// Verifies and applies `plan`; the new tetrahedra's ids. A refusal writes nothing.
    pub(crate) fn run(&mut self, plan: Plan) -> Result<Vec<u32>> {
        if let Some(cavity) = self.verify_cavity(&plan)? {
            return self.commit_cavity(plan, cavity);
        }
        let verified = self.verify(plan)?;
        self.edit_state()?;
        self.commit(verified)
    }

    /// Runs the operation `op` on the element `what` names, whose plan `plan` makes: the
    /// new tetrahedra's ids; a refusal, in the plan or in the run, names both.
    pub(crate) fn run_op(
        &mut self, op: &'static str, what: impl std::fmt::Display + Copy,
        plan: impl FnOnce(&Chf) -> Result<Plan>,
    ) -> Result<Vec<u32>> {
        let plan = plan(self).map_err(context(op, what))?;
        self.run(plan).map_err(context(op, what))
    }

    /// Would [`Chf::run_op`] succeed? Changes nothing.
    pub(crate) fn check_op(
        &self, op: &'static str, what: impl std::fmt::Display + Copy,
        plan: impl FnOnce(&Chf) -> Result<Plan>,
    ) -> Result<()> {
        let plan = plan(self).map_err(context(op, what))?;
        self.check_plan(&plan).map_err(context(op, what))
    }

    /// A split's plan, to be filled, and the id of the vertex it adds: at `position`, else
    /// (when the mesh has positions) at the centroid of `corners`.
    pub(crate) fn split_plan(
        &self, position: Option<DVec3>, corners: &[u32],
    ) -> Result<(Plan, u32)> {
        let p = self.new_position(position, || self.centroid(corners))?;
        let plan = Plan {
            new_vertex: Some(p),
            ..Plan::default()
        };
        Ok((plan, self.n_vertices as u32))
    }

    /// Runs `plan`, a split's: the vertex it adds; a refusal names `op` on `what`.
    pub(crate) fn run_split(
        &mut self, plan: Plan, op: &'static str, what: impl std::fmt::Display,
    ) -> Result<u32> {
        let x = self.n_vertices as u32;
        self.run(plan).map_err(context(op, what))?;
        Ok(x)
    }

    /// The position of a new vertex: `given`, else `default` when the mesh has positions;
    /// `None` (and no position given) when it has none.
    pub(crate) fn new_position(
        &self, given: Option<DVec3>, default: impl FnOnce() -> DVec3,
    ) -> Result<Option<DVec3>> {
        match (self.positions.is_empty(), given) {
            (true, Some(_)) => Err(Error::invalid(
                "a position was given but the mesh has no positions",
            )),
            (true, None) => Ok(None),
            (false, Some(p)) if !p.is_finite() => {
                Err(Error::invalid(format!("position {p} is not finite")))
            }
            (false, p) => Ok(Some(p.unwrap_or_else(default))),
        }
    }

    /// The mean position of `xs` (the mesh has positions).
    pub(crate) fn centroid(&self, xs: &[u32]) -> DVec3 {
        xs.iter()
            .map(|&x| self.positions[x as usize])
            .sum::<DVec3>()
            / xs.len() as f64
    }
}

/// `q` with vertex `from` replaced by `to`.
pub(crate) fn replaced(mut q: [u32; 4], from: u32, to: u32) -> [u32; 4] {
    for x in &mut q {
        if *x == from {
            *x = to;
        }
    }
    q
}
