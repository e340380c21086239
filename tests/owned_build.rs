//! The builds from arrays handed over (`Che::from_vecs`, `Chf::from_vecs`) equal the builds
//! from borrowed arrays, every array and the report, on meshes that need every repair, with
//! and without the weld, at every level; and they refuse what the borrowed builds refuse.

mod che_common;
mod chf_common;

use che_common::{che_n, surfaces};
use chf_common::volumes;
use topomesh::{BuildOptions, Che, Chf, ErrorKind, chf};

#[test]
fn surfaces_built_from_vecs_equal_the_borrowed_builds() {
    for (tris, positions) in surfaces() {
        let n = che_n(&tris, &positions);
        for level in 0..=3 {
            for weld in [0.0, 1e-9] {
                if weld > 0.0 && positions.is_empty() {
                    continue;
                }
                let options = BuildOptions {
                    weld_tolerance: weld,
                    ..BuildOptions::level(level)
                };
                let borrowed = Che::from_triangles(&tris, n, &positions, options).unwrap();
                let owned = Che::from_vecs(tris.clone(), n, positions.clone(), options).unwrap();
                assert_eq!(
                    format!("{owned:?}"),
                    format!("{borrowed:?}"),
                    "level {level}"
                );
            }
        }
    }
}

#[test]
fn volumes_built_from_vecs_equal_the_borrowed_builds() {
    for mesh in volumes() {
        let n = mesh.positions.len();
        for level in 0..=3 {
            for positions in [mesh.positions.clone(), Vec::new()] {
                let options = chf::BuildOptions::level(level);
                let borrowed = Chf::from_tetrahedra(&mesh.tets, n, &positions, options).unwrap();
                let owned = Chf::from_vecs(mesh.tets.clone(), n, positions, options).unwrap();
                assert_eq!(
                    format!("{owned:?}"),
                    format!("{borrowed:?}"),
                    "level {level}"
                );
            }
        }
    }
}

#[test]
fn builds_from_vecs_refuse_what_the_borrowed_builds_refuse() {
    let tris = vec![[0, 1, 2], [0, 2, 7]];
    let e = Che::from_vecs(tris, 4, Vec::new(), BuildOptions::level(2)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    assert!(
        e.message.contains("triangle 1, corner 2: vertex 7"),
        "{}",
        e.message
    );
    let tets = vec![[0, 1, 2, 3], [0, 1, 2, 9]];
    let e = Chf::from_vecs(tets, 5, Vec::new(), chf::BuildOptions::level(1)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    assert!(
        e.message.contains("tetrahedron 1, corner 3: vertex 9"),
        "{}",
        e.message
    );
    let strict = BuildOptions {
        strict: true,
        ..BuildOptions::level(1)
    };
    let pinch = vec![[0, 1, 2], [0, 1, 3], [0, 1, 4]];
    let e = Che::from_vecs(pinch, 5, Vec::new(), strict).unwrap_err();
    assert_eq!(e.kind, ErrorKind::NonManifold);
}
