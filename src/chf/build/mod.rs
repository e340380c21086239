//! From a tetrahedron list to a CHF: validate, drop degenerate tetrahedra, match
//! half-faces, orient, split non-manifold vertices, name the edges, then build the
//! requested level. Everything changed or left unpaired is counted in the report.

pub(crate) mod level2;
pub(crate) mod level3;
mod orient;
pub(crate) mod report;
mod soup;
mod split;
mod strict;

use self::orient::flipped_id;
pub use self::report::ChfBuildReport;
use self::strict::{strict_after_split, strict_faces};
use crate::NONE;
use crate::chf::Chf;
use crate::chf::edges::{self, EdgeCensus};
use crate::chf::ids::tet;
use crate::chf::star_pass::{self as stars, Pairs, merged};
use crate::error::{Error, Result};
use crate::util::rank::RankBits;
use glam::DVec3;

/// How to build: the level (0..=3) and whether non-manifold input is an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChfBuildOptions {
    pub level: u8,
    /// Reject non-manifold faces, edges and vertices and duplicate tetrahedra instead of
    /// keeping them.
    pub strict: bool,
    /// Threads for the build: 0 (the default) for as many as the machine runs at once, 1
    /// for the calling thread alone. The structure is the same whatever the number.
    pub threads: usize,
}

impl Default for ChfBuildOptions {
    fn default() -> Self {
        ChfBuildOptions {
            level: 2,
            strict: false,
            threads: 0,
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
    let n_threads = crate::util::par::build_threads(options.threads, tets.len());
    let mut soup = soup::soup(tets, n_vertices, positions, &mut report, n_threads)?;
    let tet_origin = std::mem::take(&mut soup.tet_origin);
    let origin_of = |t: u32| {
        if tet_origin.is_empty() {
            t
        } else {
            tet_origin[t as usize]
        }
    };

    // One pass over the vertex stars: faces and their pairs, pieces, edges, and `VH` and the
    // edge bits for level 2. Level 0 keeps no pairs unless it must orient or split.
    let tables = options.level >= 2;
    let first_pairs = if options.level == 0 {
        Pairs::Census
    } else {
        Pairs::Partners
    };
    let star_threads = stars::threads_for(soup.v.len() / 4, n_vertices, n_threads);
    let mut stars = stars::stars(&soup.v, n_vertices, &[], first_pairs, tables, star_threads);
    let (faces, mut partner) = stars.faces.take().expect("faces were asked for");
    if partner.is_empty() && (faces.same_direction || stars.split_needed) {
        partner = stars::stars(
            &soup.v,
            n_vertices,
            &[],
            Pairs::Partners,
            false,
            star_threads,
        )
        .faces
        .expect("faces were asked for")
        .1;
    }
    // Triples of two half-faces: all of them are pairs unless there are seams.
    let pairs = faces.input_faces - faces.boundary_faces - faces.non_manifold_faces;
    report.input_faces = faces.input_faces;
    report.boundary_faces = faces.boundary_faces;
    report.non_manifold_faces = faces.non_manifold_faces;
    report.non_manifold_face_examples = faces.non_manifold_face_examples;
    report.duplicate_tetrahedra = faces.duplicates;
    report.duplicate_examples = faces
        .duplicate_examples
        .iter()
        .map(|&[s, t]| [origin_of(s), origin_of(t)])
        .collect();
    let mut non_manifold = faces.non_manifold;
    if options.strict {
        strict_faces(&report, &soup.v, &non_manifold, &origin_of)?;
    }

    // Orient only when some pair still runs the same way after the soup's flips: otherwise
    // the pairs are the opposites (see `soup.rs`) and the stars are right as found.
    let (o, seams, links) = if !faces.same_direction {
        report.flipped_tetrahedra = soup.flipped;
        (partner, Vec::new(), Vec::new())
    } else {
        // Back to the input's numbering, then orient as given.
        let unflip = |hf: u32| {
            if soup.is_flipped(tet(hf)) {
                flipped_id(hf)
            } else {
                hf
            }
        };
        let mut input_partner = vec![NONE; partner.len()];
        for (h, &g) in partner.iter().enumerate() {
            if g != NONE {
                input_partner[unflip(h as u32) as usize] = unflip(g);
            }
        }
        drop(partner);
        for hf in non_manifold.iter_mut() {
            *hf = unflip(*hf);
        }
        soup.unflip();
        let oriented = orient::orient(&mut soup.v, &input_partner, &soup.sign);
        drop(input_partner);
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
        stars = stars::stars(
            &soup.v,
            n_vertices,
            &oriented.seams,
            Pairs::No,
            tables,
            star_threads,
        );
        (oriented.o, oriented.seams, oriented.links)
    };
    non_manifold.sort_unstable();
    let mut v = std::mem::take(&mut soup.v);
    drop(soup);

    let mut copies = Vec::new();
    if stars.split_needed {
        let split = split::split(&mut v, &o, &links, n_vertices);
        report.split_vertices = split.split_vertices;
        report.split_vertex_examples = split.split_examples;
        report.seam_split_vertices = split.seam_split_vertices;
        report.added_vertices = split.copies.len();
        copies = split.copies;
    }
    drop(links);
    let n_total = n_vertices + copies.len();
    if n_total >= NONE as usize {
        return Err(Error::too_large(format!(
            "splitting non-manifold vertices makes {n_total} vertices: ids must fit below 2^32 - 1"
        )));
    }
    let vertex_origin: Vec<u32> = if copies.is_empty() {
        Vec::new()
    } else {
        (0..n_vertices as u32)
            .chain(copies.iter().copied())
            .collect()
    };
    let census = if copies.is_empty() {
        std::mem::take(&mut stars.census)
    } else {
        // Every star is one piece now; the census groups by input pair.
        let flagged = merged(&non_manifold, &seams);
        stars = stars::stars(&v, n_total, &flagged, Pairs::No, true, star_threads);
        debug_assert!(!stars.split_needed);
        edges::census(&v, &stars.edge_bits, n_vertices, |x| {
            vertex_origin[x as usize]
        })
    };
    let edge_bits = std::mem::take(&mut stars.edge_bits);
    record_edges(&mut report, &census);
    if options.strict {
        strict_after_split(&report, &v, &vertex_origin, &origin_of)?;
    }

    let mut positions = positions.to_vec();
    if !positions.is_empty() {
        for &c in &copies {
            positions.push(positions[c as usize]);
        }
    }
    // Canonical half-faces: the unpaired ones and one per pair.
    let num_faces = if seams.is_empty() {
        v.len() - pairs
    } else {
        o.iter()
            .enumerate()
            .filter(|&(hf, &g)| g == NONE || (hf as u32) < g)
            .count()
    };

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
        num_edges: stars.num_edges,
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
        level2::build(&mut chf, edge_bits, std::mem::take(&mut stars.vh));
        chf.level = 2;
    }
    if options.level >= 3 {
        chf.boundary = Some(level3::build(&chf, n_threads)?);
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
