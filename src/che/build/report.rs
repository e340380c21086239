//! What a build did to its input: nothing is dropped or changed without being listed here.
//! Lists keep the first [`crate::REPORT_EXAMPLES`] offending ids.

/// The counts of [`BuildReport`], once for it and for its C mirror in `ffi` (see
/// `util::fields`); `extra` fields follow them.
macro_rules! report_fields {
    ($int:ty; [$($head:tt)*] $($extra:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            /// Triangles given.
            input_triangles: $int,
            /// Vertices given (the structure may hold more after splitting).
            input_vertices: $int,
            /// Triangles with a repeated vertex id, dropped.
            dropped_degenerate: $int,
            /// Pairs of triangles with the same three vertices (kept).
            duplicate_triangles: $int,
            /// Unique input edges.
            input_edges: $int,
            /// Input edges with one triangle.
            boundary_edges: $int,
            /// Input edges with three or more triangles (their half-edges stay unpaired).
            non_manifold_edges: $int,
            /// Input vertices whose star is several fans (non-manifold vertices), split into one
            /// copy per fan.
            split_vertices: $int,
            /// Input vertices split only because a non-orientable seam crosses them.
            seam_split_vertices: $int,
            /// Vertex copies appended after the input vertices (by both kinds of split).
            added_vertices: $int,
            /// Triangles whose orientation was reversed to agree with their neighbours.
            flipped_triangles: $int,
            /// Components that cannot be oriented; one input triangle of each.
            non_orientable_components: $int,
            /// Half-edges left unpaired on the seams of non-orientable components.
            seam_edges: $int,
            /// Input vertices with a NaN or infinite coordinate (kept: the CHE build uses no
            /// positions, but a host computing geometry must skip them).
            non_finite_vertices: u64,
            /// Vertices merged into another by the weld (`weld_tolerance` of the build options):
            /// no element uses them any more; they keep their ids.
            welded_vertices: $int,
            $($extra)*
        }}
    };
}
pub(crate) use report_fields;

report_fields! { usize; [
    /// Counts, plus the first [`REPORT_EXAMPLES`](crate::REPORT_EXAMPLES) offending ids of each kind (input ids).
    #[derive(Clone, Debug, Default, PartialEq, Eq)]
    pub struct BuildReport
]
    degenerate_examples: Vec<u32>,
    duplicate_examples: Vec<[u32; 2]>,
    /// Vertex pairs (input ids) of non-manifold edges; their half-edges stay unpaired.
    non_manifold_edge_examples: Vec<[u32; 2]>,
    split_vertex_examples: Vec<u32>,
    non_orientable_examples: Vec<u32>,
    non_finite_vertex_examples: Vec<u32>,
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
