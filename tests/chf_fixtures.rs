//! Small pathological meshes, each with its exact summary and build report, checked at
//! every level against the brute-force reference too.

mod chf_common;

use chf_common::*;
use glam::DVec3;
use topomesh::chf::{self, Chf};
use topomesh::{ErrorKind, NONE};

fn p(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The unit corner tetrahedron's points, then `more`.
fn corner_points(more: &[DVec3]) -> Vec<DVec3> {
    let mut v = vec![p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.), p(0., 0., 1.)];
    v.extend_from_slice(more);
    v
}

/// Builds at every level, checks all relations against the reference, returns level 3.
fn build_checked(tets: &[[u32; 4]], positions: &[DVec3], given: bool) -> Chf {
    let mesh = Mesh {
        tets: tets.to_vec(),
        positions: positions.to_vec(),
    };
    let chf = mesh.build(3, given);
    check_build(&chf, tets, positions, given);
    let reference = Reference::new(&chf, tets);
    let a = answers(&chf);
    check_against_reference(&chf, &a, &reference);
    for level in 0..3 {
        let low = mesh.build(level, given);
        check_invariants(&low);
        assert_eq!(answers(&low), a, "level {level}");
    }
    chf
}

fn summary(
    counts: [u64; 4], boundary: [u64; 4], components: u64, isolated: u64, euler: i64,
) -> chf::Summary {
    chf::Summary {
        vertices: counts[0],
        edges: counts[1],
        faces: counts[2],
        tetrahedra: counts[3],
        boundary_faces: boundary[0],
        boundary_edges: boundary[1],
        boundary_vertices: boundary[2],
        boundary_components: boundary[3],
        components,
        isolated_vertices: isolated,
        euler_characteristic: euler,
        manifold: true,
        orientable: true,
        ..chf::Summary::default()
    }
}

fn report(tets: usize, vertices: usize, faces: [usize; 2], edges: usize) -> chf::BuildReport {
    chf::BuildReport {
        input_tetrahedra: tets,
        input_vertices: vertices,
        input_faces: faces[0],
        boundary_faces: faces[1],
        input_edges: edges,
        ..chf::BuildReport::default()
    }
}

#[test]
fn chf_single_tetrahedron() {
    let chf = build_checked(&[[0, 1, 2, 3]], &corner_points(&[]), true);
    assert_eq!(chf.summary(), summary([4, 6, 4, 1], [4, 6, 4, 1], 1, 0, 1));
    assert_eq!(*chf.report(), report(1, 4, [4, 4], 6));
    assert_eq!(
        (chf.num_edges(), chf.num_faces(), chf.num_vertices()),
        (6, 4, 4)
    );
    assert_eq!(chf.boundary().unwrap().summary().genus, 0);
    assert_eq!(chf.edge_tetrahedra(0).collect::<Vec<_>>(), vec![0]);
    assert_eq!(chf.edge_faces(0).count(), 2);
}

#[test]
fn chf_two_tetrahedra_sharing_a_face() {
    // The second is given inside out: the build flips it.
    let pts = corner_points(&[p(1., 1., 1.)]);
    let chf = build_checked(&[[0, 1, 2, 3], [1, 3, 2, 4]], &pts, true);
    assert_eq!(
        chf.summary(),
        chf::Summary {
            flipped_tetrahedra: 1,
            ..summary([5, 9, 7, 2], [6, 9, 5, 1], 1, 0, 1)
        }
    );
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            flipped_tetrahedra: 1,
            ..report(2, 5, [7, 6], 9)
        }
    );
    assert!(det(&pts, chf.tetrahedron_vertices(1)) > 0.0);
    assert_eq!(chf.tetrahedron_tetrahedra(0), [1, NONE, NONE, NONE]);
    assert_eq!(chf.boundary().unwrap().summary().genus, 0);
}

