//! Every relation at every level against a brute-force reference computed from the raw
//! tetrahedron list, on subdivided boxes with tetrahedra removed (holes, several
//! components, non-manifold vertices and edges), duplicated (non-manifold faces) and
//! degenerate ones added, vertices relabelled, tetrahedra shuffled and locally permuted.

mod chf_common;

use chf_common::*;
use proptest::prelude::*;
use topomesh::chf::Chf;

/// Appends `dups` permuted copies of random tetrahedra and inserts `degenerate` tetrahedra
/// with a repeated vertex at random places.
fn perturb(mesh: &mut Mesh, seed: u64, dups: usize, degenerate: usize) {
    let mut rng = Rng(seed ^ 0xD1B5_4A32_D192_ED03);
    for _ in 0..dups {
        if mesh.tets.is_empty() {
            break;
        }
        let mut t = mesh.tets[rng.below(mesh.tets.len())];
        rng.shuffle(&mut t);
        let at = rng.below(mesh.tets.len() + 1);
        mesh.tets.insert(at, t);
    }
    for _ in 0..degenerate {
        let n = mesh.n() as u32;
        let a = rng.below(n as usize) as u32;
        let b = (a + 1 + rng.below(n as usize - 1) as u32) % n;
        let mut t = [a, a, b, (b + 1) % n];
        rng.shuffle(&mut t);
        let at = rng.below(mesh.tets.len() + 1);
        mesh.tets.insert(at, t);
    }
}

fn check_all_levels(mesh: &Mesh, with_positions: bool) {
    let chf = mesh.build(2, with_positions);
    check_build(&chf, &mesh.tets, &mesh.positions, with_positions);
    let reference = Reference::new(&chf, &mesh.tets);
    let at2 = answers(&chf);
    check_against_reference(&chf, &at2, &reference);
    for level in [0, 1, 3] {
        let other = mesh.build(level, with_positions);
        assert_eq!(other.level(), level);
        check_invariants(&other);
        assert_eq!(
            answers(&other),
            at2,
            "level {level} answers differ from level 2"
        );
        assert_eq!(other.summary(), chf.summary());
    }
    // Going up and down in place keeps the ids.
    let mut moving: Chf = mesh.build(0, with_positions);
    for level in [3, 1, 2, 0, 3] {
        moving.build_level(level).unwrap();
        check_invariants(&moving);
        assert_eq!(moving.half_face_vertices(), chf.half_face_vertices());
    }
    assert_eq!(answers(&moving), at2);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    #[test]
    fn chf_relations_match_brute_force(
        dims in (1u32..=3, 1u32..=2, 1u32..=2),
        five in any::<bool>(),
        seed in any::<u64>(),
        keep in 35u64..=100,
        with_positions in any::<bool>(),
    ) {
        let mesh = scramble(&cube(dims.0, dims.1, dims.2, five), seed, keep);
        check_all_levels(&mesh, with_positions);
    }

    #[test]
    fn chf_duplicates_and_degenerate_tetrahedra(
        five in any::<bool>(),
        seed in any::<u64>(),
        keep in 50u64..=100,
        dups in 0usize..3,
        degenerate in 0usize..3,
        with_positions in any::<bool>(),
    ) {
        let mut mesh = scramble(&cube(2, 2, 1, five), seed, keep);
        perturb(&mut mesh, seed, dups, degenerate);
        check_all_levels(&mesh, with_positions);
    }
}

#[test]
fn chf_whole_boxes_at_every_level() {
    for five in [false, true] {
        let mesh = cube(3, 2, 2, five);
        check_all_levels(&mesh, true);
        let chf = mesh.build(2, true);
        let s = chf.summary();
        assert_eq!(s.euler_characteristic, 1);
        assert_eq!(s.boundary_components, 1);
        assert!(s.manifold);
        assert_eq!(chf.report().flipped_tetrahedra, 0);
    }
}
