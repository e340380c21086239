//! The build report as text: `info` prints it, `check --verbose` too.

use crate::output::Out;
use crate::print::report_line;
use std::io::{self, Write};
use topomesh::{BuildReport, chf};

pub fn surface(out: &mut Out, r: &BuildReport) -> io::Result<()> {
    writeln!(out, "build report")?;
    report_line(
        out,
        "dropped degenerate",
        r.dropped_degenerate,
        &r.degenerate_examples,
    )?;
    report_line(
        out,
        "duplicate triangle pairs",
        r.duplicate_triangles,
        &r.duplicate_examples,
    )?;
    report_line(
        out,
        "non-manifold edges",
        r.non_manifold_edges,
        &r.non_manifold_edge_examples,
    )?;
    report_line(
        out,
        "split vertices",
        r.split_vertices,
        &r.split_vertex_examples,
    )?;
    report_line::<u32>(out, "flipped triangles", r.flipped_triangles, &[])?;
    report_line(
        out,
        "non-orientable components",
        r.non_orientable_components,
        &r.non_orientable_examples,
    )?;
    report_line::<u32>(out, "seam edges left unpaired", r.seam_edges, &[])?;
    report_line::<u32>(out, "vertices added by splits", r.added_vertices, &[])?;
    report_line::<u32>(out, "welded vertices", r.welded_vertices, &[])?;
    non_finite(out, r.non_finite_vertices, &r.non_finite_vertex_examples)
}

fn non_finite(out: &mut Out, n: u64, examples: &[u32]) -> io::Result<()> {
    report_line(out, "non-finite vertices", n as usize, examples)
}

pub fn volume(out: &mut Out, r: &chf::BuildReport) -> io::Result<()> {
    writeln!(out, "build report")?;
    report_line(
        out,
        "dropped degenerate",
        r.dropped_degenerate,
        &r.degenerate_examples,
    )?;
    report_line(
        out,
        "zero volume (kept)",
        r.zero_volume,
        &r.zero_volume_examples,
    )?;
    report_line(
        out,
        "inverted (kept)",
        r.inverted_tetrahedra,
        &r.inverted_examples,
    )?;
    report_line(
        out,
        "duplicate pairs",
        r.duplicate_tetrahedra,
        &r.duplicate_examples,
    )?;
    report_line(
        out,
        "non-manifold faces",
        r.non_manifold_faces,
        &r.non_manifold_face_examples,
    )?;
    report_line(
        out,
        "non-manifold edges",
        r.non_manifold_edges,
        &r.non_manifold_edge_examples,
    )?;
    report_line(
        out,
        "split vertices",
        r.split_vertices,
        &r.split_vertex_examples,
    )?;
    report_line::<u32>(out, "flipped tetrahedra", r.flipped_tetrahedra, &[])?;
    report_line(
        out,
        "non-orientable components",
        r.non_orientable_components,
        &r.non_orientable_examples,
    )?;
    report_line(
        out,
        "non-manifold edges kept",
        r.kept_non_manifold_edges,
        &r.kept_non_manifold_edge_examples,
    )?;
    report_line::<u32>(out, "seam faces left unpaired", r.seam_faces, &[])?;
    report_line::<u32>(out, "vertices added by splits", r.added_vertices, &[])?;
    report_line::<u32>(out, "welded vertices", r.welded_vertices, &[])?;
    non_finite(out, r.non_finite_vertices, &r.non_finite_vertex_examples)
}
