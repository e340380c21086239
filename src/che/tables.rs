//! Tables derived from `V` and `O` that both the build passes and the queries compute:
//! the starting half-edge of every vertex, the edge-id directory and edge ids.

use crate::NONE;
use crate::error::Result;
use crate::util::rank_directory::RankDirectory;

/// The starting half-edge of every vertex (`VH`: the boundary one on a boundary vertex,
/// `NONE` for an isolated vertex), from `V` and `O` in one pass.
pub(crate) fn vertex_half_edges(n_vertices: usize, v: &[u32], o: &[u32]) -> Result<Vec<u32>> {
    vertex_half_edges_in(Vec::new(), n_vertices, v, o)
}

/// [`vertex_half_edges`] in `spare`'s memory when it has the room (`pages::reusing`).
pub(crate) fn vertex_half_edges_in(
    spare: Vec<u32>, n_vertices: usize, v: &[u32], o: &[u32],
) -> Result<Vec<u32>> {
    let what = "the vertex half-edges VH";
    let mut vh = crate::util::pages::reusing(spare, n_vertices, what)?;
    vh.resize(n_vertices, NONE);
    for (h, (&x, &g)) in v.iter().zip(o).enumerate() {
        // Written every time, without a branch: whether a vertex is met for the first
        // time follows no pattern a branch predictor can learn.
        let slot = &mut vh[x as usize];
        let keep = *slot != NONE && g != NONE;
        *slot = if keep { *slot } else { h as u32 };
    }
    Ok(vh)
}

/// Is `h` the canonical half-edge of its edge (`O[h] == NONE || h < O[h]`)?
#[inline]
pub(crate) fn is_canonical(o: &[u32], h: usize) -> bool {
    // `NONE` is above every id, so one comparison answers both cases, without the branch
    // that an `||` may become (mispredicted half the time: which twin comes first is a
    // coin toss).
    (h as u32) < o[h]
}

/// The canonical half-edge of `h`'s edge: `h` itself when unpaired or smaller (`NONE` is
/// above every id).
#[inline]
pub(crate) fn canonical_half_edge(o: &[u32], h: u32) -> u32 {
    o[h as usize].min(h)
}

/// The edge-id directory of the opposites `o`: the rank over the canonical half-edges.
pub(crate) fn edge_directory(o: &[u32]) -> Result<RankDirectory> {
    RankDirectory::from_fn(o.len(), |h| is_canonical(o, h))
}

/// The edge id of every half-edge, as a table.
pub(crate) fn edge_ids(o: &[u32]) -> Result<Vec<u32>> {
    let mut ids = crate::util::alloc::try_vec(o.len(), NONE, "the edge ids")?;
    let mut next_id = 0u32;
    for h in 0..o.len() {
        let g = o[h];
        if is_canonical(o, h) {
            ids[h] = next_id;
            if g != NONE {
                ids[g as usize] = next_id;
            }
            next_id += 1;
        }
    }
    Ok(ids)
}
