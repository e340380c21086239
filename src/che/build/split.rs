//! Splitting non-manifold vertices: a vertex whose outgoing half-edges form several fans
//! (rotation-connected pieces) gets one copy per extra fan, appended after the input
//! vertices, so that one `VH` entry reaches the whole star of every vertex.

use super::report::push_example;
use crate::NONE;
use crate::che::ids::{next, prev};
use crate::error::Result;
use crate::util::alloc::{try_collect, try_push, try_to_vec, try_vec, try_with_capacity};
use crate::util::dsu::Dsu;

fn test(bits: &[u64], i: u32) -> bool {
    (bits[(i >> 6) as usize] >> (i & 63)) & 1 == 1
}

fn set(bits: &mut [u64], i: u32) {
    bits[(i >> 6) as usize] |= 1 << (i & 63);
}

/// Walks the fan of `h`'s origin through `h`: counter-clockwise until back at `h` (a closed
/// fan) or the boundary, then clockwise from `h` for the rest of an open fan. Calls `visit`
/// on every half-edge of the fan; returns the fan's `VH` half-edge (its outgoing boundary
/// half-edge, or `h` when closed) and its size.
pub(crate) fn walk_fan(o: &[u32], h: u32, visit: &mut impl FnMut(u32)) -> (u32, u32) {
    let mut count = 1;
    visit(h);
    let mut g = h;
    loop {
        let around = o[prev(g) as usize];
        if around == h {
            return (h, count);
        }
        if around == NONE {
            break;
        }
        g = around;
        count += 1;
        visit(g);
    }
    let mut start = h;
    loop {
        let back = o[start as usize];
        if back == NONE {
            return (start, count);
        }
        start = next(back);
        count += 1;
        visit(start);
    }
}

/// `VH` of every vertex whose outgoing half-edges form one fan, and the vertices whose do
/// not (several fans). One counting pass finds each vertex's first outgoing half-edge and
/// its number of them; then a walk from that half-edge must meet them all. The walks are
/// dependent chains of random `O` loads, so `LANES` of them advance in step: their cache
/// misses overlap instead of queueing.
/// The walks share out among up to `threads` threads, each over a range of vertices.
fn single_fans(
    v: &[u32], o: &[u32], n_vertices: usize, threads: usize,
) -> Result<(Vec<u32>, Vec<u32>)> {
    let mut vh = crate::util::pages::filled(n_vertices, NONE, "the vertex half-edges VH")?;
    let mut degree: Vec<u32> = crate::util::pages::zeroed(n_vertices, "the vertex degrees")?;
    for h in (0..v.len() as u32).rev() {
        let x = v[h as usize] as usize;
        vh[x] = h;
        degree[x] += 1;
    }
    let chunk = n_vertices.div_ceil(threads.max(1)).max(1);
    let jobs: Vec<_> = vh
        .chunks_mut(chunk)
        .zip(degree.chunks(chunk))
        .enumerate()
        .map(|(j, (vh, degree))| (j * chunk, vh, degree))
        .collect();
    let found = crate::util::par::run_all(jobs, |(first, vh, degree)| {
        single_fans_of(o, first, vh, degree)
    });
    let found = found.into_iter().collect::<Result<Vec<_>>>()?;
    let mut several = try_collect(found.into_iter().flatten(), "the non-manifold vertices")?;
    several.sort_unstable();
    Ok((vh, several))
}

