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
    /// for the calling thread alone. The structure is the same whatever the number.
    pub threads: usize,
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

/// The level is in 0..=3, vertex ids fit below `NONE`, the elements fit (`too_many`, the
/// structure's own message when they do not) and positions are none or one per vertex.
pub(crate) fn check_input(
    options: &BuildOptions, n_vertices: usize, n_positions: usize, too_many: Option<String>,
) -> Result<()> {
    check_level(options.level)?;
    if n_vertices >= NONE as usize {
        return Err(Error::too_large(format!(
            "{n_vertices} vertices: ids must fit below 2^32 - 1"
        )));
    }
    if let Some(message) = too_many {
        return Err(Error::too_large(message));
    }
    if n_positions != 0 && n_positions != n_vertices {
        return Err(Error::invalid(format!(
            "{n_positions} positions given for {n_vertices} vertices"
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
