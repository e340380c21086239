//! Splitting non-manifold vertices: a vertex whose star (the tetrahedra holding it) falls
//! into several pieces, face-connected through paired faces that contain the vertex, gets
//! one copy per extra piece, appended after the input vertices. Then one `VH` entry reaches
//! the whole star of every vertex.
//!
//! Two tetrahedra sharing only a vertex or only an edge are two pieces for each shared
//! vertex, so both ends of such an edge are split and the edge falls apart. An edge can
//! still carry several fans after the split when the stars of both its ends are connected
//! through other tetrahedra (the link of an end vertex is then a pinched surface); the
//! structure keeps one edge id per fan there (see `edges.rs`).

use crate::NONE;
use crate::chf::build::report::push_example;
use crate::chf::ids::{first, tet};
use crate::error::Result;
use crate::util::alloc::{try_push, try_to_vec, try_vec, try_with_capacity};

pub(crate) struct Split {
    /// Origins of the appended copies (input ids), in order of creation.
    pub copies: Vec<u32>,
    /// Input vertices split because their input star is in several pieces.
    pub split_vertices: usize,
    pub split_examples: Vec<u32>,
    /// Input vertices split only because an orientation seam cuts their star.
    pub seam_split_vertices: usize,
}

/// Rewrites `v` so that every vertex id names one piece of a star, pieces connected
/// through `o`. `links` is empty, or `o` plus the seam pairs: the input adjacency, used to
/// tell apart the vertices cut only by a seam.
pub(crate) fn split(v: &mut [u32], o: &[u32], links: &[u32], n_vertices: usize) -> Result<Split> {
    // The input adjacency first, on the unsplit ids.
    let mut non_manifold = Vec::new();
    if !links.is_empty() {
        non_manifold = pieces(v, links, n_vertices, false)?;
        non_manifold.sort_unstable();
        non_manifold.dedup();
    }
    let copies = pieces(v, o, n_vertices, true)?;
    let mut split_origins = try_to_vec(&copies, "the split vertices")?;
    split_origins.sort_unstable();
    split_origins.dedup();
    if links.is_empty() {
        non_manifold = try_to_vec(&split_origins, "the split vertices")?;
    }
    let mut split_examples = Vec::new();
    for &x in &non_manifold {
        push_example(&mut split_examples, x);
    }
    Ok(Split {
        split_vertices: non_manifold.len(),
        seam_split_vertices: split_origins.len() - non_manifold.len(),
        split_examples,
        copies,
    })
}

/// Walks the pieces of every vertex star, through `links`; every piece after the first of
/// a vertex is a copy. With `relabel`, the copies get new ids in `v` (after `n_vertices`);
/// returns the vertex each copy comes from, in order of creation.
fn pieces(v: &mut [u32], links: &[u32], n_vertices: usize, relabel: bool) -> Result<Vec<u32>> {
    let mut visited = try_vec(v.len().div_ceil(64), 0u64, "the split's occurrence marks")?;
    let mut has_piece = try_vec(n_vertices.div_ceil(64), 0u64, "the split's vertex marks")?;
    let test = |bits: &[u64], i: usize| (bits[i >> 6] >> (i & 63)) & 1 == 1;
    fn set(bits: &mut [u64], i: usize) {
        bits[i >> 6] |= 1 << (i & 63);
    }
    let mut copies: Vec<u32> = Vec::new();
    // A piece has at most every occurrence: the queue never grows past this.
    let mut queue: Vec<u32> = try_with_capacity(v.len(), "the split's queue")?;
    for s in 0..v.len() as u32 {
        if test(&visited, s as usize) {
            continue;
        }
        // Occurrence `s = 4t + i` is vertex `i` of tetrahedron `t`; the piece is every
        // occurrence of the same vertex reachable through faces holding it.
        let x = v[s as usize];
        set(&mut visited, s as usize);
        queue.clear();
        queue.push(s);
        let mut head = 0;
        while head < queue.len() {
            let occ = queue[head];
            head += 1;
            let t = tet(occ);
            for hf in first(t)..first(t) + 4 {
                let g = if hf == occ { NONE } else { links[hf as usize] };
                if g == NONE {
                    continue;
                }
                let base = first(tet(g));
                let Some(i2) = (0..4).find(|&i| v[(base + i) as usize] == x) else {
                    continue;
                };
                let occ2 = base + i2;
                if !test(&visited, occ2 as usize) {
                    set(&mut visited, occ2 as usize);
                    queue.push(occ2);
                }
            }
        }
        if !test(&has_piece, x as usize) {
            set(&mut has_piece, x as usize);
            continue;
        }
        try_push(&mut copies, x, "the vertex copies")?;
        if relabel {
            let id = (n_vertices + copies.len() - 1) as u32;
            for &occ in &queue {
                v[occ as usize] = id;
            }
        }
    }
    Ok(copies)
}
