//! Welding: vertices at most a tolerance apart become one before either build, so that a
//! soup whose shared corners were written as separate, nearly equal points (STL, some
//! exporters) builds with its topology.
//!
//! The rule. Two vertices are *close* when the Euclidean distance of their positions is at
//! most the tolerance. The clusters are the connected components of the "close" relation
//! (single linkage: a chain of close pairs joins its ends, even when the ends are farther
//! apart). Each cluster's representative is its smallest vertex id. Every element corner
//! is rewritten to its representative; nothing is renumbered, so a welded vertex keeps its
//! id and its position but no element uses it any more. An element whose corners meet
//! under the weld is then degenerate and dropped by the soup step (counted as such).
//!
//! How. A grid of cubic cells whose side is (a little more than) the tolerance: two close
//! vertices lie in the same or in neighbouring cells. The vertices are sorted by cell (one
//! array of keys, no per-element allocation), and each cell is compared with itself and
//! with the 13 of its 26 neighbours that come after it in that order, each found by binary
//! search: O(n log n) for points spread at least a tolerance apart, more where many points
//! crowd one cell (all pairs of a cell are compared). The unions go through a union-find
//! whose smaller root wins, so the clusters and their representatives do not depend on the
//! order of the pairs.

use crate::NONE;
use crate::error::{Error, Result};
use crate::util::alloc::try_with_capacity;
use crate::util::dsu::Dsu;
use glam::DVec3;
use std::borrow::Cow;

/// The elements after the weld, and how many vertices it merged into another.
pub(crate) struct Welded<'a, const K: usize> {
    /// The elements with every corner replaced by its cluster's representative (borrowed as
    /// given when the weld is off).
    pub elements: Cow<'a, [[u32; K]]>,
    /// Vertices that are not their cluster's representative.
    pub welded_vertices: usize,
}

/// The weld of `elements` over `positions` (one per vertex) at `tolerance`: off at 0 (the
/// elements pass through, borrowed or owned as given). A tolerance that is negative or not
/// finite, or a weld without positions, is an error. Corner ids out of range are kept as
/// they are, for the soup step to report.
pub(crate) fn weld_elements<'a, const K: usize>(
    elements: Cow<'a, [[u32; K]]>, positions: &[DVec3], tolerance: f64,
) -> Result<Welded<'a, K>> {
    if tolerance == 0.0 {
        return Ok(Welded {
            elements,
            welded_vertices: 0,
        });
    }
    if positions.is_empty() && !elements.is_empty() {
        return Err(Error::invalid(format!(
            "weld_tolerance {tolerance} given without vertex positions"
        )));
    }
    let representative = representatives(positions, tolerance)?;
    let welded_vertices = representative
        .iter()
        .enumerate()
        .filter(|&(v, &r)| v as u32 != r)
        .count();
    let mut out = try_with_capacity(elements.len(), "the welded elements")?;
    out.extend(
        elements
            .iter()
            .map(|e| e.map(|x| representative.get(x as usize).copied().unwrap_or(x))),
    );
    Ok(Welded {
        elements: Cow::Owned(out),
        welded_vertices,
    })
}

/// The weld alone: for each vertex, the smallest id of its cluster of vertices at most
/// `tolerance` apart (single linkage; see the rule in the module `util::weld`), the
/// vertex itself when it welds to none. What the builds do with
/// `BuildOptions::weld_tolerance`, for a caller that rewrites its own arrays (the CLI's
/// `convert --weld`). A tolerance that is not finite and positive, or a position that is
/// not finite, is an error.
pub fn representatives(positions: &[DVec3], tolerance: f64) -> Result<Vec<u32>> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::invalid(format!(
            "weld_tolerance {tolerance}: must be a finite positive distance (0 is off)"
        )));
    }
    let by_cell = sorted_cells(positions, tolerance)?;
    let mut dsu = Dsu::new(positions.len())?;
    let mut start = 0;
    while start < by_cell.len() {
        let cell = by_cell[start].0;
        let end = start + by_cell[start..].partition_point(|&(c, _)| c == cell);
        for (k, &(_, a)) in by_cell[start..end].iter().enumerate() {
            for &(_, b) in &by_cell[start + k + 1..end] {
                join_if_close(&mut dsu, positions, tolerance, a, b);
            }
        }
        for offset in FORWARD_NEIGHBOURS {
            let Some(other) = shifted(cell, offset) else {
                continue;
            };
            let from = by_cell.partition_point(|&(c, _)| c < other);
            for &(_, b) in by_cell[from..].iter().take_while(|&&(c, _)| c == other) {
                for &(_, a) in &by_cell[start..end] {
                    join_if_close(&mut dsu, positions, tolerance, a, b);
                }
            }
        }
        start = end;
    }
    let mut out = try_with_capacity(positions.len(), "the weld's representatives")?;
    out.extend((0..positions.len() as u32).map(|v| dsu.find(v)));
    Ok(out)
}

