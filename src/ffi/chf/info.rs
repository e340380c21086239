//! What a volume mesh is (topology summary), what its build did (report), what it
//! costs (memory per container), and whether its invariants hold (validate).

use super::ChfMesh;
use crate::chf::{BuildReport, Memory, Summary};
use crate::ffi::boundary::report_kind;
use crate::ffi::declare::exports;

crate::chf::query::summary::summary_fields! {
    /// The topology of the input complex as given (input vertices, unique input edges and
    /// faces, kept tetrahedra), whatever the build split or left unpaired, and what the build
    /// did. Field names match the CLI's JSON.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct ChfSummary from Summary
}

exports! { ChfMesh;
    /// The topology summary into `*out`. O(T log T) at every level.
    value fn chf_mesh_summary() -> ChfSummary { |c| c.try_summary().map(|s| (&s).into()) }
}

crate::chf::build::report::report_fields! { u64; [
    /// What the build did to its input (counts; `chf_mesh_report_examples` gives ids).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct ChfBuildReport from BuildReport
] }

exports! { ChfMesh;
    /// The build report into `*out`. O(1).
    value fn chf_mesh_report() -> ChfBuildReport { |c| Ok(c.report().into()) }
}

/// Which offending ids `chf_mesh_report_examples` returns (at most 16 items of each kind,
/// input ids).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChfReportKind {
    /// Input tetrahedra dropped as degenerate (one id each).
    Degenerate = 0,
    /// Input tetrahedra of zero volume (one id each).
    ZeroVolume = 1,
    /// Input tetrahedra inverted against their component (one id each).
    Inverted = 2,
    /// Pairs of input tetrahedra with the same vertices (two ids each).
    Duplicate = 3,
    /// Non-manifold faces as sorted input vertex triples (three ids each).
    NonManifoldFace = 4,
    /// Non-manifold edges as input vertex pairs (two ids each, smaller first).
    NonManifoldEdge = 5,
    /// Non-manifold edges kept as several edges (two ids each, smaller first).
    KeptNonManifoldEdge = 6,
    /// Input vertices split because their star is several pieces (one id each).
    SplitVertex = 7,
    /// One input tetrahedron of each non-orientable component (one id each).
    NonOrientable = 8,
    /// Input vertices with a NaN or infinite coordinate (one id each).
    NonFiniteVertex = 9,
}

exports! { ChfMesh;
    /// The first offending ids of one kind (a `chf_report_kind` value), flattened, into `buf`
    /// (the buffer rules of the relations). An unknown kind gives OUT_OF_RANGE.
    ids fn chf_mesh_report_examples(kind) {
        try |c| {
            let lists = c.report().example_lists();
            report_kind(lists, kind, "chf_report_kind").map(|l| l.iter().copied())
        }
    }
}

crate::chf::query::memory::memory_fields! { u64;
    /// Bytes held by each container (lengths, not capacities).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct ChfMemory from Memory
}

exports! { ChfMesh;
    /// Memory per container into `*out`. O(1).
    value fn chf_mesh_memory() -> ChfMemory { |c| Ok((&c.memory_bytes()).into()) }
    /// Checks every invariant of the mesh at its level: `TOPOMESH_STATUS_OK`, or
    /// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (the element and what is
    /// wrong) in `topomesh_last_error`. O(T); the mesh is unchanged.
    check fn chf_mesh_validate() { |c| c.validate() }
}
