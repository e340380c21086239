//! Level files: what mapping buys. On bunny00-sub3 (4.8M triangles, from
//! $TOPOMESH_MESH_DIR or the mesh cache; a generated 4.8M-triangle torus when it is
//! absent), at level 2: `open` mapped and trusted plus the first VV query, against building
//! from the arrays and against a loaded open; then a full VV sweep on the mapped file
//! (in the page cache) against the same sweep on the built structure.

mod common;

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::PathBuf;
use topomesh::levelfile::{OpenOptions, Verify};
use topomesh::{BuildOptions, Che};

struct Input {
    triangles: Vec<[u32; 3]>,
    n_vertices: usize,
    path: PathBuf,
}

fn input() -> Input {
    let (triangles, n_vertices) =
        match topomesh::io::read(&common::mesh_dir().join("bunny00-sub3.off")) {
            Ok(data) => {
                let n = data.num_vertices();
                (data.triangles, n)
            }
            Err(_) => {
                let t = topomesh::generate::torus(2000, 1200);
                (t.triangles, t.positions.len())
            }
        };
    let path = std::env::temp_dir().join(format!("topomesh-bench-{}.che", std::process::id()));
    Input {
        triangles,
        n_vertices,
        path,
    }
}

fn build(input: &Input) -> Che {
    Che::from_triangles(
        &input.triangles,
        input.n_vertices,
        &[],
        BuildOptions::level(2),
    )
    .unwrap()
}

fn first_vv(che: &Che) -> u64 {
    che.vertex_vertices(0).map(u64::from).sum()
}

fn sweep_vv(che: &Che) -> u64 {
    (0..che.num_vertices() as u32)
        .flat_map(|v| che.vertex_vertices(v))
        .fold(0u64, |a, x| a + u64::from(x))
}

fn open(c: &mut Criterion) {
    let input = input();
    let built = build(&input);
    built.save(&input.path).unwrap();
    let mut group = c.benchmark_group("levelfile/open+VV");
    group.sample_size(10);
    group.bench_function("build", |b| {
        b.iter(|| first_vv(&build(&input)));
    });
    for (name, options) in [
        ("mapped-trusted", OpenOptions::mapped(Verify::Trusted)),
        ("mapped-checksums", OpenOptions::mapped(Verify::Checksums)),
        ("mapped-full", OpenOptions::mapped(Verify::Full)),
        ("loaded-trusted", OpenOptions::loaded(Verify::Trusted)),
        ("loaded-full", OpenOptions::loaded(Verify::Full)),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| first_vv(&Che::open(black_box(&input.path), options).unwrap()));
        });
    }
    group.finish();

    let mapped = Che::open(&input.path, OpenOptions::mapped(Verify::Trusted)).unwrap();
    assert_eq!(sweep_vv(&mapped), sweep_vv(&built));
    let mut group = c.benchmark_group("levelfile/sweep-VV");
    group.sample_size(10);
    group.bench_function("in-memory", |b| b.iter(|| sweep_vv(black_box(&built))));
    group.bench_function("mapped", |b| b.iter(|| sweep_vv(black_box(&mapped))));
    group.finish();
    drop(mapped);
    let _ = std::fs::remove_file(&input.path);
}

criterion_group!(benches, open);
criterion_main!(benches);
