//! Compaction: the live tetrahedra rebuilt into a CHF of the same level (so `hf = 4t + i`
//! again, ids are ranks again and the edit state is gone), with old-to-new maps. A fresh
//! build costs O(T log T), more than moving the arrays down would, and gives the exact
//! structure a build of the same tetrahedra gives: the same ids, the same answers.

use crate::NONE;
use crate::chf::ids::{HalfEdge, first, he_face, he_index, local, tet};
use crate::chf::{BuildOptions, Chf, NO_HALF_EDGE};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_vec};

/// Old id -> new id after [`Chf::garbage_collect`], `NONE` for a removed element.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GarbageMaps {
    pub vertices: Vec<u32>,
    pub tetrahedra: Vec<u32>,
    pub faces: Vec<u32>,
    pub edges: Vec<u32>,
}

/// `0, 1, ...` over the live ids, `NONE` over the removed ones.
fn compaction(removed: &[bool], what: &str) -> Result<Vec<u32>> {
    let mut next = 0u32;
    try_collect(
        removed.iter().map(|&r| {
            if r {
                NONE
            } else {
                next += 1;
                next - 1
            }
        }),
        what,
    )
}

impl Chf {
    /// The live tetrahedra and vertices built afresh, with the vertex and tetrahedron maps.
    pub(crate) fn compacted(&self) -> Result<(Chf, Vec<u32>, Vec<u32>)> {
        let s = self.edit.as_ref().expect("an edited CHF");
        let vmap = compaction(&s.vertex_removed, "the vertex map")?;
        let tmap = compaction(&s.tet_removed, "the tetrahedron map")?;
        let mut tets = try_vec(s.live_tetrahedra, [0u32; 4], "the live tetrahedra")?;
        for (t, &n) in tmap.iter().enumerate() {
            if n != NONE {
                tets[n as usize] = self
                    .tetrahedron_vertices(t as u32)
                    .map(|x| vmap[x as usize]);
            }
        }
        let positions = if self.positions.is_empty() {
            Vec::new()
        } else {
            let live = (0..self.n_vertices).filter(|&x| vmap[x] != NONE);
            try_collect(live.map(|x| self.positions[x]), "the live positions")?
        };
        let options = BuildOptions {
            threads: 1,
            ..BuildOptions::level(self.level)
        };
        let fresh = Chf::from_tetrahedra(&tets, s.live_vertices, &positions, options)?;
        if fresh.num_tetrahedra() != tets.len() || fresh.num_vertices() != s.live_vertices {
            return Err(Error::invalid(
                "the live tetrahedra did not rebuild one to one (an edit broke an invariant)",
            ));
        }
        Ok((fresh, vmap, tmap))
    }

    /// Compacts an edited CHF: removed elements go, the ids of the rest become those a
    /// fresh build of the live tetrahedra gives (their order kept), and the maps say where
    /// each old id went. The origin maps then name the compacted ids. On a CHF never
    /// edited, identity maps and no change. O(T log T).
    pub fn garbage_collect(&mut self) -> Result<GarbageMaps> {
        if self.edit.is_none() {
            let ids = |n: usize| try_collect(0..n as u32, "the identity map");
            return Ok(GarbageMaps {
                vertices: ids(self.n_vertices)?,
                tetrahedra: ids(self.num_tetrahedra())?,
                faces: ids(self.num_faces)?,
                edges: ids(self.num_edges)?,
            });
        }
        let (fresh, vertices, tetrahedra) = self.compacted()?;
        let s = self.edit.as_ref().expect("edited");
        let new_hf = |h: u32| 4 * tetrahedra[tet(h) as usize] + local(h);
        let faces = remap(&s.face_hf, NONE, "the face map", |h| {
            fresh.face_of(new_hf(h))
        })?;
        let new_he = |he: HalfEdge| 3 * new_hf(he_face(he)) as u64 + he_index(he) as u64;
        let edges = remap(&s.edge_he, NO_HALF_EDGE, "the edge map", |he| {
            fresh.edge_of(new_he(he))
        })?;
        let _ = first;
        *self = fresh;
        Ok(GarbageMaps {
            vertices,
            tetrahedra,
            faces,
            edges,
        })
    }
}

/// The new id of each element of an edited CHF from its canonical part in `old` (`new`
/// maps it), `NONE` where that is `gone` (the element was removed).
fn remap<T: Copy + PartialEq>(
    old: &[T], gone: T, what: &str, new: impl Fn(T) -> u32,
) -> Result<Vec<u32>> {
    try_collect(
        old.iter().map(|&x| if x == gone { NONE } else { new(x) }),
        what,
    )
}
