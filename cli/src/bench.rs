//! `topomesh bench`: the median time of the build of every level and of full sweeps of the
//! relations, with the topology's bytes per element.

use crate::input::{build_surface, build_volume, load};
use crate::progress::Progress;
use std::hint::black_box;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, Che, Error, chf};

#[derive(clap::Args)]
pub struct BenchOptions {
    file: Option<PathBuf>,
    /// Repetitions (the median is printed).
    #[arg(long, default_value_t = 5)]
    repeat: usize,
    /// Threads for the build (0: as many as the machine runs at once).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

impl BenchOptions {
    /// At least one repetition, so that there is a median.
    fn repeat(&self) -> usize {
        self.repeat.max(1)
    }
}

pub fn run(options: &BenchOptions) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let (name, data) = load(options.file.as_deref(), &progress)?;
    drop(progress);
    if data.is_volume() {
        bench_volume(&name, &data, options)?;
    } else {
        bench_surface(&name, &data, options)?;
    }
    Ok(ExitCode::SUCCESS)
}

fn bench_surface(name: &str, data: &MeshData, options: &BenchOptions) -> Result<(), Error> {
    let repeat = options.repeat();
    let n = data.triangles.len();
    println!("{name}: {n} triangles, median of {repeat}");
    for level in 0..=3u8 {
        let build = BuildOptions {
            level,
            strict: false,
            threads: options.threads,
            weld_tolerance: options.weld,
        };
        let (che, secs) = timed_builds(repeat, || build_surface(data, build))?;
        build_line(level, secs, n, che.memory_bytes().topology, "triangle");
        if level >= 1 {
            surface_sweeps(&che, repeat);
        }
    }
    Ok(())
}

fn bench_volume(name: &str, data: &MeshData, options: &BenchOptions) -> Result<(), Error> {
    let repeat = options.repeat();
    let n = data.tetrahedra.len();
    println!("{name}: {n} tetrahedra, median of {repeat}");
    for level in 0..=3u8 {
        let build = chf::BuildOptions {
            level,
            strict: false,
            threads: options.threads,
            weld_tolerance: options.weld,
        };
        let (chf, secs) = timed_builds(repeat, || build_volume(data, build))?;
        build_line(level, secs, n, chf.memory_bytes().topology, "tetrahedron");
        if level >= 2 {
            volume_sweeps(&chf, repeat);
        }
    }
    Ok(())
}

/// Builds `repeat` times; the last structure and the median time.
fn timed_builds<T>(
    repeat: usize, mut build: impl FnMut() -> Result<T, Error>,
) -> Result<(T, f64), Error> {
    let mut times = Vec::with_capacity(repeat);
    let mut last = None;
    for _ in 0..repeat {
        let start = Instant::now();
        last = Some(build()?);
        times.push(start.elapsed().as_secs_f64());
    }
    Ok((last.expect("repeat >= 1"), median(times)))
}

fn build_line(level: u8, secs: f64, elements: usize, topology: usize, unit: &str) {
    let n = elements.max(1) as f64;
    println!(
        "build level {level}: {:8.2} ms  {:6.1} ns/{unit}  {:6.2} bytes/{unit}",
        secs * 1e3,
        secs * 1e9 / n,
        topology as f64 / n
    );
}

/// The median time of `repeat` runs of `sweep` (its result kept from the optimiser).
fn timed(repeat: usize, sweep: &dyn Fn() -> u64) -> f64 {
    median(
        (0..repeat)
            .map(|_| {
                let start = Instant::now();
                black_box(sweep());
                start.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

fn median(mut times: Vec<f64>) -> f64 {
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

fn sum(ids: impl Iterator<Item = u32>) -> u64 {
    ids.map(u64::from).sum()
}

fn surface_sweeps(che: &Che, repeat: usize) {
    let nv = che.num_vertices() as u32;
    let nt = che.num_triangles() as u32;
    if che.level() < 2 {
        // Per-vertex queries scan below level 2: sweep with the bulk calls instead.
        let csr = |c: topomesh::che::Csr| sum(c.indices.into_iter());
        let vv = timed(repeat, &|| csr(che.all_vertex_vertices()));
        let vf = timed(repeat, &|| csr(che.all_vertex_triangles()));
        let ff = timed(repeat, &|| sum(che.all_triangle_triangles().into_iter()));
        sweep_line("  bulk sweeps", [("VV", vv), ("VF", vf), ("FF", ff)]);
        return;
    }
    let vv = timed(
        repeat,
        &|| sum((0..nv).flat_map(|v| che.vertex_vertices(v))),
    );
    let vf = timed(repeat, &|| {
        sum((0..nv).flat_map(|v| che.vertex_triangles(v)))
    });
    let ff = timed(repeat, &|| {
        sum((0..nt).flat_map(|t| che.triangle_triangles(t)))
    });
    sweep_line("  sweeps", [("VV", vv), ("VF", vf), ("FF", ff)]);
}

fn volume_sweeps(chf: &topomesh::Chf, repeat: usize) {
    let nt = chf.num_tetrahedra() as u32;
    let nv = chf.num_vertices() as u32;
    let tt = timed(repeat, &|| {
        sum((0..nt).flat_map(|x| chf.tetrahedron_tetrahedra(x)))
    });
    let vt = timed(repeat, &|| {
        sum((0..nv).flat_map(|v| chf.vertex_tetrahedra(v)))
    });
    let vv = timed(
        repeat,
        &|| sum((0..nv).flat_map(|v| chf.vertex_vertices(v))),
    );
    sweep_line("  sweeps", [("TT", tt), ("VT", vt), ("VV", vv)]);
}

/// `label: VV <t> ms, VF <t> ms, FF <t> ms` (the three sweeps, in milliseconds).
fn sweep_line(label: &str, times: [(&str, f64); 3]) {
    let parts: Vec<String> = times
        .iter()
        .map(|(name, secs)| format!("{name} {:.2} ms", secs * 1e3))
        .collect();
    println!("{label}: {}", parts.join(", "));
}
