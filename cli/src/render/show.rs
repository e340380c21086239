//! What `--show` can ask for, and what is shown without it.

use clap::ValueEnum;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Show {
    /// Each boundary curve in its own colour, numbered.
    Boundary,
    /// Non-manifold edges (lines) and vertices (discs).
    NonManifold,
    /// The edges along which a non-orientable component was cut.
    Seams,
    /// Rings at the vertices the build split into copies.
    Split,
    /// A dot on each triangle the build turned over.
    Flipped,
    /// A cross at each input triangle the build dropped.
    Dropped,
    /// Each connected component in its own colour.
    Components,
    /// Volumes: vertices and edges coloured interior, boundary or non-manifold.
    Classes,
}

/// The marks of everything a surface can be wrong in, and its boundary.
pub const SURFACE_DEFAULT: &[Show] = &[
    Show::Boundary,
    Show::NonManifold,
    Show::Seams,
    Show::Split,
    Show::Flipped,
    Show::Dropped,
];

/// A volume's classes of vertices and edges.
pub const VOLUME_DEFAULT: &[Show] = &[Show::Classes];

/// The problems `check` lists, for `check --render`.
pub const PROBLEMS: &[Show] = &[
    Show::NonManifold,
    Show::Seams,
    Show::Split,
    Show::Flipped,
    Show::Dropped,
];
