//! Every relation at every level against brute force, on generated and perturbed meshes.

mod che_common;

use che_common::{Rng, check_all, perturb};
use proptest::prelude::*;
use topomesh::generate::{grid, sphere, torus};

fn base(kind: u8, a: u32, b: u32) -> (Vec<[u32; 3]>, usize) {
    let s = match kind % 3 {
        0 => grid(a, b),
        1 => torus(a + 2, b + 2),
        _ => sphere(a + 2, b + 1),
    };
    (s.triangles, s.positions.len())
}

#[test]
fn clean_meshes_at_every_level() {
    for (kind, a, b) in [(0, 1, 1), (0, 4, 3), (1, 3, 4), (2, 4, 3), (1, 6, 1)] {
        let (tris, n) = base(kind, a, b);
        let che = check_all(&tris, n, &[0, 1, 2, 3]);
        assert!(che.report().is_clean());
        assert_eq!(che.report().flipped_triangles, 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    /// Relabelled, shuffled, partly flipped: the build must orient every component back.
    #[test]
    fn perturbed_meshes(kind in 0u8..3, a in 1u32..6, b in 1u32..6, seed in any::<u64>()) {
        let (tris, n) = base(kind, a, b);
        let mut rng = Rng(seed);
        let input = perturb(&tris, n, &mut rng, 0.4);
        let che = check_all(&input, n, &[1, 2]);
        prop_assert_eq!(che.report().non_orientable_components, 0);
        prop_assert_eq!(che.report().split_vertices, 0);
        let s = che.summary();
        prop_assert!(s.orientable && s.manifold);
    }

    /// Random subsets (holes, several components, non-manifold vertices), random extra
    /// triangles (non-manifold edges, duplicates, degenerate ones).
    #[test]
    fn damaged_meshes(kind in 0u8..3, a in 1u32..6, b in 1u32..6, seed in any::<u64>(),
                      keep in 0.3f64..1.0, extra in 0usize..6) {
        let (tris, n) = base(kind, a, b);
        let mut rng = Rng(seed);
        let mut input: Vec<[u32; 3]> = tris.into_iter().filter(|_| rng.chance(keep)).collect();
        for _ in 0..extra {
            let t = [rng.below(n) as u32, rng.below(n) as u32, rng.below(n) as u32];
            input.push(t);
        }
        if !input.is_empty() && rng.chance(0.5) {
            let t = input[rng.below(input.len())];
            input.push(t);
        }
        let input = perturb(&input, n, &mut rng, 0.3);
        check_all(&input, n, &[1, 2]);
    }

    /// Level 0 scans: small meshes only.
    #[test]
    fn level_zero(kind in 0u8..3, a in 1u32..4, b in 1u32..3, seed in any::<u64>(), keep in 0.5f64..1.0) {
        let (tris, n) = base(kind, a, b);
        let mut rng = Rng(seed);
        let input: Vec<[u32; 3]> = tris.into_iter().filter(|_| rng.chance(keep)).collect();
        let input = perturb(&input, n, &mut rng, 0.3);
        check_all(&input, n, &[0]);
    }
}
