//! The `topomesh` command: summaries, checks, conversions and timings of mesh files.

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};
use topomesh::io::{self, MeshData};
use topomesh::{BuildOptions, Che, Chf, ChfBuildOptions, Error};

/// The mesh `topomesh info` describes when no file is given: a 24 x 12 torus.
const DEFAULT_MESH: &str = include_str!("../../data/default.off");

#[derive(Parser)]
#[command(
    name = "topomesh",
    version,
    about = "Compact half-edge and half-face topology of meshes"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Topology summary and build report of a mesh (the embedded torus when no file).
    Info {
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
    },
    /// Exit 0 when the mesh is a clean manifold, 1 and a list of problems otherwise.
    Check { file: PathBuf },
    /// Convert between formats (read: off obj ply stl node/ele mesh msh vtk; write: off mesh vtk).
    Convert { input: PathBuf, output: PathBuf },
    /// Time the build of every level and full sweeps of the relations.
    Bench {
        file: Option<PathBuf>,
        /// Repetitions (the median is printed).
        #[arg(long, default_value_t = 5)]
        repeat: usize,
        /// Threads for the build (0: as many as the machine runs at once).
        #[arg(long, default_value_t = 0)]
        threads: usize,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let command = cli.command.unwrap_or(Command::Info {
        file: None,
        level: 3,
        strict: false,
        json: false,
        threads: 0,
    });
    let result = match command {
        Command::Info {
            file,
            level,
            strict,
            json,
            threads,
        } => info(file.as_deref(), level, strict, json, threads),
        Command::Check { file } => check(&file),
        Command::Convert { input, output } => convert(&input, &output),
        Command::Bench {
            file,
            repeat,
            threads,
        } => bench(file.as_deref(), repeat.max(1), threads),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("topomesh: error: {}", e.message);
            ExitCode::FAILURE
        }
    }
}

/// A spinner on stderr while slow work runs, only on a terminal.
struct Progress(Option<ProgressBar>);

impl Progress {
    fn new() -> Self {
        if !std::io::stderr().is_terminal() {
            return Progress(None);
        }
        let bar = ProgressBar::new_spinner();
        bar.set_style(ProgressStyle::with_template("{spinner} {msg} {elapsed}").unwrap());
        bar.enable_steady_tick(Duration::from_millis(120));
        Progress(Some(bar))
    }
    fn step(&self, msg: String) {
        if let Some(bar) = &self.0 {
            bar.set_message(msg);
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}

fn load(file: Option<&Path>, progress: &Progress) -> Result<(String, MeshData), Error> {
    match file {
        None => Ok((
            "<embedded torus>".to_string(),
            io::parse(DEFAULT_MESH.as_bytes(), io::Format::Off, "<embedded torus>")?,
        )),
        Some(path) => {
            progress.step(format!("reading {}", path.display()));
            Ok((path.display().to_string(), io::read(path)?))
        }
    }
}

fn build_surface(data: &MeshData, options: BuildOptions) -> Result<Che, Error> {
    Che::from_triangles(
        &data.triangles,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

#[derive(serde::Serialize)]
struct InfoJson<'a> {
    file: &'a str,
    kind: &'static str,
    level: u8,
    #[serde(flatten)]
    summary: topomesh::Summary,
    structure: Structure,
    report: &'a topomesh::BuildReport,
    memory: topomesh::che::Memory,
    read_seconds: f64,
    build_seconds: f64,
}

#[derive(serde::Serialize)]
struct Structure {
    vertices: usize,
    edges: usize,
    half_edges: usize,
    boundary_curves: usize,
}

fn info(
    file: Option<&Path>,
    level: u8,
    strict: bool,
    json: bool,
    threads: usize,
) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let start = Instant::now();
    let (name, data) = load(file, &progress)?;
    let read_seconds = start.elapsed().as_secs_f64();
    if data.is_volume() {
        drop(progress);
        return volume_info(&name, &data, level, strict, json, threads);
    }
    progress.step(format!(
        "building level {level} from {} triangles",
        data.triangles.len()
    ));
    let start = Instant::now();
    let che = build_surface(
        &data,
        BuildOptions {
            level,
            strict,
            threads,
        },
    )?;
    let build_seconds = start.elapsed().as_secs_f64();
    progress.step("summarising".to_string());
    let out = InfoJson {
        file: &name,
        kind: "surface",
        level,
        summary: che.summary(),
        structure: Structure {
            vertices: che.num_vertices(),
            edges: che.num_edges(),
            half_edges: che.num_half_edges(),
            boundary_curves: che.num_boundary_curves(),
        },
        report: che.report(),
        memory: che.memory_bytes(),
        read_seconds,
        build_seconds,
    };
    drop(progress);
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("plain data serialises")
        );
    } else {
        print_surface(&out);
    }
    Ok(ExitCode::SUCCESS)
}

