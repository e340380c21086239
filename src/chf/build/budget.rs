//! The memory a CHF build will take at its peak, from the input's sizes: the arrays each
//! step makes, in bytes per input tetrahedron and per input vertex (see `util::budget`).
//! The boundary surface of level 3 is a CHE build of its own, checked against what is left
//! of the limit once the volume is built.

use crate::util::budget::{Cost, peak};

/// The star pass's peak: `V` (16), the determinant signs (1), the records buffer (16, 20
/// with the level-2 tables), the pairs (8 per half-face, 32) and each thread's vertex
/// stamps (at most 8 per vertex and 2 per tetrahedron in all; see `threads_for`).
const STAR_PASS: Cost = Cost::new(16 + 1 + 16 + 32 + 2, 8);
/// The star pass's level-2 tables: the larger records (4), the edge slots (8 per
/// estimated edge, about one per vertex and 1.25 per tetrahedron) and `VH`.
const STAR_PASS_TABLES: Cost = Cost::new(4 + 10, 8 + 4);
/// What the build keeps from level 1 on: `V` and `O` (16 each, `O` made at every level).
const LEVEL_1: Cost = Cost::new(32, 0);
/// Level 2: `FH`, at most a face per half-face (16), `EH`, at most an edge per slot (24),
/// the face and edge bits (3) and `VH` (4 per vertex).
const LEVEL_2: Cost = Cost::new(43, 4);

/// The bytes a build of `tets` tetrahedra over `vertices` vertices (with positions or not)
/// at `level` is estimated to hold at its peak, the boundary surface of level 3 aside (a
/// CHE build of its own, checked against what is left of the limit): what
/// `BuildOptions::memory_limit_bytes` is checked against. At least what the structure
/// holds once built ([`Chf::memory_bytes`](crate::Chf::memory_bytes): topology, positions
/// and maps), and at most eight times that on a manifold mesh.
pub fn estimated_build_bytes(tets: usize, vertices: usize, positions: bool, level: u8) -> u64 {
    let (pass, kept) = if level >= 2 {
        (STAR_PASS.plus(STAR_PASS_TABLES), LEVEL_1.plus(LEVEL_2))
    } else {
        (STAR_PASS, LEVEL_1)
    };
    peak(&[pass, kept], tets, vertices, positions)
}

#[cfg(test)]
mod tests {
    use crate::chf::{BuildOptions, Chf};
    use crate::util::budget::assert_bounds;
    use glam::DVec3;

    fn cubes(n: u32) -> (Vec<[u32; 4]>, Vec<DVec3>) {
        let v = crate::generate::cube_grid(n);
        (v.tetrahedra, v.positions)
    }

    /// The estimate bounds what the structure holds, within the factor the docs state.
    #[test]
    fn the_estimate_bounds_the_structure_within_a_factor_of_eight() {
        for n in [3, 12] {
            let (tets, positions) = cubes(n);
            let nv = positions.len();
            let estimate = |with_positions, level| {
                super::estimated_build_bytes(tets.len(), nv, with_positions, level)
            };
            assert_bounds(&positions, 0..=2, estimate, |pos, level| {
                let chf = Chf::from_tetrahedra(&tets, nv, pos, BuildOptions::level(level));
                let chf = chf.unwrap();
                assert_eq!(chf.report.inverted_tetrahedra, 0, "positive determinants");
                let m = chf.memory_bytes();
                m.topology + m.positions + m.maps
            });
        }
    }
}
