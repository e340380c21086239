//! topomesh: the Compact Half-Edge (CHE) for triangle surfaces and the Compact Half-Face (CHF)
//! for tetrahedral meshes (Lage, Lewiner, Lopes and Velho), built in levels, with a C ABI.
//!
//! Ids are `u32` positions in flat arrays; [`NONE`] (`u32::MAX`) means "none" or "boundary".

pub mod che;
pub mod chf;
pub mod error;
pub mod ffi;
pub mod generate;
pub mod io;
pub mod levelfile;
mod util;

pub use che::{BuildOptions, BuildReport, Che, Summary};
pub use chf::Chf;
#[allow(
    deprecated,
    reason = "the old names stay at the crate root for one release"
)]
pub use chf::{ChfBuildOptions, ChfBuildReport, ChfSummary};
pub use error::{Error, ErrorKind};
pub use util::par::planned_threads;
pub use util::progress::BuildProgress;
pub use util::small_ids::Ids;
pub use util::source::{SliceSource, Source};
pub use util::weld::{representatives as weld_representatives, weld_arrays};
pub use util::{REPORT_EXAMPLES, non_finite_vertices};

/// "No element": the opposite of a boundary half-edge, the start of an isolated vertex, ...
pub const NONE: u32 = u32::MAX;

/// The README's Rust example, compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
