//! The editable form: what the first edit materialises, and the working tables an edit
//! below level 2 computes for itself, so that every operation is written once.

use super::arrays::{o_mut, vh_mut};
use crate::NONE;
use crate::che::ids::next;
use crate::che::tables::edge_ids;
use crate::che::{Che, Checked};
use crate::error::Result;
use crate::util::alloc::{or_panic, try_push, try_vec};
use crate::util::live_ranks::LiveRanks;
use crate::util::marks::Marks;
use std::sync::OnceLock;

/// What an edited CHE keeps beside its arrays.
#[derive(Clone, Debug, Default)]
pub(crate) struct EditState {
    /// From level 2: the edge id of every half-edge (`NONE` on a removed one). Empty when
    /// the ranks of the edge directory are the ids (right after garbage collection).
    pub(crate) edge_of: Vec<u32>,
    /// The removed vertices (an isolated vertex is not removed).
    pub(crate) removed_vertex: Marks,
    pub(crate) live_vertices: usize,
    pub(crate) live_triangles: usize,
    pub(crate) live_edges: usize,
    /// Level 3: the curves, computed at the first curve query after an edit.
    pub(crate) curves: OnceLock<Curves>,
    /// Level 3: where the next curve computation starts from.
    pub(crate) boundary: super::boundary::BoundaryLog,
    /// An operation has changed the mesh since the last garbage collection, so the level
    /// tables the build's rules define (edge ranks, curves) no longer describe it.
    pub(crate) changed: bool,
    /// Below level 2: the working tables between edits.
    pub(crate) working: Option<WorkingTables>,
    /// Below level 2, beside the working tables: the live edges counted by block, so
    /// that an operation finds edge `e` (the `e`-th live canonical half-edge, since ids are
    /// ranks there) without counting the edges before it. Kept up to date by the writes
    /// of `arrays.rs` and recounted at the end of each operation.
    pub(crate) edge_ranks: Option<LiveRanks>,
}

/// Below level 2, the `O` (level 0) and `VH` that the operations find stars with and keep
/// up to date, which the level does not store. The first edit computes them, O(T); they
/// are kept between edits, so that each later one costs the stars it touches, as from
/// level 2. Outside an edit they sit here, not in the `Che`'s arrays, so every query
/// answers as its level does. Dropped by a level change and by `garbage_collect`.
#[derive(Clone, Debug, Default)]
pub(crate) struct WorkingTables {
    /// Level 0 only (level 1 stores `O`): empty at level 1.
    pub(crate) o: Vec<u32>,
    pub(crate) vh: Vec<u32>,
}

/// Boundary curves of an edited CHE.
#[derive(Clone, Debug, Default)]
pub(crate) struct Curves {
    /// The smallest half-edge of each curve, increasing.
    pub(crate) ch: Vec<u32>,
    /// The boundary half-edges, increasing, and the curve of each.
    pub(crate) boundary: Vec<u32>,
    pub(crate) curve: Vec<u32>,
    /// How many unpaired half-edges the boundary log held when these were computed.
    pub(crate) noted: usize,
}

impl EditState {
    /// Drops what the edits keep below level 2 (the working tables and the live edges'
    /// counts, which describe them): a collection or a level change makes them stale.
    pub(crate) fn drop_kept_tables(&mut self) {
        self.working = None;
        self.edge_ranks = None;
    }
    /// Bytes of the edge ids and the removed-vertex flags (lengths, as [`crate::che::Memory`]).
    pub(crate) fn edge_bytes(&self) -> usize {
        let ranks = self.edge_ranks.as_ref().map_or(0, LiveRanks::memory_bytes);
        4 * self.edge_of.len() + self.removed_vertex.memory_bytes() + ranks
    }
    /// Bytes of the level-3 boundary log and of the curves computed from it.
    pub(crate) fn curve_bytes(&self) -> usize {
        let curves = self.curves.get();
        let computed = curves.map_or(0, |c| c.ch.len() + c.boundary.len() + c.curve.len());
        self.boundary.memory_bytes() + 4 * computed
    }
}

impl Che {
    /// The edit state, when the CHE has been edited.
    #[inline]
    pub(crate) fn edits(&self) -> Option<&EditState> {
        self.edit.as_deref()
    }

    pub(super) fn st(&self) -> &EditState {
        self.edit.as_deref().expect("an edit has begun")
    }
    pub(super) fn st_mut(&mut self) -> &mut EditState {
        self.edit.as_deref_mut().expect("an edit has begun")
    }

