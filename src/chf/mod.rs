//! CHF, the Compact Half-Face for tetrahedral meshes, in levels:
//! - 0: `V[4T]`, the (oriented, manifold-split) tetrahedron soup;
//! - 1: `O[4T]`, twin half-faces (`NONE` on the boundary);
//! - 2: `VH[V]` (a boundary vertex stores a boundary half-face), edge ids and face ids;
//! - 3: the boundary surface as a [`crate::che::Che`], with maps to and from the boundary half-faces
//!   and a boundary-component id per boundary vertex.
//!
//! The arithmetic (half-faces, edge slots, the half-edge encoding, mate and radial) is in
//! [`ids`], the edge fans in `edges.rs`. `build/` is the pipeline from a tetrahedron list
//! (`build/mod.rs` names its steps), `query/` answers the relations on a view of the level's
//! tables, and `star_pass/` is the one pass over every vertex star that both use: the build
//! for `O`, `VH` and the edge ids, a query below level 2 for the ranks it lacks.
//!
//! Every query works at every level; a higher level only answers faster. The build always
//! canonicalises the input (degenerate tetrahedra dropped, components oriented,
//! non-manifold vertices split) so that half-face, edge and face ids are the same at every
//! level, and so are the answers, in the same order.
//!
//! Ids: a face is named by its canonical half-face (`O[hf] == NONE || hf < O[hf]`), face
//! `f` being the `f`-th; an edge is a fan of tetrahedra around a vertex pair (see
//! `edges.rs`), edge `e` the `e`-th canonical edge slot. Below level 2 the ranks are
//! computed for the query (O(T)); level 0 also computes `O` (the rule level 1 stores).
//!
//! The 16 relations (k = tetrahedra around an edge, S = tetrahedra around a vertex):
//!
//! | relation | answer | cost at level 2 |
//! |---|---|---|
//! | VV, VE, VF, VT | each once, in increasing order (a walk over the star, sorted) | O(S) |
//! | EV | the canonical half-edge's origin and target | O(1) |
//! | ET, EF | rotation order, from the boundary on a boundary edge | O(k) |
//! | EE | the two other edges of each face of EF, each once | O(k) walks |
//! | FV, FE | the canonical half-face's order; edge `j` from vertex `j` to `j + 1` | O(1), O(k) per edge |
//! | FF | the other faces of the face's one or two tetrahedra ("wings"), each once | O(1) |
//! | FT | the canonical half-face's tetrahedron, then its twin's | O(1) (level 1 on half-faces) |
//! | TV, TF, TT | local order; `TT[i]` across face `i`, `NONE` on the boundary | O(1) (TT from level 1) |
//! | TE | local pairs (0,1) (0,2) (0,3) (1,2) (1,3) (2,3) | O(k) per edge |
//!
//! Naming an edge from a half-edge walks around the edge to its canonical slot (O(k)); a
//! per-slot edge array would make it O(1) for 24 bytes per tetrahedron (see `edges.rs`).

pub(crate) mod build;
mod edges;
pub mod edit;
pub mod export;
pub(crate) mod geometry;
pub mod ids;
pub(crate) mod query;
mod star_pass;

pub use crate::Ids;
pub use crate::util::options::MAX_UNUSED_VERTICES;
pub use build::{
    BuildOptions, BuildReport, MAX_TETRAHEDRA, SweepLimits, check_counts, estimated_build_bytes,
};
pub use edit::GarbageMaps;
pub use export::{HalfFaceArrays, VolumeMatrixKind};
pub use ids::{HalfEdge, NO_HALF_EDGE};
pub use query::{Csr, EdgeIds, Memory, STAR_INLINE, Summary, VertexIds};

/// The name before the types took their module's name (`chf::BuildOptions`).
#[deprecated(since = "0.2.0", note = "use chf::BuildOptions")]
pub type ChfBuildOptions = BuildOptions;
/// The name before the types took their module's name (`chf::BuildReport`).
#[deprecated(since = "0.2.0", note = "use chf::BuildReport")]
pub type ChfBuildReport = BuildReport;
/// The name before the types took their module's name (`chf::Csr`).
#[deprecated(since = "0.2.0", note = "use chf::Csr")]
pub type ChfCsr = Csr;
/// The name before the types took their module's name (`chf::Memory`).
#[deprecated(since = "0.2.0", note = "use chf::Memory")]
pub type ChfMemory = Memory;
/// The name before the types took their module's name (`chf::Summary`).
#[deprecated(since = "0.2.0", note = "use chf::Summary")]
pub type ChfSummary = Summary;

