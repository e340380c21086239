//! Pathological inputs, each with its exact summary and build report.

mod che_common;

use che_common::check_all;
use topomesh::{BuildOptions, Che, ErrorKind, Summary};

fn build(tris: &[[u32; 3]], n: usize) -> Che {
    check_all(tris, n, &[0, 1, 2])
}

/// (V, E, F, boundary edges, curves, components, isolated, chi, genus, orientable, manifold)
type Shape = (u64, u64, u64, u64, u64, u64, u64, i64, i64, bool, bool);

fn shape(s: &Summary) -> Shape {
    (
        s.vertices,
        s.edges,
        s.triangles,
        s.boundary_edges,
        s.boundary_curves,
        s.components,
        s.isolated_vertices,
        s.euler_characteristic,
        s.genus,
        s.orientable,
        s.manifold,
    )
}

fn tetrahedron(a: u32, b: u32, c: u32, d: u32) -> Vec<[u32; 3]> {
    vec![[a, b, c], [a, d, b], [b, d, c], [a, c, d]]
}

/// A strip of `n` quads, its two ends glued with a half twist.
fn moebius(n: u32) -> Vec<[u32; 3]> {
    let (top, bottom) = (|i: u32| i, |i: u32| n + i);
    let mut tris = Vec::new();
    for i in 0..n {
        let (t0, b0) = (top(i), bottom(i));
        let (t1, b1) = if i + 1 < n {
            (top(i + 1), bottom(i + 1))
        } else {
            (bottom(0), top(0))
        };
        tris.push([t0, b0, b1]);
        tris.push([t0, b1, t1]);
    }
    tris
}

/// An `m` by `n` grid with rows glued straight and columns glued with a reflection.
fn klein(m: u32, n: u32) -> Vec<[u32; 3]> {
    let id = |i: u32, j: u32| {
        if j == n {
            (m - i % m) % m
        } else {
            j * m + i % m
        }
    };
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    tris
}

#[test]
fn moebius_strip() {
    let che = build(&moebius(6), 12);
    let s = che.summary();
    assert_eq!(shape(&s), (12, 24, 12, 12, 1, 1, 0, 0, -1, false, true));
    let r = che.report();
    assert_eq!(r.non_orientable_components, 1);
    assert_eq!(r.non_orientable_examples, vec![0]);
    assert_eq!(r.seam_edges, 1);
    assert_eq!(
        r.split_vertices, 0,
        "a seam does not make the input non-manifold"
    );
    assert_eq!(che.seam_half_edges().len(), 2);
}

#[test]
fn klein_bottle() {
    let che = build(&klein(5, 5), 25);
    let s = che.summary();
    assert_eq!(shape(&s), (25, 75, 50, 0, 0, 1, 0, 0, -1, false, true));
    assert_eq!(che.report().non_orientable_components, 1);
    assert!(che.report().seam_edges >= 1);
    assert_eq!(che.report().split_vertices, 0);
}

#[test]
fn two_triangles_sharing_a_vertex() {
    let che = build(&[[0, 1, 2], [0, 3, 4]], 5);
    assert_eq!(
        shape(&che.summary()),
        (5, 6, 2, 6, 1, 1, 0, 1, -1, true, false)
    );
    let r = che.report();
    assert_eq!((r.split_vertices, r.added_vertices), (1, 1));
    assert_eq!(r.split_vertex_examples, vec![0]);
    assert_eq!(che.num_vertices(), 6);
    assert_eq!(che.vertex_origin(5), 0);
}

