//! Level files written by the streaming builds: the elements come from a source block by
//! block and go straight into the file's `V`, and every array is filled in place in the
//! mapped file (`placed.rs`), so that a mesh larger than memory is built. `che.rs` writes
//! a surface at level 1 or 2, `chf.rs` a volume at level 1. On input that needs no repair
//! each writes the file that an in-memory build and `save` write, byte for byte.

mod che;
mod chf;

pub use che::{StreamOptions, save_streamed};
pub use chf::save_streamed_chf;

use super::format::{Elem, FLAG_POSITIONS};
use super::placed::{Part, Placed};
use super::write::Section;
use crate::error::Result;
use glam::DVec3;

/// Elements (or vertices) a source writes at a time.
const BLOCK: usize = 1 << 20;

/// The `positions` section, block by block from `read(first, out)`.
fn fill_positions(
    file: &mut Placed, read: impl Fn(usize, &mut [DVec3]) -> Result<()>,
) -> Result<()> {
    let p = file.section_mut::<DVec3>("positions");
    for (k, block) in p.chunks_mut(BLOCK).enumerate() {
        read(k * BLOCK, block)?;
    }
    Ok(())
}

/// A section whose length is known now and its contents later.
fn later(name: &str, elem: Elem, count: u64) -> Part<'static> {
    Part::Later {
        name: name.to_string(),
        elem,
        count,
    }
}

/// An empty list of ids: an origin map that is the identity, no flagged element.
fn empty(name: &str) -> Part<'static> {
    Part::Now(Section::u32s(name, Vec::new()))
}

/// The positions (`n` points, when there are any) and the report's sections, the counts
/// `r` filled later and the example lists written now (empty: nothing was repaired).
fn positions_and_report<'a>(
    parts: &mut Vec<Part<'a>>, positions: Option<u64>, report: Vec<Section<'a>>,
) {
    if let Some(n) = positions {
        parts.push(later("positions", Elem::F64, 3 * n));
    }
    for s in report {
        parts.push(match s.name.as_str() {
            "r" => later("r", Elem::U64, s.data.len() as u64),
            _ => Part::Now(s),
        });
    }
}

/// The header's flags.
fn flags(positions: bool) -> u32 {
    if positions { FLAG_POSITIONS } else { 0 }
}
