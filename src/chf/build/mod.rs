//! From a tetrahedron list to a CHF: validate, drop degenerate tetrahedra, match
//! half-faces, orient, split non-manifold vertices, name the edges, then build the
//! requested level. Everything changed or left unpaired is counted in the report.

mod budget;
pub(crate) mod level2;
pub(crate) mod level3;
mod orient;
pub(crate) mod report;
mod soup;
mod split;
pub(crate) mod stream;
mod strict;

pub(crate) use self::orient::flipped_id;
pub use self::report::BuildReport;
use self::soup::Soup;
use self::strict::Strict;
use crate::NONE;
use crate::chf::Chf;
use crate::chf::edges::{self, EdgeCensus};
use crate::chf::ids::tet;
use crate::chf::star_pass::link::FaceCensus;
use crate::chf::star_pass::{self as stars, Pairs, StarPass, Stars, merged};
use crate::error::{Error, Result};
use crate::util::alloc::try_vec;
use crate::util::input::{Input, positions_with_copies};
use crate::util::options::{Cells, check_input};
use crate::util::origin::OriginMap;
use crate::util::progress::BuildProgress;
use glam::DVec3;
use std::borrow::Cow;

pub use crate::util::options::BuildOptions;
pub use budget::estimated_build_bytes;
pub use stream::SweepLimits;

/// Largest tetrahedron count whose half-face ids (`4T`) fit below `NONE`.
pub const MAX_TETRAHEDRA: usize = (u32::MAX as usize) / 4;

/// How the build orients each face-connected component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Orientation {
    /// The way most of its determinants agree with (positive volumes on a valid mesh): a
    /// build from the user's input.
    ByDeterminants,
    /// As given where it is consistent, else flipping the fewest tetrahedra; determinants
    /// only count zero volumes and inversions. A rebuild of an edited CHF's live
    /// tetrahedra: garbage collection renumbers, it does not turn a component over.
    AsGiven,
}

/// A build from the user's input, oriented by the determinants.
pub(crate) fn build(
    input: Input<'_, 4>, options: BuildOptions, progress: BuildProgress,
) -> Result<Chf> {
    build_oriented(input, options, progress, Orientation::ByDeterminants)
}

/// The pipeline: each step is a function below, in this order.
pub(crate) fn build_oriented(
    input: Input<'_, 4>, options: BuildOptions, progress: BuildProgress, orientation: Orientation,
) -> Result<Chf> {
    let (mut report, welded) = prepared(input, &options)?;
    let (tets, n_vertices, positions) = (welded.elements, welded.n_vertices, welded.positions);
    let n_threads = crate::util::par::build_threads(options.threads, tets.len());
    // Steps 1 to 3, each component turned the way `orientation` says.
    let how = (options, orientation);
    progress.at(0.0, "stars and orientation");
    let Oriented {
        mut v,
        o,
        seams,
        links,
        mut non_manifold,
        mut stars,
        tet_origin,
        pairs,
        pass,
    } = oriented(tets, n_vertices, &positions, how, &mut report)?;
    let origin_of = |t: u32| tet_origin.get(t);
    non_manifold.sort_unstable();
    // 4. Vertex split, when some star is in several pieces.
    progress.at(0.5, "splitting vertices");
    let copies = if stars.split_needed {
        split_vertices(&mut v, &o, &links, n_vertices, &mut report)?
    } else {
        Vec::new()
    };
    drop(links);
    let n_total = n_vertices + copies.len();
    let vertex_origin = OriginMap::with_copies(n_vertices, &copies)?;
    // 5. Edges: the census by input vertex pair (after a split, one more star pass).
    progress.at(0.6, "edges");
    let census = if copies.is_empty() {
        std::mem::take(&mut stars.census)
    } else {
        // Every star is one piece now; the census groups by input pair.
        let flagged = merged(&non_manifold, &seams)?;
        stars = stars::stars(&v, n_total, &flagged, pass.with_tables())?;
        debug_assert!(!stars.split_needed);
        edges::census(&v, &stars.edge_bits, n_vertices, |x| {
            vertex_origin[x as usize]
        })?
    };
    record_edges(&mut report, &census);
    if options.strict {
        let strict = Strict {
            report: &report,
            v: &v,
            origin_of: &origin_of,
        };
        strict.after_split(&vertex_origin)?;
    }
    // 6. Level 1, then the levels above it.
    let chf = Chf {
        level: 1,
        n_input_vertices: n_vertices,
        n_vertices: n_total,
        num_edges: stars.num_edges,
        num_faces: count_faces(&o, &seams, v.len() - pairs),
        positions: positions_with_copies(positions, &copies)?.into(),
        vertex_origin,
        tet_origin,
        non_manifold,
        seams,
        multi_fan: census.multi_fan,
        report,
        v: v.into(),
        o: o.into(),
        ..Chf::empty()
    };
    progress.at(0.75, "levels 2 and 3");
    let chf = raise(chf, options, stars, n_threads)?;
    progress.at(1.0, "done");
    Ok(chf)
}

