//! Helpers below both structures: build options and size checks, orientation, origin
//! maps, the accessors both structures share, CSR arrays, threads, huge pages, prefetches,
//! rank directories and select over changing bits, marks (one bit per element), union-find, small id lists, closing the
//! holes of dropped elements, the build input (borrowed or handed over), the weld of
//! nearly equal vertices, and the build reports' example lists.

#[allow(dead_code)]
pub(crate) mod alloc;
pub(crate) mod betti;
pub(crate) mod budget;
pub(crate) mod csr;
pub(crate) mod dsu;
pub(crate) mod fields;
pub(crate) mod holes;
pub(crate) mod input;
pub(crate) mod live_ranks;
pub(crate) mod marks;
pub(crate) mod options;
pub(crate) mod orient;
pub(crate) mod origin;
pub(crate) mod pages;
pub(crate) mod panics;
pub(crate) mod par;
pub(crate) mod prefetch;
pub mod progress;
pub(crate) mod rank;
pub(crate) mod rank_directory;
pub(crate) mod sink;
pub(crate) mod small_ids;
pub mod source;
pub mod sparse;
pub(crate) mod store;
pub(crate) mod structure;
pub(crate) mod sweep;
pub(crate) mod weld;

/// How many offending ids a build report keeps of each kind.
pub const REPORT_EXAMPLES: usize = 16;

/// The vertices with a NaN or infinite coordinate: how many, and the first
/// [`REPORT_EXAMPLES`] ids. The readers warn of them and the build reports count them.
pub fn non_finite_vertices(positions: &[glam::DVec3]) -> (u64, Vec<u32>) {
    let mut examples = Vec::new();
    let mut count = 0u64;
    for (v, p) in positions.iter().enumerate() {
        if !p.is_finite() {
            count += 1;
            push_example(&mut examples, v as u32);
        }
    }
    (count, examples)
}

/// Keeps the first [`REPORT_EXAMPLES`] examples of a kind in a build report.
pub(crate) fn push_example<T>(list: &mut Vec<T>, item: T) {
    if list.len() < REPORT_EXAMPLES {
        list.push(item);
    }
}

/// Unit tests' random numbers: xorshift64 from `seed`, reduced below the bound asked for.
#[cfg(test)]
pub(crate) fn test_rng(seed: u64) -> impl FnMut(usize) -> u32 {
    let mut x = seed;
    move |m: usize| {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % m as u64) as u32
    }
}

/// Unit tests' random soups, `rounds` of them from `seed`: in round `r`,
/// `vertices.0 + r % vertices.1` vertices and `elements.0 + r % elements.1` elements of `K`
/// ids each, repeats and all.
#[cfg(test)]
pub(crate) fn test_soups<const K: usize>(
    seed: u64, rounds: usize, vertices: (usize, usize), elements: (usize, usize),
) -> impl Iterator<Item = (usize, Vec<[u32; K]>)> {
    let mut rnd = test_rng(seed);
    (0..rounds).map(move |r| {
        let n = vertices.0 + r % vertices.1;
        let soup = (0..elements.0 + r % elements.1)
            .map(|_| [0; K].map(|_| rnd(n)))
            .collect();
        (n, soup)
    })
}

/// [`push_example`] for each of `items`, in order: the examples a build thread found after
/// those already in `list`.
pub(crate) fn extend_examples<T>(list: &mut Vec<T>, items: impl IntoIterator<Item = T>) {
    let room = REPORT_EXAMPLES.saturating_sub(list.len());
    list.extend(items.into_iter().take(room));
}
