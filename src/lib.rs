//! topomesh: the Compact Half-Edge (CHE) for triangle surfaces and the Compact Half-Face (CHF)
//! for tetrahedral meshes (Lage, Lewiner, Lopes and Velho), built in levels, with a C ABI.
//!
//! Ids are `u32` positions in flat arrays; [`NONE`] (`u32::MAX`) means "none" or "boundary".

pub mod che;
pub mod chf;
mod dsu;
pub mod error;
pub mod ffi;
pub mod generate;
mod holes;
pub mod io;
mod pages;
mod par;
mod rank;
mod rank_directory;
mod small_ids;

pub use che::{BuildOptions, BuildReport, Che, Summary};
pub use chf::{Chf, ChfBuildOptions, ChfBuildReport, ChfSummary};
pub use error::{Error, ErrorKind};
pub use small_ids::Ids;

/// "No element": the opposite of a boundary half-edge, the start of an isolated vertex, ...
pub const NONE: u32 = u32::MAX;

/// How many offending ids a build report keeps of each kind.
pub const REPORT_EXAMPLES: usize = 16;

/// Keeps the first [`REPORT_EXAMPLES`] examples of a kind in a build report.
pub(crate) fn push_example<T>(list: &mut Vec<T>, item: T) {
    if list.len() < REPORT_EXAMPLES {
        list.push(item);
    }
}

/// Unit tests' random numbers: xorshift64 from `seed`, reduced below the bound asked for.
#[cfg(test)]
pub(crate) fn test_rng(seed: u64) -> impl FnMut(usize) -> u32 {
    let mut x = seed;
    move |m: usize| {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % m as u64) as u32
    }
}

/// [`push_example`] for each of `items`, in order: the examples a build thread found after
/// those already in `list`.
pub(crate) fn extend_examples<T>(list: &mut Vec<T>, items: impl IntoIterator<Item = T>) {
    let room = REPORT_EXAMPLES.saturating_sub(list.len());
    list.extend(items.into_iter().take(room));
}

/// The README's Rust example, compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
