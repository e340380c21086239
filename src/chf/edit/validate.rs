//! The invariant checker of an edited CHF: its own tables (marks, `O`, `VH`, the explicit
//! ids) checked element by element, then the live tetrahedra built afresh and compared
//! with (the twins and the counts a build gives), unless the build flagged faces or edges:
//! a build of the same tetrahedra, whose vertices it split already, then pairs what the
//! first build kept apart. O(T log T).

use crate::NONE;
use crate::chf::Chf;
use crate::chf::edit::garbage_collect::Compacted;
use crate::chf::ids::{first, slot_half_edges, tet};
use crate::chf::query::view::Need;
use crate::error::{Error, Result};

fn ensure(ok: bool, what: impl FnOnce() -> String) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(Error::invalid(format!("invalid edited CHF: {}", what())))
    }
}

/// Which vertices of `chf`, whose `O` is `o`, lie on an unpaired half-face (below level
/// 2, asking `is_boundary_vertex` of each vertex would compute `O` for every one).
fn boundary_marks(chf: &Chf, o: &[u32]) -> Result<Vec<bool>> {
    let unpaired = (0..o.len() as u32).filter(|&hf| o[hf as usize] == NONE);
    crate::chf::query::vertices_on(chf, unpaired)
}

impl Chf {
    /// [`Chf::validate`] of an edited CHF.
    pub(crate) fn validate_edited(&self) -> Result<()> {
        let s = self.edit.as_ref().expect("edited");
        let n_t = self.num_tetrahedra();
        ensure(
            s.tet_removed.len() == n_t && s.hf_face.len() == 4 * n_t,
            || "mark or face-id arrays of the wrong length".into(),
        )?;
        ensure(
            s.slot_edge.len() == 6 * n_t && self.o.len() == 4 * n_t,
            || "edge-id or O arrays of the wrong length".into(),
        )?;
        for t in 0..n_t as u32 {
            self.validate_edited_tetrahedron(t)?;
        }
        self.validate_edited_ids()?;
        let compacted = self.compacted()?;
        let fresh = &compacted.chf;
        fresh.validate()?;
        if !(self.non_manifold.is_empty() && self.seams.is_empty() && self.multi_fan.is_empty()) {
            // The build kept half-faces of a non-manifold face or a seam unpaired, or an
            // edge in several fans, where a build of the same tetrahedra (its vertices
            // split already) pairs or joins them: the counts and twins may differ.
            return Ok(());
        }
        ensure(fresh.num_faces() == s.live_faces, || {
            format!(
                "{} live faces, a build gives {}",
                s.live_faces,
                fresh.num_faces()
            )
        })?;
        ensure(fresh.num_edges() == s.live_edges, || {
            format!(
                "{} live edges, a build gives {}",
                s.live_edges,
                fresh.num_edges()
            )
        })?;
        self.validate_as_built(&compacted)
    }

    /// The twins and the boundary vertices are those of `compacted`, a build of the live
    /// tetrahedra. Its `O` is taken once (computed below level 1), not asked per half-face.
    fn validate_as_built(&self, compacted: &Compacted) -> Result<()> {
        let fresh = &compacted.chf;
        let fresh_o = fresh.try_view(Need::NOTHING)?.o;
        for (t, &n) in compacted.tetrahedra.iter().enumerate() {
            if n == NONE {
                continue;
            }
            for hf in first(t as u32)..first(t as u32) + 4 {
                let g = self.o[hf as usize];
                let mapped = if g == NONE {
                    NONE
                } else {
                    compacted.half_face(self, g)
                };
                ensure(
                    fresh_o[compacted.half_face(self, hf) as usize] == mapped,
                    || format!("O[{hf}] = {g}, a build of the live tetrahedra differs"),
                )?;
            }
        }
        let on_boundary = boundary_marks(fresh, &fresh_o)?;
        for (x, &n) in compacted.vertices.iter().enumerate() {
            ensure(
                n == NONE || on_boundary[n as usize] == self.is_boundary_vertex(x as u32),
                || format!("VH[{x}] does not say whether vertex {x} is on the boundary"),
            )?;
        }
        Ok(())
    }

    /// One tetrahedron: removed ones are their own twins, live ones hold live vertices
    /// and pair with live tetrahedra.
    fn validate_edited_tetrahedron(&self, t: u32) -> Result<()> {
        let s = self.edit.as_ref().expect("edited");
        let q = self.tetrahedron_vertices(t);
        for hf in first(t)..first(t) + 4 {
            let g = self.o[hf as usize];
            if s.tet_removed[t as usize] {
                ensure(g == hf, || {
                    format!("removed tetrahedron {t} has O[{hf}] = {g}")
                })?;
                continue;
            }
            ensure(
                g == NONE || (!s.tet_removed[tet(g) as usize] && self.o[g as usize] == hf),
                || format!("O[{hf}] = {g} is not a live twin"),
            )?;
        }
        if s.tet_removed[t as usize] {
            return Ok(());
        }
        for (i, &x) in q.iter().enumerate() {
            ensure(
                (x as usize) < self.n_vertices && !s.vertex_removed[x as usize],
                || format!("tetrahedron {t} holds vertex {x}, removed or out of range"),
            )?;
            ensure(!q[..i].contains(&x), || {
                format!("tetrahedron {t} repeats vertex {x}")
            })?;
        }
        Ok(())
    }

    /// Face and edge ids: every live half-face and slot names a live id whose canonical
    /// element is its own by the build's rule; `VH` holds its vertex.
    fn validate_edited_ids(&self) -> Result<()> {
        let s = self.edit.as_ref().expect("edited");
        for hf in 0..self.v.len() as u32 {
            if s.tet_removed[tet(hf) as usize] {
                continue;
            }
            let f = s.hf_face[hf as usize];
            let g = self.o[hf as usize];
            let canonical = if g != NONE && g < hf { g } else { hf };
            ensure(
                (f as usize) < s.face_hf.len() && s.face_hf[f as usize] == canonical,
                || format!("half-face {hf} names face {f}, whose half-face is not {canonical}"),
            )?;
        }
        for slot in 0..s.slot_edge.len() as u64 {
            if s.tet_removed[(slot / 6) as usize] {
                continue;
            }
            let e = s.slot_edge[slot as usize];
            let he = super::state::canonical_half_edge(&self.v, &self.o, slot_half_edges(slot)[0]);
            ensure(
                (e as usize) < s.edge_he.len() && s.edge_he[e as usize] == he,
                || format!("slot {slot} names edge {e}, whose half-edge is not {he}"),
            )?;
        }
        for (x, &hf) in self.vh.iter().enumerate() {
            ensure(
                hf == NONE || self.half_face_vertices_of(hf).contains(&(x as u32)),
                || format!("VH[{x}] = {hf}, a half-face without vertex {x}"),
            )?;
            ensure(hf == NONE || !s.tet_removed[tet(hf) as usize], || {
                format!("VH[{x}] = {hf} on a removed tetrahedron")
            })?;
        }
        Ok(())
    }
}