/// The checks before anything is allocated, the report of the input, and the weld: the
/// report and the input with its tetrahedra welded.
fn prepared<'a>(
    input: Input<'a, 4>, options: &BuildOptions,
) -> Result<(BuildReport, Input<'a, 4>)> {
    let Input {
        elements: tets,
        n_vertices,
        positions,
    } = input;
    check_input(
        options,
        &TETRAHEDRA,
        tets.len(),
        n_vertices,
        positions.len(),
    )?;
    check_budget(tets.len(), n_vertices, !positions.is_empty(), options)?;
    let mut report = BuildReport::of_input(tets.len(), n_vertices);
    (
        report.non_finite_vertices,
        report.non_finite_vertex_examples,
    ) = crate::util::non_finite_vertices(&positions);
    let welded = crate::util::weld::weld_elements(tets, &positions, options.weld_tolerance)?;
    report.welded_vertices = welded.welded_vertices;
    let welded = Input {
        elements: welded.elements,
        n_vertices,
        positions,
    };
    Ok((report, welded))
}

/// Refuses, before allocating, a build whose estimate exceeds the memory limit.
fn check_budget(
    tets: usize, n_vertices: usize, positions: bool, options: &BuildOptions,
) -> Result<()> {
    let estimate = budget::estimated_build_bytes(tets, n_vertices, positions, options.level);
    crate::util::budget::check(options, estimate, || {
        format!(
            "a CHF build of {tets} tetrahedra at level {}",
            options.level
        )
    })
}

/// What steps 1 to 3 leave: an oriented `V` with its pairs, before the vertex split.
struct Oriented {
    v: Vec<u32>,
    o: Vec<u32>,
    seams: Vec<u32>,
    /// With seams, every pair (for the split); else empty.
    links: Vec<u32>,
    non_manifold: Vec<u32>,
    /// The last star pass, on this `V`.
    stars: Stars,
    tet_origin: OriginMap,
    /// Triples of two half-faces.
    pairs: usize,
    /// The build's star pass, pairs aside.
    pass: StarPass,
}

