//! The build loses nothing, memory per level is what the containers hold, big stars spill
//! to the heap and stay exact.

mod chf_common;

use chf_common::*;
use glam::DVec3;
use topomesh::REPORT_EXAMPLES;
use topomesh::chf::{self, Chf};

#[test]
fn chf_nothing_disappears() {
    // Random tetrahedra over a few vertices: degenerate ones, duplicates, shared faces of
    // every kind. Every input tetrahedron is in the structure (mapped back) or dropped.
    let mut rng = Rng(7);
    let n = 12usize;
    let tets: Vec<[u32; 4]> = (0..300)
        .map(|_| [0; 4].map(|_| rng.below(n) as u32))
        .collect();
    let degenerate: Vec<u32> = (0..tets.len() as u32)
        .filter(|&t| chf_common::degenerate(tets[t as usize]))
        .collect();
    assert!(degenerate.len() > REPORT_EXAMPLES);
    for level in 0..=3 {
        let chf = Chf::from_tetrahedra(&tets, n, &[], chf::BuildOptions::level(level)).unwrap();
        let r = chf.report();
        assert_eq!(r.dropped_degenerate, degenerate.len());
        assert_eq!(r.degenerate_examples, degenerate[..REPORT_EXAMPLES]);
        let mut seen = vec![false; tets.len()];
        for t in 0..chf.num_tetrahedra() as u32 {
            let o = chf.tetrahedron_origin(t) as usize;
            assert!(!seen[o]);
            seen[o] = true;
            let back = chf.tetrahedron_vertices(t).map(|v| chf.vertex_origin(v));
            assert_eq!(sorted(back), sorted(tets[o]));
        }
        for (t, &s) in seen.iter().enumerate() {
            assert!(
                s || degenerate.binary_search(&(t as u32)).is_ok(),
                "tetrahedron {t} lost"
            );
        }
        assert!(r.duplicate_tetrahedra > 0 && r.non_manifold_faces > 0);
        check_invariants(&chf);
    }
}

#[test]
fn chf_soups_of_random_tetrahedra_match_the_reference() {
    let mut seams = 0;
    for seed in 0..40 {
        let mut rng = Rng(seed);
        let n = 9usize;
        let tets: Vec<[u32; 4]> = (0..40)
            .map(|_| [0; 4].map(|_| rng.below(n) as u32))
            .collect();
        let chf = Chf::from_tetrahedra(&tets, n, &[], chf::BuildOptions::level(3)).unwrap();
        let r = chf.report();
        let reference = Reference::new(&chf, &tets);
        let a = answers(&chf);
        check_against_reference(&chf, &a, &reference);
        check_invariants(&chf);
        for level in 0..3 {
            let low = Chf::from_tetrahedra(&tets, n, &[], chf::BuildOptions::level(level)).unwrap();
            assert_eq!(answers(&low), a);
        }
        // Seams: pairs on one triple, running the same way (they could not be glued).
        let s = chf.seam_half_faces();
        assert_eq!(s.len(), 2 * r.seam_faces);
        seams += r.seam_faces;
        // (In input ids: a seam may cut a star, so the two sides can hold vertex copies.)
        let input = |hf: u32| chf.half_face_vertices_of(hf).map(|v| chf.vertex_origin(v));
        for &h in s {
            let g = *s
                .iter()
                .find(|&&g| g != h && sorted(input(g)) == sorted(input(h)))
                .expect("seam partner");
            let (a, b) = (input(h), input(g));
            let k = b.iter().position(|&x| x == a[0]).unwrap();
            assert_eq!(b[(k + 1) % 3], a[1], "seam pairs run the same way");
        }
        assert_eq!(r.non_orientable_components > 0, r.seam_faces > 0);
    }
    assert!(seams > 0, "some soup is non-orientable");
}