fn print_surface(i: &InfoJson) {
    let s = &i.summary;
    let r = i.report;
    let yes = |b: bool| if b { "yes" } else { "no" };
    println!("file                 {}", i.file);
    println!("structure            CHE level {}", i.level);
    println!("vertices             {}", s.vertices);
    println!("edges                {}", s.edges);
    println!("triangles            {}", s.triangles);
    println!("boundary edges       {}", s.boundary_edges);
    println!("boundary curves      {}", s.boundary_curves);
    println!("components           {}", s.components);
    println!("isolated vertices    {}", s.isolated_vertices);
    println!("euler characteristic {}", s.euler_characteristic);
    let genus = if s.genus < 0 {
        "undefined".to_string()
    } else {
        s.genus.to_string()
    };
    println!("genus                {genus}");
    println!("orientable           {}", yes(s.orientable));
    println!("manifold             {}", yes(s.manifold));
    println!("build report");
    println!(
        "  dropped degenerate        {}{}",
        r.dropped_degenerate,
        examples(&r.degenerate_examples)
    );
    println!(
        "  duplicate triangle pairs  {}{}",
        r.duplicate_triangles,
        examples(&r.duplicate_examples)
    );
    println!(
        "  non-manifold edges        {}{}",
        r.non_manifold_edges,
        examples(&r.non_manifold_edge_examples)
    );
    println!(
        "  split vertices            {}{}",
        r.split_vertices,
        examples(&r.split_vertex_examples)
    );
    println!("  flipped triangles         {}", r.flipped_triangles);
    println!(
        "  non-orientable components {}{}",
        r.non_orientable_components,
        examples(&r.non_orientable_examples)
    );
    println!("  seam edges left unpaired  {}", r.seam_edges);
    println!("  vertices added by splits  {}", r.added_vertices);
    let st = &i.structure;
    println!(
        "structure counts     {} vertices, {} edges, {} half-edges, {} boundary curves",
        st.vertices, st.edges, st.half_edges, st.boundary_curves
    );
    let per = |b: usize| b as f64 / (s.triangles.max(1) as f64);
    println!(
        "topology memory      {} bytes ({:.2} bytes per triangle)",
        i.memory.topology,
        per(i.memory.topology)
    );
    println!(
        "time                 read {:.3} s, build {:.3} s",
        i.read_seconds, i.build_seconds
    );
}

fn examples<T: std::fmt::Debug>(list: &[T]) -> String {
    if list.is_empty() {
        String::new()
    } else {
        format!("  (first: {list:?})")
    }
}

#[derive(serde::Serialize)]
struct VolumeJson<'a> {
    file: &'a str,
    kind: &'static str,
    level: u8,
    #[serde(flatten)]
    summary: topomesh::ChfSummary,
    structure: VolumeStructure,
    report: &'a topomesh::ChfBuildReport,
    memory: topomesh::chf::ChfMemory,
    build_seconds: f64,
}

#[derive(serde::Serialize)]
struct VolumeStructure {
    vertices: usize,
    edges: usize,
    faces: usize,
    half_faces: usize,
}