/// Steps 1 to 3: the soup, the star pass, and the orientation when some pair needs it.
fn oriented(
    tets: Cow<'_, [[u32; 4]]>, n_vertices: usize, positions: &[DVec3],
    (options, orientation): (BuildOptions, Orientation), report: &mut BuildReport,
) -> Result<Oriented> {
    let n_threads = crate::util::par::build_threads(options.threads, tets.len());
    // 1. Soup: range check, degenerate tetrahedra dropped, flips by the determinant.
    let mut soup = soup::soup(tets, n_vertices, positions, report, n_threads)?;
    if orientation == Orientation::AsGiven {
        soup.unflip();
    }
    let tet_origin = OriginMap::from(std::mem::take(&mut soup.tet_origin));
    let origin_of = |t: u32| tet_origin.get(t);
    // 2. The star pass: faces and their pairs, pieces, edges, `VH` and the edge bits.
    let pass = StarPass {
        pairs: Pairs::No,
        tables: options.level >= 2,
        threads: stars::threads_for(soup.v.len() / 4, n_vertices, n_threads),
    };
    let (mut stars, faces, partner) = first_star_pass(&soup.v, n_vertices, pass, options.level)?;
    let pairs = faces.pairs();
    let same_direction = faces.same_direction;
    let mut non_manifold = record_faces(report, faces, &origin_of);
    if options.strict {
        let strict = Strict {
            report,
            v: &soup.v,
            origin_of: &origin_of,
        };
        strict.faces(&non_manifold)?;
    }
    // 3. Orientation, only when some pair still runs the same way after the soup's flips:
    // otherwise the pairs are the opposites (see `soup.rs`) and the stars are right as found.
    let (o, seams, links) = if !same_direction {
        report.flipped_tetrahedra = soup.flipped;
        if orientation == Orientation::AsGiven {
            (report.inverted_tetrahedra, report.inverted_examples) = soup.negative(origin_of);
        }
        (partner, Vec::new(), Vec::new())
    } else {
        let oriented = orient_soup(
            &mut soup,
            partner,
            &mut non_manifold,
            orientation,
            report,
            origin_of,
        )?;
        stars = stars::stars(&soup.v, n_vertices, &oriented.seams, pass)?;
        (oriented.o, oriented.seams, oriented.links)
    };
    Ok(Oriented {
        v: std::mem::take(&mut soup.v),
        o,
        seams,
        links,
        non_manifold,
        stars,
        tet_origin,
        pairs,
        pass,
    })
}

/// The build's first star pass, on the soup's `V`: the face census and the partners
/// (level 0 keeps no pairs unless it must orient or split), with `VH` and the edge bits
/// for level 2.
fn first_star_pass(
    v: &[u32], n_vertices: usize, pass: StarPass, level: u8,
) -> Result<(Stars, FaceCensus, Vec<u32>)> {
    let pairs = if level == 0 {
        Pairs::Census
    } else {
        Pairs::Partners
    };
    let mut stars = stars::stars(v, n_vertices, &[], StarPass { pairs, ..pass })?;
    let (faces, mut partner) = stars.faces.take().expect("faces were asked for");
    if partner.is_empty() && (faces.same_direction || stars.split_needed) {
        let pass = StarPass {
            pairs: Pairs::Partners,
            tables: false,
            ..pass
        };
        partner = stars::stars(v, n_vertices, &[], pass)?
            .faces
            .expect("faces were asked for")
            .1;
    }
    Ok((stars, faces, partner))
}

/// The face counts into the report; returns the non-manifold half-faces.
fn record_faces(
    report: &mut BuildReport, faces: FaceCensus, origin_of: &impl Fn(u32) -> u32,
) -> Vec<u32> {
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
    faces.non_manifold
}

/// Back to the input's numbering, then orients as given (`orientation` chooses each
/// component's side): `non_manifold` follows the flips.
fn orient_soup(
    soup: &mut Soup, partner: Vec<u32>, non_manifold: &mut [u32], orientation: Orientation,
    report: &mut BuildReport, origin_of: impl Fn(u32) -> u32,
) -> Result<orient::Oriented> {
    let unflip = |hf: u32| {
        if soup.is_flipped(tet(hf)) {
            flipped_id(hf)
        } else {
            hf
        }
    };
    let mut input_partner = try_vec(partner.len(), NONE, "the partners")?;
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
    let oriented = orient::orient(&mut soup.v, &input_partner, &soup.sign, orientation)?;
    drop(input_partner);
    let origins = |ts: &[u32]| ts.iter().map(|&t| origin_of(t)).collect();
    let flips = &oriented.flips;
    report.flipped_tetrahedra = flips.flipped_count;
    report.non_orientable_components = flips.non_orientable_components;
    report.non_orientable_examples = origins(&flips.non_orientable_examples);
    report.inverted_tetrahedra = oriented.inverted;
    report.inverted_examples = origins(&oriented.inverted_examples);
    report.seam_faces = oriented.seams.len() / 2;
    for hf in non_manifold.iter_mut() {
        if flips.flipped[tet(*hf) as usize] {
            *hf = flipped_id(*hf);
        }
    }
    Ok(oriented)
}

