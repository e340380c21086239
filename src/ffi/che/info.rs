//! What a mesh is (topology summary), what its build did (report), what it costs
//! (memory per container), and whether its invariants hold (validate).

use super::CheMesh;
use crate::che::{BuildReport, Memory, Summary};
use crate::ffi::boundary::report_kind;
use crate::ffi::shapes::{ids, mirror, status, value};
use crate::ffi::status::Status;

/// The topology of the input complex as given (input vertices, unique input edges, kept
/// triangles), and what the build did. Field names match the CLI's JSON.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheSummary {
    pub vertices: u64,
    pub edges: u64,
    pub triangles: u64,
    /// Edges with exactly one triangle.
    pub boundary_edges: u64,
    /// Connected components of the boundary edges (for a manifold, the boundary loops).
    pub boundary_curves: u64,
    /// Connected components of the triangles (joined through shared vertices).
    pub components: u64,
    pub isolated_vertices: u64,
    /// V - E + F of the input complex (isolated vertices count).
    pub euler_characteristic: i64,
    /// Sum of the component genera; -1 where undefined (non-manifold or non-orientable).
    pub genus: i64,
    pub orientable: bool,
    pub manifold: bool,
    pub dropped_degenerate: u64,
    pub non_manifold_edges: u64,
    pub split_vertices: u64,
    pub flipped_triangles: u64,
    pub non_orientable_components: u64,
}

mirror!(Summary => CheSummary {
    vertices, edges, triangles, boundary_edges, boundary_curves, components,
    isolated_vertices, euler_characteristic, genus, orientable, manifold, dropped_degenerate,
    non_manifold_edges, split_vertices, flipped_triangles, non_orientable_components,
});

/// The topology summary into `*out`. O(T) at every level.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_summary(m: *const CheMesh, out: *mut CheSummary) -> Status {
    value!(m, out, |c| c.try_summary().map(|s| (&s).into()))
}

/// What the build did to its input (counts; `che_mesh_report_examples` gives ids).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheBuildReport {
    /// Triangles given.
    pub input_triangles: u64,
    /// Vertices given (the structure may hold more after splitting).
    pub input_vertices: u64,
    /// Triangles with a repeated vertex id, dropped.
    pub dropped_degenerate: u64,
    /// Pairs of triangles with the same three vertices (kept).
    pub duplicate_triangles: u64,
    /// Unique input edges.
    pub input_edges: u64,
    /// Input edges with one triangle.
    pub boundary_edges: u64,
    /// Input edges with three or more triangles (their half-edges stay unpaired).
    pub non_manifold_edges: u64,
    /// Input vertices whose star is several fans (split into one copy per fan).
    pub split_vertices: u64,
    /// Input vertices split only because a non-orientable seam crosses them.
    pub seam_split_vertices: u64,
    /// Vertex copies appended after the input vertices.
    pub added_vertices: u64,
    /// Triangles whose orientation was reversed to agree with their neighbours.
    pub flipped_triangles: u64,
    /// Components that cannot be oriented.
    pub non_orientable_components: u64,
    /// Edges left unpaired on the seams of non-orientable components.
    pub seam_edges: u64,
    /// Input vertices with a NaN or infinite coordinate (kept).
    pub non_finite_vertices: u64,
    /// Vertices merged into another by the weld (`weld_tolerance` of the build options):
    /// no element uses them any more; they keep their ids.
    pub welded_vertices: u64,
}

mirror!(BuildReport => CheBuildReport {
    input_triangles, input_vertices, dropped_degenerate, duplicate_triangles, input_edges,
    boundary_edges, non_manifold_edges, split_vertices, seam_split_vertices, added_vertices,
    flipped_triangles, non_orientable_components, seam_edges, non_finite_vertices,
    welded_vertices,
});

/// The build report into `*out`. O(1).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_report(m: *const CheMesh, out: *mut CheBuildReport) -> Status {
    value!(m, out, |c| Ok(c.report().into()))
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

/// The first offending ids of one kind (a `che_report_kind` value), flattened, into `buf`
/// (the buffer rules of the relations). An unknown kind gives OUT_OF_RANGE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_report_examples(
    m: *const CheMesh, kind: u32, buf: *mut u32, cap: usize, out_len: *mut usize,
) -> Status {
    ids!(m, buf, cap, out_len, try |c| report_kind(c.report().example_lists(), kind, "che_report_kind").map(|l| l.iter().copied()))
}

/// Bytes held by each container (lengths, not capacities).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheMemory {
    /// `V`, level 0.
    pub half_edge_vertices: u64,
    /// `O`, level 1.
    pub opposites: u64,
    /// `VH`, level 2.
    pub vertex_half_edges: u64,
    /// `EH` and the edge rank bits, level 2.
    pub edges: u64,
    /// `CH` and the curve lookup, level 3.
    pub curves: u64,
    /// The sum of the above: the topology.
    pub topology: u64,
    /// Positions (not topology).
    pub positions: u64,
    /// Origin maps and non-manifold and seam flags kept by the core (not topology).
    pub maps: u64,
}

mirror!(Memory => CheMemory {
    half_edge_vertices, opposites, vertex_half_edges, edges, curves, topology, positions, maps,
});

/// Memory per container into `*out`. O(1).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_memory(m: *const CheMesh, out: *mut CheMemory) -> Status {
    value!(m, out, |c| Ok((&c.memory_bytes()).into()))
}

/// Checks every invariant of the mesh at its level (ids in range, `O` an involution on
/// matching vertex pairs, the rules of `VH`, the edge directory and `EH`, the boundary
/// curves). `TOPOMESH_STATUS_OK` when they all hold; otherwise
/// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (element and what is wrong) in
/// `topomesh_last_error`. O(T).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_validate(m: *const CheMesh) -> Status {
    status!(m, |c| c.validate())
}