    /// Runs one operation: the state materialised (first edit), the working tables below
    /// level 2 computed, `op` (which checks everything before it writes), the working
    /// tables dropped again, whatever `op` returned.
    pub(super) fn edit_with<T>(&mut self, op: impl FnOnce(&mut Che) -> Result<T>) -> Result<T> {
        self.begin_edit()?;
        let r = op(self);
        self.checked = Checked::Nothing;
        self.end_edit();
        if r.is_ok() {
            self.st_mut().changed = true;
        }
        r
    }

    fn begin_edit(&mut self) -> Result<()> {
        super::arrays::promote(self)?;
        if self.edit.is_none() {
            let st = EditState {
                removed_vertex: Marks::clear_of(self.n_vertices, "the removed-vertex flags")?,
                live_vertices: self.n_vertices,
                live_triangles: self.num_triangles(),
                live_edges: self.num_edges,
                ..Default::default()
            };
            self.edit = Some(Box::new(st));
            self.seed_boundary_log()?;
        }
        if self.level >= 2 && self.st().edge_of.is_empty() && !self.v.is_empty() {
            let ids = edge_ids(&self.o)?;
            self.st_mut().edge_of = ids;
            // The ids replace the ranks of the edge directory: nothing reads it while
            // `edge_of` is there, and `garbage_collect` builds it anew.
            self.edge_bits = Default::default();
        }
        self.add_working_tables()
    }

    /// Below level 2, the tables an edit or a check reads and the level does not store:
    /// `O` (level 0) and `VH` over the live triangles, the kept ones when an edit left
    /// them.
    fn add_working_tables(&mut self) -> Result<()> {
        if self.level >= 2 {
            return Ok(());
        }
        let kept = self.edit.as_deref_mut().and_then(|st| st.working.take());
        let WorkingTables { o, vh } = match kept {
            Some(kept) => kept,
            None => self.computed_working_tables()?,
        };
        if self.level == 0 {
            *o_mut(self) = o;
        }
        *vh_mut(self) = vh;
        Ok(())
    }

    /// The working tables from `V` (and `O` at level 1), O(T); on an edited CHE also the
    /// live edges' counts.
    fn computed_working_tables(&mut self) -> Result<WorkingTables> {
        let o = match self.level {
            0 => self.live_opposites()?,
            _ => Vec::new(),
        };
        let full_o = if self.level == 0 { &o[..] } else { &self.o[..] };
        let vh = self.live_vertex_half_edges(full_o)?;
        if self.edit.is_some() {
            let ranks = LiveRanks::new(full_o.len(), |h| self.is_live_canonical(full_o, h))?;
            self.st_mut().edge_ranks = Some(ranks);
        }
        Ok(WorkingTables { o, vh })
    }

    /// Recounts the blocks of live edges the operation touched.
    fn refresh_edge_ranks(&mut self) {
        let Some(mut ranks) = self.edit.as_deref_mut().and_then(|st| st.edge_ranks.take()) else {
            return;
        };
        ranks.refresh(self.v.len(), |h| self.is_live_canonical(&self.o, h));
        self.st_mut().edge_ranks = Some(ranks);
    }

    /// Takes the working tables out of the arrays again: into the edit state, for the next
    /// edit, or dropped when there is none (a check on a mesh never edited).
    fn drop_working_tables(&mut self) {
        if self.level >= 2 {
            return;
        }
        let o = match self.level {
            0 => std::mem::take(o_mut(self)),
            _ => Vec::new(),
        };
        let vh = std::mem::take(vh_mut(self));
        if let Some(st) = self.edit.as_deref_mut() {
            st.working = Some(WorkingTables { o, vh });
        }
    }

    /// The `VH` of an edited CHE below level 2 that its last edit kept, when there is one:
    /// a star's start by level 2's rule, without a scan.
    pub(crate) fn kept_vertex_half_edges(&self) -> Option<&[u32]> {
        let working = self.edits()?.working.as_ref()?;
        (self.level < 2).then_some(&working.vh[..])
    }

    /// The `O` of an edited CHE below level 2 that its last edit kept, when there is one:
    /// the live triangles' `O` by the level-0 rule, without computing it.
    pub(crate) fn kept_opposites(&self) -> Option<&[u32]> {
        let working = self.edits()?.working.as_ref()?;
        (self.level == 0).then_some(&working.o[..])
    }

    /// Runs a check, which never modifies the mesh: from level 2 on the arrays as they are
    /// (a mapped mesh stays mapped, nothing is marked edited, no cache is dropped); below,
    /// with the working tables: an edited mesh's kept ones, else computed for the check
    /// and dropped after.
    pub(super) fn check_with<T>(&mut self, op: impl FnOnce(&Che) -> Result<T>) -> Result<T> {
        if self.level >= 2 {
            return op(self);
        }
        self.add_working_tables()?;
        let r = op(self);
        self.drop_working_tables();
        r
    }