/// The weld applied to a mesh's own arrays, for a file writer (the CLI's `convert --weld`):
/// every corner rewritten to its representative, then the welded vertices removed and the
/// others renumbered in their order, as a file has no use for vertices no element uses.
/// Returns how many vertices were removed. Corner ids out of range stay out of range.
pub fn weld_arrays(
    positions: &mut Vec<DVec3>, triangles: &mut [[u32; 3]], tetrahedra: &mut [[u32; 4]],
    tolerance: f64,
) -> Result<usize> {
    let representative = representatives(positions, tolerance)?;
    // Representatives keep their order; a welded vertex takes its representative's new id
    // (which comes first, being smaller).
    let mut new_id = representative;
    let mut kept = 0u32;
    for v in 0..new_id.len() {
        let r = new_id[v] as usize;
        new_id[v] = if r == v {
            kept += 1;
            kept - 1
        } else {
            new_id[r]
        };
    }
    let renumber = |x: &mut u32| *x = new_id.get(*x as usize).copied().unwrap_or(*x);
    triangles.iter_mut().flatten().for_each(renumber);
    tetrahedra.iter_mut().flatten().for_each(renumber);
    // A vertex is kept when it is the first to take its new id.
    let mut next = 0u32;
    let mut k = 0;
    positions.retain(|_| {
        let keep = new_id[k] == next;
        next += u32::from(keep);
        k += 1;
        keep
    });
    Ok(new_id.len() - kept as usize)
}

type Cell = [i64; 3];

/// The 13 neighbours of a cell that sort after it (lexicographic order of the cell
/// coordinates): with the cell itself, every neighbouring pair of cells is visited once.
const FORWARD_NEIGHBOURS: [Cell; 13] = {
    let mut out = [[0; 3]; 13];
    let mut k = 0;
    let mut i = 0;
    while i < 27 {
        let d = [i / 9 - 1, (i / 3) % 3 - 1, i % 3 - 1];
        if d[0] > 0 || (d[0] == 0 && (d[1] > 0 || (d[1] == 0 && d[2] > 0))) {
            out[k] = d;
            k += 1;
        }
        i += 1;
    }
    out
};

/// The cell `offset` away, or `None` past the range of cell coordinates.
fn shifted(cell: Cell, offset: Cell) -> Option<Cell> {
    Some([
        cell[0].checked_add(offset[0])?,
        cell[1].checked_add(offset[1])?,
        cell[2].checked_add(offset[2])?,
    ])
}

/// Bound on a cell coordinate. Below it, the rounding of `position / side` is under
/// `2 * MAX_CELL * 2^-53 = 2^-12` of a cell, less than the margin `SIDE_MARGIN` leaves.
const MAX_CELL: f64 = (1u64 << 40) as f64;
/// The cell side is the tolerance times this: two vertices at most a tolerance apart are
/// then less than `1 - 2^-11` cells apart along each axis, so that rounding cannot put
/// them two cells apart.
const SIDE_MARGIN: f64 = 1.0 + 1.0 / 1024.0;

/// (cell, vertex) for every vertex, sorted: by cell, then by id. The cell side is a little
/// more than the tolerance (`SIDE_MARGIN`), or larger when the positions reach more than
/// `MAX_CELL` cells from the origin: close vertices are still in the same or neighbouring
/// cells, which only crowd.
fn sorted_cells(positions: &[DVec3], tolerance: f64) -> Result<Vec<(Cell, u32)>> {
    if positions.len() >= NONE as usize {
        return Err(Error::too_large(format!(
            "{} vertices to weld: ids must fit below 2^32 - 1",
            positions.len()
        )));
    }
    let mut reach = 0.0f64;
    for (v, p) in positions.iter().enumerate() {
        if !p.is_finite() {
            return Err(Error::invalid(format!(
                "vertex {v}: position {p} is not finite, so it cannot be welded"
            )));
        }
        reach = reach.max(p.abs().max_element());
    }
    let side = (tolerance * SIDE_MARGIN).max(reach / MAX_CELL);
    let mut out = try_with_capacity(positions.len(), "the weld's grid cells")?;
    out.extend(positions.iter().enumerate().map(|(v, p)| {
        let q = (*p / side).floor();
        ([q.x as i64, q.y as i64, q.z as i64], v as u32)
    }));
    out.sort_unstable();
    Ok(out)
}

