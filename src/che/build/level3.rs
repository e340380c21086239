//! Level 3: boundary curves. `CH` holds one half-edge per curve (its smallest), and a rank
//! over the boundary half-edges indexes the curve of each in O(1). The next boundary
//! half-edge after `h = (v -> w)` is `VH[w]`, by the level-2 rule.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::next;
use crate::error::Result;
use crate::util::alloc::{try_push, try_vec};
use crate::util::rank::{RankBits, try_for_each_one};

pub(crate) fn build(che: &mut Che) -> Result<()> {
    let (v, o, vh) = (&che.v, &che.o, &che.vh);
    let bits = RankBits::from_fn(v.len(), |h| o[h] == NONE)?;
    let mut curve_of = try_vec(bits.ones(), NONE, "the curve of each boundary half-edge")?;
    let mut ch = Vec::new();
    // The boundary half-edges in order, the `k`-th of rank `k`: a step per boundary
    // half-edge, and a rank computed only along the walks.
    let mut k = 0;
    for (w, &word) in bits.words().iter().enumerate() {
        try_for_each_one(word, 64 * w, |h| {
            if curve_of[k] == NONE {
                let c = ch.len() as u32;
                try_push(&mut ch, h as u32, "the curve half-edges CH")?;
                let mut g = h as u32;
                loop {
                    curve_of[bits.rank(g as usize)] = c;
                    g = vh[v[next(g) as usize] as usize];
                    if g as usize == h {
                        break;
                    }
                }
            }
            k += 1;
            Ok::<_, crate::error::Error>(())
        })?;
    }
    che.boundary_bits = bits;
    che.curve_of = curve_of.into();
    che.ch = ch.into();
    Ok(())
}
