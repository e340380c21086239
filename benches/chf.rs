//! CHF build and sweeps: levels 1, 2 and 3 from arrays, and full TT, VT, ET and VV sweeps,
//! on a generated box of 750k tetrahedra and on the TetGen meshes that
//! `scripts/fetch-tets.sh` makes in ${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}/tets
//! (knot1-16k, armadillo-101k, bunny00-1m). Prints bytes per tetrahedron per level.

mod common;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec3;
use std::hint::black_box;
use topomesh::{Chf, chf};

struct Input {
    name: String,
    tets: Vec<[u32; 4]>,
    positions: Vec<DVec3>,
}

/// A box of `n^3` unit cells, six positive tetrahedra each (Kuhn subdivision).
fn grid(n: u32) -> Input {
    let id = |i: u32, j: u32, k: u32| i + (n + 1) * (j + (n + 1) * k);
    let mut positions = Vec::new();
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                positions.push(DVec3::new(i as f64, j as f64, k as f64));
            }
        }
    }
    let mut tets = Vec::new();
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                for perm in [
                    [0, 1, 2],
                    [0, 2, 1],
                    [1, 0, 2],
                    [1, 2, 0],
                    [2, 0, 1],
                    [2, 1, 0],
                ] {
                    let mut p = [0u32; 3];
                    let mut t = [id(i, j, k); 4];
                    for (s, &axis) in perm.iter().enumerate() {
                        p[axis] = 1;
                        t[s + 1] = id(i + p[0], j + p[1], k + p[2]);
                    }
                    tets.push(t);
                }
            }
        }
    }
    Input {
        name: format!("box-{}k", tets.len() / 1000),
        tets,
        positions,
    }
}

fn inputs() -> Vec<Input> {
    let mut out = vec![grid(50)];
    let dir = common::mesh_dir();
    for name in ["knot1-16k.ele", "armadillo-101k.ele", "bunny00-1m.ele"] {
        let path = dir.join("tets").join(name);
        if let Ok(data) = topomesh::io::read(&path) {
            out.push(Input {
                name: name.trim_end_matches(".ele").into(),
                tets: data.tetrahedra,
                positions: data.positions,
            });
        }
    }
    out
}

fn build_chf(input: &Input, level: u8, threads: usize) -> Chf {
    let options = chf::BuildOptions {
        level,
        strict: false,
        threads,
        memory_limit_bytes: 0,
        ..chf::BuildOptions::default()
    };
    Chf::from_tetrahedra(
        &input.tets,
        input.positions.len(),
        &input.positions,
        options,
    )
    .unwrap()
}

fn build(c: &mut Criterion) {
    for input in inputs() {
        let mut group = c.benchmark_group(format!("chf build/{}", input.name));
        group.sample_size(10);
        group.throughput(Throughput::Elements(input.tets.len() as u64));
        for level in 1..=3u8 {
            let chf = build_chf(&input, level, 0);
            eprintln!(
                "{} level {level}: {:.2} topology bytes per tetrahedron ({} V, {} E, {} F)",
                input.name,
                chf.memory_bytes().topology as f64 / input.tets.len() as f64,
                chf.num_vertices(),
                chf.num_edges(),
                chf.num_faces()
            );
            // One thread (CGAL's condition) and the default, every thread.
            for (threads, on) in [(1, "one thread"), (0, "all threads")] {
                let id = BenchmarkId::new(format!("level, {on}"), level);
                group.bench_with_input(id, &level, |b, &level| {
                    b.iter(|| build_chf(black_box(&input), level, threads))
                });
            }
        }
        group.finish();
    }
}

/// Small meshes, where a build's fixed costs show (a program that builds one part at a
/// time pays them per part): the 48 tetrahedra of `grid(2)` at every level, one thread.
fn build_small(c: &mut Criterion) {
    let input = grid(2);
    let mut group = c.benchmark_group(format!("chf build/{}-tetrahedra", input.tets.len()));
    for level in 0..=3u8 {
        group.bench_with_input(BenchmarkId::new("level", level), &level, |b, &level| {
            b.iter(|| build_chf(black_box(&input), level, 1))
        });
    }
    group.finish();
}

fn sweeps(c: &mut Criterion) {
    for input in inputs() {
        let chf = build_chf(&input, 2, 0);
        let nv = chf.num_vertices() as u32;
        let nt = chf.num_tetrahedra() as u32;
        let ne = chf.num_edges() as u32;
        let mut group = c.benchmark_group(format!("chf sweep/{}", input.name));
        group.sample_size(10);
        group.throughput(Throughput::Elements(input.tets.len() as u64));
        group.bench_function("TT", |b| {
            b.iter(|| {
                (0..nt)
                    .flat_map(|t| chf.tetrahedron_tetrahedra(t))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("VT", |b| {
            b.iter(|| {
                (0..nv)
                    .flat_map(|v| chf.vertex_tetrahedra(v))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("ET", |b| {
            b.iter(|| {
                (0..ne)
                    .flat_map(|e| chf.edge_tetrahedra(e))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.bench_function("VV", |b| {
            b.iter(|| {
                (0..nv)
                    .flat_map(|v| chf.vertex_vertices(v))
                    .fold(0u64, |a, x| a + x as u64)
            })
        });
        group.finish();
    }
}

criterion_group!(benches, build, build_small, sweeps);
criterion_main!(benches);
