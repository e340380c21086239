//! The soup: range check and degenerate triangles (a repeated vertex) dropped, on up to
//! `threads` threads: runs of triangles write their own part of `V`, and a dropped
//! triangle leaves a hole closed afterwards by one pass when there is any.

use super::report::BuildReport;
use crate::error::{Error, Result};
use crate::util::alloc::{try_extend, try_push};

/// `V` and the map from structure triangle to input triangle (empty: the identity).
pub(crate) fn soup(
    triangles: &[[u32; 3]], n_vertices: usize, report: &mut BuildReport, threads: usize,
) -> Result<(Vec<u32>, Vec<u32>)> {
    let n = triangles.len();
    let chunk = n.div_ceil(threads.max(1)).max(1);
    let mut v: Vec<u32> = crate::util::pages::zeroed(3 * n, "the triangle vertices V")?;
    let jobs: Vec<_> = triangles
        .chunks(chunk)
        .zip(v.chunks_mut(3 * chunk))
        .enumerate()
        .map(|(j, (tris, v))| (j * chunk, tris, v))
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

/// One run: `tris` from input id `t0` on, into `v`. Returns the degenerate ones (input ids,
/// increasing), or the first out-of-range id.
fn run(t0: usize, tris: &[[u32; 3]], v: &mut [u32], n_vertices: usize) -> Result<Vec<u32>> {
    let mut dropped = Vec::new();
    for (k, (tri, q)) in tris.iter().zip(v.chunks_exact_mut(3)).enumerate() {
        let t = t0 + k;
        if let Some(i) = tri.iter().position(|&x| x as usize >= n_vertices) {
            return Err(Error::out_of_range(format!(
                "triangle {t}, corner {i}: vertex {} out of range (there are {n_vertices} vertices)",
                tri[i]
            )));
        }
        let [a, b, c] = *tri;
        if a == b || b == c || a == c {
            try_push(&mut dropped, t as u32, "the dropped triangles")?;
            continue;
        }
        q.copy_from_slice(tri);
    }
    Ok(dropped)
}
