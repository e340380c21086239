//! The streaming build (`levelfile::save_streamed`) writes, on clean input, the very file
//! an in-memory build and `Che::save` write, at levels 1 and 2, whatever the block size;
//! on input that needs a repair, or an order that leaves too much open, it is an error
//! naming the place, and no file (nor a temporary one) is left.

mod che_common;
mod stream_common;

use che_common::{Rng, perturb, surfaces};
use glam::DVec3;
use std::path::{Path, PathBuf};
use topomesh::SliceSource;
use topomesh::che::SweepLimits;
use topomesh::generate::{grid, sphere, torus};
use topomesh::levelfile::{OpenOptions, StreamOptions, Verify, save_streamed};
use topomesh::{BuildOptions, Che, ErrorKind};

fn folder(tag: &str) -> PathBuf {
    stream_common::folder("stream", tag)
}

fn options(level: u8, block_triangles: usize) -> StreamOptions {
    StreamOptions {
        level,
        limits: SweepLimits {
            block_triangles,
            ..SweepLimits::default()
        },
    }
}

fn streamed(
    dir: &Path, tris: &[[u32; 3]], n: usize, pos: &[DVec3], o: StreamOptions,
) -> topomesh::error::Result<Vec<u8>> {
    let path = dir.join("streamed.che");
    let source = SliceSource {
        elements: tris,
        n_vertices: n,
        positions: pos,
    };
    save_streamed(&source, &path, o)?;
    Ok(std::fs::read(&path).unwrap())
}

#[test]
fn clean_surfaces_stream_to_the_file_a_build_saves() {
    let dir = folder("same");
    let mut meshes = vec![torus(7, 5), sphere(6, 4), grid(5, 3), torus(60, 40)];
    meshes.push(topomesh::generate::Surface {
        positions: Vec::new(),
        ..grid(2, 2)
    });
    for s in &meshes {
        let n = s.positions.len().max(9);
        for level in 1..=2 {
            let built =
                Che::from_triangles(&s.triangles, n, &s.positions, BuildOptions::level(level));
            let path = dir.join("built.che");
            built.unwrap().save(&path).unwrap();
            let want = std::fs::read(&path).unwrap();
            for block in [1, 3, 64, 1 << 20] {
                let got =
                    streamed(&dir, &s.triangles, n, &s.positions, options(level, block)).unwrap();
                assert!(
                    got == want,
                    "level {level}, blocks of {block}: the files differ"
                );
            }
            let full = OpenOptions::mapped(Verify::Full);
            let che = Che::open(dir.join("streamed.che"), full).unwrap();
            assert_eq!(che.num_triangles(), s.triangles.len());
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The error's kind and words, and the folder left empty.
fn refused(tris: &[[u32; 3]], n: usize, o: StreamOptions, kind: ErrorKind, words: &[&str]) {
    let dir = folder("refused");
    let result = streamed(&dir, tris, n, &[], o);
    stream_common::assert_refused(result, &dir, kind, words);
}

#[test]
fn input_that_needs_a_repair_is_refused_and_nothing_is_left() {
    let nm = ErrorKind::NonManifold;
    let o = |block| options(2, block);
    refused(
        &[[0, 1, 2], [0, 2, 2]],
        3,
        o(8),
        nm,
        &["triangle 1 is degenerate"],
    );
    refused(
        &[[0, 1, 2], [0, 2, 9]],
        4,
        o(8),
        ErrorKind::OutOfRange,
        &["triangle 1, corner 2: vertex 9"],
    );
    let fin = [[0, 1, 2], [1, 0, 3], [0, 1, 4]];
    // All three in one block: the sweep sees them; a pair closed before the third comes:
    // the star of the edge's ends does.
    refused(&fin, 5, o(8), nm, &["vertices 0 and 1 has 3 triangles"]);
    for block in [1, 2] {
        refused(&fin, 5, o(block), nm, &["not one fan"]);
    }
    refused(
        &[[0, 1, 2], [0, 1, 3]],
        4,
        o(8),
        nm,
        &["triangles 0 and 1 run their edge"],
    );
    // Two pairs on one edge, one block each: only the star shows it.
    let book = [[0, 1, 2], [1, 0, 3], [0, 1, 4], [1, 0, 5]];
    refused(&book, 6, o(2), nm, &["not one fan"]);
    // Two triangles that share a vertex alone.
    refused(
        &[[0, 1, 2], [0, 3, 4]],
        5,
        o(8),
        nm,
        &["vertex 0", "not one fan"],
    );
    let tight = StreamOptions {
        level: 2,
        limits: SweepLimits {
            block_triangles: 4,
            max_open: 5,
        },
    };
    let s = torus(12, 10);
    refused(
        &s.triangles,
        s.positions.len(),
        tight,
        ErrorKind::TooLarge,
        &["open after triangle"],
    );
    refused(
        &s.triangles,
        s.positions.len(),
        options(3, 8),
        ErrorKind::InvalidInput,
        &["level 3"],
    );
}

/// On any soup (relabelled, shuffled, flipped, with the repairs of every kind), the
/// streaming build either refuses and leaves nothing, or writes the in-memory build's file
/// byte for byte: it never accepts what the in-memory build would repair.
#[test]
fn any_soup_streams_to_the_built_file_or_is_refused() {
    let dir = folder("soups");
    let mut rng = Rng(17);
    let mut tally = stream_common::Tally::default();
    for (tris, _) in surfaces() {
        let n = che_common::che_n(&tris, &[]);
        for round in 0..12 {
            let flip = [0.0, 0.05, 0.5][round % 3];
            let soup = perturb(&tris, n, &mut rng, flip);
            let path = dir.join("built.che");
            let built = Che::from_triangles(&soup, n, &[], BuildOptions::level(2)).unwrap();
            built.save(&path).unwrap();
            let block = [1, 5, 1 << 20][round % 3];
            let _ = std::fs::remove_file(dir.join("streamed.che"));
            let got = streamed(&dir, &soup, n, &[], options(2, block));
            tally.record(got, &std::fs::read(&path).unwrap(), &dir, round as u64);
        }
    }
    tally.check();
    let _ = std::fs::remove_dir_all(&dir);
}