fn build_volume(data: &MeshData, options: ChfBuildOptions) -> Result<Chf, Error> {
    Chf::from_tetrahedra(
        &data.tetrahedra,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

fn volume_info(
    name: &str,
    data: &MeshData,
    level: u8,
    strict: bool,
    json: bool,
    threads: usize,
) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    progress.step(format!(
        "building level {level} from {} tetrahedra",
        data.tetrahedra.len()
    ));
    let start = Instant::now();
    let chf = build_volume(
        data,
        ChfBuildOptions {
            level,
            strict,
            threads,
        },
    )?;
    let build_seconds = start.elapsed().as_secs_f64();
    progress.step("summarising".to_string());
    let out = VolumeJson {
        file: name,
        kind: "volume",
        level,
        summary: chf.summary(),
        structure: VolumeStructure {
            vertices: chf.num_vertices(),
            edges: chf.num_edges(),
            faces: chf.num_faces(),
            half_faces: chf.num_half_faces(),
        },
        report: chf.report(),
        memory: chf.memory_bytes(),
        build_seconds,
    };
    drop(progress);
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("plain data serialises")
        );
        return Ok(ExitCode::SUCCESS);
    }
    let s = &out.summary;
    let r = out.report;
    let yes = |b: bool| if b { "yes" } else { "no" };
    println!("file                 {name}");
    println!("structure            CHF level {level}");
    println!("vertices             {}", s.vertices);
    println!("edges                {}", s.edges);
    println!("faces                {}", s.faces);
    println!("tetrahedra           {}", s.tetrahedra);
    println!("boundary faces       {}", s.boundary_faces);
    println!("boundary edges       {}", s.boundary_edges);
    println!("boundary vertices    {}", s.boundary_vertices);
    println!("boundary components  {}", s.boundary_components);
    println!("components           {}", s.components);
    println!("isolated vertices    {}", s.isolated_vertices);
    println!("euler characteristic {}", s.euler_characteristic);
    println!("orientable           {}", yes(s.orientable));
    println!("manifold             {}", yes(s.manifold));
    println!("build report");
    println!(
        "  dropped degenerate        {}{}",
        r.dropped_degenerate,
        examples(&r.degenerate_examples)
    );
    println!(
        "  zero volume (kept)        {}{}",
        r.zero_volume,
        examples(&r.zero_volume_examples)
    );
    println!(
        "  inverted (kept)           {}{}",
        r.inverted_tetrahedra,
        examples(&r.inverted_examples)
    );
    println!(
        "  duplicate pairs           {}{}",
        r.duplicate_tetrahedra,
        examples(&r.duplicate_examples)
    );
    println!(
        "  non-manifold faces        {}{}",
        r.non_manifold_faces,
        examples(&r.non_manifold_face_examples)
    );
    println!(
        "  non-manifold edges        {}{}",
        r.non_manifold_edges,
        examples(&r.non_manifold_edge_examples)
    );
    println!(
        "  split vertices            {}{}",
        r.split_vertices,
        examples(&r.split_vertex_examples)
    );
    println!("  flipped tetrahedra        {}", r.flipped_tetrahedra);
    println!(
        "  non-orientable components {}{}",
        r.non_orientable_components,
        examples(&r.non_orientable_examples)
    );
    let st = &out.structure;
    println!(
        "structure counts     {} vertices, {} edges, {} faces, {} half-faces",
        st.vertices, st.edges, st.faces, st.half_faces
    );
    println!(
        "topology memory      {} bytes ({:.2} bytes per tetrahedron)",
        out.memory.topology,
        out.memory.topology as f64 / (s.tetrahedra.max(1) as f64)
    );
    println!("time                 build {:.3} s", out.build_seconds);
    Ok(ExitCode::SUCCESS)
}

fn check_volume(name: &str, data: &MeshData) -> Result<ExitCode, Error> {
    let chf = build_volume(
        data,
        ChfBuildOptions {
            level: 1,
            ..ChfBuildOptions::default()
        },
    )?;
    let r = chf.report();
    let mut problems = Vec::new();
    let mut note = |count: usize, what: &str, ex: String| {
        if count > 0 {
            problems.push(format!("{count} {what}{ex}"));
        }
    };
    note(
        r.dropped_degenerate,
        "degenerate tetrahedra",
        examples(&r.degenerate_examples),
    );
    note(
        r.zero_volume,
        "zero-volume tetrahedra",
        examples(&r.zero_volume_examples),
    );
    note(
        r.inverted_tetrahedra,
        "inverted tetrahedra",
        examples(&r.inverted_examples),
    );
    note(
        r.duplicate_tetrahedra,
        "duplicate tetrahedron pairs",
        examples(&r.duplicate_examples),
    );
    note(
        r.non_manifold_faces,
        "non-manifold faces",
        examples(&r.non_manifold_face_examples),
    );
    note(
        r.non_manifold_edges,
        "non-manifold edges",
        examples(&r.non_manifold_edge_examples),
    );
    note(
        r.split_vertices,
        "non-manifold vertices",
        examples(&r.split_vertex_examples),
    );
    note(
        r.non_orientable_components,
        "non-orientable components",
        examples(&r.non_orientable_examples),
    );
    note(
        r.flipped_tetrahedra,
        "tetrahedra oriented against their neighbours",
        String::new(),
    );
    report_problems(name, problems, || {
        let s = chf.summary();
        format!(
            "a manifold of {} tetrahedra, euler characteristic {}",
            s.tetrahedra, s.euler_characteristic
        )
    })
}

