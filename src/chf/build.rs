//! From a tetrahedron list to a CHF: validate, drop degenerate tetrahedra, match
//! half-faces, orient, split non-manifold vertices, name the edges, then build the
//! requested level. Everything changed or left unpaired is counted in the report.

use super::edges::{self, EdgeCensus};
use super::ids::tet;
use super::matching::Groups;
use super::orient::{self, flipped_id};
use super::report::{ChfBuildReport, push_example};
use super::strict::{strict_after_split, strict_faces};
use super::{Chf, level2, level3, split};
use crate::NONE;
use crate::error::{Error, Result};
use crate::rank::RankBits;
use glam::DVec3;

/// How to build: the level (0..=3) and whether non-manifold input is an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChfBuildOptions {
    pub level: u8,
    /// Reject non-manifold faces, edges and vertices and duplicate tetrahedra instead of
    /// keeping them.
    pub strict: bool,
}

impl Default for ChfBuildOptions {
    fn default() -> Self {
        ChfBuildOptions {
            level: 2,
            strict: false,
        }
    }
}

impl ChfBuildOptions {
    pub fn level(level: u8) -> Self {
        ChfBuildOptions {
            level,
            ..Self::default()
        }
    }
}

/// Largest tetrahedron count whose half-face ids (`4T`) fit below `NONE`.
pub const MAX_TETRAHEDRA: usize = (u32::MAX as usize) / 4;

pub(crate) fn build(
    tets: &[[u32; 4]],
    n_vertices: usize,
    positions: &[DVec3],
    options: ChfBuildOptions,
) -> Result<Chf> {
    check_sizes(tets.len(), n_vertices, positions.len(), options.level)?;
    let mut report = ChfBuildReport {
        input_tetrahedra: tets.len(),
        input_vertices: n_vertices,
        ..ChfBuildReport::default()
    };

    // Soup: range check, degenerate tetrahedra dropped, determinant signs.
    let mut v: Vec<u32> = Vec::with_capacity(4 * tets.len());
    // Stays empty (the identity) until the first dropped tetrahedron.
    let mut tet_origin: Vec<u32> = Vec::new();
    let mut remapped = false;
    let mut sign: Vec<i8> = Vec::new();
    for (t, tet) in tets.iter().enumerate() {
        for (i, &x) in tet.iter().enumerate() {
            if x as usize >= n_vertices {
                return Err(Error::out_of_range(format!(
                    "tetrahedron {t}, corner {i}: vertex {x} out of range (there are {n_vertices} vertices)"
                )));
            }
        }
        let [a, b, c, d] = *tet;
        if a == b || a == c || a == d || b == c || b == d || c == d {
            if !remapped {
                remapped = true;
                tet_origin.extend(0..t as u32);
            }
            report.dropped_degenerate += 1;
            push_example(&mut report.degenerate_examples, t as u32);
            continue;
        }
        if remapped {
            tet_origin.push(t as u32);
        }
        v.extend_from_slice(tet);
        if !positions.is_empty() {
            let [p0, p1, p2, p3] = tet.map(|x| positions[x as usize]);
            let det = (p1 - p0).dot((p2 - p0).cross(p3 - p0));
            let s = if det > 0.0 {
                1
            } else if det < 0.0 {
                -1
            } else {
                report.zero_volume += 1;
                push_example(&mut report.zero_volume_examples, t as u32);
                0
            };
            sign.push(s);
        }
    }
    let origin_of = |t: u32| {
        if tet_origin.is_empty() {
            t
        } else {
            tet_origin[t as usize]
        }
    };

    // Match on vertex triples; triples of exactly two half-faces are partners.
    let mut partner = vec![NONE; v.len()];
    let mut non_manifold: Vec<u32> = Vec::new();
    Groups::new(&v, n_vertices).for_each(|triple, group| {
        report.input_faces += 1;
        match group.len() {
            1 => report.boundary_faces += 1,
            2 => {
                partner[group[0] as usize] = group[1];
                partner[group[1] as usize] = group[0];
            }
            _ => {
                report.non_manifold_faces += 1;
                push_example(&mut report.non_manifold_face_examples, triple);
                non_manifold.extend_from_slice(group);
            }
        }
        count_duplicates(&v, triple[2], group, &mut report, &origin_of);
    });
    if options.strict {
        strict_faces(&report, &v, &non_manifold, &origin_of)?;
    }

    let oriented = orient::orient(&mut v, &partner, &sign);
    drop(partner);
    report.flipped_tetrahedra = oriented.flipped_count;
    report.non_orientable_components = oriented.non_orientable_components;
    report.non_orientable_examples = oriented
        .non_orientable_examples
        .iter()
        .map(|&t| origin_of(t))
        .collect();
    report.inverted_tetrahedra = oriented.inverted;
    report.inverted_examples = oriented
        .inverted_examples
        .iter()
        .map(|&t| origin_of(t))
        .collect();
    report.seam_faces = oriented.seams.len() / 2;
    for hf in non_manifold.iter_mut() {
        if oriented.flipped[tet(*hf) as usize] {
            *hf = flipped_id(*hf);
        }
    }
    non_manifold.sort_unstable();
    let (o, seams, links) = (oriented.o, oriented.seams, oriented.links);
    drop(oriented.flipped);

    let split = split::split(&mut v, &o, &links, n_vertices);
    drop(links);
    report.split_vertices = split.split_vertices;
    report.split_vertex_examples = split.split_examples;
    report.seam_split_vertices = split.seam_split_vertices;
    report.added_vertices = split.copies.len();
    let n_total = n_vertices + split.copies.len();
    if n_total >= NONE as usize {
        return Err(Error::too_large(format!(
            "splitting non-manifold vertices makes {n_total} vertices: ids must fit below 2^32 - 1"
        )));
    }
    let vertex_origin: Vec<u32> = if split.copies.is_empty() {
        Vec::new()
    } else {
        (0..n_vertices as u32)
            .chain(split.copies.iter().copied())
            .collect()
    };

    let edge_bits = edges::canonical_slots(&v, &o);
    let census = edges::census(&v, &edge_bits, n_vertices, |x| {
        if vertex_origin.is_empty() {
            x
        } else {
            vertex_origin[x as usize]
        }
    });
    record_edges(&mut report, &census);
    if options.strict {
        strict_after_split(&report, &v, &vertex_origin, &origin_of)?;
    }

    let mut positions = positions.to_vec();
    if !positions.is_empty() {
        for &c in &split.copies {
            positions.push(positions[c as usize]);
        }
    }
    let num_faces = o
        .iter()
        .enumerate()
        .filter(|&(hf, &g)| g == NONE || (hf as u32) < g)
        .count();

    let mut chf = Chf {
        level: 1,
        n_input_vertices: n_vertices,
        n_vertices: n_total,
        v,
        o,
        vh: Vec::new(),
        face_bits: RankBits::default(),
        fh: Vec::new(),
        edge_bits: RankBits::default(),
        eh: Vec::new(),
        boundary: None,
        num_edges: edge_bits.ones(),
        num_faces,
        positions,
        vertex_origin,
        tet_origin,
        non_manifold,
        seams,
        multi_fan: census.multi_fan,
        report,
    };
    if options.level == 0 {
        chf.o = Vec::new();
        chf.level = 0;
    }
    if options.level >= 2 {
        level2::build(&mut chf, edge_bits);
        chf.level = 2;
    }
    if options.level >= 3 {
        chf.boundary = Some(level3::build(&chf)?);
        chf.level = 3;
    }
    Ok(chf)
}

