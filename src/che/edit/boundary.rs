//! The boundary half-edges of an edited CHE at level 3, kept so that the curves are rebuilt
//! at the next curve query from the boundary and the edits since, not from a scan of the
//! mesh: the sorted boundary of the last computation, and every half-edge an edit has left
//! unpaired since (each such write notes it).

use crate::NONE;
use crate::che::Che;
use crate::error::Result;
use crate::util::alloc::{try_collect, try_with_capacity};

/// What the next curve computation starts from.
///
/// Unscanned (after a level change of an edited CHE, or when the log could not grow), the
/// next computation scans the mesh, so nothing is noted until then: a log that waited for
/// that scan would hold every half-edge an edit unpairs, as much as the edit state again.
#[derive(Clone, Debug, Default)]
pub(crate) struct BoundaryLog {
    /// `known` and `touched` hold every boundary half-edge (else the next computation scans
    /// and `touched` is empty).
    scanned: bool,
    /// The boundary when the curves were last computed, increasing (some may be paired or
    /// removed since).
    known: Vec<u32>,
    /// Half-edges left unpaired since (any order, may repeat).
    touched: Vec<u32>,
}

impl BoundaryLog {
    pub(crate) fn memory_bytes(&self) -> usize {
        4 * (self.known.len() + self.touched.len())
    }
}

impl Che {
    /// Half-edge `h` may have become a boundary half-edge.
    pub(super) fn note_unpaired(&mut self, h: u32) {
        if self.level < 3 {
            return;
        }
        let st = self.st_mut();
        // Curves computed by a scan become the known boundary when this operation ends
        // (`settle_boundary_log`), so what it unpairs after them is noted.
        if !st.boundary.scanned && st.curves.get().is_none() {
            return;
        }
        // Without room the log gives up, and the next computation scans: never a panic.
        // Curves computed before it go too, or `settle_boundary_log` would take them as
        // the known boundary without this half-edge.
        if st.boundary.touched.try_reserve(1).is_ok() {
            st.boundary.touched.push(h);
        } else {
            st.curves.take();
            st.boundary = BoundaryLog::default();
        }
    }

    /// At level 3, on a CHE whose level-3 tables describe it (its first edit, or right
    /// after garbage collection): the boundary of those tables becomes the known one, so
    /// that no curve computation has to scan the mesh.
    pub(super) fn seed_boundary_log(&mut self) -> crate::error::Result<()> {
        if self.level < 3 {
            return Ok(());
        }
        let mut known = Vec::new();
        let what = "the boundary half-edges of the edit state";
        self.boundary_bits
            .ones_map(&mut known, |h| h as u32, what)?;
        self.st_mut().boundary = BoundaryLog {
            scanned: true,
            known,
            touched: Vec::new(),
        };
        Ok(())
    }

    /// The boundary half-edges, increasing, and how many half-edges had been noted then: O(B + k log k) for B boundary half-edges and k
    /// noted since the last computation, one O(T) scan when there is none.
    pub(super) fn boundary_half_edges(&self) -> Result<(Vec<u32>, usize)> {
        let is_boundary = |h: u32| self.v[h as usize] != NONE && self.o[h as usize] == NONE;
        let log = &self.st().boundary;
        let noted = log.touched.len();
        let what = "the boundary half-edges";
        if !log.scanned {
            let all = (0..self.v.len() as u32).filter(|&h| is_boundary(h));
            return Ok((try_collect(all, what)?, noted));
        }
        let mut all = try_with_capacity(log.known.len() + log.touched.len(), what)?;
        all.extend_from_slice(&log.known);
        all.extend_from_slice(&log.touched);
        all.sort_unstable();
        all.dedup();
        all.retain(|&h| is_boundary(h));
        Ok((all, noted))
    }

    /// At the end of an operation at level 3: the boundary of computed curves becomes the
    /// known one (the curves themselves are dropped by the caller), and a long log is folded
    /// into it, so that it stays within the boundary (or the mesh) plus a constant.
    pub(super) fn settle_boundary_log(&mut self) {
        if self.level < 3 {
            return;
        }
        let st = self.st_mut();
        if let Some(c) = st.curves.take() {
            // What was noted after the computation (by this operation) stays noted.
            let log = &mut st.boundary;
            log.touched.drain(..c.noted.min(log.touched.len()));
            log.known = c.boundary;
            log.scanned = true;
            return;
        }
        let log = &st.boundary;
        // Folding costs a merge: past this length its cost is spread over at least as many
        // edits. An unscanned log notes nothing.
        // Without the memory to fold, the log stays as it is: longer, as correct.
        if log.scanned
            && log.touched.len() > log.known.len() + 1024
            && let Ok((known, _)) = self.boundary_half_edges()
        {
            let log = &mut self.st_mut().boundary;
            log.known = known;
            log.touched.clear();
            log.scanned = true;
        }
    }
}
