//! Classic representations of a built CHF: half-face arrays, the dual graph of the
//! tetrahedra, the incidence (boundary) matrices `d1`, `d2`, `d3` and Betti numbers over
//! Z/2. Queries: one view of the level's tables (`O`, face and edge ranks computed once
//! below level 2), never a build pass.

mod betti;
mod matrices;

pub use matrices::VolumeMatrixKind;

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{face_cycle, tet};
use crate::chf::query::view::Need;
use crate::error::Result;
use crate::util::sparse::reserve;

/// Half-face arrays. Half-face `hf = 4t + i` is face `i` of tetrahedron `t = hf / 4`
/// (the face opposite its vertex `i`), its vertices in the order that points out of `t`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct HalfFaceArrays {
    /// The twin half-face (the same face seen from the other tetrahedron), `NONE` on the
    /// boundary.
    pub twin: Vec<u32>,
    /// 3 per half-face: its vertices, outward for its tetrahedron (a twin lists the same
    /// vertices in the reverse cyclic order).
    pub vertices: Vec<u32>,
    /// The face id of each half-face (the ids of `Chf::face_of`).
    pub face: Vec<u32>,
}

impl Chf {
    /// The half-face arrays; see [`HalfFaceArrays`].
    pub fn half_face_arrays(&self) -> Result<HalfFaceArrays> {
        self.check_collected("the half-face export")?;
        let view = self.try_view(Need::FACES)?;
        let n = self.v.len();
        let mut a = HalfFaceArrays::default();
        reserve(&mut a.twin, n, "half-face twins")?;
        reserve(&mut a.vertices, 3 * n, "half-face vertices")?;
        reserve(&mut a.face, n, "half-face faces")?;
        for hf in 0..n as u32 {
            a.twin.push(view.opposite(hf));
            a.vertices.extend(face_cycle(&self.v, hf));
            a.face.push(view.face_of(hf));
        }
        Ok(a)
    }

    /// The dual graph: 4 entries per tetrahedron, the tetrahedron across each of its faces
    /// (`NONE` on the boundary), as `Chf::tetrahedron_tetrahedra`.
    pub fn tetrahedron_dual_graph(&self) -> Result<Vec<u32>> {
        self.check_collected("the dual graph")?;
        let view = self.try_view(Need::NOTHING)?;
        let mut out = Vec::new();
        reserve(&mut out, view.o.len(), "dual graph")?;
        out.extend(
            view.o
                .iter()
                .map(|&g| if g == NONE { NONE } else { tet(g) }),
        );
        Ok(out)
    }
}
