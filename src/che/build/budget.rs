//! The memory a CHE build will take at its peak, from the input's sizes: the arrays each
//! step makes, in bytes per input triangle and per input vertex (see `util::budget`).

use crate::util::budget::{Cost, peak};

/// The matching step's peak: `V` (12), the pair keys (8 per half-edge, 24), the smaller
/// vertices when the keys do not pack (12), the partners (12) and the direction bits (1).
const MATCHING: Cost = Cost::new(61, 0);
/// From the split on: `V` and `O` (12 each, `O` made at every level), and `VH` with the
/// degrees while splitting (4 each per vertex).
const LEVEL_1: Cost = Cost::new(24, 8);
/// Level 2: `EH`, at most an edge per half-edge (12), and the edge-id directory (1).
const LEVEL_2: Cost = Cost::new(13, 0);
/// Level 3: the curve of each boundary half-edge and `CH`, at most 8 bytes per half-edge
/// (24), and the boundary bits (1).
const LEVEL_3: Cost = Cost::new(25, 0);

/// The bytes a build of `triangles` triangles over `vertices` vertices (with positions or
/// not) at `level` is estimated to hold at its peak: what `BuildOptions::memory_limit_bytes`
/// is checked against. At least what the structure holds once built
/// ([`Che::memory_bytes`](crate::Che::memory_bytes): topology, positions and maps), and at
/// most eight times that on a manifold mesh.
pub fn estimated_build_bytes(triangles: usize, vertices: usize, positions: bool, level: u8) -> u64 {
    let mut kept = LEVEL_1;
    if level >= 2 {
        kept = kept.plus(LEVEL_2);
    }
    if level >= 3 {
        kept = kept.plus(LEVEL_3);
    }
    peak(&[MATCHING, kept], triangles, vertices, positions)
}

#[cfg(test)]
mod tests {
    use crate::che::{BuildOptions, Che};
    use crate::generate;
    use crate::util::budget::assert_bounds;

    /// The estimate bounds what the structure holds, within the factor the docs state.
    #[test]
    fn the_estimate_bounds_the_structure_within_a_factor_of_eight() {
        let meshes = [generate::torus(40, 30), generate::sphere(20, 30)];
        for mesh in meshes {
            let (triangles, positions) = (mesh.triangles, mesh.positions);
            let n = positions.len();
            let estimate = |with_positions, level| {
                super::estimated_build_bytes(triangles.len(), n, with_positions, level)
            };
            assert_bounds(&positions, 0..=3, estimate, |pos, level| {
                let che = Che::from_triangles(&triangles, n, pos, BuildOptions::level(level));
                let m = che.unwrap().memory_bytes();
                m.topology + m.positions + m.maps
            });
        }
    }
}
