//! What a build did to its input: nothing is dropped or changed without being listed here.

/// Counts, plus the first [`REPORT_EXAMPLES`](crate::REPORT_EXAMPLES) offending ids of each kind (input ids:
/// input tetrahedra, input vertices).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BuildReport {
    /// Tetrahedra given.
    pub input_tetrahedra: usize,
    /// Vertices given (the structure may hold more after splitting).
    pub input_vertices: usize,
    /// Tetrahedra with a repeated vertex id, dropped.
    pub dropped_degenerate: usize,
    pub degenerate_examples: Vec<u32>,
    /// Tetrahedra whose positions have a zero determinant (kept; oriented by their
    /// neighbours).
    pub zero_volume: usize,
    pub zero_volume_examples: Vec<u32>,
    /// Tetrahedra whose determinant has the sign opposite to the orientation of their
    /// component (a folded or tangled mesh; kept, oriented with their neighbours).
    pub inverted_tetrahedra: usize,
    pub inverted_examples: Vec<u32>,
    /// Pairs of tetrahedra with the same four vertices (kept).
    pub duplicate_tetrahedra: usize,
    pub duplicate_examples: Vec<[u32; 2]>,
    /// Unique input faces (vertex triples), those with one tetrahedron (boundary) and those
    /// with three or more (non-manifold: their half-faces stay unpaired).
    pub input_faces: usize,
    pub boundary_faces: usize,
    pub non_manifold_faces: usize,
    pub non_manifold_face_examples: Vec<[u32; 3]>,
    /// Unique input edges (vertex pairs).
    pub input_edges: usize,
    /// Input edges whose tetrahedra form several fans (face-connected pieces around the
    /// edge): two tetrahedra sharing only an edge, the edges of a non-manifold face, ...
    pub non_manifold_edges: usize,
    pub non_manifold_edge_examples: Vec<[u32; 2]>,
    /// Of those, the ones whose fans still share both end vertices after the vertex split
    /// (the stars of both ends are connected through other tetrahedra): the structure
    /// keeps one edge id per fan, all with the same two vertices.
    pub kept_non_manifold_edges: usize,
    pub kept_non_manifold_edge_examples: Vec<[u32; 2]>,
    /// Input vertices whose star falls into several face-connected pieces (non-manifold
    /// vertices), split into one vertex per piece.
    pub split_vertices: usize,
    pub split_vertex_examples: Vec<u32>,
    /// Input vertices split only because an orientation seam crosses their star.
    pub seam_split_vertices: usize,
    /// Vertex copies appended after the input vertices (by both kinds of split).
    pub added_vertices: usize,
    /// Tetrahedra whose local vertices 1 and 2 were swapped to orient them.
    pub flipped_tetrahedra: usize,
    /// Face-connected components that cannot be consistently oriented; one input
    /// tetrahedron of each.
    pub non_orientable_components: usize,
    pub non_orientable_examples: Vec<u32>,
    /// Faces left unpaired because their two tetrahedra could not agree on an orientation.
    pub seam_faces: usize,
    /// Input vertices with a NaN or infinite coordinate. Their tetrahedra have no
    /// determinant sign: they are oriented by their neighbours, and counted neither as
    /// zero-volume nor as inverted.
    pub non_finite_vertices: u64,
    pub non_finite_vertex_examples: Vec<u32>,
    /// Vertices merged into another by the weld (`BuildOptions::weld_tolerance`): no
    /// element uses them any more; they keep their ids.
    pub welded_vertices: usize,
}

impl BuildReport {
    /// The example lists, flattened, in the order of the C API's `chf_report_kind`.
    pub fn example_lists(&self) -> [&[u32]; 10] {
        [
            &self.degenerate_examples,
            &self.zero_volume_examples,
            &self.inverted_examples,
            self.duplicate_examples.as_flattened(),
            self.non_manifold_face_examples.as_flattened(),
            self.non_manifold_edge_examples.as_flattened(),
            self.kept_non_manifold_edge_examples.as_flattened(),
            &self.split_vertex_examples,
            &self.non_orientable_examples,
            &self.non_finite_vertex_examples,
        ]
    }

    /// True when the build changed nothing but orientation.
    pub fn is_clean(&self) -> bool {
        self.dropped_degenerate == 0
            && self.duplicate_tetrahedra == 0
            && self.non_manifold_faces == 0
            && self.non_manifold_edges == 0
            && self.split_vertices == 0
            && self.non_orientable_components == 0
    }
}

pub(crate) use crate::util::push_example;
