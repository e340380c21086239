//! Matching half-edges on the same unordered vertex pair: a counting pass buckets the
//! half-edges by their smaller vertex, then each (small) bucket is sorted by the larger
//! vertex. O(T) plus tiny sorts; no hash map, no global comparison sort.

use super::ids::next;
use crate::NONE;

/// Half-edges in groups of equal unordered vertex pair, in increasing (min, max) order.
pub(crate) struct Groups {
    /// `(max << 32) | h`, bucketed by min vertex and sorted inside each bucket.
    keys: Vec<u64>,
    /// Bucket `v` is `keys[start[v]..start[v + 1]]`.
    start: Vec<u32>,
}

impl Groups {
    pub(crate) fn new(v: &[u32], n_vertices: usize) -> Groups {
        let mut start = vec![0u32; n_vertices + 1];
        for h in 0..v.len() as u32 {
            let (a, b) = (v[h as usize], v[next(h) as usize]);
            start[a.min(b) as usize + 1] += 1;
        }
        for i in 0..n_vertices {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut keys = vec![0u64; v.len()];
        for h in 0..v.len() as u32 {
            let (a, b) = (v[h as usize], v[next(h) as usize]);
            let slot = &mut fill[a.min(b) as usize];
            keys[*slot as usize] = ((a.max(b) as u64) << 32) | h as u64;
            *slot += 1;
        }
        drop(fill);
        for w in start.windows(2) {
            let bucket = &mut keys[w[0] as usize..w[1] as usize];
            if bucket.len() > 1 {
                bucket.sort_unstable();
            }
        }
        Groups { keys, start }
    }

    /// Calls `f(min, max, half_edges)` for every unordered vertex pair; `half_edges` holds
    /// the packed keys (the low 32 bits are the half-edges, in increasing order).
    pub(crate) fn for_each(&self, mut f: impl FnMut(u32, u32, &[u64])) {
        for (min, w) in self.start.windows(2).enumerate() {
            let bucket = &self.keys[w[0] as usize..w[1] as usize];
            let mut i = 0;
            while i < bucket.len() {
                let max = bucket[i] >> 32;
                let mut j = i + 1;
                while j < bucket.len() && bucket[j] >> 32 == max {
                    j += 1;
                }
                f(min as u32, max as u32, &bucket[i..j]);
                i = j;
            }
        }
    }
}

/// The half-edge packed in a group key.
#[inline]
pub(crate) fn half_edge(key: u64) -> u32 {
    key as u32
}

/// Opposites of an already canonical `V` (oriented, split): `h` and `g` are opposite when
/// they are the only two half-edges on their vertex pair, run opposite ways, and are not
/// flagged non-manifold. Level 0 queries answer with the same rule by scanning.
pub(crate) fn opposites_by_rule(v: &[u32], n_vertices: usize, non_manifold: &[u32]) -> Vec<u32> {
    let mut o = vec![NONE; v.len()];
    Groups::new(v, n_vertices).for_each(|_, _, group| {
        if let [a, b] = *group {
            let (h, g) = (half_edge(a), half_edge(b));
            if v[h as usize] != v[g as usize] && non_manifold.binary_search(&h).is_err() {
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
    fn groups_collect_both_directions() {
        // Two triangles sharing edge {1, 2}: (0,1,2) and (2,1,3).
        let v = [0, 1, 2, 2, 1, 3];
        let mut seen = Vec::new();
        Groups::new(&v, 4).for_each(|a, b, g| {
            seen.push((a, b, g.iter().map(|&k| half_edge(k)).collect::<Vec<_>>()))
        });
        assert_eq!(
            seen,
            vec![
                (0, 1, vec![0]),
                (0, 2, vec![2]),
                (1, 2, vec![1, 3]),
                (1, 3, vec![4]),
                (2, 3, vec![5]),
            ]
        );
        let o = opposites_by_rule(&v, 4, &[]);
        assert_eq!(o, vec![NONE, 3, NONE, 1, NONE, NONE]);
    }
}
