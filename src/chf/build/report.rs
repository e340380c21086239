//! What a build did to its input: nothing is dropped or changed without being listed here.

/// The counts of [`BuildReport`], once for it and for its C mirror in `ffi` (see
/// `util::fields`); `extra` fields follow them.
macro_rules! report_fields {
    ($int:ty; [$($head:tt)*] $($extra:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            /// Tetrahedra given.
            input_tetrahedra: $int,
            /// Vertices given (the structure may hold more after splitting).
            input_vertices: $int,
            /// Tetrahedra with a repeated vertex id, dropped.
            dropped_degenerate: $int,
            /// Tetrahedra whose positions have a zero determinant (kept; oriented by their
            /// neighbours).
            zero_volume: $int,
            /// Tetrahedra whose determinant has the sign opposite to the orientation of their
            /// component (a folded or tangled mesh; kept, oriented with their neighbours).
            inverted_tetrahedra: $int,
            /// Pairs of tetrahedra with the same four vertices (kept).
            duplicate_tetrahedra: $int,
            /// Unique input faces (vertex triples).
            input_faces: $int,
            /// Input faces with one tetrahedron.
            boundary_faces: $int,
            /// Input faces with three or more tetrahedra (their half-faces stay unpaired).
            non_manifold_faces: $int,
            /// Unique input edges (vertex pairs).
            input_edges: $int,
            /// Input edges whose tetrahedra form several fans (face-connected pieces around the
            /// edge): two tetrahedra sharing only an edge, the edges of a non-manifold face, ...
            non_manifold_edges: $int,
            /// Of the non-manifold edges, the ones whose fans still share both end vertices after
            /// the vertex split (the stars of both ends are connected through other tetrahedra):
            /// the structure keeps one edge id per fan, all with the same two vertices.
            kept_non_manifold_edges: $int,
            /// Input vertices whose star falls into several face-connected pieces (non-manifold
            /// vertices), split into one vertex per piece.
            split_vertices: $int,
            /// Input vertices split only because an orientation seam crosses their star.
            seam_split_vertices: $int,
            /// Vertex copies appended after the input vertices (by both kinds of split).
            added_vertices: $int,
            /// Tetrahedra whose local vertices 1 and 2 were swapped to orient them.
            flipped_tetrahedra: $int,
            /// Face-connected components that cannot be consistently oriented; one input
            /// tetrahedron of each.
            non_orientable_components: $int,
            /// Faces left unpaired because their two tetrahedra could not agree on an orientation.
            seam_faces: $int,
            /// Input vertices with a NaN or infinite coordinate. Their tetrahedra have no
            /// determinant sign: they are oriented by their neighbours, and counted neither as
            /// zero-volume nor as inverted.
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
    /// Counts, plus the first [`REPORT_EXAMPLES`](crate::REPORT_EXAMPLES) offending ids of each kind (input ids:
    /// input tetrahedra, input vertices).
    #[derive(Clone, Debug, Default, PartialEq, Eq)]
    pub struct BuildReport
]
    degenerate_examples: Vec<u32>,
    zero_volume_examples: Vec<u32>,
    inverted_examples: Vec<u32>,
    duplicate_examples: Vec<[u32; 2]>,
    non_manifold_face_examples: Vec<[u32; 3]>,
    non_manifold_edge_examples: Vec<[u32; 2]>,
    kept_non_manifold_edge_examples: Vec<[u32; 2]>,
    split_vertex_examples: Vec<u32>,
    non_orientable_examples: Vec<u32>,
    non_finite_vertex_examples: Vec<u32>,
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
