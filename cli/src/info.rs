//! `topomesh info`: the topology summary, build report, structure counts and memory of a
//! mesh, as text or JSON.

use crate::exit::Failure;
use crate::input::{LevelFile, Opened, build_surface_shown, build_volume_shown, load, open};
use crate::json::{
    INFO_SCHEMA, SurfaceMemory, SurfaceReport, SurfaceSummary, VolumeMemory, VolumeReport,
    VolumeSummary,
};
use crate::output::{Out, verbose};
use crate::print::{count, line, yes};
use crate::progress::Progress;
use crate::report;
use serde::Serialize;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, Che, Chf, Error, chf};

#[derive(clap::Args)]
pub struct InfoOptions {
    /// The mesh file, its format by extension (none: the embedded torus); a level file
    /// (.che, .chf, written by `convert`) is opened instead of built.
    file: Option<PathBuf>,
    /// Structure level, 0 to 3 (the library's default is 2: see the README).
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

pub fn run(options: &InfoOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let start = Instant::now();
    if let Some(path) = options.file.as_deref()
        && let Some(kind) = LevelFile::of(path)
    {
        return opened_info(path, kind, options, progress);
    }
    let (name, data) = load(options.file.as_deref(), &progress)?;
    let read_seconds = start.elapsed().as_secs_f64();
    if data.is_volume() {
        volume_info(&name, &data, options, progress)
    } else {
        surface_info(&name, &data, options, progress, read_seconds)
    }
}

/// `info` on a level file: the structure opened (the read time), then raised or lowered
/// to `--level` (the build time).
fn opened_info(
    path: &Path, kind: LevelFile, options: &InfoOptions, progress: Progress,
) -> Result<ExitCode, Failure> {
    let start = Instant::now();
    let opened = open(path, kind, &progress)?;
    let read_seconds = start.elapsed().as_secs_f64();
    let name = path.display().to_string();
    let message = format!("level {}", options.level);
    match opened {
        Opened::Surface(mut che) => {
            let (che, build_seconds) = timed_build(&progress, message, || {
                che.build_level(options.level)?;
                Ok(che)
            })?;
            surface_out(
                &name,
                &che,
                options,
                progress,
                [read_seconds, build_seconds],
                Vec::new(),
            )
        }
        Opened::Volume(mut chf) => {
            let (chf, build_seconds) = timed_build(&progress, message, || {
                chf.build_level(options.level)?;
                Ok(chf)
            })?;
            volume_out(&name, &chf, options, progress, build_seconds, Vec::new())
        }
    }
}

impl InfoOptions {
    fn surface(&self) -> BuildOptions {
        BuildOptions {
            level: self.level,
            strict: self.strict,
            threads: self.threads,
            weld_tolerance: self.weld,
            ..BuildOptions::default()
        }
    }

