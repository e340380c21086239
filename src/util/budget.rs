//! The memory budget of a build (`BuildOptions::memory_limit_bytes`): each build estimates,
//! from the input's sizes alone, the bytes its arrays will take at their peak, and refuses
//! before allocating when the estimate exceeds the limit.
//!
//! The estimates (`che::build::budget`, `chf::build::budget`) add up the arrays each build
//! makes, per triangle or tetrahedron and per vertex, with upper bounds where a count is
//! only known later (edges, faces, boundary). They cover the usual path: an input that
//! must be re-oriented or split takes more, and those allocations stay fallible.

use super::options::BuildOptions;
use crate::error::{Error, Result};

/// Bytes per element and per vertex of a part of a build.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Cost {
    pub per_element: u64,
    pub per_vertex: u64,
}

impl Cost {
    pub(crate) const fn new(per_element: u64, per_vertex: u64) -> Self {
        Cost {
            per_element,
            per_vertex,
        }
    }

    /// The bytes for `elements` elements over `vertices` vertices (saturating).
    pub(crate) fn bytes(self, elements: usize, vertices: usize) -> u64 {
        let e = self.per_element.saturating_mul(elements as u64);
        e.saturating_add(self.per_vertex.saturating_mul(vertices as u64))
    }

    pub(crate) const fn plus(self, other: Cost) -> Cost {
        Cost::new(
            self.per_element + other.per_element,
            self.per_vertex + other.per_vertex,
        )
    }
}

/// The origin maps (4 bytes per element and per vertex), which every build keeps.
const MAPS: Cost = Cost::new(4, 4);
/// The positions (24 bytes per vertex), when given.
const POSITIONS: Cost = Cost::new(0, 24);

/// The peak of a build of `elements` elements over `vertices` vertices (with `positions`
/// or not) whose steps peak at `steps` (the largest counts): that, plus the origin maps
/// and the positions held throughout.
pub(crate) fn peak(steps: &[Cost], elements: usize, vertices: usize, positions: bool) -> u64 {
    let steps = steps.iter().map(|s| s.bytes(elements, vertices)).max();
    let extra = if positions {
        MAPS.plus(POSITIONS)
    } else {
        MAPS
    };
    steps
        .unwrap_or(0)
        .saturating_add(extra.bytes(elements, vertices))
}

/// At each of `levels`, with `positions` and without: the `estimate` (of the positions
/// given or not, and the level) bounds the bytes the structure built `held` (topology,
/// positions and maps), within the factor of eight its docs state.
#[cfg(test)]
pub(crate) fn assert_bounds(
    positions: &[glam::DVec3], levels: std::ops::RangeInclusive<u8>,
    estimate: impl Fn(bool, u8) -> u64, held: impl Fn(&[glam::DVec3], u8) -> usize,
) {
    for level in levels {
        for with_positions in [false, true] {
            let pos = if with_positions { positions } else { &[] };
            let held = held(pos, level) as u64;
            let estimate = estimate(with_positions, level);
            assert!(held <= estimate, "level {level}: {held} > {estimate}");
            assert!(
                estimate <= 8 * held,
                "level {level}: {estimate} > 8 x {held}"
            );
        }
    }
}

/// An [`ErrorKind::OutOfMemory`](crate::ErrorKind::OutOfMemory) error when `estimate`
/// exceeds the options' limit (0: none). `what` names the build ("a CHE build of 10
/// triangles at level 2").
pub(crate) fn check(
    options: &BuildOptions, estimate: u64, what: impl FnOnce() -> String,
) -> Result<()> {
    let limit = options.memory_limit_bytes;
    if limit == 0 || estimate <= limit {
        return Ok(());
    }
    Err(Error::over_limit(estimate, limit, &what()))
}

/// What is left of the options' limit once `used` bytes are held (0 stays none; a limit
/// used up leaves 1 byte, so that a later build still refuses).
pub(crate) fn remaining(options: &BuildOptions, used: usize) -> u64 {
    match options.memory_limit_bytes {
        0 => 0,
        limit => limit.saturating_sub(used as u64).max(1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ErrorKind;

    #[test]
    fn a_limit_below_the_estimate_refuses_naming_both() {
        let mut options = BuildOptions::default();
        assert!(check(&options, u64::MAX, || unreachable!()).is_ok());
        options.memory_limit_bytes = 1000;
        assert!(check(&options, 1000, || unreachable!()).is_ok());
        let e = check(&options, 3 << 20, || "a test build".into()).unwrap_err();
        assert_eq!((e.kind, e.bytes()), (ErrorKind::OutOfMemory, Some(3 << 20)));
        assert_eq!(
            e.message,
            "out of memory: a test build needs an estimated 3.0 MiB, over the limit of 1000 B"
        );
        assert_eq!(
            (remaining(&options, 10), remaining(&options, 5000)),
            (990, 1)
        );
        options.memory_limit_bytes = 0;
        assert_eq!(remaining(&options, 5000), 0);
        assert_eq!(Cost::new(2, 3).plus(Cost::new(1, 1)).bytes(10, 100), 430);
        assert_eq!(Cost::new(u64::MAX, 1).bytes(2, 2), u64::MAX);
    }
}
