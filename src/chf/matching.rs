//! Matching half-faces on the same vertex triple: a counting pass buckets the half-faces by
//! their smallest vertex, then each (small) bucket is sorted by the two others. O(T) plus
//! tiny sorts; no hash map, no global comparison sort, 4 bytes per half-face.

use super::ids::{same_direction, sorted_triple};
use crate::NONE;

/// Half-faces in groups of equal vertex triple, in increasing (min, mid, max) order.
pub(crate) struct Groups<'a> {
    v: &'a [u32],
    /// Half-faces bucketed by smallest vertex, sorted by (mid, max, hf) inside a bucket.
    hfs: Vec<u32>,
    /// Bucket `x` is `hfs[start[x]..start[x + 1]]`.
    start: Vec<u32>,
}

impl<'a> Groups<'a> {
    pub(crate) fn new(v: &'a [u32], n_vertices: usize) -> Groups<'a> {
        let n_hf = v.len() as u32;
        let mut start = vec![0u32; n_vertices + 1];
        for hf in 0..n_hf {
            start[sorted_triple(v, hf)[0] as usize + 1] += 1;
        }
        for i in 0..n_vertices {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut hfs = vec![0u32; v.len()];
        for hf in 0..n_hf {
            let slot = &mut fill[sorted_triple(v, hf)[0] as usize];
            hfs[*slot as usize] = hf;
            *slot += 1;
        }
        drop(fill);
        // One scratch buffer of keys, reused by every bucket.
        let mut keys: Vec<(u64, u32)> = Vec::new();
        for w in start.windows(2) {
            let bucket = &mut hfs[w[0] as usize..w[1] as usize];
            if bucket.len() < 2 {
                continue;
            }
            keys.clear();
            keys.extend(bucket.iter().map(|&hf| (mid_max(v, hf), hf)));
            keys.sort_unstable();
            for (dst, &(_, hf)) in bucket.iter_mut().zip(&keys) {
                *dst = hf;
            }
        }
        Groups { v, hfs, start }
    }

    /// Calls `f(sorted triple, half-faces)` for every vertex triple; the half-faces are in
    /// increasing order.
    pub(crate) fn for_each(&self, mut f: impl FnMut([u32; 3], &[u32])) {
        for w in self.start.windows(2) {
            let bucket = &self.hfs[w[0] as usize..w[1] as usize];
            let mut i = 0;
            while i < bucket.len() {
                let key = mid_max(self.v, bucket[i]);
                let mut j = i + 1;
                while j < bucket.len() && mid_max(self.v, bucket[j]) == key {
                    j += 1;
                }
                f(sorted_triple(self.v, bucket[i]), &bucket[i..j]);
                i = j;
            }
        }
    }
}

#[inline]
fn mid_max(v: &[u32], hf: u32) -> u64 {
    let [_, b, c] = sorted_triple(v, hf);
    ((b as u64) << 32) | c as u64
}

/// Opposites of an already canonical `V` (oriented, split): two half-faces are twins when
/// they are the only two on their vertex triple, run opposite ways, and are flagged neither
/// non-manifold nor seam. Level 0 queries compute this same table on the fly.
pub(crate) fn opposites_by_rule(
    v: &[u32],
    n_vertices: usize,
    non_manifold: &[u32],
    seams: &[u32],
) -> Vec<u32> {
    let mut o = vec![NONE; v.len()];
    Groups::new(v, n_vertices).for_each(|_, group| {
        if let [h, g] = *group {
            let flagged = non_manifold.binary_search(&h).is_ok() || seams.binary_search(&h).is_ok();
            if !flagged && !same_direction(v, h, g) {
                o[h as usize] = g;
                o[g as usize] = h;
            }
        }
    });
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_gather_equal_triples() {
        // (0,1,2,3) and (4,1,3,2) share face {1,2,3}.
        let v = [0, 1, 2, 3, 4, 1, 3, 2];
        let mut seen = Vec::new();
        Groups::new(&v, 5).for_each(|t, g| seen.push((t, g.to_vec())));
        assert_eq!(seen.len(), 7);
        assert!(seen.contains(&([1, 2, 3], vec![0, 4])));
        assert!(seen.windows(2).all(|w| w[0].0 < w[1].0));
        let o = opposites_by_rule(&v, 5, &[], &[]);
        assert_eq!(o, vec![4, NONE, NONE, NONE, 0, NONE, NONE, NONE]);
        assert_eq!(opposites_by_rule(&v, 5, &[0, 4], &[]), vec![NONE; 8]);
    }
}
