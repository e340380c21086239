//! Bulk relations for every element at once, in compressed sparse rows, at every level
//! and without raising it (no copy of the mesh).
//!
//! Around the vertices (VT, VF, VE, VV) the rows come from counting passes, O(T) with no
//! walk: count the occurrences per vertex, prefix sums, then place each id in its rows in
//! increasing id order, which is the order of the one-element calls. VT scans `V`; VF and
//! VE scan the canonical half-faces and edge slots (ranks the view computes below level
//! 2); VV takes both ends of every canonical edge slot, then sorts each row and drops the
//! repeats. Every pass reads `V` in order (sequential memory). Around the edges (ET, EF) the rows are the rotations,
//! walked on one view shared by all of them.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{EDGE, face_cycle};
use crate::chf::query::fan::EdgeIds;
use crate::chf::query::view::{Need, View};
use crate::error::Result;
use crate::util::alloc::{try_extend, try_to_vec, try_vec, try_with_capacity};

/// Row `i` is `indices[offsets[i] as usize..offsets[i + 1] as usize]`.
pub type Csr = crate::util::csr::Csr<u32>;

/// Rows over `n` vertices from `(vertex, id)` pairs given twice by `each` (once to count,
/// once to place), ids in increasing order per pass, so that every row is sorted.
fn by_counting(n: usize, each: impl Fn(&mut dyn FnMut(u32, u32))) -> Result<Csr> {
    let mut offsets = try_vec(n + 1, 0u32, "the CSR offsets")?;
    each(&mut |x, _| offsets[x as usize + 1] += 1);
    for i in 0..n {
        offsets[i + 1] += offsets[i];
    }
    let mut fill = try_to_vec(&offsets[..n], "the CSR fill")?;
    let mut indices = try_vec(offsets[n] as usize, 0u32, "the CSR indices")?;
    each(&mut |x, id| {
        let f = &mut fill[x as usize];
        indices[*f as usize] = id;
        *f += 1;
    });
    Ok(Csr { offsets, indices })
}

impl Chf {
    /// The rows of an edited CHF from the one-element calls (removed vertices get empty
    /// rows); `None` on a CHF never edited.
    fn edited_rows<I: Iterator<Item = u32>>(&self, row: impl Fn(u32) -> I) -> Option<Result<Csr>> {
        self.edit.as_ref()?;
        Some(self.try_edited_rows(row))
    }

    fn try_edited_rows<I: Iterator<Item = u32>>(&self, row: impl Fn(u32) -> I) -> Result<Csr> {
        let mut offsets = try_with_capacity(self.n_vertices + 1, "the CSR offsets")?;
        let mut indices = Vec::new();
        offsets.push(0u32);
        for x in 0..self.n_vertices as u32 {
            if !self.is_vertex_removed(x) {
                try_extend(&mut indices, row(x), "the CSR indices")?;
            }
            offsets.push(indices.len() as u32);
        }
        Ok(Csr { offsets, indices })
    }

    /// `O` at every level: borrowed from level 1, computed below (O(T), the rule level 1
    /// stores).
    ///
    /// An [`ErrorKind::OutOfMemory`](crate::ErrorKind::OutOfMemory) error when the answer
    /// (or the tables computed for it below the level that stores them) does not fit in
    /// memory; the same for every bulk relation.
    pub fn all_opposites(&self) -> Result<Vec<u32>> {
        match self.opposites() {
            Some(o) => try_to_vec(o, "the opposites O"),
            None => self.try_opposites_by_rule(),
        }
    }

    /// VT for every vertex: row `v` is [`Chf::vertex_tetrahedra`]`(v)`. O(T) at every level.
    pub fn all_vertex_tetrahedra(&self) -> Result<Csr> {
        if let Some(rows) = self.edited_rows(|x| self.vertex_tetrahedra(x)) {
            return rows;
        }
        let v = &self.v;
        by_counting(self.n_vertices, |f| {
            for (hf, &x) in v.iter().enumerate() {
                f(x, (hf >> 2) as u32);
            }
        })
    }

    /// VF for every vertex: row `v` is [`Chf::vertex_faces`]`(v)`. O(T) at every level.
    pub fn all_vertex_faces(&self) -> Result<Csr> {
        if let Some(rows) = self.edited_rows(|x| self.vertex_faces(x)) {
            return rows;
        }
        let view = self.try_view(Need::FACES)?;
        let mut fh = Vec::new();
        let fh: &[u32] = match self.face_half_faces() {
            Some(fh) => fh,
            None => {
                view.faces
                    .ones_map(&mut fh, |hf| hf as u32, "the face half-faces")?;
                &fh
            }
        };
        by_counting(self.n_vertices, |f| {
            for (id, &hf) in fh.iter().enumerate() {
                for x in face_cycle(&self.v, hf) {
                    f(x, id as u32);
                }
            }
        })
    }

    /// VE for every vertex: row `v` is [`Chf::vertex_edges`]`(v)`. O(T) at every level.
    pub fn all_vertex_edges(&self) -> Result<Csr> {
        if let Some(rows) = self.edited_rows(|x| self.vertex_edges(x)) {
            return rows;
        }
        let view = self.try_view(Need::EDGES)?;
        let mut slots = Vec::new();
        view.edges
            .ones_map(&mut slots, |s| s as u64, "the edge slots")?;
        by_counting(self.n_vertices, |f| {
            for (id, &s) in slots.iter().enumerate() {
                let base = 4 * (s / 6) as usize;
                let [a, b] = EDGE[(s % 6) as usize];
                f(self.v[base + a as usize], id as u32);
                f(self.v[base + b as usize], id as u32);
            }
        })
    }

