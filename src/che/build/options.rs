//! How to build a CHE.

pub use crate::util::options::BuildOptions;

/// Largest triangle count whose half-edge ids fit below `NONE`.
pub const MAX_TRIANGLES: usize = (u32::MAX as usize) / 3;