fn report_problems(
    name: &str,
    problems: Vec<String>,
    ok: impl FnOnce() -> String,
) -> Result<ExitCode, Error> {
    if problems.is_empty() {
        println!("{name}: ok: {}", ok());
        return Ok(ExitCode::SUCCESS);
    }
    for p in &problems {
        println!("{name}: {p}");
    }
    Ok(ExitCode::FAILURE)
}

fn check(file: &Path) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let (name, data) = load(Some(file), &progress)?;
    drop(progress);
    if data.is_volume() {
        return check_volume(&name, &data);
    }
    let che = build_surface(&data, BuildOptions::level(1))?;
    let r = che.report();
    let mut problems = Vec::new();
    let mut note = |count: usize, what: &str, ex: String| {
        if count > 0 {
            problems.push(format!("{count} {what}{ex}"));
        }
    };
    note(
        r.dropped_degenerate,
        "degenerate triangles",
        examples(&r.degenerate_examples),
    );
    note(
        r.duplicate_triangles,
        "duplicate triangle pairs",
        examples(&r.duplicate_examples),
    );
    note(
        r.non_manifold_edges,
        "non-manifold edges",
        examples(&r.non_manifold_edge_examples),
    );
    note(
        r.split_vertices,
        "non-manifold vertices",
        examples(&r.split_vertex_examples),
    );
    note(
        r.non_orientable_components,
        "non-orientable components",
        examples(&r.non_orientable_examples),
    );
    note(
        r.flipped_triangles,
        "triangles oriented against their neighbours",
        String::new(),
    );
    report_problems(&name, problems, || {
        let s = che.summary();
        format!(
            "a manifold of {} triangles, euler characteristic {}",
            s.triangles, s.euler_characteristic
        )
    })
}

fn convert(input: &Path, output: &Path) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let (_, data) = load(Some(input), &progress)?;
    progress.step(format!("writing {}", output.display()));
    io::write(output, &data)?;
    drop(progress);
    println!(
        "{} -> {}: {} vertices, {} triangles, {} tetrahedra",
        input.display(),
        output.display(),
        data.num_vertices(),
        data.triangles.len(),
        data.tetrahedra.len()
    );
    Ok(ExitCode::SUCCESS)
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn bench(file: Option<&Path>, repeat: usize, threads: usize) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let (name, data) = load(file, &progress)?;
    drop(progress);
    if data.is_volume() {
        return bench_volume(&name, &data, repeat, threads);
    }
    let t = data.triangles.len().max(1) as f64;
    println!(
        "{name}: {} triangles, median of {repeat}",
        data.triangles.len()
    );
    for level in 0..=3u8 {
        let mut times = Vec::new();
        let mut che = None;
        for _ in 0..repeat {
            let start = Instant::now();
            che = Some(build_surface(
                &data,
                BuildOptions {
                    level,
                    strict: false,
                    threads,
                },
            )?);
            times.push(start.elapsed().as_secs_f64());
        }
        let che = che.expect("repeat >= 1");
        let secs = median(times);
        println!(
            "build level {level}: {:8.2} ms  {:6.1} ns/triangle  {:6.2} bytes/triangle",
            secs * 1e3,
            secs * 1e9 / t,
            che.memory_bytes().topology as f64 / t
        );
        if level >= 1 {
            sweeps(&che, repeat);
        }
    }
    Ok(ExitCode::SUCCESS)
}