    /// VV for every vertex: row `v` is [`Chf::vertex_vertices`]`(v)`. O(T) at every level
    /// (plus sorting the rows): both ends of every canonical edge slot, read in
    /// tetrahedron order (sequential memory), then each row sorted and its repeats (a pair
    /// of vertices with several fans) dropped.
    pub fn all_vertex_vertices(&self) -> Result<Csr> {
        if let Some(rows) = self.edited_rows(|x| self.vertex_vertices(x)) {
            return rows;
        }
        let view = self.try_view(Need::EDGES)?;
        let bits = &view.edges;
        let v = &self.v;
        let mut c = by_counting(self.n_vertices, |f| {
            for (t, q) in v.chunks_exact(4).enumerate() {
                for (k, [a, b]) in EDGE.iter().enumerate() {
                    if bits.get(6 * t + k) {
                        let (x, y) = (q[*a as usize], q[*b as usize]);
                        f(x, y);
                        f(y, x);
                    }
                }
            }
        })?;
        // Sort each row and drop repeats, compacting in place.
        let mut end = 0usize;
        let mut start = 0usize;
        for x in 0..self.n_vertices {
            let stop = c.offsets[x + 1] as usize;
            c.indices[start..stop].sort_unstable();
            c.offsets[x] = end as u32;
            let mut last = NONE;
            for k in start..stop {
                let w = c.indices[k];
                if w != last {
                    c.indices[end] = w;
                    end += 1;
                    last = w;
                }
            }
            start = stop;
        }
        c.offsets[self.n_vertices] = end as u32;
        c.indices.truncate(end);
        Ok(c)
    }

    /// TT for every tetrahedron: calls `row(t)` for each tetrahedron in order with
    /// [`Chf::tetrahedron_tetrahedra`]`(t)`. O(T) at every level (`O` computed once below
    /// level 1).
    pub fn for_each_tetrahedron_tetrahedra(&self, mut row: impl FnMut([u32; 4])) {
        let view = self.view(Need::NOTHING);
        for (t, q) in view.o.chunks_exact(4).enumerate() {
            if self.is_tetrahedron_removed(t as u32) {
                // A removed tetrahedron keeps its row, empty, so rows stay ids.
                row([NONE; 4]);
                continue;
            }
            row([0, 1, 2, 3].map(|i| if q[i] == NONE { NONE } else { q[i] >> 2 }));
        }
    }

    /// ET for every edge: calls `row(e, tetrahedra)` for each edge in order, with the
    /// answer of [`Chf::edge_tetrahedra`]. O(T) in all at every level.
    pub fn for_each_edge_tetrahedra(&self, row: impl FnMut(u32, EdgeIds<'_>)) {
        self.edge_rows(Need::EDGES, false, row)
    }

    /// EF for every edge, as [`Chf::for_each_edge_tetrahedra`] with [`Chf::edge_faces`].
    pub fn for_each_edge_faces(&self, row: impl FnMut(u32, EdgeIds<'_>)) {
        let need = Need {
            faces: true,
            edges: true,
        };
        self.edge_rows(need, true, row)
    }

    fn edge_rows(&self, need: Need, faces: bool, mut row: impl FnMut(u32, EdgeIds<'_>)) {
        let view: View<'_> = self.view(need);
        for e in 0..self.num_edges as u32 {
            if self.is_edge_removed(e) {
                continue;
            }
            row(e, EdgeIds::on(view.reborrow(), e, faces));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chf::BuildOptions;

    #[test]
    fn bulk_rows_are_the_one_element_answers_at_every_level() {
        let seed = 0x2545_F491_4F6C_DD1Du64;
        for (round, (n, tets)) in
            crate::util::test_soups::<4>(seed, 60, (6, 15), (8, 40)).enumerate()
        {
            for level in 0..=3 {
                let chf = Chf::from_tetrahedra(&tets, n, &[], BuildOptions::level(level)).unwrap();
                let nv = chf.num_vertices();
                let (vt, vf) = (chf.all_vertex_tetrahedra(), chf.all_vertex_faces());
                let (ve, vv) = (chf.all_vertex_edges(), chf.all_vertex_vertices());
                let [vt, vf, ve, vv] = [vt, vf, ve, vv].map(Result::unwrap);
                for v in 0..nv as u32 {
                    let at = format!("round {round}, level {level}, vertex {v}");
                    let row = |c: &Csr| c.row(v as usize).to_vec();
                    assert_eq!(
                        row(&vt),
                        chf.vertex_tetrahedra(v).collect::<Vec<_>>(),
                        "{at}"
                    );
                    assert_eq!(row(&vf), chf.vertex_faces(v).collect::<Vec<_>>(), "{at}");
                    assert_eq!(row(&ve), chf.vertex_edges(v).collect::<Vec<_>>(), "{at}");
                    assert_eq!(row(&vv), chf.vertex_vertices(v).collect::<Vec<_>>(), "{at}");
                }
                let mut rows = 0;
                chf.for_each_edge_tetrahedra(|e, r| {
                    assert_eq!(
                        r.collect::<Vec<_>>(),
                        chf.edge_tetrahedra(e).collect::<Vec<_>>()
                    );
                    rows += 1;
                });
                chf.for_each_edge_faces(|e, r| {
                    assert_eq!(r.collect::<Vec<_>>(), chf.edge_faces(e).collect::<Vec<_>>());
                });
                assert_eq!(rows, chf.num_edges());
            }
        }
    }
}
