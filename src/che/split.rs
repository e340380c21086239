//! Splitting non-manifold vertices: a vertex whose outgoing half-edges form several fans
//! (rotation-connected pieces) gets one copy per extra fan, appended after the input
//! vertices, so that one `VH` entry reaches the whole star of every vertex.

use super::ids::{next, prev};
use super::report::push_example;
use crate::NONE;
use crate::dsu::Dsu;

pub(crate) struct Split {
    /// Origins of the appended copies (input ids), in order of creation.
    pub copies: Vec<u32>,
    /// Input vertices split because their input star is several fans.
    pub split_vertices: usize,
    pub split_examples: Vec<u32>,
    /// Input vertices split only because a non-orientable seam crosses them.
    pub seam_split_vertices: usize,
    /// `VH` as level 2 wants it, found on the way: per vertex (copies included) its
    /// outgoing boundary half-edge, or any outgoing half-edge of a closed fan.
    pub vh: Vec<u32>,
}

/// Rewrites `v` so that every vertex id names one fan. `seams` (sorted, pairs running the
/// same way) tell which extra fans are only cut by a seam, not non-manifold in the input.
pub(crate) fn split(v: &mut [u32], o: &[u32], n_vertices: usize, seams: &[u32]) -> Split {
    let mut visited = vec![0u64; v.len().div_ceil(64)];
    let mut vh = vec![NONE; n_vertices];
    let mut copies: Vec<u32> = Vec::new();
    let test = |bits: &[u64], i: usize| (bits[i >> 6] >> (i & 63)) & 1 == 1;
    fn set(bits: &mut [u64], i: usize) {
        bits[i >> 6] |= 1 << (i & 63);
    }
    for h in 0..v.len() as u32 {
        if test(&visited, h as usize) {
            continue;
        }
        let vertex = v[h as usize];
        let id = if vh[vertex as usize] != NONE {
            copies.push(vertex);
            vh.push(NONE);
            (n_vertices + copies.len() - 1) as u32
        } else {
            vertex
        };
        // Counter-clockwise from `h` until back at `h` (a closed fan, the common case) or
        // the boundary; then clockwise from `h` for the rest of an open fan.
        let mut g = h;
        let closed = loop {
            set(&mut visited, g as usize);
            if id != vertex {
                v[g as usize] = id;
            }
            let around = o[prev(g) as usize];
            if around == NONE {
                break false;
            }
            if around == h {
                break true;
            }
            g = around;
        };
        let mut start = h;
        if !closed {
            loop {
                let back = o[start as usize];
                if back == NONE {
                    break;
                }
                start = next(back);
                set(&mut visited, start as usize);
                if id != vertex {
                    v[start as usize] = id;
                }
            }
        }
        vh[id as usize] = start;
    }

    let mut split_origins: Vec<u32> = copies.clone();
    split_origins.sort_unstable();
    split_origins.dedup();
    let non_manifold = if seams.is_empty() || split_origins.is_empty() {
        vec![true; split_origins.len()]
    } else {
        still_split(v, n_vertices, &copies, &split_origins, seams)
    };
    let mut split_examples = Vec::new();
    for (&x, _) in split_origins
        .iter()
        .zip(&non_manifold)
        .filter(|(_, nm)| **nm)
    {
        push_example(&mut split_examples, x);
    }
    let split_vertices = non_manifold.iter().filter(|&&nm| nm).count();
    Split {
        split_vertices,
        seam_split_vertices: split_origins.len() - split_vertices,
        split_examples,
        copies,
        vh,
    }
}

/// Joins the fans of each vertex that a seam pair connects; a split vertex whose fans all
/// join was manifold in the input. Returns, per split origin, whether it is non-manifold.
fn still_split(
    v: &[u32],
    n_vertices: usize,
    copies: &[u32],
    split_origins: &[u32],
    seams: &[u32],
) -> Vec<bool> {
    let n = n_vertices + copies.len();
    let mut dsu = Dsu::new(n);
    // Seams come in pairs (h, g) of half-edges on one vertex pair running the same way.
    let mut by_pair: Vec<(u32, u32, u32)> = Vec::with_capacity(seams.len());
    let origin = |x: u32| {
        if (x as usize) < n_vertices {
            x
        } else {
            copies[x as usize - n_vertices]
        }
    };
    for &h in seams {
        by_pair.push((origin(v[h as usize]), origin(v[next(h) as usize]), h));
    }
    by_pair.sort_unstable();
    for pair in by_pair.chunks(2) {
        if let [(_, _, h), (_, _, g)] = *pair {
            dsu.union(v[h as usize], v[g as usize]);
            dsu.union(v[next(h) as usize], v[next(g) as usize]);
        }
    }
    let mut root_of_origin = vec![NONE; split_origins.len()];
    let mut apart = vec![false; split_origins.len()];
    for x in split_origins
        .iter()
        .copied()
        .chain((0..copies.len()).map(|c| (n_vertices + c) as u32))
    {
        let o = origin(x);
        let k = split_origins.binary_search(&o).expect("split vertex");
        let r = dsu.find(x);
        if root_of_origin[k] == NONE {
            root_of_origin[k] = r;
        } else if root_of_origin[k] != r {
            apart[k] = true;
        }
    }
    apart
}