fn bench_volume(
    name: &str,
    data: &MeshData,
    repeat: usize,
    threads: usize,
) -> Result<ExitCode, Error> {
    let t = data.tetrahedra.len().max(1) as f64;
    println!(
        "{name}: {} tetrahedra, median of {repeat}",
        data.tetrahedra.len()
    );
    for level in 0..=3u8 {
        let mut times = Vec::new();
        let mut chf = None;
        for _ in 0..repeat {
            let start = Instant::now();
            chf = Some(build_volume(
                data,
                ChfBuildOptions {
                    level,
                    strict: false,
                    threads,
                },
            )?);
            times.push(start.elapsed().as_secs_f64());
        }
        let chf = chf.expect("repeat >= 1");
        let secs = median(times);
        println!(
            "build level {level}: {:8.2} ms  {:6.1} ns/tetrahedron  {:6.2} bytes/tetrahedron",
            secs * 1e3,
            secs * 1e9 / t,
            chf.memory_bytes().topology as f64 / t
        );
        if level >= 2 {
            let nt = chf.num_tetrahedra() as u32;
            let nv = chf.num_vertices() as u32;
            let timed = |f: &dyn Fn() -> u64| {
                median(
                    (0..repeat)
                        .map(|_| {
                            let start = Instant::now();
                            std::hint::black_box(f());
                            start.elapsed().as_secs_f64()
                        })
                        .collect(),
                )
            };
            let tt = timed(&|| {
                (0..nt)
                    .flat_map(|x| chf.tetrahedron_tetrahedra(x))
                    .map(u64::from)
                    .sum()
            });
            let vt = timed(&|| {
                (0..nv)
                    .flat_map(|v| chf.vertex_tetrahedra(v))
                    .map(u64::from)
                    .sum()
            });
            let vv = timed(&|| {
                (0..nv)
                    .flat_map(|v| chf.vertex_vertices(v))
                    .map(u64::from)
                    .sum()
            });
            println!(
                "  sweeps: TT {:.2} ms, VT {:.2} ms, VV {:.2} ms",
                tt * 1e3,
                vt * 1e3,
                vv * 1e3
            );
        }
    }
    Ok(ExitCode::SUCCESS)
}

fn sweeps(che: &Che, repeat: usize) {
    let time = |f: &dyn Fn() -> u64| {
        let mut check = 0;
        let secs = median(
            (0..repeat)
                .map(|_| {
                    let start = Instant::now();
                    check = f();
                    start.elapsed().as_secs_f64()
                })
                .collect(),
        );
        (secs, check)
    };
    let nv = che.num_vertices() as u32;
    let nt = che.num_triangles() as u32;
    if che.level() < 2 {
        // Per-vertex queries scan below level 2: sweep with the bulk calls instead.
        let sum = |c: topomesh::che::Csr| c.indices.iter().map(|&x| u64::from(x)).sum::<u64>();
        let (vv, _) = time(&|| sum(che.all_vertex_vertices()));
        let (vf, _) = time(&|| sum(che.all_vertex_triangles()));
        let (ff, _) = time(&|| {
            che.all_triangle_triangles()
                .iter()
                .map(|&x| u64::from(x))
                .sum()
        });
        println!(
            "  bulk sweeps: VV {:.2} ms, VF {:.2} ms, FF {:.2} ms",
            vv * 1e3,
            vf * 1e3,
            ff * 1e3
        );
        return;
    }
    let (vv, _) = time(&|| {
        (0..nv)
            .flat_map(|v| che.vertex_vertices(v))
            .map(u64::from)
            .sum()
    });
    let (vf, _) = time(&|| {
        (0..nv)
            .flat_map(|v| che.vertex_triangles(v))
            .map(u64::from)
            .sum()
    });
    let (ff, _) = time(&|| {
        (0..nt)
            .flat_map(|t| che.triangle_triangles(t))
            .map(u64::from)
            .sum()
    });
    println!(
        "  sweeps: VV {:.2} ms, VF {:.2} ms, FF {:.2} ms",
        vv * 1e3,
        vf * 1e3,
        ff * 1e3
    );
}
