//! The streaming build's pass: triangles from a [`Source`](crate::Source) in their order, `O`
//! found by the sweep of `util::sweep` (half-edges keyed by their vertex pair), which holds
//! only the *open* half-edges in memory, so that a surface larger than memory is paired
//! block by block straight into a mapped file.
//!
//! It pairs; it does not repair. A degenerate triangle, a vertex out of range, an edge met
//! by a third triangle or run the same way by two: each is an error naming the triangles,
//! since the in-memory build (which repairs them) is the one for such input.

use crate::che::ids::next;
use crate::error::{Error, Result};
use crate::util::sweep;

/// How the sweep runs.
#[derive(Clone, Copy, Debug)]
pub struct SweepLimits {
    /// Triangles sorted at a time.
    pub block_triangles: usize,
    /// The most half-edges left open at once; past it the order does not suit the
    /// streaming build and it stops.
    pub max_open: usize,
}

impl Default for SweepLimits {
    fn default() -> Self {
        SweepLimits {
            block_triangles: 1 << 20,
            max_open: 1 << 27,
        }
    }
}

/// The pairing rules of half-edges: keyed by their unordered vertex pair, twins run the
/// other way, no edge has three.
struct HalfEdges<'a> {
    v: &'a [u32],
}

impl sweep::Rules for HalfEdges<'_> {
    /// `min << 32 | max`.
    type Key = u64;

    fn key(&self, h: u32) -> u64 {
        let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
        (u64::from(a.min(b)) << 32) | u64::from(a.max(b))
    }

    fn check_pair(&self, g: u32, h: u32) -> Result<()> {
        let v = self.v;
        if v[g as usize] == v[h as usize] {
            return Err(refused(format!(
                "triangles {} and {} run their edge of vertices {} and {} the same way",
                g / 3,
                h / 3,
                v[g as usize],
                v[next(g) as usize]
            )));
        }
        Ok(())
    }

    fn crowded(&self, k: u64, group: [u32; 3], n: usize) -> Error {
        let [a, b, c] = group.map(|h| h / 3);
        refused(format!(
            "the edge of vertices {} and {} has {n} triangles ({a}, {b}, {c}, ...)",
            k >> 32,
            k as u32
        ))
    }

    fn too_open(&self, open: usize, last: u32, max_open: usize) -> Error {
        Error::too_large(format!(
            "{open} half-edges open after triangle {}: the triangles' order does not sweep \
             the surface (at most {max_open} open); build it in memory",
            last / 3
        ))
    }
}

/// Checks triangles `first..` of `v` (ids below `n_vertices`, three distinct corners).
pub(crate) fn check_triangles(v: &[u32], first: usize, n_vertices: usize) -> Result<()> {
    for (k, c) in v.chunks_exact(3).enumerate() {
        let t = first + k;
        super::soup::check_corners(t, c, n_vertices)?;
        if c[0] == c[1] || c[1] == c[2] || c[0] == c[2] {
            return Err(refused(format!("triangle {t} is degenerate ({c:?})")));
        }
    }
    Ok(())
}

/// An input the streaming build does not take.
fn refused(what: String) -> Error {
    Error::non_manifold(format!(
        "{what}: the streaming build pairs clean input only (the in-memory build repairs it)"
    ))
}

/// Fills `o` (all `NONE` on entry) for `v`, block by block: the edges are its keys, the
/// boundary edges the half-edges left open.
pub(crate) fn sweep(v: &[u32], o: &mut [u32], limits: SweepLimits) -> Result<sweep::Swept> {
    let block = 3 * limits.block_triangles.max(1);
    let max_open = limits.max_open;
    sweep::sweep(&HalfEdges { v }, o, sweep::Limits { block, max_open })
}
