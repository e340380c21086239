//! The explicit ids an edited CHF keeps (see the module doc), made on the first edit.

use super::boundary::LazyBoundary;
use crate::NONE;
use crate::chf::Chf;
use crate::chf::edges::{FanEnd, walk};
use crate::chf::ids::{HalfEdge, NO_HALF_EDGE, face_cycle, he_face, slot_of};
use crate::chf::query::view::Need;
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_vec};
use crate::util::marks::Marks;

/// Marks and explicit ids of an edited CHF.
#[derive(Clone, Debug, Default)]
pub(crate) struct EditState {
    pub tet_removed: Marks,
    pub vertex_removed: Marks,
    /// Face id of each half-face (`NONE` on removed tetrahedra).
    pub hf_face: Vec<u32>,
    /// Canonical half-face of each face id, `NONE` once removed.
    pub face_hf: Vec<u32>,
    /// Edge id of each edge slot (`NONE` on removed tetrahedra).
    pub slot_edge: Vec<u32>,
    /// Canonical half-edge of each edge id, [`NO_HALF_EDGE`] once removed.
    pub edge_he: Vec<HalfEdge>,
    pub live_tetrahedra: usize,
    pub live_vertices: usize,
    pub live_faces: usize,
    pub live_edges: usize,
    /// Level 3: the boundary surface, rebuilt at the first boundary query after an edit.
    pub boundary: super::boundary::LazyBoundary,
}

impl EditState {
    /// The explicit ids of `chf` as built (O(T)).
    fn of(chf: &Chf) -> Result<EditState> {
        let view = chf.try_view(Need {
            faces: true,
            edges: true,
        })?;
        let n_hf = chf.v.len();
        let hf_face = try_collect((0..n_hf as u32).map(|h| view.face_of(h)), "the face ids")?;
        let face_hf = try_collect(
            (0..chf.num_faces as u32).map(|f| view.face_half_face(f)),
            "the face half-faces",
        )?;
        let mut slot_edge = try_vec(6 * (n_hf / 4), NONE, "the edge ids")?;
        let edge_he = try_collect(
            (0..chf.num_edges as u32).map(|e| view.edge_half_edge(e)),
            "the edge half-edges",
        )?;
        for (e, &he) in edge_he.iter().enumerate() {
            for_each_fan_slot(&chf.v, &view.o, he, |s| slot_edge[s as usize] = e as u32);
        }
        Ok(EditState {
            tet_removed: Marks::clear_of(n_hf / 4, "the tetrahedron marks")?,
            vertex_removed: Marks::clear_of(chf.n_vertices, "the vertex marks")?,
            hf_face,
            face_hf,
            slot_edge,
            edge_he,
            live_tetrahedra: n_hf / 4,
            live_vertices: chf.n_vertices,
            live_faces: chf.num_faces,
            live_edges: chf.num_edges,
            boundary: Default::default(),
        })
    }

    /// Bytes of the face ids (per half-face, and the canonical half-face per face id).
    pub(crate) fn face_bytes(&self) -> usize {
        4 * (self.hf_face.len() + self.face_hf.len())
    }

    /// Bytes of the edge ids (per edge slot, and the canonical half-edge per edge id) and
    /// of the removed marks.
    pub(crate) fn edge_bytes(&self) -> usize {
        4 * self.slot_edge.len()
            + std::mem::size_of_val(&self.edge_he[..])
            + self.tet_removed.memory_bytes()
            + self.vertex_removed.memory_bytes()
    }
}

/// Calls `f` with every slot of the fan of `he`.
pub(crate) fn for_each_fan_slot(v: &[u32], o: &[u32], he: HalfEdge, mut f: impl FnMut(u64)) {
    let end = walk(v, o, he, |g, _| {
        f(slot_of(g));
        false
    });
    if let FanEnd::Boundary(_) = end {
        // The walk stopped at one end; the slots behind the start are the other way.
        let n = crate::chf::ids::radial(v, o, he);
        if n != NO_HALF_EDGE {
            walk(v, o, n, |g, _| {
                f(slot_of(g));
                false
            });
        }
    }
}

