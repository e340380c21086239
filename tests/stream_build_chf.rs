//! The streaming build of a volume (`levelfile::save_streamed_chf`) writes, on input that
//! needs no repair, the very file an in-memory build at level 1 and `Chf::save` write,
//! whatever the block size and however few records its edge census may hold; on input that
//! needs a repair, or an order that leaves too much open, it is an error naming the place,
//! and no file (nor a temporary one) is left.

mod chf_common;
mod stream_common;

use chf_common::{Mesh, Rng, cube, scramble, volumes};
use glam::DVec3;
use std::path::{Path, PathBuf};
use topomesh::SliceSource;
use topomesh::chf::{self, Chf, SweepLimits};
use topomesh::levelfile::{OpenOptions, Verify, save_streamed_chf};
use topomesh::{ErrorKind, generate};

fn folder(tag: &str) -> PathBuf {
    stream_common::folder("stream-chf", tag)
}

/// Blocks of `block` tetrahedra, the census's records held to the least it takes.
fn limits(block: usize, small_census: bool) -> SweepLimits {
    SweepLimits {
        block_tetrahedra: block,
        census_bytes: if small_census { 0 } else { 1 << 30 },
        ..SweepLimits::default()
    }
}

fn streamed(
    dir: &Path, tets: &[[u32; 4]], n: usize, pos: &[DVec3], limits: SweepLimits,
) -> topomesh::error::Result<Vec<u8>> {
    let path = dir.join("streamed.chf");
    let source = SliceSource {
        elements: tets,
        n_vertices: n,
        positions: pos,
    };
    save_streamed_chf(&source, &path, limits)?;
    Ok(std::fs::read(&path).unwrap())
}

/// The bytes `Chf::save` writes after an in-memory build at level 1.
fn built(dir: &Path, tets: &[[u32; 4]], n: usize, pos: &[DVec3]) -> (Chf, Vec<u8>) {
    let chf = Chf::from_tetrahedra(tets, n, pos, chf::BuildOptions::level(1)).unwrap();
    let path = dir.join("built.chf");
    chf.save(&path).unwrap();
    (chf, std::fs::read(&path).unwrap())
}

/// Boxes with and without positions, some tetrahedra given inverted (the build flips them
/// back by the determinant), one large enough for the census to run in several rounds.
fn clean_volumes() -> Vec<Mesh> {
    let g = generate::cube_grid(22);
    let mut inverted = cube(3, 2, 2, true);
    for t in inverted.tets.iter_mut().step_by(3) {
        t.swap(0, 3);
    }
    vec![
        cube(2, 2, 1, false),
        cube(3, 1, 2, true),
        inverted,
        scramble(&cube(3, 3, 3, false), 5, 100),
        Mesh {
            tets: g.tetrahedra,
            positions: g.positions,
        },
    ]
}

