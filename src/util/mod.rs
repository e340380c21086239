//! Helpers below both structures: threads, huge pages, rank directories, union-find,
//! small id lists, closing the holes of dropped elements, and the build reports' example
//! lists.

pub(crate) mod csr;
pub(crate) mod dsu;
pub(crate) mod holes;
pub(crate) mod options;
pub(crate) mod origin;
pub(crate) mod pages;
pub(crate) mod par;
pub(crate) mod rank;
pub(crate) mod rank_directory;
pub(crate) mod small_ids;

/// How many offending ids a build report keeps of each kind.
pub const REPORT_EXAMPLES: usize = 16;

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

/// [`push_example`] for each of `items`, in order: the examples a build thread found after
/// those already in `list`.
pub(crate) fn extend_examples<T>(list: &mut Vec<T>, items: impl IntoIterator<Item = T>) {
    let room = REPORT_EXAMPLES.saturating_sub(list.len());
    list.extend(items.into_iter().take(room));
}