#[test]
fn chf_two_tetrahedra_sharing_an_edge() {
    let pts = corner_points(&[p(0., -1., 0.), p(0., 0., -1.)]);
    let chf = build_checked(&[[0, 1, 2, 3], [0, 1, 4, 5]], &pts, true);
    assert_eq!(
        chf.summary(),
        chf::Summary {
            manifold: false,
            non_manifold_edges: 1,
            split_vertices: 2,
            ..summary([6, 11, 8, 2], [8, 11, 6, 1], 1, 0, 1)
        }
    );
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            non_manifold_edges: 1,
            non_manifold_edge_examples: vec![[0, 1]],
            split_vertices: 2,
            split_vertex_examples: vec![0, 1],
            added_vertices: 2,
            ..report(2, 6, [8, 8], 11)
        }
    );
    // Both ends split, so the edge fell apart: two edges, two boundary components.
    assert_eq!((chf.num_vertices(), chf.num_edges()), (8, 12));
    assert_eq!(chf.vertex_origins().unwrap(), &[0, 1, 2, 3, 4, 5, 0, 1]);
    assert_eq!(chf.num_boundary_components(), 2);
    let strict = Chf::from_tetrahedra(
        &[[0, 1, 2, 3], [0, 1, 4, 5]],
        6,
        &pts,
        chf::BuildOptions {
            level: 2,
            strict: true,
            ..chf::BuildOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(strict.kind, ErrorKind::NonManifold);
    assert!(strict.message.contains("edge (0, 1)") && strict.message.contains("tetrahedra 0, 1"));
}

#[test]
fn chf_two_tetrahedra_sharing_a_vertex() {
    let pts = corner_points(&[p(-1., 0., 0.), p(0., -1., 0.), p(0., 0., -1.)]);
    let tets = [[0, 1, 2, 3], [0, 4, 6, 5]];
    let chf = build_checked(&tets, &pts, true);
    assert_eq!(
        chf.summary(),
        chf::Summary {
            manifold: false,
            split_vertices: 1,
            ..summary([7, 12, 8, 2], [8, 12, 7, 1], 1, 0, 1)
        }
    );
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            split_vertices: 1,
            split_vertex_examples: vec![0],
            added_vertices: 1,
            ..report(2, 7, [8, 8], 12)
        }
    );
    assert_eq!(chf.num_vertices(), 8);
    assert_eq!(chf.vertex_origin(7), 0);
    let strict = Chf::from_tetrahedra(
        &tets,
        7,
        &pts,
        chf::BuildOptions {
            level: 1,
            strict: true,
            ..chf::BuildOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(strict.kind, ErrorKind::NonManifold);
    assert!(strict.message.contains("vertex 0"), "{}", strict.message);
}

#[test]
fn chf_three_tetrahedra_on_one_face() {
    let pts = corner_points(&[p(0., 0., -1.), p(0.2, 0.2, 2.)]);
    let tets = [[0, 1, 2, 3], [0, 2, 1, 4], [0, 1, 2, 5]];
    let chf = build_checked(&tets, &pts, true);
    assert_eq!(
        chf.summary(),
        chf::Summary {
            manifold: false,
            non_manifold_faces: 1,
            non_manifold_edges: 3,
            split_vertices: 3,
            ..summary([6, 12, 10, 3], [9, 12, 6, 1], 1, 0, 1)
        }
    );
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            non_manifold_faces: 1,
            non_manifold_face_examples: vec![[0, 1, 2]],
            non_manifold_edges: 3,
            non_manifold_edge_examples: vec![[0, 1], [0, 2], [1, 2]],
            split_vertices: 3,
            split_vertex_examples: vec![0, 1, 2],
            added_vertices: 6,
            ..report(3, 6, [10, 9], 12)
        }
    );
    assert_eq!(
        (chf.num_faces(), chf.num_edges(), chf.num_vertices()),
        (12, 18, 12)
    );
    assert_eq!(chf.non_manifold_half_faces(), &[3, 7, 11]);
    // The shared face is no boundary face: 9 of them; its three half-faces are unpaired and
    // make three more triangles of the boundary surface (three closed tetrahedra after the
    // split, so three spheres).
    assert_eq!(chf.num_boundary_faces(), 9);
    assert_eq!(chf.num_non_manifold_half_faces(), 3);
    assert_eq!(chf.num_seam_half_faces(), 0);
    assert_eq!(chf.num_boundary_triangles(), 12);
    assert_eq!(chf.num_boundary_vertices(), 12);
    let che = chf.boundary().unwrap().summary();
    assert_eq!(
        (che.vertices, che.isolated_vertices, che.components),
        (12, 0, 3)
    );
    assert_eq!(che.euler_characteristic, 6);
    for level in 0..3 {
        let mut low = chf.clone();
        low.build_level(level).unwrap();
        assert_eq!(low.num_boundary_faces(), 9, "level {level}");
        assert_eq!(low.num_boundary_triangles(), 12, "level {level}");
    }
    let strict = Chf::from_tetrahedra(
        &tets,
        6,
        &pts,
        chf::BuildOptions {
            level: 0,
            strict: true,
            ..chf::BuildOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(strict.kind, ErrorKind::NonManifold);
    assert!(
        strict
            .message
            .contains("face (0, 1, 2) is shared by tetrahedra 0, 1, 2")
    );
}

#[test]
fn chf_cavity_has_two_boundary_components() {
    // A 3x3x3 box of cells without its middle cell.
    let full = cube(3, 3, 3, false);
    let middle: Vec<usize> = (0..6).map(|k| 13 * 6 + k).collect();
    let tets: Vec<[u32; 4]> = full
        .tets
        .iter()
        .enumerate()
        .filter(|(i, _)| !middle.contains(i))
        .map(|(_, &t)| t)
        .collect();
    let chf = build_checked(&tets, &full.positions, true);
    assert_eq!(
        chf.summary(),
        summary([64, 278, 372, 156], [120, 180, 64, 2], 1, 0, 2)
    );
    assert_eq!(*chf.report(), report(156, 64, [372, 120], 278));
    assert_eq!(chf.num_boundary_components(), 2);
    let che = chf.boundary().unwrap().summary();
    assert_eq!((che.components, che.genus, che.boundary_curves), (2, 0, 0));
    // Two spheres, no interior vertex among them.
    assert_eq!((che.vertices, che.isolated_vertices), (64, 0));
    assert_eq!(che.euler_characteristic, 4);
    assert_eq!(chf.num_boundary_faces(), 120);
    // The inner sphere's 8 vertices form component 1.
    let inner = chf
        .boundary_vertices()
        .iter()
        .filter(|&&v| chf.boundary_component(v) == 1)
        .count();
    assert_eq!(inner, 8);
}

#[test]
fn chf_boundary_of_a_ball_holds_only_boundary_vertices() {
    // A 3x3x3 box of cells: 64 vertices, 8 of them interior.
    let full = cube(3, 3, 3, false);
    let chf = build_checked(&full.tets, &full.positions, true);
    assert_eq!(chf.num_boundary_vertices(), 56);
    let che = chf.boundary().unwrap();
    let s = che.summary();
    assert_eq!((s.vertices, s.isolated_vertices, s.components), (56, 0, 1));
    assert_eq!(
        (s.euler_characteristic, s.genus, s.boundary_curves),
        (2, 0, 0)
    );
    assert_eq!(chf.summary().boundary_vertices, 56);
    // The interior ones map to no boundary vertex.
    let interior: Vec<u32> = (0..64)
        .filter(|&v| chf.boundary_vertex(v) == NONE)
        .collect();
    assert_eq!(interior.len(), 8);
    assert!(interior.iter().all(|&v| !chf.is_boundary_vertex(v)));
    // Positions follow the compact ids.
    for b in 0..56u32 {
        let v = chf.boundary_vertex_volume_vertex(b);
        assert_eq!(che.positions()[b as usize], chf.positions()[v as usize]);
    }
    // The same surface below level 3.
    let mut low = chf.clone();
    low.build_level(2).unwrap();
    let t = low.boundary_surface().unwrap().summary();
    assert_eq!(t, s);
}

#[test]
fn chf_solid_torus() {
    // A ring of 3x3x1 cells without the middle one.
    let full = cube(3, 3, 1, false);
    let tets: Vec<[u32; 4]> = full
        .tets
        .iter()
        .enumerate()
        .filter(|(i, _)| i / 6 != 4)
        .map(|(_, &t)| t)
        .collect();
    let chf = build_checked(&tets, &full.positions, true);
    assert_eq!(
        chf.summary(),
        summary([32, 112, 128, 48], [64, 96, 32, 1], 1, 0, 0)
    );
    assert_eq!(*chf.report(), report(48, 32, [128, 64], 112));
    let che = chf.boundary_surface().unwrap().summary();
    assert_eq!(
        (che.genus, che.components, che.euler_characteristic),
        (1, 1, 0)
    );
    assert!(che.manifold && che.orientable);
    // Every vertex of the ring is on its boundary.
    assert_eq!((che.vertices, che.isolated_vertices), (32, 0));
    assert_eq!(chf.boundary().unwrap().summary(), che);
}

#[test]
fn chf_degenerate_tetrahedra_are_dropped() {
    // The first one is degenerate too: the origin map must not read as the identity.
    let tets = [[0, 0, 1, 2], [0, 1, 2, 3], [1, 1, 2, 3]];
    let chf = build_checked(&tets, &corner_points(&[]), false);
    assert_eq!(
        chf.summary(),
        chf::Summary {
            dropped_degenerate: 2,
            ..summary([4, 6, 4, 1], [4, 6, 4, 1], 1, 0, 1)
        }
    );
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            dropped_degenerate: 2,
            degenerate_examples: vec![0, 2],
            ..report(3, 4, [4, 4], 6)
        }
    );
    assert_eq!(chf.tetrahedron_origin(0), 1);
    assert_eq!(chf.tetrahedron_origins().unwrap(), &[1]);
}

