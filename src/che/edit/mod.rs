//! Editing a built CHE in place, at any level: add and remove vertices and triangles, flip,
//! split and collapse edges, split triangles, and compact with [`Che::garbage_collect`].
//!
//! Removed elements are marked, not moved: a removed triangle's half-edges have `V = O =
//! NONE`, a removed vertex `VH = NONE` and a flag, a removed edge `EH = NONE`. Every id of an
//! untouched element stays valid until [`Che::garbage_collect`], which compacts the arrays
//! (`h = 3t + i` without holes) and returns old -> new maps. The `num_*` counts stay the
//! id bounds until then (as OpenMesh's); [`Che::num_live_vertices`] and its siblings, the
//! summary and every relation skip the removed elements.
//!
//! The editable form is materialised on the first edit, in an [`EditState`] behind an
//! `Option<Box<_>>`, so a CHE that is never edited keeps its memory and speed. At level 2
//! edge ids must stay stable (a removed id is not reused, a new edge gets a new id), which
//! ranks over a bit directory cannot do: the state holds the edge id of every half-edge
//! (4 bytes per half-edge), and `EH` grows by one entry per new edge. Level 3 curves are
//! recomputed at the first curve query after an edit, from the boundary half-edges of the
//! last computation and those the edits have unpaired since: O(boundary + edits since),
//! kept until the next edit.
//!
//! Cost of one operation: local (the stars it touches) at every level. Below level 2 the
//! level stores no `VH` (and at level 0 no `O`) to find a star from: the first edit
//! computes them, O(T) once, and the edit state keeps them up to date between edits
//! (`state.rs`), with the live edges counted by block so that an edge id, a rank there,
//! is found in O(log T).

mod add;
mod add_repair;
mod arrays;
mod boundary;
mod checks;
mod collapse;
mod flip;
mod garbage;
mod remove;
mod split;
mod state;
mod summary;
mod work;

pub use garbage::{GarbageMaps, GarbageMapsOut};
pub(crate) use state::EditState;
