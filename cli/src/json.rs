//! The JSON of `info --json`: the library's summary, build report and memory types carry no
//! serde derives, so the command names their fields here, in the order they are printed.

use serde::Serialize;
use serde::ser::SerializeStruct;
use topomesh::{che, chf};

/// A borrowed view of a core type that serialises the listed fields, in order, as a JSON
/// object. The fields are destructured without `..`, so a field added to the core type is a
/// compile error here rather than a silent gap in the JSON.
macro_rules! json_fields {
    ($wrapper:ident($($ty:ident)::+) { $($field:ident),* $(,)? }) => {
        pub struct $wrapper<'a>(pub &'a $($ty)::+);

        impl Serialize for $wrapper<'_> {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let $($ty)::+ { $($field),* } = self.0;
                let names = [$(stringify!($field)),*];
                let mut s = serializer.serialize_struct(stringify!($wrapper), names.len())?;
                $(s.serialize_field(stringify!($field), $field)?;)*
                s.end()
            }
        }
    };
}

json_fields!(SurfaceSummary(che::Summary) {
    vertices, edges, triangles, boundary_edges, boundary_curves, components,
    isolated_vertices, euler_characteristic, genus, orientable, manifold, dropped_degenerate,
    non_manifold_edges, split_vertices, flipped_triangles, non_orientable_components,
});

json_fields!(SurfaceReport(che::BuildReport) {
    input_triangles, input_vertices, dropped_degenerate, degenerate_examples,
    duplicate_triangles, duplicate_examples, input_edges, boundary_edges, non_manifold_edges,
    non_manifold_edge_examples, split_vertices, split_vertex_examples, seam_split_vertices,
    added_vertices, flipped_triangles, non_orientable_components, non_orientable_examples,
    seam_edges, welded_vertices,
});

json_fields!(SurfaceMemory(che::Memory) {
    half_edge_vertices, opposites, vertex_half_edges, edges, curves, topology, positions, maps,
});

json_fields!(VolumeSummary(chf::Summary) {
    vertices, edges, faces, tetrahedra, boundary_faces, boundary_edges, boundary_vertices,
    boundary_components, components, isolated_vertices, euler_characteristic, manifold,
    orientable, dropped_degenerate, zero_volume, inverted_tetrahedra, non_manifold_faces,
    non_manifold_edges, split_vertices, flipped_tetrahedra, non_orientable_components,
});

json_fields!(VolumeReport(chf::BuildReport) {
    input_tetrahedra, input_vertices, dropped_degenerate, degenerate_examples, zero_volume,
    zero_volume_examples, inverted_tetrahedra, inverted_examples, duplicate_tetrahedra,
    duplicate_examples, input_faces, boundary_faces, non_manifold_faces,
    non_manifold_face_examples, input_edges, non_manifold_edges, non_manifold_edge_examples,
    kept_non_manifold_edges, kept_non_manifold_edge_examples, split_vertices,
    split_vertex_examples, seam_split_vertices, added_vertices, flipped_tetrahedra,
    non_orientable_components, non_orientable_examples, seam_faces, welded_vertices,
});

json_fields!(VolumeMemory(chf::Memory) {
    half_face_vertices, opposites, vertex_half_faces, edges, faces, boundary, topology,
    positions, maps,
});

/// Pretty-printed JSON on stdout.
pub fn print(value: &impl Serialize) {
    println!(
        "{}",
        serde_json::to_string_pretty(value).expect("plain data serialises")
    );
}