#[test]
fn chf_zero_volume_tetrahedron_is_kept_and_oriented_by_its_neighbour() {
    // Point 4 lies in the plane of face (1, 2, 3); the flat tetrahedron is given with that
    // face running the same way as in tetrahedron 0, so it must be flipped.
    let pts = corner_points(&[p(1., 1., -1.)]);
    let chf = build_checked(&[[0, 1, 2, 3], [1, 3, 2, 4]], &pts, true);
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            zero_volume: 1,
            zero_volume_examples: vec![1],
            flipped_tetrahedra: 1,
            ..report(2, 5, [7, 6], 9)
        }
    );
    assert_eq!(
        chf.summary(),
        chf::Summary {
            zero_volume: 1,
            flipped_tetrahedra: 1,
            ..summary([5, 9, 7, 2], [6, 9, 5, 1], 1, 0, 1)
        }
    );
}

#[test]
fn chf_folded_tetrahedron_is_reported_inverted() {
    // Tetrahedra 0 and 1 share face (0, 1, 2) and lie on the same side of it; 2 is glued
    // to 0 properly. Topology wins: 1 is flipped and reported inverted.
    let pts = corner_points(&[p(0.1, 0.1, 0.5), p(1., 1., 1.)]);
    let tets = [[0, 1, 2, 3], [0, 1, 2, 4], [1, 2, 3, 5]];
    let chf = build_checked(&tets, &pts, true);
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            flipped_tetrahedra: 1,
            inverted_tetrahedra: 1,
            inverted_examples: vec![1],
            ..report(3, 6, [10, 8], 12)
        }
    );
    assert_eq!(
        chf.summary(),
        chf::Summary {
            flipped_tetrahedra: 1,
            inverted_tetrahedra: 1,
            ..summary([6, 12, 10, 3], [8, 12, 6, 1], 1, 0, 1)
        }
    );
    assert_eq!(chf.opposites().unwrap()[3], 7);
}

