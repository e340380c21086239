//! A `.che` level file written by the streaming build: the triangles come from a
//! [`Source`](crate::Source) block by block and go straight into the file's `V`; `O` is paired by
//! the sweep of `che::build::stream` into the mapped file; `VH`, the edge directory and
//! `EH` follow from them as the in-memory build computes them. Memory holds the open
//! half-edges, one block, `VH` and the edge directory (about 5 bytes per vertex and 1 per
//! half-edge); `V`, `O`, `EH` and the positions live in the file. On input that pairs
//! cleanly the file is the one `Che::save` writes after an in-memory build, byte for byte.
//!
//! Before the file takes its name every star is walked (one fan per vertex, no edge met
//! twice at a vertex), which is what the in-memory build repairs and the sweep cannot see.

use super::{empty, flags, later, positions_and_report};
use crate::NONE;
use crate::Source;
use crate::che::BuildReport;
use crate::che::build::stream;
use crate::che::ids::prev;
use crate::che::tables::{edge_directory, vertex_half_edges};
use crate::che::{StarStep, SweepLimits, for_each_step};
use crate::error::{Error, Result};
use crate::levelfile::format::{Elem, Kind};
use crate::levelfile::placed::Placed;
use crate::levelfile::write::Section;
use crate::util::alloc::try_vec;
use std::path::Path;

/// How the streaming build runs.
#[derive(Clone, Copy, Debug)]
pub struct StreamOptions {
    /// 1 or 2.
    pub level: u8,
    pub limits: SweepLimits,
}

impl Default for StreamOptions {
    fn default() -> Self {
        StreamOptions {
            level: 2,
            limits: SweepLimits::default(),
        }
    }
}

/// Builds the surface of `source` at `options.level` (1 or 2) straight into the level file
/// `path`, never holding its arrays in memory; the report (input counts, edges, boundary
/// edges: nothing was repaired). An input that needs a repair (a degenerate triangle, an
/// edge of three triangles or run the same way twice, a vertex whose star is several fans)
/// or an order that leaves too many half-edges open is an error, and no file is left.
pub fn save_streamed(
    source: &impl Source<3>, path: &Path, options: StreamOptions,
) -> Result<BuildReport> {
    let (t, n) = (source.num_elements(), source.num_vertices());
    crate::che::build::check_counts(t, n)?;
    if !(1..=2).contains(&options.level) {
        return Err(Error::invalid(format!(
            "level {}: the streaming build writes levels 1 and 2",
            options.level
        )));
    }
    let mut file = create(path, source, options.level)?;
    fill_v(&mut file, source)?;
    if source.has_positions() {
        super::fill_positions(&mut file, |first, out| source.positions(first, out))?;
    }
    let (v, o) = file.pair_mut::<u32, u32>("V", "O");
    o.fill(NONE);
    let swept = stream::sweep(v, o, options.limits)?;
    let vh = vertex_half_edges(n, v, o)?;
    check_stars(v, o, &vh)?;
    let report = BuildReport {
        input_triangles: t,
        input_vertices: n,
        input_edges: swept.keys(),
        boundary_edges: swept.open,
        ..BuildReport::default()
    };
    if options.level == 2 {
        fill_edges(&mut file, &vh)?;
    }
    let counts = [n as u64, n as u64, swept.keys() as u64, 3 * t as u64];
    file.section_mut::<u64>("counts").copy_from_slice(&counts);
    let r = crate::levelfile::che::report_sections(&report, "").swap_remove(0);
    let Section { data, .. } = r;
    data.copy_to(file.section_mut::<u8>("r"));
    file.finish()?;
    Ok(report)
}

/// The file laid out as `Che::save` lays out a structure of this size: the sections whose
/// contents are known now are written, the others filled later (`EH` at its largest,
/// shrunk when the edges are counted).
fn create(path: &Path, source: &impl Source<3>, level: u8) -> Result<Placed> {
    let (t, n) = (source.num_elements() as u64, source.num_vertices() as u64);
    let mut parts = vec![
        later("counts", Elem::U64, 4),
        later("V", Elem::U32, 3 * t),
        empty("vertex_origin"),
        empty("triangle_origin"),
        empty("non_manifold"),
        empty("seams"),
    ];
    let report = BuildReport::default();
    let sections = crate::levelfile::che::report_sections(&report, "");
    positions_and_report(&mut parts, source.has_positions().then_some(n), sections);
    parts.push(later("O", Elem::U32, 3 * t));
    if level == 2 {
        parts.push(later("VH", Elem::U32, n));
        parts.push(later("edge_ranks", Elem::U64, (3 * t).div_ceil(32)));
        parts.push(later("EH", Elem::U32, 3 * t));
    }
    let flags = flags(source.has_positions());
    Placed::create(path, (Kind::Che, level, flags), &parts)
}

fn fill_v(file: &mut Placed, source: &impl Source<3>) -> Result<()> {
    let n = source.num_vertices();
    let v = file.section_mut::<[u32; 3]>("V");
    for (k, block) in v.chunks_mut(super::BLOCK).enumerate() {
        source.elements(k * super::BLOCK, block)?;
        stream::check_triangles(block.as_flattened(), k * super::BLOCK, n)?;
    }
    Ok(())
}

/// `VH`, the edge directory and `EH` (shrunk to the edges).
fn fill_edges(file: &mut Placed, vh: &[u32]) -> Result<()> {
    file.section_mut::<u32>("VH").copy_from_slice(vh);
    let bits = edge_directory(file.section::<u32>("O"))?;
    file.section_mut::<u64>("edge_ranks")
        .copy_from_slice(bits.entries());
    let eh = file.section_mut::<u32>("EH");
    let mut e = 0;
    for h in (0..eh.len()).filter(|&h| bits.get(h)) {
        eh[e] = h as u32;
        e += 1;
    }
    file.shrink_last(e as u64);
    Ok(())
}

/// Every vertex's star is one fan that its rotation from `VH` walks whole, and no two of its
/// triangles share the far end of their outgoing (or incoming) edge: a third triangle on
/// an edge, or two pairs on one, shows there.
fn check_stars(v: &[u32], o: &[u32], vh: &[u32]) -> Result<()> {
    let mut degree = try_vec(vh.len(), 0u32, "the vertex degrees")?;
    for &x in v {
        degree[x as usize] += 1;
    }
    let (mut heads, mut tails) = (Vec::new(), Vec::new());
    for (x, &h) in vh.iter().enumerate().filter(|&(_, &h)| h != NONE) {
        heads.clear();
        tails.clear();
        for_each_step(o, h, |s| {
            if let StarStep::Out(h) = s {
                heads.push(v[crate::che::ids::next(h) as usize]);
                tails.push(v[prev(h) as usize]);
            }
        });
        if heads.len() != degree[x] as usize || repeats(&mut heads) || repeats(&mut tails) {
            return Err(Error::non_manifold(format!(
                "vertex {x}: its triangles are not one fan (the in-memory build splits it); \
                 the streaming build pairs clean input only"
            )));
        }
    }
    Ok(())
}

/// Does `xs` hold a value twice?
fn repeats(xs: &mut [u32]) -> bool {
    xs.sort_unstable();
    xs.windows(2).any(|w| w[0] == w[1])
}