use crate::error::{Error, Result};
use crate::util::input::Input;
use crate::util::origin::OriginMap;
use crate::util::progress::BuildProgress;
use crate::util::rank::RankBits;
use crate::util::store::Store;
use crate::util::structure::{as_elements, check_id};
use build::level2;
use build::level3;
pub(crate) use build::level3::Boundary;
pub(crate) use edges::MultiFan;
use glam::DVec3;
use star_pass as stars;

/// A tetrahedral mesh in the Compact Half-Face structure.
#[derive(Clone, Debug)]
pub struct Chf {
    pub(crate) level: u8,
    pub(crate) n_input_vertices: usize,
    pub(crate) n_vertices: usize,
    /// `V[hf]`: vertex `hf & 3` of tetrahedron `hf >> 2`.
    pub(crate) v: Store<u32>,
    /// Level 1: `O[hf]`, the twin half-face.
    pub(crate) o: Store<u32>,
    /// Level 2: a half-face holding each vertex, a boundary one on the boundary.
    pub(crate) vh: Store<u32>,
    /// Level 2: bit `hf` set on canonical half-faces (`O[hf] == NONE || hf < O[hf]`); the
    /// face id is the rank.
    pub(crate) face_bits: RankBits,
    /// Level 2: the canonical half-face of each face.
    pub(crate) fh: Store<u32>,
    /// Level 2: bit `s` set on the canonical edge slot of each fan; the edge id is the rank.
    pub(crate) edge_bits: RankBits,
    /// Level 2: the tetrahedron of each edge's canonical slot (the slot is the right one
    /// among the six marked bits of that tetrahedron: 4 bytes per edge, not 8).
    pub(crate) eh: Store<u32>,
    /// Level 3.
    pub(crate) boundary: Option<level3::Boundary>,
    /// Counts, the same at every level.
    pub(crate) num_edges: usize,
    pub(crate) num_faces: usize,
    pub(crate) positions: Store<DVec3>,
    /// Structure vertex -> input vertex; empty when the identity.
    pub(crate) vertex_origin: OriginMap,
    /// Structure tetrahedron -> input tetrahedron; empty when the identity.
    pub(crate) tet_origin: OriginMap,
    /// Sorted half-faces of non-manifold faces (3+ tetrahedra), unpaired at every level.
    pub(crate) non_manifold: Vec<u32>,
    /// Sorted half-faces on orientation seams, unpaired at every level.
    pub(crate) seams: Vec<u32>,
    /// Structure vertex pairs carrying several fans (several edge ids), sorted.
    pub(crate) multi_fan: Vec<MultiFan>,
    pub(crate) report: BuildReport,
    /// Marks and explicit ids, from the first edit on (see `edit/`); `None` on a CHF
    /// never edited, which keeps its memory and speed.
    pub(crate) edit: Option<Box<edit::EditState>>,
}

impl Chf {
    /// No tetrahedron, no vertex: what the build fills in.
    pub(crate) fn empty() -> Chf {
        Chf {
            level: 0,
            n_input_vertices: 0,
            n_vertices: 0,
            v: Store::default(),
            o: Store::default(),
            vh: Store::default(),
            face_bits: RankBits::default(),
            fh: Store::default(),
            edge_bits: RankBits::default(),
            eh: Store::default(),
            boundary: None,
            num_edges: 0,
            num_faces: 0,
            positions: Store::default(),
            vertex_origin: OriginMap::default(),
            tet_origin: OriginMap::default(),
            non_manifold: Vec::new(),
            seams: Vec::new(),
            multi_fan: Vec::new(),
            report: BuildReport::default(),
            edit: None,
        }
    }

    crate::util::structure::build_constructors!(
        Chf,
        4,
        from_tetrahedra,
        from_tetrahedra_with_progress,
        "tetrahedra",
        "tetrahedron"
    );

    /// The threads `build_level` takes: the build's default for this mesh.
    fn build_threads(&self) -> usize {
        crate::util::par::build_threads(0, self.num_tetrahedra())
    }

    crate::util::structure::structure_accessors!(BuildReport);

