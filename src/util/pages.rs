//! Fresh arrays for the builds, backed by transparent huge pages where the kernel has them.
//!
//! A large build writes much fresh memory, much of it at random (pairs, stars). With 4 KiB
//! pages every 4 KiB costs a page fault and most random accesses a TLB miss. Asking for
//! 2 MiB pages (`madvise(MADV_HUGEPAGE)`, a hint the kernel may ignore) before the first
//! touch cuts both; BENCHMARKS.md and the changelog give the effect measured.

/// Arrays smaller than this keep the allocator's default pages.
#[cfg(target_os = "linux")]
const MIN_BYTES: usize = 8 << 20;
#[cfg(target_os = "linux")]
const HUGE_PAGE: usize = 2 << 20;

/// An empty vector with room for `capacity` elements.
pub(crate) fn with_capacity<T>(capacity: usize) -> Vec<T> {
    let v = Vec::with_capacity(capacity);
    advise(&v);
    v
}

/// `vec![value; len]`, on huge pages where possible.
pub(crate) fn filled<T: Clone>(len: usize, value: T) -> Vec<T> {
    let mut v = with_capacity(len);
    v.resize(len, value);
    v
}

/// `vec![0; len]`: fresh pages that the kernel zeroes, not written by us before use.
pub(crate) fn zeroed<T: Copy + Default>(len: usize) -> Vec<T> {
    // `vec!` of a zero integer allocates zeroed memory without writing it, so the advice
    // still comes before the first touch.
    let v = vec![T::default(); len];
    advise(&v);
    v
}

#[cfg(target_os = "linux")]
fn advise<T>(v: &Vec<T>) {
    let bytes = v.capacity() * std::mem::size_of::<T>();
    if bytes < MIN_BYTES {
        return;
    }
    let start = v.as_ptr() as usize;
    let first = start.next_multiple_of(HUGE_PAGE);
    let end = (start + bytes) / HUGE_PAGE * HUGE_PAGE;
    if end > first {
        // SAFETY: `madvise` only changes how the kernel backs the pages of
        // [first, end), which lies inside this vector's own allocation (its capacity,
        // rounded inwards to huge-page boundaries): no memory is read, written, freed or
        // remapped from Rust's point of view, and contents stay as they are. The call is a
        // hint; its failure (no THP, old kernel) is harmless and ignored.
        unsafe {
            libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise<T>(_: &Vec<T>) {}

#[cfg(test)]
mod tests {
    #[test]
    fn arrays_hold_what_was_asked() {
        for len in [0usize, 1, 1000, (9 << 20) / 4 + 3] {
            let v = super::filled(len, 7u32);
            assert_eq!(v.len(), len);
            assert!(v.iter().all(|&x| x == 7));
            let w: Vec<u64> = super::with_capacity(len);
            assert!(w.is_empty() && w.capacity() >= len);
            let z: Vec<u64> = super::zeroed(len);
            assert!(z.len() == len && z.iter().all(|&x| x == 0));
        }
    }
}
