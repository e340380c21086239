//! Orienting every edge-connected component by a breadth-first traversal: a neighbour
//! whose shared half-edge runs the same way is flipped. Where a component cannot be
//! oriented (Moebius strip, Klein bottle) the conflicting pairs become seams: left unpaired.

use super::report::push_example;
use crate::NONE;
use crate::che::ids::{first, tri};
use crate::util::orient::{Walk, settle};

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
    let choice = choose_flips(v, partner);
    for (t, &f) in choice.flipped.iter().enumerate() {
        if f {
            v.swap(3 * t + 1, 3 * t + 2);
        }
    }
    let (o, seams) = renumber_pairs(partner, &choice.flipped, &choice.seam_pairs);
    Oriented {
        o,
        seams,
        flipped: choice.flipped,
        flipped_count: choice.flipped_count,
        non_orientable_components: choice.non_orientable_components,
        non_orientable_examples: choice.non_orientable_examples,
    }
}

/// Which triangles to flip, and the pairs that conflict (seams, in the input numbering).
#[derive(Default)]
struct Choice {
    flipped: Vec<bool>,
    seam_pairs: Vec<u32>,
    flipped_count: usize,
    non_orientable_components: usize,
    non_orientable_examples: Vec<u32>,
}

/// A breadth-first traversal of each edge-connected component; each keeps as much of the
/// input orientation as possible.
fn choose_flips(v: &[u32], partner: &[u32]) -> Choice {
    let n_tris = v.len() / 3;
    let mut choice = Choice::default();
    let mut flipped = vec![false; n_tris];
    let mut visited = vec![false; n_tris];
    let mut queue: Vec<u32> = Vec::new();
    let mut walk = Walk::<3, _> {
        partner,
        // Partners on one vertex pair run the same way when they start at the same vertex.
        same_direction: |h: u32, g: u32| v[h as usize] == v[g as usize],
        flipped: &mut flipped,
        visited: &mut visited,
        seam_pairs: &mut choice.seam_pairs,
    };
    for root in 0..n_tris as u32 {
        if walk.visited[root as usize] {
            continue;
        }
        let conflict = walk.component(root, &mut queue);
        choice.flipped_count += settle(&queue, walk.flipped, &[]);
        if conflict {
            choice.non_orientable_components += 1;
            push_example(&mut choice.non_orientable_examples, root);
        }
    }
    choice.flipped = flipped;
    choice
}

/// The opposites and the sorted seams in the flipped numbering: every partner pair but
/// the seams.
fn renumber_pairs(partner: &[u32], flipped: &[bool], seam_pairs: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let renumber = |h: u32| {
        if flipped[tri(h) as usize] {
            flipped_id(h)
        } else {
            h
        }
    };
    let mut is_seam = vec![false; 0];
    if !seam_pairs.is_empty() {
        is_seam = vec![false; partner.len()];
        for &h in seam_pairs {
            is_seam[h as usize] = true;
        }
    }
    let mut o = crate::util::pages::filled(partner.len(), NONE);
    for h in 0..partner.len() as u32 {
        let g = partner[h as usize];
        if g != NONE && (is_seam.is_empty() || !is_seam[h as usize]) {
            o[renumber(h) as usize] = renumber(g);
        }
    }
    let mut seams: Vec<u32> = seam_pairs.iter().map(|&h| renumber(h)).collect();
    seams.sort_unstable();
    (o, seams)
}
