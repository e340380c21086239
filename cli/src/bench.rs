//! `topomesh bench`: the median time of the build of every level and of full sweeps of the
//! relations, with the topology's bytes per element, as text or JSON. Every timed build
//! and sweep follows one untimed warm-up run, so that the first repetition does not pay
//! for cold caches and page faults alone. On a level file (`.che`, `.chf`), the time to
//! open it (mapped or loaded, trusted or checked) and answer a first VV query, and the
//! sweeps on the mapped structure.

use crate::exit::Failure;
use crate::input::{LevelFile, build_surface, build_volume, load};
use crate::json::BENCH_SCHEMA;
use crate::output::{Out, verbose};
use crate::print::count;
use crate::progress::Progress;
use serde::Serialize;
use std::hint::black_box;
use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use topomesh::io::MeshData;
use topomesh::levelfile::{Mode, OpenOptions, Verify};
use topomesh::{BuildOptions, Che, Chf, Error, chf};

#[derive(clap::Args)]
pub struct BenchOptions {
    /// The mesh file, its format by extension (none: the embedded torus).
    file: Option<PathBuf>,
    /// Repetitions (the median is printed).
    #[arg(long, default_value_t = 5)]
    repeat: usize,
    /// Threads for the build (0: as many as the machine runs at once).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Print JSON: per level, the build and sweep times (median, fastest, slowest).
    #[arg(long)]
    json: bool,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
    /// On a level file: only the mapped, trusted open and the sweeps, the runs that read no
    /// more of the file than the queries touch (a file larger than memory is neither loaded
    /// nor checksummed in bounded memory).
    #[arg(long)]
    trusted_only: bool,
}

impl BenchOptions {
    /// At least one repetition, so that there is a median.
    fn repeat(&self) -> usize {
        self.repeat.max(1)
    }
}

/// What `bench --json` prints.
#[derive(Serialize)]
struct Bench {
    file: String,
    kind: &'static str,
    /// Triangles or tetrahedra in the file.
    elements: usize,
    repeat: usize,
    threads: usize,
    levels: Vec<Level>,
}

#[derive(Serialize)]
struct Level {
    level: u8,
    build: Timing,
    topology_bytes: usize,
    /// `null` at the levels where the sweeps are not timed.
    sweeps: Option<Sweeps>,
}

/// Seconds over the repetitions.
#[derive(Clone, Copy, Serialize)]
struct Timing {
    median: f64,
    min: f64,
    max: f64,
}

#[derive(Serialize)]
struct Sweeps {
    /// `per_element` (one query per element) or `bulk` (the CSR calls, below level 2).
    method: &'static str,
    relations: Vec<Sweep>,
}

#[derive(Serialize)]
struct Sweep {
    relation: &'static str,
    seconds: Timing,
}

/// What `bench --json` prints for a level file.
#[derive(Serialize)]
struct OpenBench {
    file: String,
    kind: &'static str,
    elements: usize,
    level: u8,
    repeat: usize,
    /// Open then the first VV query, per mode and check.
    opens: Vec<Open>,
    /// On the mapped, trusted structure; `null` below the level the sweeps need.
    sweeps: Option<Sweeps>,
}

#[derive(Serialize)]
struct Open {
    mode: &'static str,
    verify: &'static str,
    seconds: Timing,
}

