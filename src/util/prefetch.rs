//! Asking the memory system for a cache line before it is read: the one `unsafe` of the
//! whole-mesh checks, which read arrays larger than the caches at places known a little
//! ahead of the read (a partner a few half-edges on, the next step of a rotation).

/// Starts fetching the cache line of `xs[i]` into the cache, when `i` is in range; reads
/// nothing and returns at once. Elsewhere than on x86-64, nothing.
#[inline(always)]
pub(crate) fn prefetch<T>(xs: &[T], i: usize) {
    #[cfg(target_arch = "x86_64")]
    if let Some(x) = xs.get(i) {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        // SAFETY: `_mm_prefetch` is `unsafe` only because it is a `target_feature` function
        // (SSE, which every x86-64 processor has and the target enables). A prefetch is a
        // hint: it writes nothing, its address (here a live element of `xs`) is not
        // dereferenced by the program, and it cannot fault.
        unsafe { _mm_prefetch::<_MM_HINT_T0>(std::ptr::from_ref(x).cast()) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (xs, i);
}