/// Splits the non-manifold vertices of `v`; returns the copies' origins.
fn split_vertices(
    v: &mut [u32], o: &[u32], links: &[u32], n_vertices: usize, report: &mut BuildReport,
) -> Result<Vec<u32>> {
    let split = split::split(v, o, links, n_vertices)?;
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
    Ok(split.copies)
}

/// Canonical half-faces: the unpaired ones and one per pair (`unpaired_or_pairs` when
/// there are no seams).
fn count_faces(o: &[u32], seams: &[u32], unpaired_or_pairs: usize) -> usize {
    if seams.is_empty() {
        unpaired_or_pairs
    } else {
        o.iter()
            .enumerate()
            .filter(|&(hf, &g)| g == NONE || (hf as u32) < g)
            .count()
    }
}

impl StarPass {
    /// The same pass with the level-2 tables.
    fn with_tables(self) -> StarPass {
        StarPass {
            tables: true,
            ..self
        }
    }
}

impl FaceCensus {
    /// Triples of two half-faces: all of them are pairs unless there are seams.
    fn pairs(&self) -> usize {
        self.input_faces - self.boundary_faces - self.non_manifold_faces
    }
}

impl BuildReport {
    /// The report of a build from `tets` tetrahedra over `vertices` vertices, before any
    /// step.
    fn of_input(tets: usize, vertices: usize) -> Self {
        BuildReport {
            input_tetrahedra: tets,
            input_vertices: vertices,
            ..BuildReport::default()
        }
    }
}

/// From level 1 to `level`, with the tables of the last star pass.
fn raise(mut chf: Chf, options: BuildOptions, mut stars: Stars, n_threads: usize) -> Result<Chf> {
    let level = options.level;
    let edge_bits = std::mem::take(&mut stars.edge_bits);
    if level == 0 {
        chf.o = Vec::new().into();
        chf.level = 0;
    }
    if level >= 2 {
        level2::build(&mut chf, edge_bits, std::mem::take(&mut stars.vh))?;
        chf.level = 2;
    }
    if level >= 3 {
        let m = chf.memory_bytes();
        let limit = crate::util::budget::remaining(&options, m.topology + m.positions + m.maps);
        chf.boundary = Some(level3::build(&chf, n_threads, limit)?);
        chf.level = 3;
    }
    Ok(chf)
}

/// A CHF build's elements, for the size checks.
pub(crate) const TETRAHEDRA: Cells = Cells {
    per: 4,
    max: MAX_TETRAHEDRA,
    name: "tetrahedra",
    ids: "half-face",
};

/// Whether a build of `n_tets` tetrahedra on `n_vertices` vertices fits, checked from the
/// counts alone (the build checks this first, before it allocates or reads anything): at
/// most [`MAX_TETRAHEDRA`] tetrahedra, fewer than 2^32 - 1 vertices, and at most
/// [`MAX_UNUSED_VERTICES`](crate::chf::MAX_UNUSED_VERTICES) vertices beyond the
/// `4 * n_tets` the tetrahedra can name. A failure is `ErrorKind::TooLarge`, naming the
/// limit.
pub fn check_counts(n_tets: usize, n_vertices: usize) -> Result<()> {
    crate::util::options::check_counts(&TETRAHEDRA, n_tets, n_vertices)
}