pub fn run(options: &BenchOptions) -> Result<ExitCode, Failure> {
    if let Some(path) = options.file.as_deref()
        && let Some(kind) = LevelFile::of(path)
    {
        let bench = bench_level_file(path, kind, options)?;
        let mut out = Out::new();
        if options.json {
            crate::json::write(&mut out, BENCH_SCHEMA, &bench)?;
        } else {
            print_opens(&mut out, &bench)?;
        }
        out.finish()?;
        return Ok(ExitCode::SUCCESS);
    }
    let progress = Progress::new();
    let (name, data) = load(options.file.as_deref(), &progress)?;
    // Four levels, each a warm-up build and the timed ones.
    let builds = 4 * (options.repeat() as u64 + 1);
    progress.start("building every level".to_string(), builds);
    let bench = if data.is_volume() {
        bench_volume(name, &data, options, &progress)?
    } else {
        bench_surface(name, &data, options, &progress)?
    };
    drop(progress);
    let mut out = Out::new();
    if options.json {
        crate::json::write(&mut out, BENCH_SCHEMA, &bench)?;
    } else {
        print(&mut out, &bench)?;
    }
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

fn bench_surface(
    file: String, data: &MeshData, options: &BenchOptions, progress: &Progress,
) -> Result<Bench, Error> {
    let repeat = options.repeat();
    let mut levels = Vec::new();
    for level in 0..=3u8 {
        let build = BuildOptions {
            level,
            strict: false,
            threads: options.threads,
            memory_limit_bytes: 0,
            weld_tolerance: options.weld,
        };
        let (che, timing) = timed_builds(repeat, progress, || build_surface(data, build))?;
        let sweeps = if level >= 1 {
            Some(surface_sweeps(&che, repeat)?)
        } else {
            None
        };
        levels.push(Level {
            level,
            build: timing,
            topology_bytes: che.memory_bytes().topology,
            sweeps,
        });
    }
    Ok(Bench {
        file,
        kind: "surface",
        elements: data.triangles.len(),
        repeat,
        threads: options.threads,
        levels,
    })
}

fn bench_volume(
    file: String, data: &MeshData, options: &BenchOptions, progress: &Progress,
) -> Result<Bench, Error> {
    let repeat = options.repeat();
    let mut levels = Vec::new();
    for level in 0..=3u8 {
        let build = chf::BuildOptions {
            level,
            strict: false,
            threads: options.threads,
            memory_limit_bytes: 0,
            weld_tolerance: options.weld,
        };
        let (chf, timing) = timed_builds(repeat, progress, || build_volume(data, build))?;
        levels.push(Level {
            level,
            build: timing,
            topology_bytes: chf.memory_bytes().topology,
            sweeps: (level >= 2).then(|| volume_sweeps(&chf, repeat)),
        });
    }
    Ok(Bench {
        file,
        kind: "volume",
        elements: data.tetrahedra.len(),
        repeat,
        threads: options.threads,
        levels,
    })
}

/// The structure of a level file, either kind.
enum Opened {
    Surface(Box<Che>),
    Volume(Box<Chf>),
}

impl Opened {
    fn open(path: &std::path::Path, kind: LevelFile, options: OpenOptions) -> Result<Self, Error> {
        Ok(match kind {
            LevelFile::Surface => Opened::Surface(Box::new(Che::open(path, options)?)),
            LevelFile::Volume => Opened::Volume(Box::new(Chf::open(path, options)?)),
        })
    }
    /// The first VV query: the neighbours of vertex 0.
    fn first_vv(&self) -> u64 {
        match self {
            Opened::Surface(che) if che.num_vertices() > 0 => sum(che.vertex_vertices(0)),
            Opened::Volume(chf) if chf.num_vertices() > 0 => sum(chf.vertex_vertices(0)),
            _ => 0,
        }
    }
}

/// Every way to open `path`, timed with the first query after it (the mapped ones first,
/// so that the page cache holds the file for all, as it would for a file just written).
fn bench_level_file(
    path: &std::path::Path, kind: LevelFile, options: &BenchOptions,
) -> Result<OpenBench, Error> {
    let repeat = options.repeat();
    let ways = [
        (Mode::Mapped, Verify::Trusted),
        (Mode::Mapped, Verify::Checksums),
        (Mode::Mapped, Verify::Full),
        (Mode::Loaded, Verify::Trusted),
        (Mode::Loaded, Verify::Full),
    ];
    let mut opens = Vec::new();
    let ways = ways
        .into_iter()
        .filter(|&way| way == (Mode::Mapped, Verify::Trusted) || !options.trusted_only);
    for (mode, verify) in ways {
        let options = OpenOptions { verify, mode };
        black_box(Opened::open(path, kind, options)?.first_vv());
        let mut times = Vec::new();
        for _ in 0..repeat {
            let start = Instant::now();
            black_box(Opened::open(path, kind, options)?.first_vv());
            times.push(start.elapsed().as_secs_f64());
        }
        opens.push(Open {
            mode: if mode == Mode::Mapped {
                "mapped"
            } else {
                "loaded"
            },
            verify: match verify {
                Verify::Full => "full",
                Verify::Checksums => "checksums",
                Verify::Trusted => "trusted",
            },
            seconds: Timing::of(times),
        });
    }
    let mapped = Opened::open(path, kind, OpenOptions::mapped(Verify::Trusted))?;
    let (kind, elements, level, sweeps) = match &mapped {
        Opened::Surface(che) => {
            let sweeps = (che.level() >= 1).then(|| surface_sweeps(che, repeat));
            (
                "surface",
                che.num_triangles(),
                che.level(),
                sweeps.transpose()?,
            )
        }
        Opened::Volume(chf) => (
            "volume",
            chf.num_tetrahedra(),
            chf.level(),
            (chf.level() >= 1).then(|| volume_sweeps(chf, repeat)),
        ),
    };
    Ok(OpenBench {
        file: path.display().to_string(),
        kind,
        elements,
        level,
        repeat,
        opens,
        sweeps,
    })
}

fn print_opens(out: &mut Out, b: &OpenBench) -> io::Result<()> {
    let (one, many) = match b.kind {
        "volume" => ("tetrahedron", "tetrahedra"),
        _ => ("triangle", "triangles"),
    };
    let elements = count(b.elements as u64, one, many);
    writeln!(
        out,
        "{}: {elements}, level {}, median of {}",
        b.file, b.level, b.repeat
    )?;
    for o in &b.opens {
        let label = format!("open {} {} + first VV:", o.mode, o.verify);
        write!(out, "{label:34} {:10.3} ms", o.seconds.median * 1e3)?;
        spread(out, o.seconds)?;
        writeln!(out)?;
    }
    if let Some(s) = &b.sweeps {
        let parts: Vec<String> = s
            .relations
            .iter()
            .map(|r| format!("{} {:.2} ms", r.relation, r.seconds.median * 1e3))
            .collect();
        writeln!(out, "sweeps on the mapping: {}", parts.join(", "))?;
    }
    Ok(())
}

/// One untimed warm-up build, then `repeat` timed ones; the last structure and the times.
fn timed_builds<T>(
    repeat: usize, progress: &Progress, mut build: impl FnMut() -> Result<T, Error>,
) -> Result<(T, Timing), Error> {
    let mut last = build()?;
    progress.advance(1);
    let mut times = Vec::new();
    for _ in 0..repeat {
        let start = Instant::now();
        last = build()?;
        times.push(start.elapsed().as_secs_f64());
        progress.advance(1);
    }
    Ok((last, Timing::of(times)))
}

/// One untimed warm-up sweep, then the times of `repeat` (the result kept from the
/// optimiser).
fn timed(repeat: usize, sweep: &dyn Fn() -> u64) -> Timing {
    black_box(sweep());
    Timing::of(
        (0..repeat)
            .map(|_| {
                let start = Instant::now();
                black_box(sweep());
                start.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

impl Timing {
    /// Of at least one time.
    fn of(mut times: Vec<f64>) -> Timing {
        times.sort_by(f64::total_cmp);
        Timing {
            median: times[times.len() / 2],
            min: times[0],
            max: times[times.len() - 1],
        }
    }
}

fn sum(ids: impl Iterator<Item = u32>) -> u64 {
    ids.map(u64::from).sum()
}

fn sweeps<const N: usize>(method: &'static str, times: [(&'static str, Timing); N]) -> Sweeps {
    let relations = times
        .into_iter()
        .map(|(relation, seconds)| Sweep { relation, seconds })
        .collect();
    Sweeps { method, relations }
}

/// Elements a sweep visits between two gives-back of a mapped file's pages.
const RELEASE_EVERY: usize = 1 << 22;

fn surface_sweeps(che: &Che, repeat: usize) -> Result<Sweeps, Error> {
    let nv = che.num_vertices() as u32;
    let nt = che.num_triangles() as u32;
    if che.level() < 2 {
        // Per-vertex queries scan below level 2: sweep with the bulk calls instead. A bulk
        // call that runs out of memory ends the benchmark with its error.
        let failed = std::cell::RefCell::new(None);
        let ids = |r: Result<Vec<u32>, Error>| match r {
            Ok(ids) => sum(ids.into_iter()),
            Err(e) => {
                failed.borrow_mut().get_or_insert(e);
                0
            }
        };
        let csr = |r: Result<topomesh::che::Csr, Error>| ids(r.map(|c| c.indices));
        let vv = timed(repeat, &|| csr(che.all_vertex_vertices()));
        let vf = timed(repeat, &|| csr(che.all_vertex_triangles()));
        let ff = timed(repeat, &|| ids(che.all_triangle_triangles()));
        if let Some(e) = failed.into_inner() {
            return Err(e);
        }
        return Ok(sweeps("bulk", [("VV", vv), ("VF", vf), ("FF", ff)]));
    }
    let released = |ids, each: &dyn Fn(u32) -> u64| {
        released(ids, each, &|| {
            let _ = che.release_mapped_pages();
        })
    };
    let vv = timed(repeat, &|| {
        released(0..nv, &|v| sum(che.vertex_vertices(v)))
    });
    let vf = timed(repeat, &|| {
        released(0..nv, &|v| sum(che.vertex_triangles(v)))
    });
    let ff = timed(repeat, &|| {
        released(0..nt, &|t| sum(che.triangle_triangles(t).into_iter()))
    });
    Ok(sweeps("per_element", [("VV", vv), ("VF", vf), ("FF", ff)]))
}

/// The sum of `each` over `ids`, calling `release` every so many ids: on a mapped file the
/// pages read are given back, so that a sweep over a file larger than memory keeps a
/// bounded resident set.
fn released(ids: std::ops::Range<u32>, each: &dyn Fn(u32) -> u64, release: &dyn Fn()) -> u64 {
    let mut total = 0;
    for first in ids.clone().step_by(RELEASE_EVERY) {
        let last = first.saturating_add(RELEASE_EVERY as u32).min(ids.end);
        total += (first..last).map(each).sum::<u64>();
        release();
    }
    total
}

/// TT from level 1 on, VT and VV from level 2 (below it they scan the mesh per vertex).
fn volume_sweeps(chf: &topomesh::Chf, repeat: usize) -> Sweeps {
    let nt = chf.num_tetrahedra() as u32;
    let nv = chf.num_vertices() as u32;
    let released = |ids, each: &dyn Fn(u32) -> u64| {
        released(ids, each, &|| {
            let _ = chf.release_mapped_pages();
        })
    };
    let tt = timed(repeat, &|| {
        released(0..nt, &|t| sum(chf.tetrahedron_tetrahedra(t).into_iter()))
    });
    if chf.level() < 2 {
        return sweeps("per_element", [("TT", tt)]);
    }
    let vt = timed(repeat, &|| {
        released(0..nv, &|v| sum(chf.vertex_tetrahedra(v)))
    });
    let vv = timed(repeat, &|| {
        released(0..nv, &|v| sum(chf.vertex_vertices(v)))
    });
    sweeps("per_element", [("TT", tt), ("VT", vt), ("VV", vv)])
}

fn print(out: &mut Out, b: &Bench) -> io::Result<()> {
    let (one, many, unit) = match b.kind {
        "volume" => ("tetrahedron", "tetrahedra", "tetrahedron"),
        _ => ("triangle", "triangles", "triangle"),
    };
    let elements = count(b.elements as u64, one, many);
    writeln!(out, "{}: {elements}, median of {}", b.file, b.repeat)?;
    let n = b.elements.max(1) as f64;
    for l in &b.levels {
        let t = l.build;
        write!(
            out,
            "build level {}: {:8.2} ms  {:6.1} ns/{unit}  {:6.2} bytes/{unit}",
            l.level,
            t.median * 1e3,
            t.median * 1e9 / n,
            l.topology_bytes as f64 / n
        )?;
        spread(out, t)?;
        writeln!(out)?;
        if let Some(s) = &l.sweeps {
            let label = if s.method == "bulk" {
                "bulk sweeps"
            } else {
                "sweeps"
            };
            let parts: Vec<String> = s
                .relations
                .iter()
                .map(|r| format!("{} {:.2} ms", r.relation, r.seconds.median * 1e3))
                .collect();
            writeln!(out, "  {label}: {}", parts.join(", "))?;
        }
    }
    Ok(())
}

/// `  (min .. max ms)` after a median, under `--verbose`.
fn spread(out: &mut Out, t: Timing) -> io::Result<()> {
    if verbose() {
        write!(out, "  ({:.2} .. {:.2} ms)", t.min * 1e3, t.max * 1e3)?;
    }
    Ok(())
}
