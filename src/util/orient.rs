//! Orientation by breadth-first propagation, for both builds: across every pair of
//! partner halves (half-edges of triangles, half-faces of tetrahedra) a neighbour whose
//! shared half runs the same way gets the other flip; pairs that still disagree are the
//! seams. Then each component keeps the orientation most determinants agree with, or most
//! of the input's.

use crate::NONE;
use crate::error::Result;
use crate::util::alloc::{try_push, try_vec, try_with_capacity};
use crate::util::push_example;

/// The flips the propagation chooses, in the input numbering.
#[derive(Default)]
pub(crate) struct Flips {
    /// Per element: is it flipped.
    pub flipped: Vec<bool>,
    /// Pairs that disagree (the seams), `h < g` each.
    pub seam_pairs: Vec<u32>,
    pub flipped_count: usize,
    pub non_orientable_components: usize,
    /// One element of each non-orientable component.
    pub non_orientable_examples: Vec<u32>,
}

/// Orients each component of the elements of `K` halves that `partner` links: every
/// element's flip, the seams, and the components that cannot be oriented. `sign` is empty
/// or holds the sign of each element's determinant.
pub(crate) fn choose_flips<const K: usize>(
    partner: &[u32], same_direction: impl Fn(u32, u32) -> bool, sign: &[i8],
) -> Result<Flips> {
    let n = partner.len() / K;
    let mut out = Flips::default();
    let mut flipped = try_vec(n, false, "the orientation's flips")?;
    let mut visited = try_vec(n, false, "the orientation's marks")?;
    // A component has at most `n` elements: the queue never grows past this.
    let mut queue: Vec<u32> = try_with_capacity(n, "the orientation's queue")?;
    let mut walk = Walk::<K, _> {
        partner,
        same_direction,
        flipped: &mut flipped,
        visited: &mut visited,
        seam_pairs: &mut out.seam_pairs,
    };
    for root in 0..n as u32 {
        if walk.visited[root as usize] {
            continue;
        }
        let conflict = walk.component(root, &mut queue)?;
        out.flipped_count += settle(&queue, walk.flipped, sign);
        if conflict {
            out.non_orientable_components += 1;
            push_example(&mut out.non_orientable_examples, root);
        }
    }
    out.flipped = flipped;
    Ok(out)
}

/// The propagation's state over elements of `K` halves each (half `h` of element `h / K`):
/// a flip per element, relative to its component's root.
struct Walk<'a, const K: usize, S> {
    partner: &'a [u32],
    /// Whether half `h` and its partner `g` run the same way.
    same_direction: S,
    flipped: &'a mut [bool],
    visited: &'a mut [bool],
    /// Pairs that disagree, `h < g` each.
    seam_pairs: &'a mut Vec<u32>,
}

impl<const K: usize, S: Fn(u32, u32) -> bool> Walk<'_, K, S> {
    /// Visits the component of `root` breadth first into `queue`, flipping each element to
    /// agree with the one it is reached from; true when some pair disagrees anyway.
    fn component(&mut self, root: u32, queue: &mut Vec<u32>) -> Result<bool> {
        self.visited[root as usize] = true;
        queue.clear();
        queue.push(root);
        let mut head = 0;
        let mut conflict = false;
        while head < queue.len() {
            let t = queue[head];
            head += 1;
            let ft = self.flipped[t as usize];
            let first = K as u32 * t;
            for h in first..first + K as u32 {
                let g = self.partner[h as usize];
                if g == NONE {
                    continue;
                }
                let t2 = g / K as u32;
                let want = ft ^ (self.same_direction)(h, g);
                if !self.visited[t2 as usize] {
                    self.visited[t2 as usize] = true;
                    self.flipped[t2 as usize] = want;
                    queue.push(t2);
                } else if self.flipped[t2 as usize] != want && h < g {
                    conflict = true;
                    try_push(self.seam_pairs, h, "the seams")?;
                    try_push(self.seam_pairs, g, "the seams")?;
                }
            }
        }
        Ok(conflict)
    }
}

/// Chooses the orientation of a component (`queue`): the one most determinants agree
/// with (`sign`, empty without positions), else the one that keeps most of the input's.
/// Returns the elements it flips.
fn settle(queue: &[u32], flipped: &mut [bool], sign: &[i8]) -> usize {
    let (mut pos, mut neg) = (0usize, 0usize);
    if !sign.is_empty() {
        for &t in queue {
            let s = sign[t as usize];
            match if flipped[t as usize] { -s } else { s } {
                1 => pos += 1,
                -1 => neg += 1,
                _ => {}
            }
        }
    }
    let count = queue.iter().filter(|&&t| flipped[t as usize]).count();
    let flip_all = if pos != neg {
        neg > pos
    } else {
        // Keep as much of the input orientation as possible.
        2 * count > queue.len()
    };
    if flip_all {
        for &t in queue {
            flipped[t as usize] = !flipped[t as usize];
        }
        queue.len() - count
    } else {
        count
    }
}
