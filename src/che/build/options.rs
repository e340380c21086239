//! How to build a CHE.

use crate::util::options::Cells;
pub use crate::util::options::{BuildOptions, MAX_UNUSED_VERTICES};

/// Largest triangle count whose half-edge ids fit below `NONE`.
pub const MAX_TRIANGLES: usize = (u32::MAX as usize) / 3;

/// A CHE build's elements, for the size checks.
pub(crate) const TRIANGLES: Cells = Cells {
    per: 3,
    max: MAX_TRIANGLES,
    name: "triangles",
    ids: "half-edge",
};

/// Whether a build of `n_triangles` triangles on `n_vertices` vertices fits, checked from
/// the counts alone (the build checks this first, before it allocates or reads anything):
/// at most [`MAX_TRIANGLES`] triangles, fewer than 2^32 - 1 vertices, and at most
/// [`MAX_UNUSED_VERTICES`] vertices beyond the `3 * n_triangles` the triangles can name.
/// A failure is `ErrorKind::TooLarge`, naming the limit.
pub fn check_counts(n_triangles: usize, n_vertices: usize) -> crate::error::Result<()> {
    crate::util::options::check_counts(&TRIANGLES, n_triangles, n_vertices)
}