    fn volume(&self) -> chf::BuildOptions {
        chf::BuildOptions {
            level: self.level,
            strict: self.strict,
            threads: self.threads,
            weld_tolerance: self.weld,
            ..chf::BuildOptions::default()
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

/// Prints `info` as JSON or as text, once the spinner is gone.
fn emit<T: Serialize>(
    options: &InfoOptions, progress: Progress, info: &T, text: fn(&mut Out, &T) -> io::Result<()>,
) -> Result<ExitCode, Failure> {
    drop(progress);
    let mut out = Out::new();
    if options.json {
        crate::json::write(&mut out, INFO_SCHEMA, info)?;
    } else {
        text(&mut out, info)?;
    }
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

fn surface_info(
    name: &str, data: &MeshData, options: &InfoOptions, progress: Progress, read_seconds: f64,
) -> Result<ExitCode, Failure> {
    let n = data.triangles.len() as u64;
    let message = format!(
        "building level {} from {}",
        options.level,
        count(n, "triangle", "triangles")
    );
    let (che, build_seconds) = timed_build(&progress, message, || {
        build_surface_shown(data, options.surface(), &progress)
    })?;
    surface_out(
        name,
        &che,
        options,
        progress,
        [read_seconds, build_seconds],
        warning_lines(data),
    )
}

/// Prints what `info` says of a surface.
/// `seconds`: reading, then building; `warnings`: the reader's.
fn surface_out(
    name: &str, che: &Che, options: &InfoOptions, progress: Progress, seconds: [f64; 2],
    warnings: Vec<String>,
) -> Result<ExitCode, Failure> {
    let [read_seconds, build_seconds] = seconds;
    let (summary, memory) = (che.summary(), che.memory_bytes());
    let betti = che.betti_numbers()?;
    let out = SurfaceInfo {
        file: name,
        kind: "surface",
        level: options.level,
        summary: SurfaceSummary(&summary),
        betti,
        structure: SurfaceStructure::of(che),
        report: SurfaceReport(che.report()),
        memory: SurfaceMemory(&memory),
        read_seconds,
        build_seconds,
        warnings,
    };
    emit(options, progress, &out, print_surface)
}

#[derive(Serialize)]
struct SurfaceInfo<'a> {
    file: &'a str,
    kind: &'static str,
    level: u8,
    #[serde(flatten)]
    summary: SurfaceSummary<'a>,
    /// Betti numbers over Z/2 of the surface as given: `[b0, b1, b2]`.
    betti: [u64; 3],
    structure: SurfaceStructure,
    report: SurfaceReport<'a>,
    memory: SurfaceMemory<'a>,
    read_seconds: f64,
    build_seconds: f64,
    /// What the reader read past or found odd, `file:line: message` each.
    warnings: Vec<String>,
}

/// The reader's warnings, one line each.
fn warning_lines(data: &MeshData) -> Vec<String> {
    data.warnings.iter().map(|w| w.to_string()).collect()
}

/// The reader's warnings, under their heading, when there are any.
fn print_warnings(out: &mut Out, warnings: &[String]) -> io::Result<()> {
    if !warnings.is_empty() {
        writeln!(out, "reader warnings")?;
        for w in warnings {
            writeln!(out, "  {w}")?;
        }
    }
    Ok(())
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

fn print_surface(out: &mut Out, i: &SurfaceInfo) -> io::Result<()> {
    let s = i.summary.0;
    line(out, "file", i.file)?;
    line(out, "structure", format!("CHE level {}", i.level))?;
    line(out, "vertices", s.vertices)?;
    line(out, "edges", s.edges)?;
    line(out, "triangles", s.triangles)?;
    line(out, "boundary edges", s.boundary_edges)?;
    line(out, "boundary curves", s.boundary_curves)?;
    line(out, "components", s.components)?;
    line(out, "isolated vertices", s.isolated_vertices)?;
    line(out, "euler characteristic", s.euler_characteristic)?;
    let genus = if s.genus < 0 {
        "undefined".to_string()
    } else {
        s.genus.to_string()
    };
    line(out, "genus", genus)?;
    let [b0, b1, b2] = i.betti;
    line(out, "betti numbers (Z/2)", format!("{b0} {b1} {b2}"))?;
    line(out, "orientable", yes(s.orientable))?;
    line(out, "manifold", yes(s.manifold))?;
    report::surface(out, i.report.0)?;
    let st = &i.structure;
    let counts = [
        count(st.vertices as u64, "vertex", "vertices"),
        count(st.edges as u64, "edge", "edges"),
        count(st.half_edges as u64, "half-edge", "half-edges"),
        count(
            st.boundary_curves as u64,
            "boundary curve",
            "boundary curves",
        ),
    ];
    line(out, "structure counts", counts.join(", "))?;
    memory_lines(out, i.memory.0.topology, s.triangles, "triangle")?;
    if verbose() {
        crate::json::memory_table(out, &i.memory)?;
    }
    let time = format!(
        "read {:.3} s, build {:.3} s",
        i.read_seconds, i.build_seconds
    );
    line(out, "time", time)?;
    print_warnings(out, &i.warnings)
}

/// The topology's bytes, in all and per element.
fn memory_lines(out: &mut Out, topology: usize, elements: u64, unit: &str) -> io::Result<()> {
    let per = topology as f64 / (elements.max(1) as f64);
    line(
        out,
        "topology memory",
        format!("{topology} bytes ({per:.2} bytes per {unit})"),
    )
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
    /// What the reader read past or found odd, `file:line: message` each.
    warnings: Vec<String>,
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
) -> Result<ExitCode, Failure> {
    let n = data.tetrahedra.len() as u64;
    let message = format!(
        "building level {} from {}",
        options.level,
        count(n, "tetrahedron", "tetrahedra")
    );
    let (chf, build_seconds) = timed_build(&progress, message, || {
        build_volume_shown(data, options.volume(), &progress)
    })?;
    volume_out(
        name,
        &chf,
        options,
        progress,
        build_seconds,
        warning_lines(data),
    )
}

/// Prints what `info` says of a volume.
fn volume_out(
    name: &str, chf: &Chf, options: &InfoOptions, progress: Progress, build_seconds: f64,
    warnings: Vec<String>,
) -> Result<ExitCode, Failure> {
    let (summary, memory) = (chf.summary(), chf.memory_bytes());
    let out = VolumeInfo {
        file: name,
        kind: "volume",
        level: options.level,
        summary: VolumeSummary(&summary),
        structure: VolumeStructure::of(chf),
        report: VolumeReport(chf.report()),
        memory: VolumeMemory(&memory),
        build_seconds,
        warnings,
    };
    emit(options, progress, &out, print_volume)
}

fn print_volume(out: &mut Out, i: &VolumeInfo) -> io::Result<()> {
    let s = i.summary.0;
    line(out, "file", i.file)?;
    line(out, "structure", format!("CHF level {}", i.level))?;
    line(out, "vertices", s.vertices)?;
    line(out, "edges", s.edges)?;
    line(out, "faces", s.faces)?;
    line(out, "tetrahedra", s.tetrahedra)?;
    line(out, "boundary faces", s.boundary_faces)?;
    line(out, "boundary edges", s.boundary_edges)?;
    line(out, "boundary vertices", s.boundary_vertices)?;
    line(out, "boundary components", s.boundary_components)?;
    line(out, "components", s.components)?;
    line(out, "isolated vertices", s.isolated_vertices)?;
    line(out, "euler characteristic", s.euler_characteristic)?;
    line(out, "orientable", yes(s.orientable))?;
    line(out, "manifold", yes(s.manifold))?;
    report::volume(out, i.report.0)?;
    let st = &i.structure;
    let counts = [
        count(st.vertices as u64, "vertex", "vertices"),
        count(st.edges as u64, "edge", "edges"),
        count(st.faces as u64, "face", "faces"),
        count(st.half_faces as u64, "half-face", "half-faces"),
    ];
    line(out, "structure counts", counts.join(", "))?;
    memory_lines(out, i.memory.0.topology, s.tetrahedra, "tetrahedron")?;
    if verbose() {
        crate::json::memory_table(out, &i.memory)?;
    }
    line(out, "time", format!("build {:.3} s", i.build_seconds))?;
    print_warnings(out, &i.warnings)
}
