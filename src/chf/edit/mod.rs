//! Editing a built CHF in place, at every level.
//!
//! **Ids.** Vertex and tetrahedron ids never move until [`Chf::garbage_collect`](crate::Chf::garbage_collect): removed
//! elements are marked, new ones appended. Face and edge ids are ranks of bit directories
//! in a built CHF; an edit would shift them, so the first edit materialises explicit ids
//! in an `EditState` (a face id per half-face, an edge id per edge slot, and their
//! inverses), and from then on the queries read those. A CHF never edited has no
//! `EditState` (one `None` pointer) and answers exactly as before, at the same cost.
//!
//! **Levels.** The first edit also stores `O` and `VH` whatever the level (the operations
//! walk stars and pair faces through them), so an edited CHF at level 0 or 1 answers from
//! them as level 2 would; a removed tetrahedron's half-faces are their own twins (so
//! nothing sees them as boundary or canonical) and no live half-face points to them. At
//! level 3 an operation only notes the half-faces it leaves unpaired (`boundary.rs`); the
//! boundary surface is rebuilt lazily, at the first boundary query after an edit, from the
//! boundary half-faces of the last rebuild and those notes: O((B + k) log(B + k)) for B
//! boundary half-faces and k notes, never a scan of the tetrahedra. Its lookups then
//! binary-search (O(log B)) where a built CHF takes a rank over all half-faces.
//!
//! **Operations** are transactions (`plan.rs`): a set of tetrahedra to remove and a list to
//! add, checked first (faces held at most twice and running opposite ways, every touched
//! vertex star and edge fan in one piece, no flagged face touched, no inverted tetrahedron
//! when positions exist), then applied by local updates of `V`, `O`, `VH` and the ids:
//! O(the stars of the touched vertices). A plan that only re-triangulates a cavity (the
//! splits and flips, `cavity.rs`) is checked and applied without star walks, in O(1). A
//! refused operation returns an error naming the element and the reason, and changes
//! nothing.
//!
//! **Memory** once edited: 1 byte per tetrahedron and vertex for the marks, 4 per
//! half-face (face ids) and 6 x 4 per tetrahedron (edge ids), 4 per face and 8 per edge
//! (inverses), plus `O` and `VH` if the level did not store them; at level 3, 4 per
//! boundary half-face and per note (the notes are folded once they outnumber the boundary
//! by a constant), and the rebuilt surface in place of the built one.

mod add_tetrahedron;
mod add_vertex;
mod arrays;
mod boundary;
mod cavity;
mod collapse_edge;
mod flip_23;
mod flip_32;
mod garbage_collect;
mod plan;
mod refusal;
mod remove_tetrahedron;
mod remove_vertex;
mod split_edge;
mod split_face;
mod split_tetrahedron;
mod state;
mod validate;

pub use garbage_collect::GarbageMaps;
pub(crate) use state::{EditState, removed};

/// A grid of `n`^3 cubes ([`crate::generate::cube_grid`]) built at `level`, with or without
/// positions: the mesh of the editing unit tests.
#[cfg(test)]
pub(crate) fn test_grid(n: u32, level: u8, positions: bool) -> crate::chf::Chf {
    let g = crate::generate::cube_grid(n);
    let p = if positions { &g.positions[..] } else { &[] };
    let options = crate::chf::BuildOptions::level(level);
    crate::chf::Chf::from_tetrahedra(&g.tetrahedra, g.positions.len(), p, options).unwrap()
}
