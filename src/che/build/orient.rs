//! Orienting every edge-connected component by a breadth-first traversal: a neighbour
//! whose shared half-edge runs the same way is flipped. Where a component cannot be
//! oriented (Moebius strip, Klein bottle) the conflicting pairs become seams: left unpaired.

use crate::NONE;
use crate::che::ids::{first, tri};
use crate::error::Result;
use crate::util::alloc::{try_collect, try_vec};
use crate::util::orient::{Flips, choose_flips};

pub(crate) struct Oriented {
    /// Opposites in the flipped numbering.
    pub o: Vec<u32>,
    /// Seam half-edges in the flipped numbering, sorted.
    pub seams: Vec<u32>,
    /// Per triangle: was it flipped; the counts and examples for the report.
    pub flips: Flips,
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
pub(crate) fn orient(v: &mut [u32], partner: &[u32]) -> Result<Oriented> {
    // Partners on one vertex pair run the same way when they start at the same vertex.
    let flips = choose_flips::<3>(partner, |h, g| v[h as usize] == v[g as usize], &[])?;
    for (t, &f) in flips.flipped.iter().enumerate() {
        if f {
            v.swap(3 * t + 1, 3 * t + 2);
        }
    }
    let (o, seams) = renumber_pairs(partner, &flips.flipped, &flips.seam_pairs)?;
    Ok(Oriented { o, seams, flips })
}

/// The opposites and the sorted seams in the flipped numbering: every partner pair but
/// the seams.
fn renumber_pairs(
    partner: &[u32], flipped: &[bool], seam_pairs: &[u32],
) -> Result<(Vec<u32>, Vec<u32>)> {
    let renumber = |h: u32| {
        if flipped[tri(h) as usize] {
            flipped_id(h)
        } else {
            h
        }
    };
    let mut is_seam = vec![false; 0];
    if !seam_pairs.is_empty() {
        is_seam = try_vec(partner.len(), false, "the seam marks")?;
        for &h in seam_pairs {
            is_seam[h as usize] = true;
        }
    }
    let mut o = crate::util::pages::filled(partner.len(), NONE, "the opposites O (level 1)")?;
    for h in 0..partner.len() as u32 {
        let g = partner[h as usize];
        if g != NONE && (is_seam.is_empty() || !is_seam[h as usize]) {
            o[renumber(h) as usize] = renumber(g);
        }
    }
    let mut seams = try_collect(seam_pairs.iter().map(|&h| renumber(h)), "the seams")?;
    seams.sort_unstable();
    Ok((o, seams))
}