/// Level, counts and lengths, before anything is allocated.
fn check_sizes(n_tets: usize, n_vertices: usize, n_positions: usize, level: u8) -> Result<()> {
    if level > 3 {
        return Err(Error::out_of_range(format!(
            "level {level} is not in 0..=3"
        )));
    }
    if n_vertices >= NONE as usize {
        return Err(Error::too_large(format!(
            "{n_vertices} vertices: ids must fit below 2^32 - 1"
        )));
    }
    if n_tets > MAX_TETRAHEDRA {
        return Err(Error::too_large(format!(
            "tetrahedron {MAX_TETRAHEDRA} (of {n_tets}): half-face ids must fit below 2^32 - 1, so at most {MAX_TETRAHEDRA} tetrahedra"
        )));
    }
    if n_positions != 0 && n_positions != n_vertices {
        return Err(Error::invalid(format!(
            "{n_positions} positions given for {n_vertices} vertices"
        )));
    }
    Ok(())
}

fn record_edges(report: &mut ChfBuildReport, census: &EdgeCensus) {
    report.input_edges = census.input_edges;
    report.non_manifold_edges = census.non_manifold;
    report.non_manifold_edge_examples = census.non_manifold_examples.clone();
    report.kept_non_manifold_edges = census.kept;
    report.kept_non_manifold_edge_examples = census.kept_examples.clone();
}

/// Two tetrahedra with the same four vertices share all four triples; count each such
/// pair once, on the triple made of their three smallest vertices (the fourth vertex,
/// `V[hf]`, is the one opposite the half-face).
fn count_duplicates(
    v: &[u32],
    max: u32,
    group: &[u32],
    report: &mut ChfBuildReport,
    origin_of: &impl Fn(u32) -> u32,
) {
    if group.len() < 2 {
        return;
    }
    let fourth = |hf: u32| v[hf as usize];
    let mut by_fourth: Vec<(u32, u32)> = group
        .iter()
        .map(|&hf| (fourth(hf), hf))
        .filter(|&(d, _)| d > max)
        .collect();
    by_fourth.sort_unstable();
    for run in by_fourth.chunk_by(|x, y| x.0 == y.0) {
        for (i, &(_, a)) in run.iter().enumerate() {
            for &(_, b) in &run[i + 1..] {
                report.duplicate_tetrahedra += 1;
                push_example(
                    &mut report.duplicate_examples,
                    [origin_of(tet(a)), origin_of(tet(b))],
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ErrorKind;

    #[test]
    fn sizes_are_checked_before_allocating() {
        assert!(check_sizes(MAX_TETRAHEDRA, 10, 0, 3).is_ok());
        let e = check_sizes(MAX_TETRAHEDRA + 1, 10, 0, 2).unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge);
        assert!(e.message.contains(&format!("tetrahedron {MAX_TETRAHEDRA}")));
        assert!(4 * MAX_TETRAHEDRA < NONE as usize);
        assert!(4 * (MAX_TETRAHEDRA + 1) > NONE as usize);
        let e = check_sizes(1, NONE as usize, 0, 2).unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge);
        assert_eq!(
            check_sizes(1, 4, 3, 2).unwrap_err().kind,
            ErrorKind::InvalidInput
        );
        assert_eq!(
            check_sizes(1, 4, 0, 4).unwrap_err().kind,
            ErrorKind::OutOfRange
        );
    }
}
