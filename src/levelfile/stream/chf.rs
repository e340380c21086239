//! A `.chf` level file at level 1 written by the streaming build: the tetrahedra come from
//! a [`Source`](crate::Source) block by block and go straight into the file's `V`, checked and
//! flipped by the determinant there as the soup does; `O` is paired by the face sweep of
//! `chf::build::stream` into the mapped file; the edges are counted by the star pass in
//! rounds whose records stay within `SweepLimits::census_bytes`. Memory holds the open
//! half-faces, one block, the census's records and its vertex stamps (4 bytes per vertex
//! and thread); `V`, `O` and the positions live in the file. On input that needs no repair
//! the file is the one `Chf::save` writes after an in-memory build at level 1, byte for byte.

use super::{empty, flags, later, positions_and_report};
use crate::NONE;
use crate::Source;
use crate::chf::build::stream;
use crate::chf::{BuildReport, SweepLimits};
use crate::error::Result;
use crate::levelfile::format::{Elem, Kind};
use crate::levelfile::placed::{Part, Placed};
use crate::levelfile::write::Section;
use glam::DVec3;
use std::path::Path;

/// Builds the volume of `source` at level 1 straight into the level file `path`, never
/// holding its arrays in memory; the report (input counts, faces, edges, tetrahedra
/// flipped by the determinant: nothing else was changed). An input that needs a repair (a
/// degenerate or flat tetrahedron, a face of three tetrahedra, two tetrahedra on the same
/// vertices, a pair of faces running the same way, an edge or vertex whose tetrahedra fall
/// apart) or an order that leaves too many half-faces open is an error, and no file is
/// left.
pub fn save_streamed_chf(
    source: &impl Source<4>, path: &Path, limits: SweepLimits,
) -> Result<BuildReport> {
    let (t, n) = (source.num_elements(), source.num_vertices());
    crate::chf::check_counts(t, n)?;
    let mut file = create(path, source)?;
    if source.has_positions() {
        super::fill_positions(&mut file, |first, out| source.positions(first, out))?;
    }
    let flipped = fill_v(&mut file, source)?;
    let (v, o) = file.pair_mut::<u32, u32>("V", "O");
    o.fill(NONE);
    let swept = stream::sweep(v, o, limits)?;
    let census = stream::census(v, n, limits.census_bytes)?;
    // With no face of three tetrahedra, the sweep paired every face it counted.
    debug_assert_eq!(swept, census.faces);
    let (faces, edges) = (census.faces, census.edges);
    let mut report = BuildReport {
        input_tetrahedra: t,
        input_vertices: n,
        input_faces: faces.keys(),
        boundary_faces: faces.open,
        input_edges: edges,
        flipped_tetrahedra: flipped,
        ..BuildReport::default()
    };
    if source.has_positions() {
        (
            report.non_finite_vertices,
            report.non_finite_vertex_examples,
        ) = crate::util::non_finite_vertices(file.section::<DVec3>("positions"));
    }
    let counts = [n, n, edges, faces.keys(), 4 * t].map(|x| x as u64);
    file.section_mut::<u64>("counts").copy_from_slice(&counts);
    let r = crate::levelfile::chf::report_sections(&report, "").swap_remove(0);
    r.data.copy_to(file.section_mut::<u8>("r"));
    file.finish()?;
    Ok(report)
}

/// The file laid out as `Chf::save` lays out a level-1 structure of this size: the
/// sections whose contents are known now are written, the others filled later.
fn create(path: &Path, source: &impl Source<4>) -> Result<Placed> {
    let (t, n) = (source.num_elements() as u64, source.num_vertices() as u64);
    let mut parts = vec![
        later("counts", Elem::U64, 5),
        later("V", Elem::U32, 4 * t),
        empty("vertex_origin"),
        empty("tetrahedron_origin"),
        empty("non_manifold"),
        empty("seams"),
        Part::Now(Section::u64s("multi_fan", Vec::new())),
    ];
    let report = BuildReport::default();
    let sections = crate::levelfile::chf::report_sections(&report, "");
    positions_and_report(&mut parts, source.has_positions().then_some(n), sections);
    parts.push(later("O", Elem::U32, 4 * t));
    let flags = flags(source.has_positions());
    Placed::create(path, (Kind::Chf, 1, flags), &parts)
}

/// `V` from the source, each block checked and oriented as the soup does; returns the
/// tetrahedra flipped.
fn fill_v(file: &mut Placed, source: &impl Source<4>) -> Result<usize> {
    let n = source.num_vertices();
    let (positions, v) = if source.has_positions() {
        file.pair_mut::<DVec3, [u32; 4]>("positions", "V")
    } else {
        (&[][..], file.section_mut::<[u32; 4]>("V"))
    };
    let mut flipped = 0;
    for (k, block) in v.chunks_mut(super::BLOCK).enumerate() {
        let t0 = k * super::BLOCK;
        source.elements(t0, block)?;
        flipped += stream::check_tetrahedra(block.as_flattened_mut(), t0, n, positions)?;
    }
    Ok(flipped)
}