/// [`single_fans`] for the vertices from `first` on (`vh` and `degree` are theirs): sets
/// their `VH` and returns those with several fans.
fn single_fans_of(o: &[u32], first: usize, vh: &mut [u32], degree: &[u32]) -> Result<Vec<u32>> {
    const LANES: usize = 8;
    let n_vertices = vh.len();
    let mut several = Vec::new();
    let mut lane = [(0u32, 0u32, 0u32, false); LANES]; // (start, current, count, walking)
    let mut open: Vec<u32> = Vec::new();
    let mut x = 0usize;
    while x < n_vertices {
        let mut vertices = [0u32; LANES];
        let mut n = 0;
        while n < LANES && x < n_vertices {
            if vh[x] != NONE {
                vertices[n] = x as u32;
                lane[n] = (vh[x], vh[x], 1, true);
                n += 1;
            }
            x += 1;
        }
        let mut walking = n;
        while walking > 0 {
            for l in lane[..n].iter_mut().filter(|l| l.3) {
                let around = o[prev(l.1) as usize];
                if around == l.0 || around == NONE {
                    l.3 = false;
                    walking -= 1;
                    if around == NONE {
                        l.2 = NONE; // open: finished below
                    }
                } else {
                    l.1 = around;
                    l.2 += 1;
                }
            }
        }
        for (&vertex, l) in vertices[..n].iter().zip(&lane[..n]) {
            if l.2 == NONE {
                try_push(&mut open, vertex, "the boundary vertices")?;
            } else if l.2 != degree[vertex as usize] {
                try_push(
                    &mut several,
                    first as u32 + vertex,
                    "the non-manifold vertices",
                )?;
            }
        }
    }
    // Boundary vertices: the whole walk again, with the clockwise part (rare enough).
    for x in open {
        let (start, count) = walk_fan(o, vh[x as usize], &mut |_| {});
        if count == degree[x as usize] {
            vh[x as usize] = start;
        } else {
            try_push(&mut several, first as u32 + x, "the non-manifold vertices")?;
        }
    }
    Ok(several)
}

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
///
/// Most vertices are manifold: one walk from their first outgoing half-edge meets all of
/// them ([`single_fans`], several walks at a time). Only the others take the general walk
/// over every one of their half-edges, in half-edge order, which numbers the copies.
pub(crate) fn split(
    v: &mut [u32], o: &[u32], n_vertices: usize, seams: &[u32], threads: usize,
) -> Result<Split> {
    let (mut vh, several) = single_fans(v, o, n_vertices, threads)?;
    let mut copies: Vec<u32> = Vec::new();
    if !several.is_empty() {
        let mut pending = try_vec(n_vertices.div_ceil(64), 0u64, "the split's vertex marks")?;
        for &x in &several {
            pending[(x >> 6) as usize] |= 1 << (x & 63);
            vh[x as usize] = NONE;
        }
        let is_pending = |x: u32| (pending[(x >> 6) as usize] >> (x & 63)) & 1 == 1;
        let mut visited = try_vec(v.len().div_ceil(64), 0u64, "the split's half-edge marks")?;
        for h in 0..v.len() as u32 {
            let vertex = v[h as usize];
            if (vertex as usize) >= n_vertices || !is_pending(vertex) || test(&visited, h) {
                continue;
            }
            let id = if vh[vertex as usize] != NONE {
                try_push(&mut copies, vertex, "the vertex copies")?;
                try_push(&mut vh, NONE, "the vertex half-edges VH")?;
                (n_vertices + copies.len() - 1) as u32
            } else {
                vertex
            };
            let mut fan = |g: u32| {
                set(&mut visited, g);
                v[g as usize] = id;
            };
            vh[id as usize] = walk_fan(o, h, &mut fan).0;
        }
    }
    let mut split_origins = try_to_vec(&copies, "the split vertices")?;
    split_origins.sort_unstable();
    split_origins.dedup();
    let non_manifold = if seams.is_empty() || split_origins.is_empty() {
        try_vec(split_origins.len(), true, "the split vertices")?
    } else {
        still_split(v, n_vertices, &copies, &split_origins, seams)?
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
    Ok(Split {
        split_vertices,
        seam_split_vertices: split_origins.len() - split_vertices,
        split_examples,
        copies,
        vh,
    })
}

/// Joins the fans of each vertex that a seam pair connects; a split vertex whose fans all
/// join was manifold in the input. Returns, per split origin, whether it is non-manifold.
fn still_split(
    v: &[u32], n_vertices: usize, copies: &[u32], split_origins: &[u32], seams: &[u32],
) -> Result<Vec<bool>> {
    let n = n_vertices + copies.len();
    let mut dsu = Dsu::new(n)?;
    // Seams come in pairs (h, g) of half-edges on one vertex pair running the same way.
    let mut by_pair: Vec<(u32, u32, u32)> = try_with_capacity(seams.len(), "the seams")?;
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
    let mut root_of_origin = try_vec(split_origins.len(), NONE, "the split vertices")?;
    let mut apart = try_vec(split_origins.len(), false, "the split vertices")?;
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
    Ok(apart)
}