/// The canonical half-edge of the fan of `he` by the build's rule: on a boundary fan the
/// smaller of the two half-edges on boundary half-faces, on a closed fan the smallest.
pub(crate) fn canonical_half_edge(v: &[u32], o: &[u32], he: HalfEdge) -> HalfEdge {
    let mut best = NO_HALF_EDGE;
    let end = walk(v, o, he, |g, m| {
        best = best.min(g).min(m);
        false
    });
    let FanEnd::Boundary(m1) = end else {
        return best;
    };
    let end = walk(v, o, m1, |_, _| false);
    let FanEnd::Boundary(m2) = end else {
        unreachable!("a fan open one way is open the other")
    };
    m1.min(m2)
}

impl Chf {
    /// The edit state, made on the first edit (O(T) once): `O` and `VH` stored whatever
    /// the level, and the explicit ids.
    pub(crate) fn edit_state(&mut self) -> Result<&mut EditState> {
        super::arrays::promote(self)?;
        if self.edit.is_none() {
            // Everything that can fail first: a refusal leaves the CHF as it was.
            let mut state = EditState::of(self)?;
            let identity = |n: usize, what| try_collect(0..n as u32, what);
            let o = (self.level < 1)
                .then(|| self.try_opposites_by_rule())
                .transpose()?;
            let o_now = o.as_deref().unwrap_or(&self.o);
            let vh = (self.level < 2)
                .then(|| vertex_half_faces(self, o_now))
                .transpose()?;
            let tet_origin = (self.tet_origin.is_empty())
                .then(|| identity(self.num_tetrahedra(), "the tetrahedron origins"))
                .transpose()?;
            let vertex_origin = (self.vertex_origin.is_empty())
                .then(|| identity(self.n_vertices, "the vertex origins"))
                .transpose()?;
            // The built surface serves until the first edit, which keeps its half-faces.
            state.boundary = LazyBoundary::new(self.boundary.take());
            if let Some(o) = o {
                self.o = o.into();
            }
            if let Some(vh) = vh {
                self.vh = vh.into();
            }
            if let Some(ids) = tet_origin {
                self.tet_origin = ids.into();
            }
            if let Some(ids) = vertex_origin {
                self.vertex_origin = ids.into();
            }
            // The explicit ids replace the rank directories of the faces and edges:
            // nothing reads those of an edited mesh, and `garbage_collect` builds anew.
            self.face_bits = Default::default();
            self.fh = Default::default();
            self.edge_bits = Default::default();
            self.eh = Default::default();
            self.edit = Some(Box::new(state));
        }
        Ok(self.edit.as_mut().expect("made above"))
    }

    /// Has this CHF been edited (so that it carries explicit ids)?
    pub fn is_edited(&self) -> bool {
        self.edit.is_some()
    }

    /// Is tetrahedron `t` removed? False for every id of a never-edited CHF.
    pub fn is_tetrahedron_removed(&self, t: u32) -> bool {
        self.edit
            .as_ref()
            .is_some_and(|s| s.tet_removed.get(t as usize).unwrap_or(false))
    }
    /// Is vertex `v` removed?
    pub fn is_vertex_removed(&self, v: u32) -> bool {
        self.edit
            .as_ref()
            .is_some_and(|s| s.vertex_removed.get(v as usize).unwrap_or(false))
    }
    /// Is face `f` removed?
    pub fn is_face_removed(&self, f: u32) -> bool {
        self.edit
            .as_ref()
            .is_some_and(|s| s.face_hf.get(f as usize).is_some_and(|&h| h == NONE))
    }
    /// Is edge `e` removed?
    pub fn is_edge_removed(&self, e: u32) -> bool {
        self.edit.as_ref().is_some_and(|s| {
            s.edge_he
                .get(e as usize)
                .is_some_and(|&h| h == NO_HALF_EDGE)
        })
    }

