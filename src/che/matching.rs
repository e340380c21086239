//! Matching half-edges on the same unordered vertex pair: a counting pass buckets the
//! half-edges by their smaller vertex, then each (small) bucket is sorted by the larger
//! vertex. O(T) plus tiny sorts; no hash map, no global comparison sort.

use super::ids::next;
use crate::NONE;

/// Calls `f(min, max, group)` for every unordered vertex pair of `v`, in increasing
/// (min, max) order; `group` holds packed keys `(max << 32) | h` whose low 32 bits are the
/// half-edges on that pair, in increasing order. Each bucket is sorted just before its
/// groups are visited, while it is in cache.
pub(crate) fn for_each_group(v: &[u32], n_vertices: usize, mut f: impl FnMut(u32, u32, &[u64])) {
    // Counting pass: bucket `m` ends at `end[m]`; the scatter fills buckets backwards.
    let mut end = vec![0u32; n_vertices + 1];
    for h in 0..v.len() as u32 {
        let (a, b) = (v[h as usize], v[next(h) as usize]);
        end[a.min(b) as usize] += 1;
    }
    let mut total = 0u32;
    for e in end.iter_mut() {
        total += *e;
        *e = total;
    }
    let mut keys = vec![0u64; v.len()];
    for h in (0..v.len() as u32).rev() {
        let (a, b) = (v[h as usize], v[next(h) as usize]);
        let slot = &mut end[a.min(b) as usize];
        *slot -= 1;
        keys[*slot as usize] = ((a.max(b) as u64) << 32) | h as u64;
    }
    // Now `end[m]` is where bucket `m` starts.
    for min in 0..n_vertices {
        let bucket = &mut keys[end[min] as usize..end[min + 1] as usize];
        if bucket.len() > 1 {
            bucket.sort_unstable();
        }
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
    for_each_group(v, n_vertices, |_, _, group| {
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
        for_each_group(&v, 4, |a, b, g| {
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