/// A cone from the origin over a UV sphere: the apex's star has `2 * lon * (lat - 1)`
/// tetrahedra.
fn cone(lat: u32, lon: u32) -> Mesh {
    let mut positions = vec![DVec3::ZERO, DVec3::Z, -DVec3::Z];
    let ring = |k: u32, j: u32| 3 + (k - 1) * lon + (j % lon);
    for k in 1..lat {
        let theta = std::f64::consts::PI * k as f64 / lat as f64;
        for j in 0..lon {
            let phi = 2.0 * std::f64::consts::PI * j as f64 / lon as f64;
            positions.push(DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    let mut tris = Vec::new();
    for j in 0..lon {
        tris.push([1, ring(1, j), ring(1, j + 1)]);
        tris.push([2, ring(lat - 1, j + 1), ring(lat - 1, j)]);
        for k in 1..lat - 1 {
            tris.push([ring(k, j), ring(k + 1, j), ring(k + 1, j + 1)]);
            tris.push([ring(k, j), ring(k + 1, j + 1), ring(k, j + 1)]);
        }
    }
    let tets = tris.iter().map(|&[a, b, c]| [0, a, b, c]).collect();
    Mesh { tets, positions }
}

#[test]
fn chf_large_star_spills_and_stays_exact() {
    let mesh = scramble(&cone(6, 16), 5, 100);
    let n_tets = mesh.tets.len();
    assert!(n_tets > 2 * 64);
    for level in 0..=3 {
        let chf = mesh.build(level, true);
        check_build(&chf, &mesh.tets, &mesh.positions, true);
        let apex = (0..chf.num_vertices() as u32)
            .find(|&v| chf.vertex_tetrahedra(v).count() == n_tets)
            .expect("the apex sees every tetrahedron");
        assert!(!chf.is_boundary_vertex(apex));
        assert_eq!(chf.vertex_vertices(apex).count(), chf.num_vertices() - 1);
        if level == 2 {
            let reference = Reference::new(&chf, &mesh.tets);
            check_against_reference(&chf, &answers(&chf), &reference);
        }
    }
}

#[test]
fn chf_memory_per_level() {
    let mesh = cube(10, 10, 10, false);
    let t = mesh.tets.len();
    let mut per_tet = Vec::new();
    for level in 0..=3 {
        let chf = mesh.build(level, true);
        let m = chf.memory_bytes();
        let (v, e, f) = (chf.num_vertices(), chf.num_edges(), chf.num_faces());
        assert_eq!(m.half_face_vertices, 16 * t);
        assert_eq!(m.opposites, if level >= 1 { 16 * t } else { 0 });
        if level >= 2 {
            assert_eq!(m.vertex_half_faces, 4 * v);
            // Rank bits: 1.5 bits per slot (6 per tetrahedron) and per half-face (4).
            assert!(m.edges >= 4 * e && m.edges <= 4 * e + (6 * t).div_ceil(64) * 12);
            assert!(m.faces >= 4 * f && m.faces <= 4 * f + (4 * t).div_ceil(64) * 12);
        } else {
            assert_eq!(m.vertex_half_faces + m.edges + m.faces, 0);
        }
        assert_eq!(m.boundary > 0, level == 3);
        assert_eq!(m.maps, 0);
        assert_eq!(m.positions, 24 * v);
        per_tet.push(m.topology as f64 / t as f64);
    }
    println!("topology bytes per tetrahedron, levels 0..=3 ({t} tetrahedra): {per_tet:.2?}");
    assert_eq!(per_tet[0], 16.0);
    assert_eq!(per_tet[1], 32.0);
}

/// Everything a build produces that a thread count could change.
fn fingerprint(chf: &Chf) -> String {
    let boundary = chf.boundary().map(|b| {
        (
            b.half_edge_vertices().to_vec(),
            b.opposites().map(<[u32]>::to_vec),
        )
    });
    format!(
        "{:?}",
        (
            (
                chf.half_face_vertices(),
                chf.opposites(),
                chf.vertex_half_faces()
            ),
            (chf.face_half_faces(), chf.edge_slot_tetrahedra()),
            (chf.num_edges(), chf.num_faces(), chf.num_vertices()),
            (chf.vertex_origins(), chf.tetrahedron_origins()),
            (chf.non_manifold_half_faces(), chf.seam_half_faces()),
            chf.report(),
            boundary,
        )
    )
}

#[test]
fn chf_build_is_the_same_on_any_number_of_threads() {
    // Large enough for the star pass to share its rounds among threads, numbered at random,
    // and damaged all over: tetrahedra glued to a face, an edge or a vertex of others make
    // non-manifold faces, edges and vertices; random ones, duplicates, inverted and
    // degenerate tetrahedra. The report's examples must come in the same order too.
    let mesh = scramble(&cube(24, 24, 24, false), 11, 100);
    let n = mesh.n();
    let mut tets = mesh.tets.clone();
    let mut rng = Rng(5);
    for k in 0..1200 {
        let t = mesh.tets[rng.below(mesh.tets.len())];
        let mut extra = [0; 4].map(|_| rng.below(n) as u32);
        extra[..3 - k % 3].copy_from_slice(&t[..3 - k % 3]);
        tets.push(extra);
    }
    let t = tets[17];
    tets.push(t);
    tets.push([t[1], t[0], t[2], t[3]]);
    // Degenerate ones (dropped, in two runs of the soup) and a flat one (zero volume).
    tets.insert(100, [5, 5, 9, 12]);
    tets.push([7, 8, 7, 1]);
    let flat: Vec<u32> = (0..n as u32)
        .filter(|&x| mesh.positions[x as usize].z == 0.0)
        .take(4)
        .collect();
    tets.push([flat[0], flat[1], flat[2], flat[3]]);
    assert!(tets.len() > 1 << 16);
    for level in 0..=3u8 {
        let build = |threads| {
            let options = chf::BuildOptions {
                level,
                threads,
                ..chf::BuildOptions::default()
            };
            Chf::from_tetrahedra(&tets, n, &mesh.positions, options).unwrap()
        };
        let one = build(1);
        let r = one.report();
        assert!(
            r.non_manifold_faces > 0
                && r.duplicate_tetrahedra > 0
                && r.split_vertices > 0
                && r.flipped_tetrahedra > 0
                && r.non_manifold_edges > 0
                && r.dropped_degenerate >= 2
                && r.zero_volume > 0,
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
            let options = chf::BuildOptions {
                level,
                threads,
                strict: true,
                memory_limit_bytes: 0,
                ..chf::BuildOptions::default()
            };
            Chf::from_tetrahedra(&tets, n, &mesh.positions, options)
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
        check_invariants(&one);
    }
}
