//! The JSON of `info`, `check`, `bench` and `export --json`. Each document starts with `"schema"`, an
//! integer raised whenever a field is renamed, removed or changes meaning (adding a field
//! keeps it); an undefined value is `null`, never a sentinel. The library's summary, build
//! report and memory types carry no serde derives, so their fields are named here, in the
//! order they are printed.

use crate::output::Out;
use serde::Serialize;
use serde::ser::{SerializeMap, SerializeStruct};
use std::io::{self, Write};
use topomesh::{NONE, che, chf};

/// `info --json`. 2: the schema field, and `genus` `null` where it was -1.
pub const INFO_SCHEMA: u32 = 2;
/// `check --json`.
pub const CHECK_SCHEMA: u32 = 1;
/// `bench --json`.
pub const BENCH_SCHEMA: u32 = 1;
/// `export --json`.
pub const EXPORT_SCHEMA: u32 = 1;

/// A document: its schema version first, then the command's fields.
#[derive(Serialize)]
pub struct Versioned<T> {
    pub schema: u32,
    #[serde(flatten)]
    pub body: T,
}

/// Pretty-printed JSON and a newline on `out`.
pub fn write(out: &mut Out, schema: u32, body: &impl Serialize) -> io::Result<()> {
    serde_json::to_writer_pretty(&mut *out, &Versioned { schema, body })?;
    writeln!(out)
}

/// The genus, which the library gives as -1 where it is undefined (a non-manifold or
/// non-orientable surface).
fn defined(genus: &i64) -> Option<i64> {
    (*genus >= 0).then_some(*genus)
}

/// A borrowed view of a core type that serialises the listed fields, in order, as a JSON
/// object; `field as f` writes `f(&field)` instead. The fields are destructured without `..`,
/// so a field added to the core type is a compile error here rather than a silent gap in
/// the JSON.
macro_rules! json_fields {
    (@value $field:ident) => { $field };
    (@value $field:ident $conv:ident) => { &$conv($field) };
    ($wrapper:ident($($ty:ident)::+) { $($field:ident $(as $conv:ident)?),* $(,)? }) => {
        pub struct $wrapper<'a>(pub &'a $($ty)::+);

        impl Serialize for $wrapper<'_> {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let $($ty)::+ { $($field),* } = self.0;
                let names = [$(stringify!($field)),*];
                let mut s = serializer.serialize_struct(stringify!($wrapper), names.len())?;
                $(s.serialize_field(stringify!($field), json_fields!(@value $field $($conv)?))?;)*
                s.end()
            }
        }
    };
}

json_fields!(SurfaceSummary(che::Summary) {
    vertices, edges, triangles, boundary_edges, boundary_curves, components,
    isolated_vertices, euler_characteristic, genus as defined, orientable, manifold, dropped_degenerate,
    non_manifold_edges, split_vertices, flipped_triangles, non_orientable_components,
});

json_fields!(SurfaceReport(che::BuildReport) {
    input_triangles, input_vertices, dropped_degenerate, degenerate_examples,
    duplicate_triangles, duplicate_examples, input_edges, boundary_edges, non_manifold_edges,
    non_manifold_edge_examples, split_vertices, split_vertex_examples, seam_split_vertices,
    added_vertices, flipped_triangles, non_orientable_components, non_orientable_examples,
    seam_edges, non_finite_vertices, non_finite_vertex_examples,
    welded_vertices,
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
    non_orientable_components, non_orientable_examples, seam_faces, non_finite_vertices,
    non_finite_vertex_examples, welded_vertices,
});

json_fields!(VolumeMemory(chf::Memory) {
    half_face_vertices, opposites, vertex_half_faces, edges, faces, boundary, topology,
    positions, maps,
});

/// The fields of a memory breakdown as `  name  bytes` lines, for `info --verbose`.
pub fn memory_table(out: &mut Out, memory: &impl Serialize) -> io::Result<()> {
    writeln!(out, "memory by container")?;
    if let serde_json::Value::Object(fields) = serde_json::to_value(memory)? {
        for (name, bytes) in fields {
            writeln!(out, "  {name:<26}{bytes} bytes")?;
        }
    }
    Ok(())
}

/// One field of an `export --json` document: an array is written whole, an id array with
/// `null` for [`NONE`].
#[derive(Clone, Copy)]
pub enum Field<'a> {
    Count(usize),
    Flag(bool),
    Ids(&'a [u32]),
    Offsets(&'a [usize]),
    Offsets64(&'a [u64]),
    Values(&'a [f64]),
}

impl Serialize for Field<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match *self {
            Field::Count(n) => s.serialize_u64(n as u64),
            Field::Flag(b) => s.serialize_bool(b),
            Field::Ids(ids) => s.collect_seq(ids.iter().map(|&x| (x != NONE).then_some(x))),
            Field::Offsets(o) => s.collect_seq(o),
            Field::Offsets64(o) => s.collect_seq(o),
            Field::Values(v) => s.collect_seq(v),
        }
    }
}

/// An `export --json` document on one line: the schema, the representation's name, then
/// `fields` in order. Streamed from the arrays, never built as a JSON value in memory.
pub fn export_document(
    out: &mut impl Write, representation: &str, fields: &[(&str, Field)],
) -> io::Result<()> {
    let mut json = serde_json::Serializer::new(&mut *out);
    let mut map = serde::Serializer::serialize_map(&mut json, Some(fields.len() + 2))?;
    map.serialize_entry("schema", &EXPORT_SCHEMA)?;
    map.serialize_entry("representation", representation)?;
    for (name, field) in fields {
        map.serialize_entry(name, field)?;
    }
    SerializeMap::end(map)?;
    writeln!(out)
}
