//! What a build did to its input: nothing is dropped or changed without being listed here.
//! Lists keep the first [`crate::REPORT_EXAMPLES`] offending ids.

/// Counts, plus the first [`REPORT_EXAMPLES`](crate::REPORT_EXAMPLES) offending ids of each kind (input ids).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BuildReport {
    /// Triangles given.
    pub input_triangles: usize,
    /// Vertices given (the structure may hold more after splitting).
    pub input_vertices: usize,
    /// Triangles with a repeated vertex id, dropped.
    pub dropped_degenerate: usize,
    pub degenerate_examples: Vec<u32>,
    /// Pairs of triangles with the same three vertices (kept).
    pub duplicate_triangles: usize,
    pub duplicate_examples: Vec<[u32; 2]>,
    /// Unique input edges, and how many carry one triangle (boundary) or 3+ (non-manifold).
    pub input_edges: usize,
    pub boundary_edges: usize,
    pub non_manifold_edges: usize,
    /// Vertex pairs (input ids) of non-manifold edges; their half-edges stay unpaired.
    pub non_manifold_edge_examples: Vec<[u32; 2]>,
    /// Input vertices whose star is several fans in the input (non-manifold vertices).
    pub split_vertices: usize,
    pub split_vertex_examples: Vec<u32>,
    /// Input vertices split only because a non-orientable seam crosses them.
    pub seam_split_vertices: usize,
    /// Vertex copies appended after the input vertices (by both kinds of split).
    pub added_vertices: usize,
    /// Triangles whose orientation was reversed to agree with their neighbours.
    pub flipped_triangles: usize,
    /// Components that cannot be oriented; one input triangle of each.
    pub non_orientable_components: usize,
    pub non_orientable_examples: Vec<u32>,
    /// Half-edges left unpaired on the seams of non-orientable components.
    pub seam_edges: usize,
    /// Input vertices with a NaN or infinite coordinate (kept: the CHE build uses no
    /// positions, but a host computing geometry must skip them).
    pub non_finite_vertices: u64,
    pub non_finite_vertex_examples: Vec<u32>,
    /// Vertices merged into another by the weld (`BuildOptions::weld_tolerance`): no
    /// element uses them any more; they keep their ids.
    pub welded_vertices: usize,
}

impl BuildReport {
    /// The example lists, flattened, in the order of the C API's `che_report_kind`.
    pub fn example_lists(&self) -> [&[u32]; 6] {
        [
            &self.degenerate_examples,
            self.duplicate_examples.as_flattened(),
            self.non_manifold_edge_examples.as_flattened(),
            &self.split_vertex_examples,
            &self.non_orientable_examples,
            &self.non_finite_vertex_examples,
        ]
    }

    /// True when the build changed nothing but orientation.
    pub fn is_clean(&self) -> bool {
        self.dropped_degenerate == 0
            && self.duplicate_triangles == 0
            && self.non_manifold_edges == 0
            && self.split_vertices == 0
            && self.non_orientable_components == 0
    }
}

pub(crate) use crate::util::push_example;
