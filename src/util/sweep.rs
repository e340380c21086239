//! The streaming builds' pairing: ids (half-edges, half-faces) come in their order, block
//! by block, and the sweep holds only the *open* ones (those whose twin has not come yet)
//! in memory. A block's ids are sorted by their key (the vertex set they run over) and
//! merged with the sorted open list: a sort and a merge, no hash map. Ids of equal keys
//! pair, writing `O` at both ends. Memory follows the open list, which stays small when the
//! order sweeps the mesh (a grid, a generator, a streaming mesh) and is refused past a
//! bound otherwise.

use crate::NONE;
use crate::error::{Error, Result};
use crate::util::alloc::{try_reserve, try_with_capacity};

/// How a sweep runs, in ids.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// Ids sorted at a time.
    pub block: usize,
    /// The most ids left open at once.
    pub max_open: usize,
}

/// What a sweep found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Swept {
    /// Pairs made.
    pub pairs: usize,
    /// Ids left open at the end (boundary half-edges or half-faces).
    pub open: usize,
}

impl Swept {
    /// The keys met: edges, faces.
    pub(crate) fn keys(&self) -> usize {
        self.pairs + self.open
    }
}

/// What the sweep needs to know of the structure it pairs.
pub(crate) trait Rules {
    type Key: Ord + Copy;
    /// The vertex set id `h` runs over.
    fn key(&self, h: u32) -> Self::Key;
    /// `g` (earlier) and `h` share a key: may they be twins? Else the error.
    fn check_pair(&self, g: u32, h: u32) -> Result<()>;
    /// The error for `key`, met by `n` ids (more than two), the first three in `first`.
    fn crowded(&self, key: Self::Key, first: [u32; 3], n: usize) -> Error;
    /// The error for `open` ids left open after id `last` (more than `max_open`).
    fn too_open(&self, open: usize, last: u32, max_open: usize) -> Error;
}

/// Fills `o` (all `NONE` on entry) for ids `0..o.len()`, block by block.
pub(crate) fn sweep<R: Rules>(rules: &R, o: &mut [u32], limits: Limits) -> Result<Swept> {
    let n = o.len();
    let block = limits.block.max(1);
    let mut open: Vec<(R::Key, u32)> = Vec::new();
    let mut keyed = try_with_capacity(block.min(n), "the sweep's block")?;
    let mut merged = Vec::new();
    let mut swept = Swept::default();
    for first in (0..n).step_by(block) {
        keyed.clear();
        let last = (first + block).min(n);
        keyed.extend((first as u32..last as u32).map(|h| (rules.key(h), h)));
        keyed.sort_unstable();
        merged.clear();
        try_reserve(&mut merged, open.len() + keyed.len(), "the open ids")?;
        swept.pairs += merge(rules, o, &open, &keyed, &mut merged)?;
        std::mem::swap(&mut open, &mut merged);
        if open.len() > limits.max_open {
            return Err(rules.too_open(open.len(), last as u32 - 1, limits.max_open));
        }
    }
    swept.open = open.len();
    Ok(swept)
}

/// Merges the sorted block `keyed` with the sorted `open` list into `out` (the ids still
/// open), pairing equal keys; returns the pairs made.
fn merge<R: Rules>(
    rules: &R, o: &mut [u32], open: &[(R::Key, u32)], keyed: &[(R::Key, u32)],
    out: &mut Vec<(R::Key, u32)>,
) -> Result<usize> {
    let (mut i, mut j, mut pairs) = (0, 0, 0);
    while j < keyed.len() {
        let k = keyed[j].0;
        while i < open.len() && open[i].0 < k {
            out.push(open[i]);
            i += 1;
        }
        let run = keyed[j..].iter().take_while(|e| e.0 == k).count();
        let earlier = (i < open.len() && open[i].0 == k).then(|| open[i].1);
        let (mut group, mut n) = ([NONE; 3], 0);
        for h in earlier
            .into_iter()
            .chain(keyed[j..j + run].iter().map(|e| e.1))
        {
            if n < 3 {
                group[n] = h;
            }
            n += 1;
        }
        match n {
            1 => out.push((k, group[0])),
            2 => {
                let [g, h, _] = group;
                rules.check_pair(g, h)?;
                debug_assert!(o[g as usize] == NONE && o[h as usize] == NONE);
                o[g as usize] = h;
                o[h as usize] = g;
                pairs += 1;
            }
            _ => return Err(rules.crowded(k, group, n)),
        }
        i += usize::from(earlier.is_some());
        j += run;
    }
    out.extend_from_slice(&open[i..]);
    Ok(pairs)
}