    /// Raises (or lowers) the level in place, on every thread of the machine. Ids do not
    /// change.
    pub fn build_level(&mut self, level: u8) -> Result<()> {
        crate::util::options::check_level(level)?;
        if self.edit.is_some() {
            return self.build_edited_level(level);
        }
        if level < self.level {
            if level < 3 {
                self.boundary = None;
            }
            if level < 2 {
                self.vh = Store::default();
                self.face_bits = RankBits::default();
                self.fh = Store::default();
                self.edge_bits = RankBits::default();
                self.eh = Store::default();
            }
            if level < 1 {
                self.o = Store::default();
            }
            self.level = level;
            return Ok(());
        }
        if self.level < 1 && level >= 1 {
            self.o = self.try_opposites_by_rule()?.into();
            self.level = 1;
        }
        if self.level < 2 && level >= 2 {
            let flagged = stars::merged(&self.non_manifold, &self.seams)?;
            let pass = stars::StarPass {
                pairs: stars::Pairs::No,
                tables: true,
                threads: stars::threads_for(
                    self.v.len() / 4,
                    self.n_vertices,
                    self.build_threads(),
                ),
            };
            let stars = stars::stars(&self.v, self.n_vertices, &flagged, pass)?;
            debug_assert!(!stars.split_needed, "the build split every vertex");
            level2::build(self, stars.edge_bits, stars.vh)?;
            self.level = 2;
        }
        if self.level < 3 && level >= 3 {
            self.boundary = Some(level3::build(self, self.build_threads(), 0)?);
            self.level = 3;
        }
        Ok(())
    }

    pub fn num_tetrahedra(&self) -> usize {
        self.v.len() / 4
    }
    pub fn num_half_faces(&self) -> usize {
        self.v.len()
    }
    pub fn num_faces(&self) -> usize {
        self.num_faces
    }

    /// `V`: vertex `hf & 3` of tetrahedron `hf >> 2`, for every half-face `hf`.
    pub fn half_face_vertices(&self) -> &[u32] {
        &self.v
    }
    /// `VH`, from level 2.
    pub fn vertex_half_faces(&self) -> Option<&[u32]> {
        (self.level >= 2).then_some(&self.vh[..])
    }
    /// `FH`: the canonical half-face of every face, from level 2.
    pub fn face_half_faces(&self) -> Option<&[u32]> {
        if let Some(s) = &self.edit {
            return (self.level >= 2).then_some(&s.face_hf[..]);
        }
        (self.level >= 2).then_some(&self.fh[..])
    }
    /// The tetrahedron holding the canonical slot of every edge, from level 2.
    pub fn edge_slot_tetrahedra(&self) -> Option<&[u32]> {
        (self.level >= 2 && self.edit.is_none()).then_some(&self.eh[..])
    }

    /// The input tetrahedron a structure tetrahedron comes from.
    pub fn tetrahedron_origin(&self, t: u32) -> u32 {
        self.tet_origin.get(t)
    }
    /// The tetrahedron origin map, or `None` when it is the identity.
    pub fn tetrahedron_origins(&self) -> Option<&[u32]> {
        self.tet_origin.explicit()
    }

    /// Half-faces of non-manifold faces (sorted); they are unpaired at every level.
    pub fn non_manifold_half_faces(&self) -> &[u32] {
        &self.non_manifold
    }
    /// Half-faces on orientation seams (sorted); they are unpaired at every level.
    pub fn seam_half_faces(&self) -> &[u32] {
        &self.seams
    }

    pub fn check_face(&self, f: u32) -> Result<()> {
        check_id(f, self.num_faces, "face", "faces")?;
        edit::removed(self.is_face_removed(f), "face", f)
    }
    pub fn check_tetrahedron(&self, t: u32) -> Result<()> {
        check_id(t, self.num_tetrahedra(), "tetrahedron", "tetrahedra")?;
        edit::removed(self.is_tetrahedron_removed(t), "tetrahedron", t)
    }
    pub fn check_half_face(&self, hf: u32) -> Result<()> {
        check_id(hf, self.v.len(), "half-face", "half-faces")
    }
    pub fn check_half_edge(&self, he: HalfEdge) -> Result<()> {
        if he < 3 * self.v.len() as u64 {
            Ok(())
        } else {
            Err(Error::out_of_range(format!(
                "half-edge {he} out of range (the mesh has {} half-edges)",
                3 * self.v.len()
            )))
        }
    }
}

const _: () = {
    // Queries are `&self` and lock-free: the structure is plain data.
    const fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<Chf>();
};
