//! The streaming build's pass: triangles from a [`TriangleSource`] in their order, `O`
//! found by a sweep that holds only the *open* half-edges (those whose partner has not come
//! yet) in memory, so that a surface larger than memory is paired block by block straight
//! into a mapped file. A block's half-edges are sorted by vertex pair and merged with the
//! sorted open list (a sort and a merge, no hash map); pairs found write `O` at both ends.
//! Memory follows the open list, which stays small when the order sweeps the surface (a
//! grid, a generator, a streaming mesh) and is refused past a bound otherwise.
//!
//! It pairs; it does not repair. A degenerate triangle, a vertex out of range, an edge met
//! by a third triangle or run the same way by two: each is an error naming the triangles,
//! since the in-memory build (which repairs them) is the one for such input.

use crate::NONE;
use crate::che::ids::next;
use crate::error::{Error, Result};
use crate::util::alloc::{try_reserve, try_with_capacity};
use glam::DVec3;

/// A surface read in order, block by block, as many times as a build needs: a generator,
/// or arrays on disk.
pub trait TriangleSource: Sync {
    fn num_triangles(&self) -> usize;
    fn num_vertices(&self) -> usize;
    /// Does [`TriangleSource::positions`] give points?
    fn has_positions(&self) -> bool;
    /// Triangles `first..first + out.len()` into `out`.
    fn triangles(&self, first: usize, out: &mut [[u32; 3]]) -> Result<()>;
    /// Positions of vertices `first..first + out.len()` into `out`.
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()>;
}

/// The arrays of a surface held in memory, as a source (tests compare the two builds).
pub struct SliceSource<'a> {
    pub triangles: &'a [[u32; 3]],
    pub n_vertices: usize,
    pub positions: &'a [DVec3],
}

impl TriangleSource for SliceSource<'_> {
    fn num_triangles(&self) -> usize {
        self.triangles.len()
    }
    fn num_vertices(&self) -> usize {
        self.n_vertices
    }
    fn has_positions(&self) -> bool {
        !self.positions.is_empty()
    }
    fn triangles(&self, first: usize, out: &mut [[u32; 3]]) -> Result<()> {
        out.copy_from_slice(&self.triangles[first..first + out.len()]);
        Ok(())
    }
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()> {
        out.copy_from_slice(&self.positions[first..first + out.len()]);
        Ok(())
    }
}

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

/// What the sweep found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Swept {
    pub edges: usize,
    pub boundary: usize,
}

/// A half-edge by its unordered vertex pair: `(min << 32 | max, h)`.
type Keyed = (u64, u32);

fn key(v: &[u32], h: u32) -> u64 {
    let (a, b) = (v[h as usize], v[next(h) as usize]);
    (u64::from(a.min(b)) << 32) | u64::from(a.max(b))
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

/// Fills `o` (all `NONE` on entry) for `v`, block by block.
pub(crate) fn sweep(v: &[u32], o: &mut [u32], limits: SweepLimits) -> Result<Swept> {
    let block = 3 * limits.block_triangles.max(1);
    let mut open: Vec<Keyed> = Vec::new();
    let mut keyed: Vec<Keyed> = try_with_capacity(block.min(v.len()), "the sweep's block")?;
    let mut merged: Vec<Keyed> = Vec::new();
    let mut swept = Swept::default();
    for first in (0..v.len()).step_by(block) {
        keyed.clear();
        let last = (first + block).min(v.len());
        keyed.extend((first as u32..last as u32).map(|h| (key(v, h), h)));
        keyed.sort_unstable();
        merged.clear();
        try_reserve(&mut merged, open.len() + keyed.len(), "the open half-edges")?;
        swept.edges += merge(v, o, &open, &keyed, &mut merged)?;
        std::mem::swap(&mut open, &mut merged);
        if open.len() > limits.max_open {
            return Err(Error::too_large(format!(
                "{} half-edges open after triangle {}: the triangles' order does not sweep \
                 the surface (at most {} open); build it in memory",
                open.len(),
                last / 3 - 1,
                limits.max_open
            )));
        }
    }
    swept.boundary = open.len();
    swept.edges += open.len();
    Ok(swept)
}

/// Merges the sorted block `keyed` with the sorted `open` list into `out` (the half-edges
/// still open), pairing equal vertex pairs; returns the pairs made.
fn merge(
    v: &[u32], o: &mut [u32], open: &[Keyed], keyed: &[Keyed], out: &mut Vec<Keyed>,
) -> Result<usize> {
    let (mut i, mut j, mut pairs) = (0, 0, 0);
    while j < keyed.len() {
        let k = keyed[j].0;
        while i < open.len() && open[i].0 < k {
            out.push(open[i]);
            i += 1;
        }
        let run = keyed[j..].iter().take_while(|e| e.0 == k).count();
        let earlier = (i < open.len() && open[i].0 == k).then(|| open[i].1);
        let (mut group, mut n) = ([NONE; 3], 0);
        for h in earlier
            .into_iter()
            .chain(keyed[j..j + run].iter().map(|e| e.1))
        {
            if n < 3 {
                group[n] = h;
            }
            n += 1;
        }
        match n {
            1 => out.push((k, group[0])),
            2 => {
                pair(v, o, group[0], group[1])?;
                pairs += 1;
            }
            _ => {
                let [a, b, c] = group.map(|h| h / 3);
                return Err(refused(format!(
                    "the edge of vertices {} and {} has {n} triangles ({a}, {b}, {c}, ...)",
                    k >> 32,
                    k as u32
                )));
            }
        }
        i += usize::from(earlier.is_some());
        j += run;
    }
    out.extend_from_slice(&open[i..]);
    Ok(pairs)
}

/// Pairs `g` and `h`, which must run the other way.
fn pair(v: &[u32], o: &mut [u32], g: u32, h: u32) -> Result<()> {
    if v[g as usize] == v[h as usize] {
        return Err(refused(format!(
            "triangles {} and {} run their edge of vertices {} and {} the same way",
            g / 3,
            h / 3,
            v[g as usize],
            v[next(g) as usize]
        )));
    }
    debug_assert!(o[g as usize] == NONE && o[h as usize] == NONE);
    o[g as usize] = h;
    o[h as usize] = g;
    Ok(())
}