#[test]
fn clean_volumes_stream_to_the_file_a_build_saves() {
    let dir = folder("same");
    for (k, mesh) in clean_volumes().iter().enumerate() {
        let n = mesh.n();
        let (chf, want) = built(&dir, &mesh.tets, n, &mesh.positions);
        // The oriented `V` is clean input without positions too.
        let oriented: Vec<[u32; 4]> = chf
            .half_face_vertices()
            .chunks_exact(4)
            .map(|q| [q[0], q[1], q[2], q[3]])
            .collect();
        let (bare, want_bare) = built(&dir, &oriented, n, &[]);
        for block in [1, 3, 64, 1 << 20] {
            for small in [false, true] {
                let l = limits(block, small);
                let got = streamed(&dir, &mesh.tets, n, &mesh.positions, l).unwrap();
                assert!(got == want, "mesh {k}, blocks of {block}: the files differ");
                let got = streamed(&dir, &oriented, n, &[], l).unwrap();
                assert!(
                    got == want_bare,
                    "mesh {k} without positions: the files differ"
                );
            }
        }
        let full = OpenOptions::mapped(Verify::Full);
        let opened = Chf::open(dir.join("streamed.chf"), full).unwrap();
        assert_eq!(opened.summary(), bare.summary(), "mesh {k}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_report_is_the_builds() {
    let dir = folder("report");
    let mesh = &clean_volumes()[2];
    let source = SliceSource {
        elements: &mesh.tets,
        n_vertices: mesh.n(),
        positions: &mesh.positions,
    };
    let path = dir.join("streamed.chf");
    let report = save_streamed_chf(&source, &path, SweepLimits::default()).unwrap();
    let (chf, _) = built(&dir, &mesh.tets, mesh.n(), &mesh.positions);
    assert_eq!(&report, chf.report());
    assert!(report.flipped_tetrahedra > 0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The error's kind and words, and the folder left empty.
fn refused(m: &Mesh, limits: SweepLimits, kind: ErrorKind, words: &[&str]) {
    let dir = folder("refused");
    let n = m.n().max(corners().len());
    let result = streamed(&dir, &m.tets, n, &m.positions, limits);
    stream_common::assert_refused(result, &dir, kind, words);
}

/// The corners of a unit tetrahedron and points around it.
fn corners() -> Vec<DVec3> {
    let p = DVec3::new;
    vec![
        p(0.0, 0.0, 0.0),
        p(1.0, 0.0, 0.0),
        p(0.0, 1.0, 0.0),
        p(0.0, 0.0, 1.0),
        p(1.0, 1.0, 1.0),
        p(-1.0, -1.0, -1.0),
        p(2.0, 0.0, 0.0),
        p(2.0, 1.0, 0.0),
        p(2.0, 0.0, 1.0),
        p(0.4, 0.4, 0.4),
        p(0.0, -1.0, 0.0),
        p(0.0, 0.0, -1.0),
    ]
}

/// `tets` over [`corners`], with their positions or none.
fn mesh(tets: &[[u32; 4]], positions: bool) -> Mesh {
    let mut p = corners();
    if !positions {
        p.clear();
    }
    Mesh {
        tets: tets.to_vec(),
        positions: p,
    }
}

#[test]
fn input_that_needs_a_repair_is_refused_and_nothing_is_left() {
    let nm = ErrorKind::NonManifold;
    let l = limits(8, false);
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 1, 1, 4]], true),
        l,
        nm,
        &["tetrahedron 1 is degenerate"],
    );
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 1, 2, 99]], true),
        l,
        ErrorKind::OutOfRange,
        &["tetrahedron 1, corner 3: vertex 99"],
    );
    // Flat: vertices 0, 1, 2 and 6 lie in one plane.
    refused(
        &mesh(&[[0, 1, 2, 6]], true),
        l,
        nm,
        &["tetrahedron 0 has no volume"],
    );
    // Three tetrahedra on the face (0, 1, 2): vertex 3 above it, 5 below, 9 above again.
    let three = [[0, 1, 2, 3], [0, 2, 1, 5], [0, 1, 2, 9]];
    refused(&mesh(&three, false), l, nm, &["has 3 tetrahedra"]);
    // A block each: the sweep closed the pair before the third came; the census sees it.
    refused(
        &mesh(&three, false),
        limits(1, false),
        nm,
        &["three tetrahedra or more"],
    );
    // The same tetrahedron twice, once each way round.
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 2, 1, 3]], false),
        l,
        nm,
        &["tetrahedra 0 and 1 have the same four vertices"],
    );
    // Two tetrahedra on both sides of a face, given the same way round, no positions to
    // flip one of them.
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 1, 2, 5]], false),
        l,
        nm,
        &["run their face", "the same way round"],
    );
    // Sharing only the edge (0, 1), whose ends then have stars in two pieces; only the
    // vertex 0.
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 1, 10, 11]], true),
        l,
        nm,
        &["around vertex 0 fall apart"],
    );
    refused(
        &mesh(&[[0, 1, 2, 3], [0, 6, 7, 8]], true),
        l,
        nm,
        &["around vertex 0 fall apart"],
    );
    let g = generate::cube_grid(6);
    let box6 = Mesh {
        tets: g.tetrahedra,
        positions: g.positions,
    };
    let tight = SweepLimits {
        block_tetrahedra: 4,
        max_open: 5,
        ..SweepLimits::default()
    };
    refused(
        &box6,
        tight,
        ErrorKind::TooLarge,
        &["open after tetrahedron"],
    );
}

/// On the damaged volumes of the build tests, shuffled and relabelled, the streaming build
/// either refuses and leaves nothing, or writes the in-memory build's file byte for byte:
/// it never accepts what the in-memory build would repair.
#[test]
fn any_soup_streams_to_the_built_file_or_is_refused() {
    let dir = folder("soups");
    let mut rng = Rng(29);
    let mut tally = stream_common::Tally::default();
    for mesh in volumes() {
        for round in 0..9u64 {
            let soup = scramble(&mesh, rng.next_u64(), [100, 90, 60][round as usize % 3]);
            let pos: &[DVec3] = if round % 2 == 0 { &soup.positions } else { &[] };
            let (_, want) = built(&dir, &soup.tets, soup.n(), pos);
            let block = [1, 5, 1 << 20][round as usize % 3];
            let _ = std::fs::remove_file(dir.join("streamed.chf"));
            let got = streamed(
                &dir,
                &soup.tets,
                soup.n(),
                pos,
                limits(block, round % 2 == 1),
            );
            tally.record(got, &want, &dir, round);
        }
    }
    tally.check();
    let _ = std::fs::remove_dir_all(&dir);
}
