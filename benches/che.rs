//! CHE build and sweeps: levels 1, 2 and 3 from arrays, full VV, VF, FF and EF sweeps,
//! the queries below level 2 that compute what their level lacks, edits at every level,
//! on a generated torus of 1.2M triangles and on real meshes found in
//! $TOPOMESH_MESH_DIR or the default mesh cache (see scripts/fetch-meshes.sh). Prints bytes per triangle per level.

mod common;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use topomesh::{BuildOptions, Che};

struct Input {
    name: String,
    triangles: Vec<[u32; 3]>,
    n_vertices: usize,
}

fn inputs() -> Vec<Input> {
    let mut out = Vec::new();
    let torus = topomesh::generate::torus(1000, 600);
    out.push(Input {
        name: "torus-1.2M".into(),
        n_vertices: torus.positions.len(),
        triangles: torus.triangles,
    });
    let dir = common::mesh_dir();
    for name in ["bunny00.off", "armadillo.off", "refined_elephant.off"] {
        let path = dir.join(name);
        if let Ok(data) = topomesh::io::read(&path) {
            out.push(Input {
                name: name.trim_end_matches(".off").into(),
                n_vertices: data.num_vertices(),
                triangles: data.triangles,
            });
        }
    }
    out
}

fn build(c: &mut Criterion) {
    for input in inputs() {
        let mut group = c.benchmark_group(format!("build/{}", input.name));
        group.sample_size(10);
        group.throughput(Throughput::Elements(input.triangles.len() as u64));
        for level in 1..=3u8 {
            let che = Che::from_triangles(
                &input.triangles,
                input.n_vertices,
                &[],
                BuildOptions::level(level),
            )
            .unwrap();
            let m = che.memory_bytes();
            let t = input.triangles.len() as f64;
            eprintln!(
                "{} level {level}: {:.3} topology bytes per triangle ({} V, {} E)",
                input.name,
                m.topology as f64 / t,
                che.num_vertices(),
                che.num_edges()
            );
            // One thread (the peers' condition) and the default, every thread.
            for (threads, on) in [(1, "one thread"), (0, "all threads")] {
                let id = BenchmarkId::new(format!("level, {on}"), level);
                group.bench_with_input(id, &level, |b, &level| {
                    b.iter(|| {
                        Che::from_triangles(
                            black_box(&input.triangles),
                            input.n_vertices,
                            &[],
                            BuildOptions {
                                level,
                                strict: false,
                                threads,
                                memory_limit_bytes: 0,
                                ..BuildOptions::default()
                            },
                        )
                        .unwrap()
                    })
                });
            }
        }
        group.finish();
    }
}

/// Small meshes, where a build's fixed costs show (a program that builds one part at a
/// time pays them per part): a 96-triangle torus at every level, one thread.
fn build_small(c: &mut Criterion) {
    let torus = topomesh::generate::torus(8, 6);
    let mut group = c.benchmark_group(format!("build/torus-{}", torus.triangles.len()));
    for level in 0..=3u8 {
        group.bench_with_input(BenchmarkId::new("level", level), &level, |b, &level| {
            b.iter(|| {
                let options = BuildOptions {
                    threads: 1,
                    ..BuildOptions::level(level)
                };
                let n = torus.positions.len();
                Che::from_triangles(black_box(&torus.triangles), n, &[], options).unwrap()
            })
        });
    }
    group.finish();
}

fn sweeps(c: &mut Criterion) {
    for input in inputs() {
        let che = Che::from_triangles(
            &input.triangles,
            input.n_vertices,
            &[],
            BuildOptions::level(2),
        )
        .unwrap();
        let nv = che.num_vertices() as u32;
        let nt = che.num_triangles() as u32;
        let ne = che.num_edges() as u32;
        let mut group = c.benchmark_group(format!("sweep/{}", input.name));
        group.sample_size(10);
        group.throughput(Throughput::Elements(input.triangles.len() as u64));
        group.bench_function("VV", |b| {
            b.iter(|| {
                (0..nv)
                    .flat_map(|v| che.vertex_vertices(v))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("VF", |b| {
            b.iter(|| {
                (0..nv)
                    .flat_map(|v| che.vertex_triangles(v))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("FF", |b| {
            b.iter(|| {
                (0..nt)
                    .flat_map(|t| che.triangle_triangles(t))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("EF", |b| {
            b.iter(|| {
                (0..ne)
                    .flat_map(|e| che.edge_triangles(e))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("VV raw arrays", |b| {
            let (v, o, vh) = (
                che.half_edge_vertices(),
                che.opposites().unwrap(),
                che.vertex_half_edges().unwrap(),
            );
            b.iter(|| {
                let mut sum = 0u64;
                for &start in vh {
                    if start == topomesh::NONE {
                        continue;
                    }
                    let mut h = start;
                    loop {
                        sum += v[topomesh::che::next(h) as usize] as u64;
                        let p = topomesh::che::prev(h);
                        let g = o[p as usize];
                        if g == topomesh::NONE {
                            sum += v[p as usize] as u64;
                            break;
                        }
                        if g == start {
                            break;
                        }
                        h = g;
                    }
                }
                sum
            })
        });
        group.bench_function("VV bulk", |b| {
            b.iter(|| che.all_vertex_vertices().unwrap().indices.len())
        });
        group.finish();
    }
}

/// The queries below level 2 that compute what their level lacks (each O(T)): a boundary
/// curve, a vertex star and its edges, at levels 0 and 1, on a grid of about 200k
/// triangles (one boundary curve).
fn below_level_2(c: &mut Criterion) {
    let grid = topomesh::generate::grid(300, 330);
    let n = grid.positions.len();
    let mut group = c.benchmark_group("below-level-2/grid-198k");
    group.sample_size(10);
    group.throughput(Throughput::Elements(grid.triangles.len() as u64));
    for level in [0u8, 1] {
        let che = Che::from_triangles(&grid.triangles, n, &[], BuildOptions::level(level)).unwrap();
        group.bench_function(BenchmarkId::new("boundary curve", level), |b| {
            b.iter(|| black_box(che.boundary_curve_vertices(0).unwrap().len()))
        });
        group.bench_function(BenchmarkId::new("VE", level), |b| {
            b.iter(|| black_box(che.vertex_edges(black_box(45_000)).count()))
        });
    }
    group.finish();
}

/// Edits at every level on a grid of about 200k triangles, after a first edit (which
/// computes, below level 2, the tables the level does not store): each operation costs
/// the stars it touches at every level, so the three levels should time alike.
fn edits(c: &mut Criterion) {
    let grid = topomesh::generate::grid(300, 330);
    let n = grid.positions.len();
    let mut group = c.benchmark_group("edits/grid-198k");
    for level in [0u8, 1, 2] {
        let options = BuildOptions::level(level);
        let mut che = Che::from_triangles(&grid.triangles, n, &grid.positions, options).unwrap();
        che.split_triangle(0, None).unwrap();
        let mut i = 0u32;
        group.bench_function(BenchmarkId::new("split_triangle", level), |b| {
            b.iter(|| {
                i = i.wrapping_add(7919);
                black_box(che.split_triangle(i % 190_000, None).unwrap())
            })
        });
        group.bench_function(BenchmarkId::new("flip_edge", level), |b| {
            b.iter(|| {
                i = i.wrapping_add(7919);
                black_box(che.flip_edge(i % 290_000).is_ok())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, build, build_small, sweeps, below_level_2, edits);
criterion_main!(benches);