#[test]
fn three_triangles_on_one_edge() {
    let che = build(&[[0, 1, 2], [1, 0, 3], [0, 1, 4]], 5);
    assert_eq!(
        shape(&che.summary()),
        (5, 7, 3, 6, 1, 1, 0, 1, -1, true, false)
    );
    let r = che.report();
    assert_eq!(r.non_manifold_edges, 1);
    assert_eq!(r.non_manifold_edge_examples, vec![[0, 1]]);
    assert_eq!(r.split_vertices, 2);
    assert_eq!(r.added_vertices, 4);
    assert_eq!(che.non_manifold_half_edges().len(), 3);
    let strict = Che::from_triangles(
        &[[0, 1, 2], [1, 0, 3], [0, 1, 4]],
        5,
        &[],
        BuildOptions {
            level: 2,
            strict: true,
            ..BuildOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(strict.kind, ErrorKind::NonManifold);
    assert!(
        strict.message.contains("(0, 1)") && strict.message.contains("0, 1, 2"),
        "{}",
        strict.message
    );
}

#[test]
fn closed_surfaces_touching_at_an_edge() {
    let mut tris = tetrahedron(0, 1, 2, 3);
    tris.extend(tetrahedron(0, 1, 4, 5).iter().map(|t| [t[0], t[2], t[1]]));
    let che = build(&tris, 6);
    assert_eq!(
        shape(&che.summary()),
        (6, 11, 8, 0, 0, 1, 0, 3, -1, true, false)
    );
    assert_eq!(che.report().non_manifold_edges, 1);
    assert_eq!(che.report().split_vertices, 2);
}

#[test]
fn closed_surfaces_touching_at_a_vertex() {
    let mut tris = tetrahedron(0, 1, 2, 3);
    tris.extend(tetrahedron(0, 4, 5, 6));
    let che = build(&tris, 7);
    assert_eq!(
        shape(&che.summary()),
        (7, 12, 8, 0, 0, 1, 0, 3, -1, true, false)
    );
    let r = che.report();
    assert_eq!(
        (r.non_manifold_edges, r.split_vertices, r.added_vertices),
        (0, 1, 1)
    );
    let strict = Che::from_triangles(
        &tris,
        7,
        &[],
        BuildOptions {
            level: 1,
            strict: true,
            ..BuildOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(strict.kind, ErrorKind::NonManifold);
    assert!(strict.message.contains("vertex 0"), "{}", strict.message);
}

#[test]
fn isolated_vertex() {
    let che = build(&[[0, 1, 2]], 4);
    assert_eq!(
        shape(&che.summary()),
        (4, 3, 1, 3, 1, 1, 1, 2, 0, true, true)
    );
    assert!(che.is_isolated_vertex(3));
    assert_eq!(che.vertex_vertices(3).count(), 0);
    assert!(!che.is_boundary_vertex(3));
}

#[test]
fn degenerate_and_duplicate_triangles() {
    // A tetrahedron with one face repeated and one degenerate triangle.
    let mut tris = tetrahedron(0, 1, 2, 3);
    tris.insert(1, [2, 2, 3]);
    tris.push([1, 2, 0]);
    let che = build(&tris, 4);
    let r = che.report();
    assert_eq!(
        (r.dropped_degenerate, r.degenerate_examples.clone()),
        (1, vec![1])
    );
    assert_eq!(
        (r.duplicate_triangles, r.duplicate_examples.clone()),
        (1, vec![[0, 5]])
    );
    assert_eq!(r.non_manifold_edges, 3);
    assert_eq!(
        shape(&che.summary()),
        (4, 6, 5, 0, 0, 1, 0, 3, -1, true, false)
    );
    assert_eq!(che.triangle_origins().unwrap(), &[0, 2, 3, 4, 5]);
    let strict = Che::from_triangles(
        &[[0, 1, 2], [0, 1, 2]],
        3,
        &[],
        BuildOptions {
            level: 1,
            strict: true,
            ..BuildOptions::default()
        },
    );
    assert_eq!(strict.unwrap_err().kind, ErrorKind::NonManifold);
}

#[test]
fn duplicate_with_one_non_manifold_edge() {
    // Triangle (0, 1, 2) twice, and a third triangle on edge {1, 2} only.
    let che = build(&[[0, 1, 2], [3, 2, 1], [0, 1, 2]], 4);
    let r = che.report();
    assert_eq!(
        (r.duplicate_triangles, r.duplicate_examples.clone()),
        (1, vec![[0, 2]])
    );
    assert_eq!(r.non_manifold_edges, 1);
}

#[test]
fn pillow_of_two_equal_triangles() {
    let che = build(&[[0, 1, 2], [0, 1, 2]], 3);
    assert_eq!(
        shape(&che.summary()),
        (3, 3, 2, 0, 0, 1, 0, 2, 0, true, true)
    );
    assert_eq!(che.report().duplicate_triangles, 1);
    assert_eq!(che.report().flipped_triangles, 1);
}

#[test]
fn empty_mesh() {
    let che = build(&[], 0);
    assert_eq!(
        shape(&che.summary()),
        (0, 0, 0, 0, 0, 0, 0, 0, 0, true, true)
    );
    let che = build(&[], 3);
    assert_eq!(
        shape(&che.summary()),
        (3, 0, 0, 0, 0, 0, 3, 3, 0, true, true)
    );
}

#[test]
fn single_triangle() {
    let che = build(&[[2, 0, 1]], 3);
    assert_eq!(
        shape(&che.summary()),
        (3, 3, 1, 3, 1, 1, 0, 1, 0, true, true)
    );
    assert_eq!(che.boundary_curve_vertices(0).unwrap(), vec![2, 0, 1]);
    assert!(che.report().is_clean());
}

#[test]
fn vertex_of_valence_2000() {
    let n = 2000u32;
    let mut tris: Vec<[u32; 3]> = (0..n).map(|i| [0, 1 + i, 1 + (i + 1) % n]).collect();
    let che = Che::from_triangles(&tris, n as usize + 1, &[], BuildOptions::level(3)).unwrap();
    assert_eq!(
        shape(&che.summary()),
        (2001, 4000, 2000, 2000, 1, 1, 0, 1, 0, true, true)
    );
    let ring: Vec<u32> = che.vertex_vertices(0).collect();
    assert_eq!(ring.len(), 2000);
    // Closed by a second apex: a bipyramid, every star in rotation order.
    tris.extend((0..n).map(|i| [n + 1, 1 + (i + 1) % n, 1 + i]));
    let che = check_all(&tris, n as usize + 2, &[2]);
    assert_eq!(
        shape(&che.summary()),
        (2002, 6000, 4000, 0, 0, 1, 0, 2, 0, true, true)
    );
    let ring: Vec<u32> = che.vertex_vertices(0).collect();
    let start = ring.iter().position(|&x| x == 1).unwrap();
    let expected: Vec<u32> = (1..=n).collect();
    let mut rotated = ring.clone();
    rotated.rotate_left(start);
    assert_eq!(rotated, expected);
}

#[test]
fn index_out_of_range() {
    let err =
        Che::from_triangles(&[[0, 1, 2], [1, 2, 7]], 4, &[], BuildOptions::default()).unwrap_err();
    assert_eq!(err.kind, ErrorKind::OutOfRange);
    assert!(
        err.message.contains("triangle 1") && err.message.contains("vertex 7"),
        "{}",
        err.message
    );
    let err = Che::from_flat(&[0, 1], 3, &[], BuildOptions::default()).unwrap_err();
    assert_eq!(err.kind, ErrorKind::InvalidInput);
    let err =
        Che::from_triangles(&[], 3, &[glam::DVec3::ZERO], BuildOptions::default()).unwrap_err();
    assert_eq!(err.kind, ErrorKind::InvalidInput);
    let err = Che::from_triangles(&[], 3, &[], BuildOptions::level(4)).unwrap_err();
    assert_eq!(err.kind, ErrorKind::OutOfRange);
    let err =
        Che::from_triangles(&[], u32::MAX as usize, &[], BuildOptions::default()).unwrap_err();
    assert_eq!(err.kind, ErrorKind::TooLarge);
}

#[test]
fn build_level_goes_up_and_down() {
    let s = topomesh::generate::torus(4, 3);
    let mut che = Che::from_triangles(
        &s.triangles,
        s.positions.len(),
        &s.positions,
        BuildOptions::level(0),
    )
    .unwrap();
    let m0 = che.memory_bytes();
    assert_eq!(m0.topology, 4 * 3 * s.triangles.len());
    che.build_level(1).unwrap();
    assert_eq!(che.memory_bytes().topology, 4 * 6 * s.triangles.len());
    che.build_level(3).unwrap();
    assert_eq!(che.level(), 3);
    assert!(che.build_level(4).is_err());
    che.build_level(1).unwrap();
    assert_eq!(che.memory_bytes().topology, 4 * 6 * s.triangles.len());
    assert!(che.vertex_half_edges().is_none());
}

/// Everything a build produces that a thread count could change.
fn fingerprint(che: &Che) -> String {
    format!(
        "{:?}",
        (
            (
                che.half_edge_vertices(),
                che.opposites(),
                che.vertex_half_edges()
            ),
            (
                che.edge_rank_directory(),
                che.edge_half_edges(),
                che.curve_half_edges()
            ),
            (che.num_vertices(), che.num_edges()),
            (che.vertex_origins(), che.triangle_origins()),
            (che.non_manifold_half_edges(), che.seam_half_edges()),
            che.report(),
        )
    )
}

#[test]
fn build_is_the_same_on_any_number_of_threads() {
    // Large enough for the matching to share its pairs among threads, and damaged all over:
    // triangles glued to an edge of others (non-manifold edges, duplicates among them) or
    // a vertex (non-manifold vertices), random and degenerate ones, and every third
    // triangle flipped (orientation). The report's examples must come in the same order.
    let s = topomesh::generate::torus(320, 160);
    let n = s.positions.len();
    let mut rng = che_common::Rng(99);
    let mut tris: Vec<[u32; 3]> = s
        .triangles
        .iter()
        .enumerate()
        .map(|(t, &[a, b, c])| if t % 3 == 0 { [a, c, b] } else { [a, b, c] })
        .collect();
    for k in 0..1500 {
        let t = s.triangles[rng.below(s.triangles.len())];
        let mut extra = [0; 3].map(|_| rng.below(n) as u32);
        extra[..2 - k % 3].copy_from_slice(&t[..2 - k % 3]);
        tris.push(extra);
    }
    let t = tris[17];
    tris.push(t);
    tris.push([5, 5, 9]);
    tris.insert(100, [3, 8, 3]);
    assert!(3 * tris.len() > 1 << 18);
    for level in 0..=3u8 {
        let build = |threads| {
            let options = BuildOptions {
                level,
                threads,
                ..BuildOptions::default()
            };
            Che::from_triangles(&tris, n, &s.positions, options).unwrap()
        };
        let one = build(1);
        let r = one.report();
        assert!(
            r.non_manifold_edges > 16
                && r.duplicate_triangles > 0
                && r.split_vertices > 0
                && r.flipped_triangles > 0
                && r.dropped_degenerate == 2,
            "the damage reaches every path: {r:?}"
        );
        let expected = fingerprint(&one);
        for threads in [2, 5] {
            assert!(
                fingerprint(&build(threads)) == expected,
                "level {level}, {threads} threads: not the single-threaded build"
            );
        }
        // Strict mode names the same first offenders.
        let strict = |threads| {
            let options = BuildOptions {
                level,
                threads,
                strict: true,
                memory_limit_bytes: 0,
                ..BuildOptions::default()
            };
            Che::from_triangles(&tris, n, &s.positions, options)
                .unwrap_err()
                .message
        };
        let expected = strict(1);
        for threads in [2, 5] {
            assert_eq!(
                strict(threads),
                expected,
                "level {level}, {threads} threads"
            );
        }
    }
}