    fn end_edit(&mut self) {
        self.refresh_edge_ranks();
        self.drop_working_tables();
        if self.level < 2 {
            self.num_edges = self.st().live_edges;
        } else {
            self.num_edges = self.eh.len();
        }
        self.lazy_edge_bits = OnceLock::new();
        self.settle_boundary_log();
        self.st_mut().curves = OnceLock::new();
    }

    /// `O` by the level-0 rule over the live triangles: a removed triangle's corners become
    /// one phantom vertex, whose half-edges pair with nothing.
    pub(crate) fn live_opposites(&self) -> Result<Vec<u32>> {
        let phantom = self.n_vertices as u32;
        let mut v = crate::util::alloc::try_to_vec(&self.v, "the live half-edges")?;
        v.iter_mut()
            .filter(|x| **x == NONE)
            .for_each(|x| *x = phantom);
        crate::che::pairs::opposites_by_rule(&v, self.n_vertices + 1, &self.non_manifold)
    }

    /// `VH` over the live half-edges, as the build computes it.
    pub(crate) fn live_vertex_half_edges(&self, o: &[u32]) -> Result<Vec<u32>> {
        let mut vh = try_vec(self.n_vertices, NONE, "the vertex half-edges VH")?;
        for (h, (&x, &g)) in self.v.iter().zip(o).enumerate() {
            if x == NONE {
                continue;
            }
            let slot = &mut vh[x as usize];
            if *slot == NONE || g == NONE {
                *slot = h as u32;
            }
        }
        Ok(vh)
    }

    /// Is `h` a live canonical half-edge (the one that names its edge by rank)?
    #[inline]
    pub(crate) fn is_live_canonical(&self, o: &[u32], h: usize) -> bool {
        self.v[h] != NONE && crate::che::tables::is_canonical(o, h)
    }

    /// The edge ids below level 2 for an edited CHE: the ranks of the live canonical
    /// half-edges.
    pub(crate) fn live_edge_directory(
        &self, o: &[u32],
    ) -> Result<crate::util::rank_directory::RankDirectory> {
        crate::util::rank_directory::RankDirectory::from_fn(o.len(), |h| {
            self.is_live_canonical(o, h)
        })
    }

    /// The edge id of every half-edge of an edited CHE below level 2 (`NONE` if removed).
    pub(crate) fn live_edge_ids(&self, o: &[u32]) -> Result<Vec<u32>> {
        let mut ids = edge_ids(o)?;
        let mut next_id = 0;
        for h in 0..o.len() {
            if self.is_live_canonical(o, h) {
                ids[h] = next_id;
                if o[h] != NONE {
                    ids[o[h] as usize] = next_id;
                }
                next_id += 1;
            } else if self.v[h] == NONE {
                ids[h] = NONE;
            }
        }
        Ok(ids)
    }

    /// The curves of an edited CHE at level 3, computed on the first request after an edit
    /// in O(B log B + k log k) for B boundary half-edges and k edits since the last one.
    /// Out of memory, a panic whose payload is the error (see `or_panic`).
    pub(crate) fn edited_curves(&self) -> &Curves {
        or_panic(self.try_edited_curves())
    }

    /// [`Che::edited_curves`], out of memory an error.
    pub(crate) fn try_edited_curves(&self) -> Result<&Curves> {
        let st = self.edits().expect("an edited CHE");
        if let Some(curves) = st.curves.get() {
            return Ok(curves);
        }
        let curves = self.computed_curves()?;
        Ok(st.curves.get_or_init(|| curves))
    }

    fn computed_curves(&self) -> Result<Curves> {
        let (boundary, noted) = self.boundary_half_edges()?;
        let mut curve = try_vec(boundary.len(), NONE, "the curve of each boundary half-edge")?;
        let mut ch = Vec::new();
        for (i, &h) in boundary.iter().enumerate() {
            if curve[i] != NONE {
                continue;
            }
            let c = ch.len() as u32;
            try_push(&mut ch, h, "the boundary curves")?;
            let mut g = h;
            loop {
                let r = boundary.binary_search(&g).expect("a boundary half-edge");
                curve[r] = c;
                g = self.vh[self.v[next(g) as usize] as usize];
                if g == h {
                    break;
                }
            }
        }
        Ok(Curves {
            ch,
            boundary,
            curve,
            noted,
        })
    }

    /// The curve of half-edge `h` of an edited CHE at level 3 (`NONE` when interior).
    pub(crate) fn edited_curve_of(&self, h: u32) -> u32 {
        let c = self.edited_curves();
        match c.boundary.binary_search(&h) {
            Ok(r) => c.curve[r],
            Err(_) => NONE,
        }
    }

