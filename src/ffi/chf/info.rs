//! What a volume mesh is (topology summary), what its build did (report), what it
//! costs (memory per container), and whether its invariants hold (validate).

use super::ChfMesh;
use crate::chf::{BuildReport as Report, Memory, Summary};
use crate::ffi::boundary::report_kind;
use crate::ffi::shapes::{ids, mirror, status, value};
use crate::ffi::status::Status;

/// The topology of the input complex as given (input vertices, unique input edges and
/// faces, kept tetrahedra), whatever the build split or left unpaired, and what the build
/// did. Field names match the CLI's JSON.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChfSummary {
    pub vertices: u64,
    pub edges: u64,
    pub faces: u64,
    pub tetrahedra: u64,
    /// Faces with exactly one tetrahedron.
    pub boundary_faces: u64,
    /// Edges and vertices of the boundary faces.
    pub boundary_edges: u64,
    pub boundary_vertices: u64,
    /// Components of the boundary faces, joined through shared vertices.
    pub boundary_components: u64,
    /// Components of the tetrahedra, joined through shared vertices.
    pub components: u64,
    pub isolated_vertices: u64,
    /// V - E + F - T of the input complex (isolated vertices count).
    pub euler_characteristic: i64,
    /// No non-manifold face, edge or vertex.
    pub manifold: bool,
    pub orientable: bool,
    pub dropped_degenerate: u64,
    /// Tetrahedra of zero volume (kept), when built with positions.
    pub zero_volume: u64,
    /// Tetrahedra whose volume has the sign opposite to their component's orientation.
    pub inverted_tetrahedra: u64,
    pub non_manifold_faces: u64,
    pub non_manifold_edges: u64,
    pub split_vertices: u64,
    pub flipped_tetrahedra: u64,
    pub non_orientable_components: u64,
}

mirror!(Summary => ChfSummary {
    vertices, edges, faces, tetrahedra, boundary_faces, boundary_edges, boundary_vertices,
    boundary_components, components, isolated_vertices, euler_characteristic, manifold,
    orientable, dropped_degenerate, zero_volume, inverted_tetrahedra, non_manifold_faces,
    non_manifold_edges, split_vertices, flipped_tetrahedra, non_orientable_components,
});

/// The topology summary into `*out`. O(T log T) at every level.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_summary(m: *const ChfMesh, out: *mut ChfSummary) -> Status {
    value!(m, out, |c| c.try_summary().map(|s| (&s).into()))
}

/// What the build did to its input (counts; `chf_mesh_report_examples` gives ids).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChfBuildReport {
    /// Tetrahedra given.
    pub input_tetrahedra: u64,
    /// Vertices given (the structure may hold more after splitting).
    pub input_vertices: u64,
    /// Tetrahedra with a repeated vertex id, dropped.
    pub dropped_degenerate: u64,
    /// Tetrahedra whose positions have a zero determinant (kept).
    pub zero_volume: u64,
    /// Tetrahedra whose determinant has the sign opposite to their component's orientation
    /// (a folded or tangled mesh; kept).
    pub inverted_tetrahedra: u64,
    /// Pairs of tetrahedra with the same four vertices (kept).
    pub duplicate_tetrahedra: u64,
    /// Unique input faces (vertex triples).
    pub input_faces: u64,
    /// Input faces with one tetrahedron.
    pub boundary_faces: u64,
    /// Input faces with three or more tetrahedra (their half-faces stay unpaired).
    pub non_manifold_faces: u64,
    /// Unique input edges (vertex pairs).
    pub input_edges: u64,
    /// Input edges whose tetrahedra form several fans.
    pub non_manifold_edges: u64,
    /// Of those, the ones whose fans still share both end vertices after the vertex split
    /// (one edge id per fan, all with the same two vertices).
    pub kept_non_manifold_edges: u64,
    /// Input vertices whose star is several face-connected pieces (split into one copy per
    /// piece).
    pub split_vertices: u64,
    /// Input vertices split only because an orientation seam crosses their star.
    pub seam_split_vertices: u64,
    /// Vertex copies appended after the input vertices.
    pub added_vertices: u64,
    /// Tetrahedra whose local vertices 1 and 2 were swapped to orient them.
    pub flipped_tetrahedra: u64,
    /// Face-connected components that cannot be consistently oriented.
    pub non_orientable_components: u64,
    /// Faces left unpaired because their two tetrahedra could not agree on an orientation.
    pub seam_faces: u64,
    /// Input vertices with a NaN or infinite coordinate (their tetrahedra are oriented by
    /// their neighbours).
    pub non_finite_vertices: u64,
    /// Vertices merged into another by the weld (`weld_tolerance` of the build options):
    /// no element uses them any more; they keep their ids.
    pub welded_vertices: u64,
}

mirror!(Report => ChfBuildReport {
    input_tetrahedra, input_vertices, dropped_degenerate, zero_volume, inverted_tetrahedra,
    duplicate_tetrahedra, input_faces, boundary_faces, non_manifold_faces, input_edges,
    non_manifold_edges, kept_non_manifold_edges, split_vertices, seam_split_vertices,
    added_vertices, flipped_tetrahedra, non_orientable_components, seam_faces,
    non_finite_vertices, welded_vertices,
});

/// The build report into `*out`. O(1).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_report(m: *const ChfMesh, out: *mut ChfBuildReport) -> Status {
    value!(m, out, |c| Ok(c.report().into()))
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

/// The first offending ids of one kind (a `chf_report_kind` value), flattened, into `buf`
/// (the buffer rules of the relations). An unknown kind gives OUT_OF_RANGE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_report_examples(
    m: *const ChfMesh, kind: u32, buf: *mut u32, cap: usize, out_len: *mut usize,
) -> Status {
    ids!(m, buf, cap, out_len, try |c| report_kind(c.report().example_lists(), kind, "chf_report_kind").map(|l| l.iter().copied()))
}

/// Bytes held by each container (lengths, not capacities).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChfMemory {
    /// `V`, level 0.
    pub half_face_vertices: u64,
    /// `O`, level 1.
    pub opposites: u64,
    /// `VH`, level 2.
    pub vertex_half_faces: u64,
    /// The canonical-edge-slot rank bits and the tetrahedron of each edge, level 2; once
    /// edited, the explicit edge ids and the removed marks.
    pub edges: u64,
    /// The canonical-half-face rank bits and `FH`, level 2; once edited, the explicit face
    /// ids.
    pub faces: u64,
    /// The boundary CHE's topology, its maps and the component of each vertex, level 3.
    pub boundary: u64,
    /// The sum of the above: the topology.
    pub topology: u64,
    /// Positions (not topology).
    pub positions: u64,
    /// Origin maps, the non-manifold and seam flags, the several-fan pairs (not topology).
    pub maps: u64,
}

mirror!(Memory => ChfMemory {
    half_face_vertices, opposites, vertex_half_faces, edges, faces, boundary, topology, positions, maps,
});

/// Memory per container into `*out`. O(1).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_memory(m: *const ChfMesh, out: *mut ChfMemory) -> Status {
    value!(m, out, |c| Ok((&c.memory_bytes()).into()))
}

/// Checks every invariant of the mesh at its level: `TOPOMESH_STATUS_OK`, or
/// `TOPOMESH_STATUS_INVALID_INPUT` with the first violation (the element and what is
/// wrong) in `topomesh_last_error`. O(T); the mesh is unchanged.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_validate(m: *const ChfMesh) -> Status {
    status!(m, |c| c.validate())
}