fn record_edges(report: &mut BuildReport, census: &EdgeCensus) {
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
        let check = |n_tets, n_vertices, n_positions, level| {
            let options = BuildOptions::level(level);
            check_input(&options, &TETRAHEDRA, n_tets, n_vertices, n_positions)
        };
        assert!(check(MAX_TETRAHEDRA, 10, 0, 3).is_ok());
        let e = check(MAX_TETRAHEDRA + 1, 10, 0, 2).unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge);
        assert!(
            e.message
                .contains(&format!("at most {MAX_TETRAHEDRA} tetrahedra"))
        );
        assert!(4 * MAX_TETRAHEDRA < NONE as usize);
        assert!(4 * (MAX_TETRAHEDRA + 1) > NONE as usize);
        let e = check(1, NONE as usize, 0, 2).unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge);
        assert_eq!(check(1, 4, 3, 2).unwrap_err().kind, ErrorKind::InvalidInput);
        assert_eq!(check(1, 4, 0, 4).unwrap_err().kind, ErrorKind::OutOfRange);
    }

    #[test]
    fn non_finite_vertices_are_reported_and_give_no_determinant_sign() {
        // Two tetrahedra on a shared face, the second given inverted; vertex 4 is NaN in
        // one coordinate, vertex 5 infinite, and unused.
        let p = |x, y, z| DVec3::new(x, y, z);
        let positions = [
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(f64::NAN, 1.0, 1.0),
            p(0.0, f64::INFINITY, 0.0),
        ];
        let tets = [[0, 1, 2, 3], [1, 2, 3, 4]];
        let chf = Chf::from_tetrahedra(&tets, 6, &positions, BuildOptions::level(1)).unwrap();
        let r = chf.report();
        assert_eq!(
            (r.non_finite_vertices, &r.non_finite_vertex_examples[..]),
            (2, &[4, 5][..])
        );
        // The NaN tetrahedron is neither zero-volume nor inverted: it has no sign, and its
        // neighbour orients it.
        assert_eq!(
            (r.zero_volume, r.inverted_tetrahedra, r.seam_faces),
            (0, 0, 0)
        );
        chf.validate().unwrap();
        let finite = [
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(1.0, 1.0, 1.0),
        ];
        let clean = Chf::from_tetrahedra(&tets, 5, &finite, BuildOptions::level(1)).unwrap();
        assert_eq!(clean.report().non_finite_vertices, 0);
        assert!(clean.report().non_finite_vertex_examples.is_empty());
    }

    /// Two tetrahedra on a shared face, both given with negative determinants: the build
    /// for users turns the component over, the rebuild of an edited CHF keeps it and counts
    /// the inversions. On the shortcut (the pairs run opposite as given), and through the
    /// propagation (a third tetrahedron given the wrong way round: as given, only that
    /// one turns over).
    #[test]
    fn as_given_keeps_each_components_side_and_counts_inversions() {
        let corners = [
            [0, 0, 0],
            [0, 1, 0],
            [1, 0, 0],
            [0, 0, 1],
            [1, 1, 1],
            [1, -1, 1],
        ];
        let positions = corners.map(|c| DVec3::from_array(c.map(f64::from)));
        let build = |tets: &[[u32; 4]], orientation| {
            let input = Input::borrowed(tets, 6, &positions);
            let progress = BuildProgress::default();
            build_oriented(input, BuildOptions::level(2), progress, orientation).unwrap()
        };
        let counts = |chf: &Chf| {
            let r = chf.report();
            (r.flipped_tetrahedra, r.inverted_tetrahedra)
        };
        let two = [[0, 1, 2, 3], [2, 1, 4, 3]];
        let three = [[0, 1, 2, 3], [2, 1, 4, 3], [1, 0, 3, 5]];
        assert_eq!(counts(&build(&two, Orientation::ByDeterminants)), (2, 0));
        assert_eq!(counts(&build(&three, Orientation::ByDeterminants)), (2, 1));
        let kept = [two.as_flattened(), &[0, 1, 2, 3, 2, 1, 4, 3, 1, 3, 0, 5]];
        for (tets, kept) in [&two[..], &three[..]].into_iter().zip(kept) {
            let chf = build(tets, Orientation::AsGiven);
            chf.validate().unwrap();
            assert_eq!(chf.half_face_vertices(), kept);
            assert_eq!(counts(&chf), (tets.len() - 2, 2));
            assert_eq!(chf.report().inverted_examples, [0, 1]);
        }
    }
}