    /// [`Che::build_level`] on an edited CHE: the same tables over the live elements.
    pub(crate) fn change_edited_level(&mut self, level: u8) -> Result<()> {
        crate::util::options::check_level(level)?;
        // The kept tables go with the level change: the kept `O` moves, not copied.
        let kept = self.st_mut().working.take().filter(|_| self.level == 0);
        let o = match self.level {
            0 if level >= 1 => match kept {
                Some(kept) => kept.o,
                None => self.live_opposites()?,
            },
            _ => std::mem::take(o_mut(self)),
        };
        let vh = if level >= 2 && self.level < 2 {
            self.live_vertex_half_edges(&o)?
        } else {
            std::mem::take(vh_mut(self))
        };
        let edge_of = if level >= 2 && self.level < 2 {
            self.live_edge_ids(&o)?
        } else {
            std::mem::take(&mut self.st_mut().edge_of)
        };
        let eh = if level >= 2 && self.level < 2 {
            let mut eh = try_vec(self.st().live_edges, NONE, "the edge half-edges EH")?;
            for h in (0..o.len()).filter(|&h| self.is_live_canonical(&o, h)) {
                eh[edge_of[h] as usize] = h as u32;
            }
            eh
        } else {
            std::mem::take(super::arrays::eh_mut(self))
        };
        *o_mut(self) = if level >= 1 { o } else { Vec::new() };
        let keep2 = level >= 2;
        *vh_mut(self) = if keep2 { vh } else { Vec::new() };
        *super::arrays::eh_mut(self) = if keep2 { eh } else { Vec::new() };
        self.st_mut().edge_of = if keep2 { edge_of } else { Vec::new() };
        self.level = level;
        self.num_edges = if keep2 {
            self.eh.len()
        } else {
            self.st().live_edges
        };
        self.lazy_edge_bits = OnceLock::new();
        self.st_mut().curves = OnceLock::new();
        self.st_mut().boundary = Default::default();
        self.st_mut().drop_kept_tables();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::che::{BuildOptions, Che};
    use crate::generate::{grid, torus};

    /// Below level 2 the first edit computes the working tables and every later one finds
    /// them kept: after each edit they are those a fresh computation gives (`O`) or follow
    /// level 2's rules (`VH`), queries read them, and a damaged kept table fails `validate`.
    #[test]
    fn working_tables_are_kept_between_edits_below_level_2() {
        for level in [0u8, 1] {
            for s in [grid(6, 5), torus(7, 5)] {
                let n = s.positions.len();
                let options = BuildOptions::level(level);
                let mut che = Che::from_triangles(&s.triangles, n, &s.positions, options).unwrap();
                let before = che.memory_bytes();
                for t in (0..che.num_triangles() as u32).step_by(7) {
                    che.split_triangle(t, None).unwrap();
                    let kept = che.edits().unwrap().working.as_ref().unwrap();
                    if level == 0 {
                        assert_eq!(kept.o, che.live_opposites().unwrap(), "level 0, t {t}");
                    }
                    assert_eq!(kept.vh.len(), che.num_vertices());
                    che.validate().unwrap();
                }
                che.remove_vertex(0).unwrap();
                che.validate().unwrap();
                // The kept tables are counted, and nothing is left in the level's arrays.
                let after = che.memory_bytes();
                assert_eq!(after.vertex_half_edges, 4 * che.num_vertices());
                assert!(che.vertex_half_edges().is_none());
                if level == 0 {
                    assert_eq!(before.opposites, 0);
                    assert_eq!(after.opposites, 4 * che.num_half_edges());
                    assert!(che.opposites().is_none());
                }
                let mut broken = che.clone();
                let st = broken.edit.as_deref_mut().unwrap();
                st.working.as_mut().unwrap().vh.swap(1, 2);
                assert!(broken.validate().is_err(), "level {level}: VH swapped");
                if level == 0 {
                    let mut broken = che.clone();
                    let st = broken.edit.as_deref_mut().unwrap();
                    let o = &mut st.working.as_mut().unwrap().o;
                    let h = o.iter().position(|&g| g != crate::NONE).unwrap();
                    o[h] = crate::NONE;
                    assert!(broken.validate().is_err(), "level 0: O[{h}] unpaired");
                }
                // A collection and a level change drop them; the next edit computes them.
                let mut collected = che.clone();
                collected.garbage_collect().unwrap();
                assert!(collected.edits().unwrap().working.is_none());
                collected.split_triangle(0, None).unwrap();
                collected.validate().unwrap();
                let mut raised = che.clone();
                raised.build_level(2).unwrap();
                assert!(raised.edits().unwrap().working.is_none());
                raised.validate().unwrap();
            }
        }
    }
}
