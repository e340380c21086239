//! From a triangle list to a CHE, as the named steps of the pipeline: check the sizes,
//! (1) the soup, (2) matching, (3) orientation (and duplicate triangles), (4) vertex
//! split, then (5) the requested level. Every step but the last works on flat arrays; the
//! `Che` is assembled at level 1 and raised or lowered to the level asked for.

mod budget;
pub(crate) mod level2;
mod level3;
mod matching;
mod options;
mod orient;
pub(crate) mod report;
mod soup;
mod split;
pub(crate) mod stream;

pub use budget::estimated_build_bytes;
pub use options::{BuildOptions, MAX_TRIANGLES, MAX_UNUSED_VERTICES, check_counts};
pub use report::BuildReport;
pub(crate) use split::walk_fan;
pub use stream::SweepLimits;

use super::Che;
use crate::error::{Error, Result};
use crate::util::input::{Input, positions_with_copies};
use crate::util::options::check_input;
use crate::util::origin::OriginMap;
use crate::util::progress::BuildProgress;
use crate::util::rank::RankBits;
use crate::util::rank_directory::RankDirectory;
use glam::DVec3;
use report::push_example;
use std::borrow::Cow;

pub(crate) fn build(
    input: Input<'_, 3>, options: BuildOptions, progress: BuildProgress,
) -> Result<Che> {
    let Input {
        elements: triangles,
        n_vertices,
        positions,
    } = input;
    let mut report = prepared(&triangles, n_vertices, &positions, &options)?;
    let welded = crate::util::weld::weld_elements(triangles, &positions, options.weld_tolerance)?;
    report.welded_vertices = welded.welded_vertices;
    let triangles = welded.elements;
    let threads = crate::util::par::build_threads(options.threads, triangles.len());
    progress.at(0.0, "the soup");
    let (mut v, triangle_origin) = soup::soup(triangles, n_vertices, &mut report, threads)?;
    let triangle_origin = OriginMap::from(triangle_origin);
    let origin_of = |t: u32| triangle_origin.get(t);
    progress.at(0.15, "pairing half-edges");
    let mut matching = matching::match_pairs(&v, n_vertices, threads, &mut report)?;
    if options.strict {
        matching::reject_non_manifold_edges(&report, &v, &matching.non_manifold, origin_of)?;
    }
    progress.at(0.45, "orienting");
    let (o, seams) = orient_step(&mut v, &mut matching, &mut report, origin_of)?;
    let mut non_manifold = std::mem::take(&mut matching.non_manifold);
    non_manifold.sort_unstable();
    duplicates_step(&o, matching.duplicates, &mut report, origin_of)?;
    reject_if_strict(&report, options.strict)?;
    progress.at(0.6, "splitting vertices");
    let mut split = split::split(&mut v, &o, n_vertices, &seams, threads)?;
    split_step(&mut split, &mut report, options.strict)?;
    let vh = std::mem::take(&mut split.vh);
    let canonical = Canonical {
        v,
        o,
        seams,
        non_manifold,
        triangle_origin,
    };
    progress.at(0.75, "assembling");
    let mut che = assemble(canonical, &split.copies, n_vertices, positions, report)?;
    che.strict = options.strict;
    progress.at(0.8, "levels 2 and 3");
    finish_level(&mut che, options.level, vh)?;
    progress.at(1.0, "done");
    Ok(che)
}

/// The checks before anything is allocated, and the report of the input.
fn prepared(
    triangles: &[[u32; 3]], n_vertices: usize, positions: &[DVec3], options: &BuildOptions,
) -> Result<BuildReport> {
    let n = triangles.len();
    check_input(options, &options::TRIANGLES, n, n_vertices, positions.len())?;
    let (non_finite_vertices, non_finite_vertex_examples) =
        crate::util::non_finite_vertices(positions);
    let estimate =
        budget::estimated_build_bytes(n, n_vertices, !positions.is_empty(), options.level);
    crate::util::budget::check(options, estimate, || {
        format!("a CHE build of {n} triangles at level {}", options.level)
    })?;
    Ok(BuildReport {
        input_triangles: n,
        input_vertices: n_vertices,
        non_finite_vertices,
        non_finite_vertex_examples,
        ..BuildReport::default()
    })
}

/// Step 3: orients only when some pair runs the same way (otherwise the partners are the
/// opposites). Returns `O` and the seam half-edges; renumbers the non-manifold half-edges
/// of flipped triangles.
fn orient_step(
    v: &mut [u32], matching: &mut matching::Matching, report: &mut BuildReport,
    origin_of: impl Fn(u32) -> u32,
) -> Result<(Vec<u32>, Vec<u32>)> {
    let partner = std::mem::take(&mut matching.partner);
    if !matching.same_direction {
        return Ok((partner, Vec::new()));
    }
    let oriented = orient::orient(v, &partner)?;
    drop(partner);
    let flips = &oriented.flips;
    report.flipped_triangles = flips.flipped_count;
    report.non_orientable_components = flips.non_orientable_components;
    report.non_orientable_examples = flips
        .non_orientable_examples
        .iter()
        .map(|&t| origin_of(t))
        .collect();
    report.seam_edges = oriented.seams.len() / 2;
    for h in matching.non_manifold.iter_mut() {
        if flips.flipped[(*h / 3) as usize] {
            *h = orient::flipped_id(*h);
        }
    }
    Ok((oriented.o, oriented.seams))
}

