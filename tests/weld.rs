//! The weld before the builds (`BuildOptions::weld_tolerance`): a soup whose shared
//! corners were written as separate points that differ in their last bits, as an STL file
//! stores them, builds as the closed manifold it is with the weld and as loose triangles
//! (or tetrahedra) without it.

use glam::DVec3;
use topomesh::{BuildOptions, Che, Chf, ErrorKind, chf};

/// The octahedron as an STL-like soup: three corners per triangle, each its own vertex,
/// each coordinate moved by a few units in the last place.
fn octahedron_soup() -> (Vec<[u32; 3]>, Vec<DVec3>) {
    let corner = [
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
    ];
    let faces = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for (k, face) in faces.iter().enumerate() {
        let mut tri = [0; 3];
        for (i, &c) in face.iter().enumerate() {
            tri[i] = positions.len() as u32;
            positions.push(corner[c].to_array().map(|x| last_bits(x, k + i)).into());
        }
        triangles.push(tri);
    }
    (triangles, positions)
}

/// `x` moved by up to 3 units in the last place of 1, up or down by `k`.
fn last_bits(x: f64, k: usize) -> f64 {
    let units = (k % 4) as f64 * if k.is_multiple_of(2) { 1.0 } else { -1.0 };
    x + units * f64::EPSILON
}

#[test]
fn stl_soup_is_a_closed_manifold_with_the_weld() {
    let (triangles, positions) = octahedron_soup();
    let options = BuildOptions {
        weld_tolerance: 1e-9,
        ..BuildOptions::level(3)
    };
    let che = Che::from_triangles(&triangles, positions.len(), &positions, options).unwrap();
    che.validate().unwrap();
    let s = che.summary();
    assert_eq!((s.vertices, s.edges, s.triangles), (6, 12, 8));
    assert_eq!(
        (s.boundary_edges, s.boundary_curves, s.isolated_vertices),
        (0, 0, 0)
    );
    assert_eq!((s.euler_characteristic, s.genus, s.components), (2, 0, 1));
    assert!(s.manifold && s.orientable);
    assert_eq!(che.report().welded_vertices, 24 - 6);
    assert_eq!(che.num_boundary_curves(), 0);
    // Nothing renumbered: each triangle's corners are the smallest ids of their clusters.
    let first_of = |c: u32| {
        (0..24)
            .find(|&v| positions[v as usize].distance(positions[c as usize]) < 1e-9)
            .unwrap()
    };
    for (t, tri) in triangles.iter().enumerate() {
        let got = che.triangle_vertices(t as u32);
        let mut want = tri.map(first_of).to_vec();
        let mut got = got.to_vec();
        want.sort_unstable();
        got.sort_unstable();
        assert_eq!(got, want, "triangle {t}");
    }
}

#[test]
fn stl_soup_is_loose_triangles_without_the_weld() {
    let (triangles, positions) = octahedron_soup();
    let che = Che::from_triangles(
        &triangles,
        positions.len(),
        &positions,
        BuildOptions::level(3),
    )
    .unwrap();
    let s = che.summary();
    assert_eq!((s.vertices, s.edges, s.triangles), (24, 24, 8));
    assert_eq!(
        (s.boundary_edges, s.boundary_curves, s.components),
        (24, 8, 8)
    );
    assert_eq!(che.report().welded_vertices, 0);
    // A tolerance below the perturbation welds only the corners written the same.
    let tiny = BuildOptions {
        weld_tolerance: 1e-300,
        ..BuildOptions::level(3)
    };
    let che = Che::from_triangles(&triangles, positions.len(), &positions, tiny).unwrap();
    let copies = (0..positions.len())
        .filter(|&v| positions[..v].contains(&positions[v]))
        .count();
    assert!(copies < 24 - 6);
    assert_eq!(che.report().welded_vertices, copies);
    assert!(che.summary().boundary_edges > 0);
}

#[test]
fn weld_collapses_triangles_into_degenerate_ones() {
    // Triangle 1's corners 3 and 4 are 0.5 apart: at tolerance 0.6 it loses an edge.
    let p = [
        [0., 0., 0.],
        [1., 0., 0.],
        [0., 1., 0.],
        [5., 0., 0.],
        [5.5, 0., 0.],
        [5., 1., 0.],
    ]
    .map(DVec3::from_array);
    let options = BuildOptions {
        weld_tolerance: 0.6,
        ..BuildOptions::level(2)
    };
    let che = Che::from_triangles(&[[0, 1, 2], [3, 4, 5]], 6, &p, options).unwrap();
    let r = che.report();
    assert_eq!((r.welded_vertices, r.dropped_degenerate), (1, 1));
    assert_eq!(r.degenerate_examples, vec![1]);
    assert_eq!(che.summary().vertices, 5);
}

#[test]
fn weld_errors_name_the_option() {
    let (triangles, positions) = octahedron_soup();
    let weld = |t: f64| BuildOptions {
        weld_tolerance: t,
        ..BuildOptions::default()
    };
    let e = Che::from_triangles(&triangles, 24, &[], weld(1e-6)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput);
    assert!(
        e.message.contains("without vertex positions"),
        "{}",
        e.message
    );
    let e = Che::from_triangles(&triangles, 24, &positions, weld(-1.0)).unwrap_err();
    assert!(e.message.contains("weld_tolerance -1"), "{}", e.message);
    let mut bad = positions.clone();
    bad[7].y = f64::INFINITY;
    let e = Che::from_triangles(&triangles, 24, &bad, weld(1e-6)).unwrap_err();
    assert!(e.message.contains("vertex 7"), "{}", e.message);
}

/// Two tetrahedra sharing a face, written as 8 separate corners with the shared ones
/// perturbed in their last bits.
#[test]
fn tet_soup_shares_its_face_with_the_weld() {
    let corner = [
        [0., 0., 0.],
        [1., 0., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
        [1., 1., 1.],
    ];
    let tets = [[0, 1, 2, 3], [1, 2, 3, 4]];
    let mut positions = Vec::new();
    let mut soup = Vec::new();
    for (k, tet) in tets.iter().enumerate() {
        let mut ids = [0; 4];
        for (i, &c) in tet.iter().enumerate() {
            ids[i] = positions.len() as u32;
            positions.push(
                DVec3::from_array(corner[c])
                    .to_array()
                    .map(|x| last_bits(x, 3 * k + i))
                    .into(),
            );
        }
        soup.push(ids);
    }
    let welded = chf::BuildOptions {
        weld_tolerance: 1e-9,
        ..chf::BuildOptions::level(3)
    };
    let chf = Chf::from_tetrahedra(&soup, 8, &positions, welded).unwrap();
    chf.validate().unwrap();
    let s = chf.summary();
    assert_eq!(
        (s.vertices, s.tetrahedra, s.faces, s.boundary_faces),
        (5, 2, 7, 6)
    );
    assert_eq!(
        (s.isolated_vertices, s.components, s.euler_characteristic),
        (0, 1, 1)
    );
    assert_eq!(chf.report().welded_vertices, 3);
    let loose = Chf::from_tetrahedra(&soup, 8, &positions, chf::BuildOptions::level(3)).unwrap();
    let s = loose.summary();
    assert_eq!(
        (s.vertices, s.faces, s.boundary_faces, s.components),
        (8, 8, 8, 2)
    );
}
