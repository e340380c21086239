//! Orienting every face-connected component by a breadth-first traversal: a neighbour
//! whose shared half-face runs the same way round is flipped (local vertices 1 and 2
//! swapped). Each component then takes the orientation most of its determinants agree
//! with (all of them on a valid mesh, so every tetrahedron ends with `det > 0`), or, without
//! positions or for a rebuild that keeps each side (`Orientation::AsGiven`), the one that
//! flips fewest tetrahedra.
//!
//! Why not orient each tetrahedron by its own determinant: on a folded or tangled mesh
//! that leaves neighbours disagreeing, and the faces between them could not be paired. Here
//! topology wins and the tetrahedra whose determinant disagrees are reported as inverted;
//! on a valid mesh both rules give the same result. Where a component cannot be oriented at
//! all (a solid Klein bottle) the conflicting pairs become seams, left unpaired.

use crate::NONE;
use crate::chf::build::Orientation;
use crate::chf::build::report::push_example;
use crate::chf::ids::{same_direction, tet};
use crate::error::Result;
use crate::util::alloc::{try_collect, try_vec};
use crate::util::orient::{Flips, choose_flips};

pub(crate) struct Oriented {
    /// Opposites in the flipped numbering (seams left unpaired).
    pub o: Vec<u32>,
    /// Seam half-faces in the flipped numbering, sorted.
    pub seams: Vec<u32>,
    /// When there are seams: the partners including the seam pairs, flipped numbering
    /// (the input's face adjacency, to tell seam splits from non-manifold vertices).
    pub links: Vec<u32>,
    /// Per tetrahedron: was it flipped; the counts and examples (structure tetrahedra) for
    /// the report.
    pub flips: Flips,
    pub inverted: usize,
    /// Structure tetrahedra.
    pub inverted_examples: Vec<u32>,
}

/// The new id of half-face `hf` once its tetrahedron is flipped: swapping local vertices 1
/// and 2 swaps the faces opposite them.
#[inline]
pub(crate) fn flipped_id(hf: u32) -> u32 {
    match hf & 3 {
        1 => hf + 1,
        2 => hf - 1,
        _ => hf,
    }
}

/// `partner[hf]` is the other half-face on `hf`'s vertex triple when there are exactly two
/// (either orientation), else `NONE`. `sign` is empty or holds the sign of each
/// tetrahedron's determinant, which chooses each component's side when `orientation` says
/// so. Flips `v` in place.
pub(crate) fn orient(
    v: &mut [u32], partner: &[u32], sign: &[i8], orientation: Orientation,
) -> Result<Oriented> {
    let side = match orientation {
        Orientation::ByDeterminants => sign,
        Orientation::AsGiven => &[],
    };
    let flips = choose_flips::<4>(partner, |h, g| same_direction(v, h, g), side)?;
    let (mut inverted, mut inverted_examples) = (0, Vec::new());
    if !sign.is_empty() {
        for (t, &f) in flips.flipped.iter().enumerate() {
            let s = if f { -sign[t] } else { sign[t] };
            if s < 0 {
                inverted += 1;
                push_example(&mut inverted_examples, t as u32);
            }
        }
    }
    let mut out = Oriented {
        o: Vec::new(),
        seams: Vec::new(),
        links: Vec::new(),
        flips: Flips::default(),
        inverted,
        inverted_examples,
    };
    apply(v, partner, &flips.flipped, &flips.seam_pairs, &mut out)?;
    out.flips = flips;
    Ok(out)
}

/// Flips the tetrahedra of `v` and renumbers the pairs: `O` without the seams, the seams,
/// and with seams the links (every pair, for the split).
fn apply(
    v: &mut [u32], partner: &[u32], flipped: &[bool], seam_pairs: &[u32], out: &mut Oriented,
) -> Result<()> {
    for (t, &f) in flipped.iter().enumerate() {
        if f {
            v.swap(4 * t + 1, 4 * t + 2);
        }
    }
    let renumber = |hf: u32| {
        if flipped[tet(hf) as usize] {
            flipped_id(hf)
        } else {
            hf
        }
    };
    let mut is_seam = Vec::new();
    if !seam_pairs.is_empty() {
        is_seam = try_vec(v.len(), false, "the seam marks")?;
        for &h in seam_pairs {
            is_seam[h as usize] = true;
        }
        out.links = try_vec(v.len(), NONE, "the face links")?;
    }
    let mut o = crate::util::pages::filled(v.len(), NONE, "the opposites O (level 1)")?;
    for h in 0..v.len() as u32 {
        let g = partner[h as usize];
        if g == NONE {
            continue;
        }
        if is_seam.is_empty() || !is_seam[h as usize] {
            o[renumber(h) as usize] = renumber(g);
        }
        if !out.links.is_empty() {
            out.links[renumber(h) as usize] = renumber(g);
        }
    }
    let mut seams = try_collect(seam_pairs.iter().map(|&h| renumber(h)), "the seams")?;
    seams.sort_unstable();
    out.o = o;
    out.seams = seams;
    Ok(())
}