    /// The tetrahedra not removed, in increasing id order (every id of a CHF never
    /// edited): what CGAL's cell iterators visit. Likewise [`Chf::live_vertices`],
    /// [`Chf::live_faces`] and [`Chf::live_edges`].
    pub fn live_tetrahedra(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.num_tetrahedra() as u32).filter(|&t| !self.is_tetrahedron_removed(t))
    }
    pub fn live_vertices(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.n_vertices as u32).filter(|&v| !self.is_vertex_removed(v))
    }
    pub fn live_faces(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.num_faces as u32).filter(|&f| !self.is_face_removed(f))
    }
    pub fn live_edges(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.num_edges as u32).filter(|&e| !self.is_edge_removed(e))
    }

    /// Live counts (the `num_*` calls are id bounds, removed ids included).
    pub fn num_live_tetrahedra(&self) -> usize {
        self.edit
            .as_ref()
            .map_or(self.num_tetrahedra(), |s| s.live_tetrahedra)
    }
    pub fn num_live_vertices(&self) -> usize {
        self.edit
            .as_ref()
            .map_or(self.n_vertices, |s| s.live_vertices)
    }
    pub fn num_live_faces(&self) -> usize {
        self.edit.as_ref().map_or(self.num_faces, |s| s.live_faces)
    }
    pub fn num_live_edges(&self) -> usize {
        self.edit.as_ref().map_or(self.num_edges, |s| s.live_edges)
    }

    /// Refuses `what` while removed elements wait for [`Self::garbage_collect`]: exports,
    /// writers and level files lay ids out without holes, so they run on a collected mesh.
    pub(crate) fn check_collected(&self, what: &str) -> Result<()> {
        let holes = self.num_live_vertices() != self.n_vertices
            || self.num_live_tetrahedra() != self.num_tetrahedra()
            || self.num_live_edges() != self.num_edges
            || self.num_live_faces() != self.num_faces;
        crate::util::structure::refuse_holes(holes, what)
    }

    /// Refuses an edited CHF (`garbage_collect` ends the edit state): its arrays are
    /// right, but a level file holds the explicit-id-free tables of the build's rules.
    pub(crate) fn check_unchanged(&self, what: &str) -> Result<()> {
        crate::util::structure::refuse_edited(self.is_edited(), what)
    }

    /// A live vertex id (or an error naming it).
    pub fn check_live_vertex(&self, v: u32) -> Result<()> {
        self.check_vertex(v)?;
        removed(self.is_vertex_removed(v), "vertex", v)
    }
    /// A live tetrahedron id.
    pub fn check_live_tetrahedron(&self, t: u32) -> Result<()> {
        self.check_tetrahedron(t)
    }
    /// A live face id.
    pub fn check_live_face(&self, f: u32) -> Result<()> {
        self.check_face(f)
    }
    /// A live edge id.
    pub fn check_live_edge(&self, e: u32) -> Result<()> {
        self.check_edge(e)?;
        removed(self.is_edge_removed(e), "edge", e)
    }
    /// A half-edge of a live tetrahedron.
    pub fn check_live_half_edge(&self, he: HalfEdge) -> Result<()> {
        self.check_half_edge(he)?;
        self.check_tetrahedron(crate::chf::ids::tet(he_face(he)))
    }
}

/// `Err` naming a removed element.
pub(crate) fn removed(is: bool, what: &str, id: u32) -> Result<()> {
    if is {
        Err(Error::out_of_range(format!("{what} {id} is removed")))
    } else {
        Ok(())
    }
}

/// `VH` by one pass over the half-faces: a boundary half-face on boundary vertices.
fn vertex_half_faces(chf: &Chf, o: &[u32]) -> Result<Vec<u32>> {
    let mut vh = try_vec(chf.n_vertices, NONE, "the vertex half-faces VH")?;
    for hf in 0..chf.v.len() as u32 {
        for x in face_cycle(&chf.v, hf) {
            let cur = vh[x as usize];
            if cur == NONE || (o[cur as usize] != NONE && o[hf as usize] == NONE) {
                vh[x as usize] = hf;
            }
        }
    }
    Ok(vh)
}

impl Chf {
    /// [`Chf::build_level`] of an edited CHF: `O`, `VH` and the ids are kept at every
    /// level (the edits need them), so only the boundary surface comes and goes; raised to
    /// level 3, it is built over the whole mesh (O(T), as a build of the level is).
    pub(crate) fn build_edited_level(&mut self, level: u8) -> Result<()> {
        if level < 3 {
            self.edit_state()?.boundary = LazyBoundary::default();
        } else if self.level < 3 {
            let built = crate::chf::build::level3::build(self, 1, 0)?;
            self.edit_state()?.boundary = LazyBoundary::new(Some(built));
        }
        self.level = level;
        Ok(())
    }
}