fn join_if_close(dsu: &mut Dsu, positions: &[DVec3], tolerance: f64, a: u32, b: u32) {
    if positions[a as usize].distance(positions[b as usize]) <= tolerance {
        dsu.union(a, b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The O(n^2) reference: the components of the "close" graph by repeated union, each
    /// named by its smallest id.
    fn brute_force(positions: &[DVec3], tolerance: f64) -> Vec<u32> {
        let n = positions.len();
        let mut rep: Vec<u32> = (0..n as u32).collect();
        loop {
            let mut changed = false;
            for a in 0..n {
                for b in 0..n {
                    if positions[a].distance(positions[b]) <= tolerance && rep[b] < rep[a] {
                        rep[a] = rep[b];
                        changed = true;
                    }
                }
            }
            if !changed {
                return rep;
            }
        }
    }

    #[test]
    fn matches_brute_force_on_random_points() {
        let mut rnd = crate::util::test_rng(0x5eed_1234);
        for round in 0..200 {
            let n = 1 + round % 60;
            // Coordinates on a coarse lattice plus jitter, so that many pairs fall near the
            // tolerance and near cell borders, negative coordinates included.
            let grid = 2 + round % 5;
            let points: Vec<DVec3> = (0..n)
                .map(|_| {
                    DVec3::from_array(
                        [0; 3].map(|_| rnd(grid) as f64 * 0.5 - 1.0 + rnd(1000) as f64 * 1e-4),
                    )
                })
                .collect();
            let tolerance = [0.05, 0.2, 0.5, 0.71, 1.3][round % 5];
            let fast = representatives(&points, tolerance).unwrap();
            assert_eq!(fast, brute_force(&points, tolerance), "round {round}");
        }
    }

    #[test]
    fn points_exactly_a_tolerance_apart_match_brute_force() {
        // Lattices whose spacing is the tolerance, where every close pair is at the bound
        // and the quotients by the cell side round near cell borders.
        for t in [0.1, 0.3, 1e-3, 7.0, 1.0 / 3.0] {
            for shift in [0.0, -2.5, 1e6] {
                let points: Vec<DVec3> = (0..60)
                    .map(|k| DVec3::new(shift + (k % 6) as f64 * t, (k / 6) as f64 * t, 0.0))
                    .collect();
                let fast = representatives(&points, t).unwrap();
                assert_eq!(fast, brute_force(&points, t), "t {t}, shift {shift}");
            }
        }
    }

    #[test]
    fn tiny_tolerance_over_a_large_reach_welds_exact_copies() {
        // Cells of side 1e-300 cannot number positions near 1e12: the side grows, and
        // exact copies still weld while neighbours one unit in the last place apart do not.
        let x = 1e12f64;
        let next = f64::from_bits(x.to_bits() + 1);
        let p = [x, next, x, -x, -x].map(|c| DVec3::new(c, 1.0, -c));
        let fast = representatives(&p, 1e-300).unwrap();
        assert_eq!(fast, vec![0, 1, 0, 3, 3]);
        assert_eq!(fast, brute_force(&p, 1e-300));
    }

    #[test]
    fn weld_arrays_removes_the_welded_vertices() {
        // 0 and 2 weld (2 goes), 1 and 4 weld (4 goes), 3 stays: 0 1 3 become 0 1 2.
        let mut p = [
            [0., 0., 0.],
            [5., 0., 0.],
            [0.1, 0., 0.],
            [9., 9., 9.],
            [5., 0.1, 0.],
        ]
        .map(DVec3::from_array)
        .to_vec();
        let mut tris = [[0, 1, 3], [2, 4, 3], [9, 2, 1]];
        let mut tets = [[4, 3, 2, 0]];
        assert_eq!(weld_arrays(&mut p, &mut tris, &mut tets, 0.2).unwrap(), 2);
        assert_eq!(tris, [[0, 1, 2], [0, 1, 2], [9, 0, 1]]);
        assert_eq!(tets, [[1, 2, 0, 0]]);
        let want = [[0., 0., 0.], [5., 0., 0.], [9., 9., 9.]].map(DVec3::from_array);
        assert_eq!(p, want);
    }

    #[test]
    fn chains_join_and_smallest_id_wins() {
        // 3 - 1 - 0 - 2 along x, each 0.9 apart at tolerance 1; 4 far away.
        let p = [0.0, -0.9, 0.9, -1.8, 50.0].map(|x| DVec3::new(x, 0.0, 0.0));
        assert_eq!(representatives(&p, 1.0).unwrap(), vec![0, 0, 0, 0, 4]);
        let w = weld_elements(Cow::Borrowed(&[[3, 4, 2], [9, 1, 4]]), &p, 1.0).unwrap();
        assert_eq!(&*w.elements, &[[0, 4, 0], [9, 0, 4]]);
        assert_eq!(w.welded_vertices, 3);
    }

    #[test]
    fn bad_tolerances_and_positions_are_errors() {
        let p = [DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0)];
        let e = weld_elements(Cow::Borrowed(&[[0, 1, 0]]), &p, 1e-3)
            .err()
            .unwrap();
        assert!(e.message.contains("vertex 1"), "{}", e.message);
        for t in [-1.0, f64::NAN, f64::INFINITY] {
            let e = weld_elements(Cow::Borrowed(&[[0, 1, 0]]), &p[..1], t)
                .err()
                .unwrap();
            assert!(e.message.contains("weld_tolerance"), "{}", e.message);
        }
        let empty = weld_elements::<3>(Cow::Borrowed(&[]), &[], 0.5).unwrap(); // an empty mesh is no error
        assert!(empty.elements.is_empty() && empty.welded_vertices == 0);
        let e = weld_elements(Cow::Borrowed(&[[0, 1, 2]]), &[], 0.5)
            .err()
            .unwrap();
        assert!(
            e.message.contains("without vertex positions"),
            "{}",
            e.message
        );
        let off = weld_elements(Cow::Borrowed(&[[0, 1, 2]]), &[], 0.0).unwrap();
        assert!(matches!(off.elements, Cow::Borrowed(_)));
    }
}
