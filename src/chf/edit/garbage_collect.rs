//! Compaction: the live tetrahedra rebuilt into a CHF of the same level (so `hf = 4t + i`
//! again, ids are ranks again and the edit state is gone), with old-to-new maps. A fresh
//! build costs O(T log T), more than moving the arrays down would, and gives the exact
//! structure a build of the same tetrahedra gives: the same ids, the same answers. That
//! build keeps each component's side, as the edits left it.

use crate::NONE;
use crate::chf::build::{Orientation, build_oriented, flipped_id};
use crate::chf::ids::{EDGE, edge_index, first, local, slot_half_edges, slot_of, tet};
use crate::chf::query::view::Need;
use crate::chf::{BuildOptions, Chf, NO_HALF_EDGE};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_vec};
use crate::util::input::Input;
use crate::util::marks::Marks;
use crate::util::progress::BuildProgress;

/// Old id -> new id after [`Chf::garbage_collect`], `NONE` for a removed element.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GarbageMaps {
    pub vertices: Vec<u32>,
    pub tetrahedra: Vec<u32>,
    pub faces: Vec<u32>,
    pub edges: Vec<u32>,
}

/// `0, 1, ...` over the live ids, `NONE` over the removed ones.
fn compaction(removed: &Marks, what: &str) -> Result<Vec<u32>> {
    let mut next = 0u32;
    try_collect(
        removed.iter().map(|r| {
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

/// An edited CHF's live tetrahedra and vertices built afresh, with the old-to-new maps.
pub(crate) struct Compacted {
    pub chf: Chf,
    pub vertices: Vec<u32>,
    pub tetrahedra: Vec<u32>,
    /// Some tetrahedron was turned over (a component that cannot be oriented): the local
    /// numbering must be looked up.
    turned: bool,
}

impl Compacted {
    /// Where local vertex `i` of live tetrahedron `t` of `old` went: the same place, or
    /// swapped with its neighbour where the build turned a component of a non-orientable
    /// mesh over (`compacted` checks there is nothing else).
    fn new_local(&self, old: &Chf, t: u32, i: u32) -> u32 {
        if !self.turned {
            return i;
        }
        let n = self.tetrahedra[t as usize];
        let x = self.vertices[old.v[(first(t) + i) as usize] as usize];
        if self.chf.v[(first(n) + i) as usize] == x {
            i
        } else {
            flipped_id(i)
        }
    }

    /// Whether every live tetrahedron of `old` kept its place and its vertices (turned
    /// over at most, which sets `turned`) and no vertex was split.
    fn one_to_one(&mut self, old: &Chf) -> bool {
        let live = |map: &[u32]| map.iter().filter(|&&n| n != NONE).count();
        if self.chf.num_tetrahedra() != live(&self.tetrahedra)
            || self.chf.num_vertices() != live(&self.vertices)
        {
            return false;
        }
        for (t, &n) in self.tetrahedra.iter().enumerate() {
            if n == NONE {
                continue;
            }
            let q = old
                .tetrahedron_vertices(t as u32)
                .map(|x| self.vertices[x as usize]);
            let now = &self.chf.v[first(n) as usize..][..4];
            if now != q {
                if now != [q[0], q[2], q[1], q[3]] {
                    return false;
                }
                self.turned = true;
            }
        }
        true
    }

    /// The new id of half-face `h` of a live tetrahedron of `old`.
    pub(crate) fn half_face(&self, old: &Chf, h: u32) -> u32 {
        4 * self.tetrahedra[tet(h) as usize] + self.new_local(old, tet(h), local(h))
    }

    /// The new id of edge slot `slot` of a live tetrahedron of `old`.
    fn slot(&self, old: &Chf, slot: u64) -> u64 {
        let t = (slot / 6) as u32;
        let [p, q] = EDGE[(slot % 6) as usize].map(|i| self.new_local(old, t, i));
        6 * u64::from(self.tetrahedra[t as usize]) + u64::from(edge_index(p, q))
    }
}

impl Chf {
    /// The live tetrahedra and vertices built afresh, each component oriented as it is
    /// here, with the vertex and tetrahedron maps.
    pub(crate) fn compacted(&self) -> Result<Compacted> {
        let s = self.edit.as_ref().expect("an edited CHF");
        let vertices = compaction(&s.vertex_removed, "the vertex map")?;
        let tetrahedra = compaction(&s.tet_removed, "the tetrahedron map")?;
        let mut tets = try_vec(s.live_tetrahedra, [0u32; 4], "the live tetrahedra")?;
        for (t, &n) in tetrahedra.iter().enumerate() {
            if n != NONE {
                tets[n as usize] = self
                    .tetrahedron_vertices(t as u32)
                    .map(|x| vertices[x as usize]);
            }
        }
        let positions = if self.positions.is_empty() {
            Vec::new()
        } else {
            let live = (0..self.n_vertices).filter(|&x| vertices[x] != NONE);
            try_collect(live.map(|x| self.positions[x]), "the live positions")?
        };
        let options = BuildOptions {
            threads: 1,
            ..BuildOptions::level(self.level)
        };
        let input = Input::owned(tets, s.live_vertices, positions);
        let progress = BuildProgress::default();
        let chf = build_oriented(input, options, progress, Orientation::AsGiven)?;
        let mut out = Compacted {
            chf,
            vertices,
            tetrahedra,
            turned: false,
        };
        if !out.one_to_one(self) {
            return Err(Error::invalid(
                "the live tetrahedra did not rebuild one to one (an edit broke an invariant)",
            ));
        }
        Ok(out)
    }

    /// Compacts an edited CHF: removed elements go, the ids of the rest become those a
    /// fresh build of the live tetrahedra gives (their order kept, and each component on
    /// the side it is on, where a build from scratch may turn a folded one over to agree
    /// with most of its determinants), and the maps say where each old id went. The origin
    /// maps then name the compacted ids. On a CHF never edited, identity maps and no
    /// change. O(T log T).
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
        let fresh = self.compacted()?;
        let s = self.edit.as_ref().expect("edited");
        // The ids of the fresh build taken once: below level 2 each one-element query
        // would compute them again.
        let need = Need {
            faces: true,
            edges: true,
        };
        let view = fresh.chf.try_view(need)?;
        let faces = remap(&s.face_hf, NONE, "the face map", |h| {
            view.face_of(fresh.half_face(self, h))
        })?;
        let edges = remap(&s.edge_he, NO_HALF_EDGE, "the edge map", |he| {
            let slot = fresh.slot(self, slot_of(he));
            view.edge_of(slot_half_edges(slot)[0])
        })?;
        drop(view);
        let Compacted {
            chf,
            vertices,
            tetrahedra,
            ..
        } = fresh;
        *self = chf;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A rebuild that turned tetrahedra over (local vertices 1 and 2 swapped): each
    /// half-face maps to the one opposite the same vertex, each edge slot to the one on
    /// the same two vertices; anything else than a swap is refused.
    #[test]
    fn maps_follow_a_turned_tetrahedron() {
        let options = BuildOptions::level(2);
        let build = |tets: &[[u32; 4]]| Chf::from_tetrahedra(tets, 5, &[], options).unwrap();
        let old = build(&[[0, 1, 2, 3], [4, 1, 2, 3]]);
        let turned = build(&[[0, 2, 1, 3], [4, 2, 1, 3]]);
        let mut c = Compacted {
            chf: turned,
            vertices: (0..5).collect(),
            tetrahedra: vec![0, 1],
            turned: false,
        };
        assert!(c.one_to_one(&old) && c.turned);
        for h in 0..8 {
            assert_eq!(c.chf.v[c.half_face(&old, h) as usize], old.v[h as usize]);
        }
        let ends = |chf: &Chf, s: u64| {
            let [p, q] = EDGE[(s % 6) as usize].map(|i| chf.v[(4 * (s / 6) as u32 + i) as usize]);
            [p.min(q), p.max(q)]
        };
        for s in 0..12 {
            assert_eq!(ends(&c.chf, c.slot(&old, s)), ends(&old, s));
        }
        c.chf = build(&[[0, 1, 3, 2], [4, 1, 2, 3]]);
        assert!(!c.one_to_one(&old));
    }
}
