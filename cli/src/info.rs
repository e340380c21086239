//! `topomesh info`: the topology summary, build report, structure counts and memory of a
//! mesh, as text or JSON.

use crate::input::{build_surface, build_volume, load};
use crate::json::{
    SurfaceMemory, SurfaceReport, SurfaceSummary, VolumeMemory, VolumeReport, VolumeSummary,
};
use crate::print::{line, report_line, yes};
use crate::progress::Progress;
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, Che, Chf, Error, chf};

#[derive(clap::Args)]
pub struct InfoOptions {
    file: Option<PathBuf>,
    /// Structure level, 0 to 3.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(0..=3))]
    level: u8,
    /// Reject non-manifold input instead of repairing it.
    #[arg(long)]
    strict: bool,
    /// Print JSON (the field names of `che_summary`).
    #[arg(long)]
    json: bool,
    /// Threads for the build (0: as many as the machine runs at once).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

/// What `topomesh` with no subcommand runs: `info` on the embedded torus at level 3.
impl Default for InfoOptions {
    fn default() -> Self {
        InfoOptions {
            file: None,
            level: 3,
            strict: false,
            json: false,
            threads: 0,
            weld: 0.0,
        }
    }
}

pub fn run(options: &InfoOptions) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let start = Instant::now();
    let (name, data) = load(options.file.as_deref(), &progress)?;
    let read_seconds = start.elapsed().as_secs_f64();
    if data.is_volume() {
        volume_info(&name, &data, options, progress)
    } else {
        surface_info(&name, &data, options, progress, read_seconds)
    }
}

impl InfoOptions {
    fn surface(&self) -> BuildOptions {
        BuildOptions {
            level: self.level,
            strict: self.strict,
            threads: self.threads,
            weld_tolerance: self.weld,
        }
    }

    fn volume(&self) -> chf::BuildOptions {
        chf::BuildOptions {
            level: self.level,
            strict: self.strict,
            threads: self.threads,
            weld_tolerance: self.weld,
        }
    }
}

/// Runs `build` under the spinner's `message`; the structure and the seconds it took.
fn timed_build<T>(
    progress: &Progress, message: String, build: impl FnOnce() -> Result<T, Error>,
) -> Result<(T, f64), Error> {
    progress.step(message);
    let start = Instant::now();
    let built = build()?;
    let seconds = start.elapsed().as_secs_f64();
    progress.step("summarising".to_string());
    Ok((built, seconds))
}

/// Prints `out` as JSON or as text, once the spinner is gone.
fn emit<T: Serialize>(options: &InfoOptions, progress: Progress, out: &T, text: fn(&T)) {
    drop(progress);
    if options.json {
        crate::json::print(out);
    } else {
        text(out);
    }
}

fn surface_info(
    name: &str, data: &MeshData, options: &InfoOptions, progress: Progress, read_seconds: f64,
) -> Result<ExitCode, Error> {
    let message = format!(
        "building level {} from {} triangles",
        options.level,
        data.triangles.len()
    );
    let (che, build_seconds) = timed_build(&progress, message, || {
        build_surface(data, options.surface())
    })?;
    let (summary, memory) = (che.summary(), che.memory_bytes());
    let out = SurfaceInfo {
        file: name,
        kind: "surface",
        level: options.level,
        summary: SurfaceSummary(&summary),
        structure: SurfaceStructure::of(&che),
        report: SurfaceReport(che.report()),
        memory: SurfaceMemory(&memory),
        read_seconds,
        build_seconds,
    };
    emit(options, progress, &out, print_surface);
    Ok(ExitCode::SUCCESS)
}

#[derive(Serialize)]
struct SurfaceInfo<'a> {
    file: &'a str,
    kind: &'static str,
    level: u8,
    #[serde(flatten)]
    summary: SurfaceSummary<'a>,
    structure: SurfaceStructure,
    report: SurfaceReport<'a>,
    memory: SurfaceMemory<'a>,
    read_seconds: f64,
    build_seconds: f64,
}

#[derive(Serialize)]
struct SurfaceStructure {
    vertices: usize,
    edges: usize,
    half_edges: usize,
    boundary_curves: usize,
}

impl SurfaceStructure {
    fn of(che: &Che) -> Self {
        SurfaceStructure {
            vertices: che.num_vertices(),
            edges: che.num_edges(),
            half_edges: che.num_half_edges(),
            boundary_curves: che.num_boundary_curves(),
        }
    }
}

fn print_surface(i: &SurfaceInfo) {
    let s = i.summary.0;
    line("file", i.file);
    line("structure", format!("CHE level {}", i.level));
    line("vertices", s.vertices);
    line("edges", s.edges);
    line("triangles", s.triangles);
    line("boundary edges", s.boundary_edges);
    line("boundary curves", s.boundary_curves);
    line("components", s.components);
    line("isolated vertices", s.isolated_vertices);
    line("euler characteristic", s.euler_characteristic);
    let genus = if s.genus < 0 {
        "undefined".to_string()
    } else {
        s.genus.to_string()
    };
    line("genus", genus);
    line("orientable", yes(s.orientable));
    line("manifold", yes(s.manifold));
    print_surface_report(i.report.0);
    let st = &i.structure;
    line(
        "structure counts",
        format!(
            "{} vertices, {} edges, {} half-edges, {} boundary curves",
            st.vertices, st.edges, st.half_edges, st.boundary_curves
        ),
    );
    memory_line(i.memory.0.topology, s.triangles, "triangle");
    line(
        "time",
        format!(
            "read {:.3} s, build {:.3} s",
            i.read_seconds, i.build_seconds
        ),
    );
}