#[test]
fn chf_duplicate_tetrahedra_glue_into_a_sphere() {
    let tets = [[0, 1, 2, 3], [0, 1, 3, 2]];
    let chf = build_checked(&tets, &corner_points(&[]), false);
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            duplicate_tetrahedra: 1,
            duplicate_examples: vec![[0, 1]],
            ..report(2, 4, [4, 0], 6)
        }
    );
    // Two tetrahedra glued along their whole boundary: a 3-sphere, Euler characteristic 0.
    assert_eq!(chf.summary(), summary([4, 6, 4, 2], [0, 0, 0, 0], 1, 0, 0));
    assert_eq!(chf.tetrahedron_tetrahedra(0), [1; 4]);
    assert_eq!(chf.face_faces(0).len(), 3);
    let strict = Chf::from_tetrahedra(
        &tets,
        4,
        &[],
        chf::BuildOptions {
            level: 2,
            strict: true,
            ..chf::BuildOptions::default()
        },
    )
    .unwrap_err();
    assert!(
        strict
            .message
            .contains("tetrahedra 0 and 1 have the same vertices")
    );
}

#[test]
fn chf_edge_with_two_fans_that_the_split_keeps() {
    // Edge (0, 1) lies in tetrahedra 0 and 1 only, which share no face; but the stars of
    // 0 and of 1 are each connected through other tetrahedra, so nothing is split and the
    // edge keeps two fans: two edge ids with the same ends. Consistently oriented input.
    let tets = [
        [0, 1, 2, 3],
        [0, 4, 1, 5],
        [0, 3, 2, 4],
        [0, 3, 4, 5],
        [1, 2, 3, 4],
        [1, 4, 3, 5],
    ];
    let pts = vec![DVec3::ZERO; 6];
    let chf = build_checked(&tets, &pts, false);
    assert_eq!(
        *chf.report(),
        chf::BuildReport {
            non_manifold_edges: 1,
            non_manifold_edge_examples: vec![[0, 1]],
            kept_non_manifold_edges: 1,
            kept_non_manifold_edge_examples: vec![[0, 1]],
            ..report(6, 6, [16, 8], 14)
        }
    );
    assert_eq!(
        chf.summary(),
        chf::Summary {
            manifold: false,
            non_manifold_edges: 1,
            ..summary([6, 14, 16, 6], [8, 11, 6, 1], 1, 0, 2)
        }
    );
    assert_eq!(chf.num_edges(), 15);
    let ends: Vec<u32> = chf
        .vertex_edges(0)
        .filter(|&e| sorted(chf.edge_vertices(e)) == [0, 1])
        .collect();
    assert_eq!(ends.len(), 2);
    assert_eq!(chf.vertex_vertices(0).filter(|&w| w == 1).count(), 1);
    // The boundary surface has a non-manifold edge there: four triangles on (0, 1).
    assert_eq!(chf.boundary().unwrap().report().non_manifold_edges, 1);
    let strict = Chf::from_tetrahedra(
        &tets,
        6,
        &[],
        chf::BuildOptions {
            level: 2,
            strict: true,
            ..chf::BuildOptions::default()
        },
    )
    .unwrap_err();
    assert!(
        strict
            .message
            .contains("edge (0, 1): tetrahedra 0, 1 form several fans")
    );
}