/// Duplicate triangles: those seen on non-manifold edges plus the closed pillows on `O`,
/// counted and listed (input ids) in the report.
fn duplicates_step(
    o: &[u32], mut duplicates: Vec<[u32; 2]>, report: &mut BuildReport,
    origin_of: impl Fn(u32) -> u32,
) -> Result<()> {
    matching::count_pillows(o, &mut duplicates)?;
    duplicates.sort_unstable();
    duplicates.dedup();
    report.duplicate_triangles = duplicates.len();
    for &[s, t] in &duplicates {
        push_example(&mut report.duplicate_examples, [origin_of(s), origin_of(t)]);
    }
    Ok(())
}

/// Strict mode: duplicate triangles are an error.
fn reject_if_strict(report: &BuildReport, strict: bool) -> Result<()> {
    if let (true, Some(&[s, t])) = (strict, report.duplicate_examples.first()) {
        return Err(Error::non_manifold(format!(
            "triangles {s} and {t} have the same vertices; duplicate pairs in all: {}",
            report.duplicate_triangles
        )));
    }
    Ok(())
}

/// Step 4's report (and, in strict mode, its error).
fn split_step(split: &mut split::Split, report: &mut BuildReport, strict: bool) -> Result<()> {
    report.split_vertices = split.split_vertices;
    report.split_vertex_examples = std::mem::take(&mut split.split_examples);
    report.seam_split_vertices = split.seam_split_vertices;
    report.added_vertices = split.copies.len();
    if strict && report.split_vertices > 0 {
        return Err(Error::non_manifold(format!(
            "non-manifold vertex {} (its star is several fans); such vertices in all: {}",
            report.split_vertex_examples[0], report.split_vertices
        )));
    }
    Ok(())
}

/// The arrays of the canonical soup, as steps 1 to 3 leave them.
struct Canonical {
    v: Vec<u32>,
    o: Vec<u32>,
    seams: Vec<u32>,
    non_manifold: Vec<u32>,
    triangle_origin: OriginMap,
}

/// The structure at level 1, with the vertex copies of the split appended.
fn assemble(
    c: Canonical, copies: &[u32], n_vertices: usize, positions: Cow<'_, [DVec3]>,
    report: BuildReport,
) -> Result<Che> {
    let vertex_origin = OriginMap::with_copies(n_vertices, copies)?;
    let positions = positions_with_copies(positions, copies)?;
    let num_edges = (0..c.o.len())
        .filter(|&h| crate::che::tables::is_canonical(&c.o, h))
        .count();
    Ok(Che {
        level: 1,
        n_input_vertices: n_vertices,
        n_vertices: n_vertices + copies.len(),
        v: c.v.into(),
        o: c.o.into(),
        vh: Vec::new().into(),
        edge_bits: RankDirectory::default(),
        eh: Vec::new().into(),
        lazy_edge_bits: Default::default(),
        ch: Vec::new().into(),
        boundary_bits: RankBits::default(),
        curve_of: Vec::new().into(),
        num_edges,
        positions: positions.into(),
        vertex_origin,
        triangle_origin: c.triangle_origin,
        non_manifold: c.non_manifold,
        seams: c.seams,
        report,
        strict: false,
        edit: None,
        checked: Default::default(),
    })
}

/// Step 5 on a fresh build: `vh` is the split's (the same `VH` level 2 would compute).
fn finish_level(che: &mut Che, level: u8, vh: Vec<u32>) -> Result<()> {
    if level == 0 {
        che.o = Vec::new().into();
        che.level = 0;
    }
    if level >= 2 {
        che.vh = vh.into();
        level2::build_edges(che)?;
        che.level = 2;
    }
    if level >= 3 {
        level3::build(che)?;
        che.level = 3;
    }
    Ok(())
}

/// Raises or lowers the level of a built structure in place (ids do not change).
pub(crate) fn change_level(che: &mut Che, level: u8) -> Result<()> {
    crate::util::options::check_level(level)?;
    che.lazy_edge_bits = Default::default();
    if level < che.level {
        if level < 3 {
            che.ch = Vec::new().into();
            che.boundary_bits = RankBits::default();
            che.curve_of = Vec::new().into();
        }
        if level < 2 {
            che.vh = Vec::new().into();
            che.edge_bits = RankDirectory::default();
            che.eh = Vec::new().into();
        }
        if level < 1 {
            che.o = Vec::new().into();
        }
        che.level = level;
        return Ok(());
    }
    if che.level < 1 && level >= 1 {
        che.o = super::pairs::opposites_by_rule(&che.v, che.n_vertices, &che.non_manifold)?.into();
        che.level = 1;
    }
    if che.level < 2 && level >= 2 {
        level2::build(che)?;
        che.level = 2;
    }
    if che.level < 3 && level >= 3 {
        level3::build(che)?;
        che.level = 3;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn non_finite_vertices_are_reported() {
        let positions = [
            DVec3::ZERO,
            DVec3::new(f64::NEG_INFINITY, 0.0, 0.0),
            DVec3::new(0.0, 1.0, f64::NAN),
        ];
        let che = Che::from_triangles(&[[0, 1, 2]], 3, &positions, BuildOptions::level(1)).unwrap();
        let r = che.report();
        assert_eq!(
            (r.non_finite_vertices, &r.non_finite_vertex_examples[..]),
            (2, &[1, 2][..])
        );
        let che = Che::from_triangles(&[[0, 1, 2]], 3, &[DVec3::ZERO; 3], BuildOptions::level(1))
            .unwrap();
        assert_eq!(che.report().non_finite_vertices, 0);
    }
}
