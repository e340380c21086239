//! The soup: range check and degenerate triangles (a repeated vertex) dropped, on up to
//! `threads` threads: runs of triangles check their own part of `V`, and a dropped
//! triangle leaves a hole closed afterwards by one pass when there is any. Triangles handed
//! over as a `Vec` become `V` in place; borrowed ones are copied into it run by run.

use super::report::BuildReport;
use crate::error::{Error, Result};
use crate::util::alloc::{try_extend, try_push};
use std::borrow::Cow;

/// `V` and the map from structure triangle to input triangle (empty: the identity).
pub(crate) fn soup(
    triangles: Cow<'_, [[u32; 3]]>, n_vertices: usize, report: &mut BuildReport, threads: usize,
) -> Result<(Vec<u32>, Vec<u32>)> {
    let n = triangles.len();
    let chunk = n.div_ceil(threads.max(1)).max(1);
    let (mut v, source) = match triangles {
        Cow::Owned(t) => (t.into_flattened(), None),
        Cow::Borrowed(t) => (
            crate::util::pages::zeroed(3 * n, "the triangle vertices V")?,
            Some(t),
        ),
    };
    let jobs: Vec<_> = v
        .chunks_mut(3 * chunk)
        .enumerate()
        .map(|(j, v)| (j * chunk, source.map(|s| &s[j * chunk..][..v.len() / 3]), v))
        .collect();
    let runs = crate::util::par::run_all(jobs, |(t0, tris, v)| run(t0, tris, v, n_vertices));
    let mut dropped = Vec::new();
    for r in runs {
        let run = r?;
        report.dropped_degenerate += run.len();
        crate::util::extend_examples(&mut report.degenerate_examples, run.iter().copied());
        try_extend(&mut dropped, run, "the dropped triangles")?;
    }
    let origin = if dropped.is_empty() {
        Vec::new()
    } else {
        crate::util::holes::close_holes(&mut v, 3, &mut Vec::<u8>::new(), &dropped)?
    };
    Ok((v, origin))
}

/// An out-of-range error naming the first corner of triangle `t` whose vertex is not below
/// `n_vertices`, if there is one.
pub(crate) fn check_corners(t: usize, tri: &[u32], n_vertices: usize) -> Result<()> {
    match tri.iter().position(|&x| x as usize >= n_vertices) {
        Some(i) => Err(Error::out_of_range(format!(
            "triangle {t}, corner {i}: vertex {} out of range (there are {n_vertices} vertices)",
            tri[i]
        ))),
        None => Ok(()),
    }
}

/// One run: the triangles from input id `t0` on, in `v` (copied from `tris` first when
/// borrowed). Returns the degenerate ones (input ids, increasing), or the first
/// out-of-range id.
fn run(t0: usize, tris: Option<&[[u32; 3]]>, v: &mut [u32], n_vertices: usize) -> Result<Vec<u32>> {
    let mut dropped = Vec::new();
    for (k, q) in v.chunks_exact_mut(3).enumerate() {
        let t = t0 + k;
        if let Some(tris) = tris {
            q.copy_from_slice(&tris[k]);
        }
        let tri = [q[0], q[1], q[2]];
        check_corners(t, &tri, n_vertices)?;
        let [a, b, c] = tri;
        if a == b || b == c || a == c {
            try_push(&mut dropped, t as u32, "the dropped triangles")?;
        }
    }
    Ok(dropped)
}
