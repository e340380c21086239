//! How to build either structure, and the size checks both builds make before they
//! allocate anything.

use crate::NONE;
use crate::error::{Error, Result};

/// How to build: the level (0..=3) and whether non-manifold input is an error. The same
/// for CHE and CHF (`che::BuildOptions`, `chf::BuildOptions`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuildOptions {
    pub level: u8,
    /// Reject non-manifold input (edges, faces, vertices and duplicate elements) instead of
    /// repairing or keeping it.
    pub strict: bool,
    /// Threads for the build: 0 (the default) for as many as the machine runs at once, 1
    /// for the calling thread alone; more than the machine runs at once, or than one per
    /// 8192 elements, are not started (see [`planned_threads`](crate::planned_threads)).
    /// The structure is the same whatever the number.
    pub threads: usize,
    /// A memory budget for the build, in bytes (0, the default: none). The build estimates
    /// the bytes its arrays will take at their peak from the input's sizes and refuses
    /// with an [`ErrorKind::OutOfMemory`](crate::ErrorKind::OutOfMemory) error, before
    /// allocating, when the estimate exceeds it.
    pub memory_limit_bytes: u64,
    /// Weld before building: vertices at most this distance apart (Euclidean, on the
    /// positions, which the weld needs) become one, the smallest id of each cluster of
    /// close vertices winning (`util::weld` gives the exact rule). 0 (the default) is off:
    /// the topology is that of the vertex ids as given.
    pub weld_tolerance: f64,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            level: 2,
            strict: false,
            threads: 0,
            memory_limit_bytes: 0,
            weld_tolerance: 0.0,
        }
    }
}

impl BuildOptions {
    pub fn level(level: u8) -> Self {
        BuildOptions {
            level,
            ..Self::default()
        }
    }
}

/// The level is in 0..=3, the counts fit (`check_counts`) and positions are none or one
/// per vertex.
pub(crate) fn check_input(
    options: &BuildOptions, cells: &Cells, n_cells: usize, n_vertices: usize, n_positions: usize,
) -> Result<()> {
    check_level(options.level)?;
    check_counts(cells, n_cells, n_vertices)?;
    if n_positions != 0 && n_positions != n_vertices {
        return Err(Error::invalid(format!(
            "{n_positions} positions given for {n_vertices} vertices"
        )));
    }
    Ok(())
}

/// What a build takes, for its size checks: `per` vertex ids per element (cell), at most
/// `max` elements so that the `ids` (half-edge or half-face ids, `per` per element) fit
/// below `NONE`; `name` names the elements in messages.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Cells {
    pub per: usize,
    pub max: usize,
    pub name: &'static str,
    pub ids: &'static str,
}

/// The most vertices a build accepts beyond the `per * n` its `n` elements can name. Every
/// vertex costs the build and the structure memory (its entry in `VH`, the split's tables,
/// the origin maps), used or not, so a vertex count far beyond what the elements use
/// (`2^32 - 2` vertices for two triangles) would ask for gigabytes that hold nothing; it
/// is refused before anything is allocated. The bound leaves room for meshes that keep
/// unused points (tens of millions of them).
pub const MAX_UNUSED_VERTICES: usize = 1 << 26;

/// The counts of a build, checked before anything is allocated or read: the elements'
/// `ids` fit below `NONE`, vertex ids fit below `NONE`, and at most `MAX_UNUSED_VERTICES`
/// vertices are beyond what the elements can name. Errors are `TooLarge`, naming the limit.
pub(crate) fn check_counts(cells: &Cells, n_cells: usize, n_vertices: usize) -> Result<()> {
    let Cells {
        per,
        max,
        name,
        ids,
    } = *cells;
    if n_cells > max {
        return Err(Error::too_large(format!(
            "{n_cells} {name}: {ids} ids must fit below 2^32 - 1 (at most {max} {name})"
        )));
    }
    if n_vertices >= NONE as usize {
        return Err(Error::too_large(format!(
            "{n_vertices} vertices: ids must fit below 2^32 - 1"
        )));
    }
    let usable = per * n_cells;
    if n_vertices.saturating_sub(usable) > MAX_UNUSED_VERTICES {
        return Err(Error::too_large(format!(
            "{n_vertices} vertices for {n_cells} {name}, which name at most {usable}: at most \
             {MAX_UNUSED_VERTICES} vertices beyond those the {name} can name (each takes \
             memory in the build and the structure)"
        )));
    }
    Ok(())
}

/// A level to build or change to is in 0..=3.
pub(crate) fn check_level(level: u8) -> Result<()> {
    if level > 3 {
        return Err(Error::out_of_range(format!(
            "level {level} is not in 0..=3"
        )));
    }
    Ok(())
}
