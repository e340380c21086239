//! Orienting every edge-connected component by a breadth-first traversal: a neighbour
//! whose shared half-edge runs the same way is flipped. Where a component cannot be
//! oriented (Moebius strip, Klein bottle) the conflicting pairs become seams: left unpaired.

use super::ids::{first, tri};
use super::report::push_example;
use crate::NONE;

pub(crate) struct Oriented {
    /// Opposites in the flipped numbering.
    pub o: Vec<u32>,
    /// Seam half-edges in the flipped numbering, sorted.
    pub seams: Vec<u32>,
    /// Per triangle: was it flipped.
    pub flipped: Vec<bool>,
    pub flipped_count: usize,
    pub non_orientable_components: usize,
    pub non_orientable_examples: Vec<u32>,
}

/// The new id of half-edge `h` once its triangle is flipped: flipping swaps corners 1 and 2,
/// so local half-edge 0 becomes 2, 1 stays, 2 becomes 0.
#[inline]
pub(crate) fn flipped_id(h: u32) -> u32 {
    let t = first(tri(h));
    t + 2 - (h - t)
}

/// `partner[h]` is the other half-edge on `h`'s vertex pair when there are exactly two (in
/// either direction), else `NONE`. Flips `v` in place and returns the opposites.
pub(crate) fn orient(v: &mut [u32], partner: &[u32]) -> Oriented {
    let n_tris = v.len() / 3;
    let mut flipped = vec![false; n_tris];
    let mut visited = vec![false; n_tris];
    let mut seam_pairs: Vec<u32> = Vec::new();
    let mut queue: Vec<u32> = Vec::new();
    let mut flipped_count = 0usize;
    let mut non_orientable_components = 0usize;
    let mut non_orientable_examples = Vec::new();

    for root in 0..n_tris as u32 {
        if visited[root as usize] {
            continue;
        }
        visited[root as usize] = true;
        queue.clear();
        queue.push(root);
        let mut head = 0;
        let mut conflict = false;
        while head < queue.len() {
            let t = queue[head];
            head += 1;
            let ft = flipped[t as usize];
            for h in first(t)..first(t) + 3 {
                let g = partner[h as usize];
                if g == NONE {
                    continue;
                }
                let t2 = tri(g);
                let same_direction = v[h as usize] == v[g as usize];
                let want = ft ^ same_direction;
                if !visited[t2 as usize] {
                    visited[t2 as usize] = true;
                    flipped[t2 as usize] = want;
                    queue.push(t2);
                } else if flipped[t2 as usize] != want && h < g {
                    conflict = true;
                    seam_pairs.push(h);
                    seam_pairs.push(g);
                }
            }
        }
        // Keep as much of the input orientation as possible.
        let count = queue.iter().filter(|&&t| flipped[t as usize]).count();
        if 2 * count > queue.len() {
            for &t in &queue {
                flipped[t as usize] = !flipped[t as usize];
            }
            flipped_count += queue.len() - count;
        } else {
            flipped_count += count;
        }
        if conflict {
            non_orientable_components += 1;
            push_example(&mut non_orientable_examples, root);
        }
    }

    for (t, &f) in flipped.iter().enumerate() {
        if f {
            v.swap(3 * t + 1, 3 * t + 2);
        }
    }
    let renumber = |h: u32| {
        if flipped[tri(h) as usize] {
            flipped_id(h)
        } else {
            h
        }
    };
    let mut is_seam = vec![false; 0];
    if !seam_pairs.is_empty() {
        is_seam = vec![false; v.len()];
        for &h in &seam_pairs {
            is_seam[h as usize] = true;
        }
    }
    let mut o = crate::util::pages::filled(v.len(), NONE);
    for h in 0..v.len() as u32 {
        let g = partner[h as usize];
        if g != NONE && (is_seam.is_empty() || !is_seam[h as usize]) {
            o[renumber(h) as usize] = renumber(g);
        }
    }
    let mut seams: Vec<u32> = seam_pairs.iter().map(|&h| renumber(h)).collect();
    seams.sort_unstable();
    Oriented {
        o,
        seams,
        flipped,
        flipped_count,
        non_orientable_components,
        non_orientable_examples,
    }
}
