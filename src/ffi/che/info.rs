//! What a mesh is (topology summary), what its build did (report), what it costs
//! (memory per container), and whether its invariants hold (validate).

use super::CheMesh;
use crate::che::{BuildReport, Memory, Summary};
use crate::ffi::boundary::report_kind;
use crate::ffi::declare::exports;

crate::che::query::summary::summary_fields! {
    /// The topology of the input complex as given (input vertices, unique input edges, kept
    /// triangles), and what the build did. Field names match the CLI's JSON.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct CheSummary from Summary
}

exports! { CheMesh;
    /// The topology summary into `*out`. O(T) at every level.
    value fn che_mesh_summary() -> CheSummary { |c| c.try_summary().map(|s| (&s).into()) }
}

crate::che::build::report::report_fields! { u64; [
    /// What the build did to its input (counts; `che_mesh_report_examples` gives ids).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct CheBuildReport from BuildReport
] }

exports! { CheMesh;
    /// The build report into `*out`. O(1).
    value fn che_mesh_report() -> CheBuildReport { |c| Ok(c.report().into()) }
}

/// Which offending ids `che_mesh_report_examples` returns (at most 16 items of each kind,
/// input ids).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheReportKind {
    /// Input triangles dropped as degenerate (one id each).
    Degenerate = 0,
    /// Pairs of input triangles with the same vertices (two ids each).
    Duplicate = 1,
    /// Non-manifold edges as input vertex pairs (two ids each, smaller first).
    NonManifoldEdge = 2,
    /// Input vertices split because their star is several fans (one id each).
    SplitVertex = 3,
    /// One input triangle of each non-orientable component (one id each).
    NonOrientable = 4,
    /// Input vertices with a NaN or infinite coordinate (one id each).
    NonFiniteVertex = 5,
}

exports! { CheMesh;
    /// The first offending ids of one kind (a `che_report_kind` value), flattened, into `buf`
    /// (the buffer rules of the relations). An unknown kind gives OUT_OF_RANGE.
    ids fn che_mesh_report_examples(kind) {
        try |c| {
            let lists = c.report().example_lists();
            report_kind(lists, kind, "che_report_kind").map(|l| l.iter().copied())
        }
    }
}

crate::che::query::memory::memory_fields! { u64;
    /// Bytes held by each container (lengths, not capacities).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct CheMemory from Memory
}

exports! { CheMesh;
    /// Memory per container into `*out`. O(1).
    value fn che_mesh_memory() -> CheMemory { |c| Ok((&c.memory_bytes()).into()) }
    /// Checks every invariant of the mesh at its level (ids in range, `O` an involution on
    /// matching vertex pairs, the rules of `VH`, the edge directory and `EH`, the boundary
    /// curves). `TOPOMESH_STATUS_OK` when they all hold; otherwise
    /// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (element and what is wrong) in
    /// `topomesh_last_error`. O(T).
    check fn che_mesh_validate() { |c| c.validate() }
}
