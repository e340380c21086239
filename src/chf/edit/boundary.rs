//! The level-3 boundary surface of an edited CHF, rebuilt lazily. An edit only notes the
//! half-faces it leaves unpaired; the first boundary query after it rebuilds the surface
//! from the boundary half-faces of the last rebuild and those noted since: O((B + k)
//! log(B + k)) for B boundary half-faces and k noted ones, never a scan of the tetrahedra.
//! The rebuilt surface sits in a `OnceLock`, so that the queries stay `&self`, as the
//! curves of an edited CHE do.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::build::level3::{self, Boundary};
use crate::error::Result;
use crate::util::alloc::{try_reserve, try_vec};
use std::sync::OnceLock;

/// What the next rebuild of the boundary surface starts from, and its result.
#[derive(Clone, Debug, Default)]
pub(crate) struct LazyBoundary {
    /// The boundary half-faces, increasing, when the surface was last rebuilt (some may
    /// be paired or removed since).
    known: Vec<u32>,
    /// Half-faces left unpaired since (any order, may repeat).
    touched: Vec<u32>,
    /// The surface, from the first query after an edit until the next edit.
    surface: OnceLock<Boundary>,
}

impl LazyBoundary {
    /// Starts from a surface built over the whole mesh (or from nothing, below level 3).
    pub(crate) fn new(built: Option<Boundary>) -> LazyBoundary {
        let surface = OnceLock::new();
        if let Some(b) = built {
            let _ = surface.set(b);
        }
        LazyBoundary {
            known: Vec::new(),
            touched: Vec::new(),
            surface,
        }
    }

    pub(crate) fn memory_bytes(&self) -> usize {
        4 * (self.known.capacity() + self.touched.capacity())
            + self.surface.get().map_or(0, Boundary::memory_bytes)
    }

    /// Room for `n` notes, so that an operation cannot fail while it writes.
    pub(crate) fn reserve(&mut self, n: usize) -> Result<()> {
        try_reserve(&mut self.touched, n, "the boundary log")
    }

    /// Half-face `hf` may have become unpaired (room reserved by [`Self::reserve`]).
    pub(crate) fn note(&mut self, hf: u32) {
        self.touched.push(hf);
    }

    /// The unpaired half-faces, increasing: those known at the last rebuild and those noted
    /// since that are still unpaired (removed tetrahedra are their own twins, so they drop
    /// out too). O((B + k) log(B + k)).
    pub(crate) fn half_faces(&self, o: &[u32]) -> Result<Vec<u32>> {
        let n = self.known.len() + self.touched.len();
        let mut all = try_vec(n, NONE, "the boundary half-faces")?;
        all[..self.known.len()].copy_from_slice(&self.known);
        all[self.known.len()..].copy_from_slice(&self.touched);
        all.sort_unstable();
        all.dedup();
        all.retain(|&h| o[h as usize] == NONE);
        Ok(all)
    }

    /// Before an operation writes: a rebuilt surface gives its half-faces as the known
    /// ones and is dropped; a long log is folded into `known`, so that it stays within the
    /// boundary plus a constant (a fold costs O(B + k log k), spread over as many edits).
    pub(crate) fn settle(&mut self, o: &[u32]) -> Result<()> {
        if let Some(b) = self.surface.take() {
            self.known = b.half_faces;
            self.touched.clear();
        } else if self.touched.len() > self.known.len() + 1024 {
            self.known = self.half_faces(o)?;
            self.touched.clear();
        }
        Ok(())
    }
}

impl super::EditState {
    /// The boundary surface, rebuilt on the first call after an edit.
    pub(crate) fn surface(&self, chf: &Chf) -> Result<&Boundary> {
        let lazy = &self.boundary;
        if let Some(b) = lazy.surface.get() {
            return Ok(b);
        }
        let b = level3::build_from_half_faces(chf, lazy.half_faces(&chf.o)?)?;
        Ok(lazy.surface.get_or_init(|| b))
    }
}

#[cfg(test)]
mod tests {
    use crate::chf::Chf;

    /// An `n`^3 grid of unit cubes, six tetrahedra each, at level 3 with positions.
    fn grid(n: u32) -> Chf {
        crate::chf::edit::test_grid(n, 3, true)
    }

    /// What the next rebuild will read: the half-faces it starts from.
    fn pending(chf: &Chf) -> usize {
        let b = &chf.edit.as_ref().unwrap().boundary;
        b.known.len() + b.touched.len()
    }

    /// The unpaired half-faces, counted by brute force.
    fn unpaired(chf: &Chf) -> usize {
        chf.o.iter().filter(|&&g| g == crate::NONE).count()
    }

    /// An operation writes no surface and leaves the next rebuild a list of the boundary's
    /// size plus what it touched, however large the mesh; the rebuild keeps no directory
    /// over the whole mesh and equals a build over the whole mesh.
    #[test]
    fn an_edit_leaves_the_rebuild_the_boundary_and_its_own_faces() {
        let mut chf = grid(12);
        let n_hf = chf.num_half_faces();
        let b0 = chf.num_boundary_triangles();
        assert!(20 * b0 < n_hf, "a mesh much larger than its boundary");
        let mut cavities = 0;
        for (step, t) in (0..chf.num_tetrahedra() as u32).step_by(7).enumerate() {
            // A cavity where it keeps every edge one fan: the boundary grows.
            let s = chf.split_tetrahedron(t, None).unwrap();
            cavities += chf.remove_vertex(s).is_ok() as usize;
            let state = chf.edit.as_ref().unwrap();
            assert!(
                state.boundary.surface.get().is_none(),
                "step {step}: an eager rebuild"
            );
            // The notes stay within the boundary of the last fold plus a constant.
            let (b, p) = (unpaired(&chf), pending(&chf));
            assert!(p <= 2 * b + 1024 + 32, "step {step}: {p} pending for {b}");
            assert!(4 * p < n_hf, "step {step}: {p} pending in a mesh of {n_hf}");
            if step % 50 == 0 {
                let mine = chf.edit.as_ref().unwrap().surface(&chf).unwrap();
                assert!(mine.bits.is_none() && mine.vertex_bits.is_none());
                let full = crate::chf::build::level3::build(&chf, 1, 0).unwrap();
                assert_eq!(mine.half_faces, full.half_faces, "step {step}");
                assert_eq!(mine.vertices, full.vertices, "step {step}");
                assert_eq!(mine.component, full.component, "step {step}");
                assert_eq!(mine.true_faces, full.true_faces, "step {step}");
                assert_eq!(mine.che.summary(), full.che.summary(), "step {step}");
            }
        }
        assert!(cavities > 100, "{cavities} cavities");
        // Removals on the boundary open the surface: the notes carry the new faces.
        let outer = chf.boundary_half_faces().to_vec();
        let opened = outer
            .iter()
            .filter(|&&hf| chf.remove_tetrahedron(hf / 4).is_ok())
            .count();
        assert!(opened > 10, "{opened} boundary tetrahedra removed");
        assert!(pending(&chf) <= 2 * unpaired(&chf) + 1024 + 32);
        let full = crate::chf::build::level3::build(&chf, 1, 0).unwrap();
        assert_eq!(chf.boundary_half_faces()[..], full.half_faces[..]);
        assert_eq!(chf.num_boundary_components(), full.components);
    }
}