/// The topology's bytes, in all and per element.
fn memory_line(topology: usize, elements: u64, unit: &str) {
    line(
        "topology memory",
        format!(
            "{topology} bytes ({:.2} bytes per {unit})",
            topology as f64 / (elements.max(1) as f64)
        ),
    );
}

fn print_surface_report(r: &topomesh::BuildReport) {
    println!("build report");
    report_line(
        "dropped degenerate",
        r.dropped_degenerate,
        &r.degenerate_examples,
    );
    report_line(
        "duplicate triangle pairs",
        r.duplicate_triangles,
        &r.duplicate_examples,
    );
    report_line(
        "non-manifold edges",
        r.non_manifold_edges,
        &r.non_manifold_edge_examples,
    );
    report_line("split vertices", r.split_vertices, &r.split_vertex_examples);
    report_line::<u32>("flipped triangles", r.flipped_triangles, &[]);
    report_line(
        "non-orientable components",
        r.non_orientable_components,
        &r.non_orientable_examples,
    );
    report_line::<u32>("seam edges left unpaired", r.seam_edges, &[]);
    report_line::<u32>("vertices added by splits", r.added_vertices, &[]);
    report_line::<u32>("welded vertices", r.welded_vertices, &[]);
}

#[derive(Serialize)]
struct VolumeInfo<'a> {
    file: &'a str,
    kind: &'static str,
    level: u8,
    #[serde(flatten)]
    summary: VolumeSummary<'a>,
    structure: VolumeStructure,
    report: VolumeReport<'a>,
    memory: VolumeMemory<'a>,
    build_seconds: f64,
}

#[derive(Serialize)]
struct VolumeStructure {
    vertices: usize,
    edges: usize,
    faces: usize,
    half_faces: usize,
}

impl VolumeStructure {
    fn of(chf: &Chf) -> Self {
        VolumeStructure {
            vertices: chf.num_vertices(),
            edges: chf.num_edges(),
            faces: chf.num_faces(),
            half_faces: chf.num_half_faces(),
        }
    }
}

fn volume_info(
    name: &str, data: &MeshData, options: &InfoOptions, progress: Progress,
) -> Result<ExitCode, Error> {
    let message = format!(
        "building level {} from {} tetrahedra",
        options.level,
        data.tetrahedra.len()
    );
    let (chf, build_seconds) =
        timed_build(&progress, message, || build_volume(data, options.volume()))?;
    let (summary, memory) = (chf.summary(), chf.memory_bytes());
    let out = VolumeInfo {
        file: name,
        kind: "volume",
        level: options.level,
        summary: VolumeSummary(&summary),
        structure: VolumeStructure::of(&chf),
        report: VolumeReport(chf.report()),
        memory: VolumeMemory(&memory),
        build_seconds,
    };
    emit(options, progress, &out, print_volume);
    Ok(ExitCode::SUCCESS)
}

fn print_volume(i: &VolumeInfo) {
    let s = i.summary.0;
    line("file", i.file);
    line("structure", format!("CHF level {}", i.level));
    line("vertices", s.vertices);
    line("edges", s.edges);
    line("faces", s.faces);
    line("tetrahedra", s.tetrahedra);
    line("boundary faces", s.boundary_faces);
    line("boundary edges", s.boundary_edges);
    line("boundary vertices", s.boundary_vertices);
    line("boundary components", s.boundary_components);
    line("components", s.components);
    line("isolated vertices", s.isolated_vertices);
    line("euler characteristic", s.euler_characteristic);
    line("orientable", yes(s.orientable));
    line("manifold", yes(s.manifold));
    print_volume_report(i.report.0);
    let st = &i.structure;
    line(
        "structure counts",
        format!(
            "{} vertices, {} edges, {} faces, {} half-faces",
            st.vertices, st.edges, st.faces, st.half_faces
        ),
    );
    memory_line(i.memory.0.topology, s.tetrahedra, "tetrahedron");
    line("time", format!("build {:.3} s", i.build_seconds));
}

fn print_volume_report(r: &topomesh::chf::BuildReport) {
    println!("build report");
    report_line(
        "dropped degenerate",
        r.dropped_degenerate,
        &r.degenerate_examples,
    );
    report_line("zero volume (kept)", r.zero_volume, &r.zero_volume_examples);
    report_line(
        "inverted (kept)",
        r.inverted_tetrahedra,
        &r.inverted_examples,
    );
    report_line(
        "duplicate pairs",
        r.duplicate_tetrahedra,
        &r.duplicate_examples,
    );
    report_line(
        "non-manifold faces",
        r.non_manifold_faces,
        &r.non_manifold_face_examples,
    );
    report_line(
        "non-manifold edges",
        r.non_manifold_edges,
        &r.non_manifold_edge_examples,
    );
    report_line("split vertices", r.split_vertices, &r.split_vertex_examples);
    report_line::<u32>("flipped tetrahedra", r.flipped_tetrahedra, &[]);
    report_line(
        "non-orientable components",
        r.non_orientable_components,
        &r.non_orientable_examples,
    );
    report_line::<u32>("welded vertices", r.welded_vertices, &[]);
}