#[test]
fn chf_empty_meshes() {
    for n in [0usize, 3] {
        for level in 0..=3 {
            let chf = Chf::from_tetrahedra(&[], n, &[], chf::BuildOptions::level(level)).unwrap();
            chf.validate().unwrap();
            assert_eq!(
                chf.summary(),
                chf::Summary {
                    isolated_vertices: n as u64,
                    euler_characteristic: n as i64,
                    ..summary([n as u64, 0, 0, 0], [0; 4], 0, n as u64, n as i64)
                }
            );
            assert_eq!(*chf.report(), report(0, n, [0, 0], 0));
            for v in 0..n as u32 {
                assert_eq!(chf.vertex_tetrahedra(v).count(), 0);
                assert_eq!(chf.vertex_vertices(v).count(), 0);
                assert!(chf.is_isolated_vertex(v) && !chf.is_boundary_vertex(v));
            }
            assert_eq!(chf.num_boundary_components(), 0);
            assert_eq!(chf.boundary_surface().unwrap().num_triangles(), 0);
        }
    }
}

#[test]
fn chf_isolated_vertices_are_kept() {
    // Vertex 1 is in no tetrahedron.
    let pts = vec![
        p(0., 0., 0.),
        p(5., 5., 5.),
        p(1., 0., 0.),
        p(0., 1., 0.),
        p(0., 0., 1.),
    ];
    let chf = build_checked(&[[0, 2, 3, 4]], &pts, true);
    assert_eq!(chf.summary(), summary([5, 6, 4, 1], [4, 6, 4, 1], 1, 1, 2));
    assert!(chf.is_isolated_vertex(1) && !chf.is_boundary_vertex(1));
    assert_eq!(chf.vertex_half_face(1), NONE);
}

#[test]
fn chf_bad_input_is_an_error_naming_the_tetrahedron() {
    let e = Chf::from_tetrahedra(
        &[[0, 1, 2, 3], [0, 1, 2, 9]],
        4,
        &[],
        chf::BuildOptions::default(),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    assert!(
        e.message.contains("tetrahedron 1, corner 3: vertex 9"),
        "{}",
        e.message
    );
    let pts = corner_points(&[]);
    let e =
        Chf::from_tetrahedra(&[[0, 1, 2, 3]], 5, &pts, chf::BuildOptions::default()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput);
    let e = Chf::from_tetrahedra(&[[0, 1, 2, 3]], 4, &[], chf::BuildOptions::level(4)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::OutOfRange);
    let e = Chf::from_flat(&[0, 1, 2], 4, &[], chf::BuildOptions::default()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput);
    let mut chf = Chf::from_flat(&[0, 1, 2, 3], 4, &[], chf::BuildOptions::default()).unwrap();
    assert_eq!(chf.build_level(4).unwrap_err().kind, ErrorKind::OutOfRange);
    assert_eq!(chf.check_vertex(4).unwrap_err().kind, ErrorKind::OutOfRange);
    assert!(chf.check_vertex(3).is_ok());
    assert!(chf.check_edge(5).is_ok() && chf.check_edge(6).is_err());
    assert!(chf.check_face(3).is_ok() && chf.check_face(4).is_err());
    assert!(chf.check_tetrahedron(0).is_ok() && chf.check_tetrahedron(1).is_err());
    assert!(chf.check_half_face(3).is_ok() && chf.check_half_face(4).is_err());
    assert!(chf.check_half_edge(11).is_ok() && chf.check_half_edge(12).is_err());
}
