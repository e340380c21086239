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

use super::alloc;
use crate::error::Result;

/// An empty vector with room for `capacity` elements (`what` names it if memory runs
/// out, as for every helper here).
pub(crate) fn with_capacity<T>(capacity: usize, what: &str) -> Result<Vec<T>> {
    let v = alloc::try_with_capacity(capacity, what)?;
    advise(&v);
    Ok(v)
}

/// [`with_capacity`] in `spare`'s memory when it has the room: a table rebuilt in place of
/// one at least as large (after garbage collection) reuses its pages, which are already
/// mapped, instead of faulting in fresh ones.
pub(crate) fn reusing<T>(mut spare: Vec<T>, capacity: usize, what: &str) -> Result<Vec<T>> {
    if spare.capacity() >= capacity {
        spare.clear();
        return Ok(spare);
    }
    with_capacity(capacity, what)
}

/// `vec![value; len]`, on huge pages where possible.
pub(crate) fn filled<T: Clone>(len: usize, value: T, what: &str) -> Result<Vec<T>> {
    let mut v = with_capacity(len, what)?;
    v.resize(len, value);
    Ok(v)
}

/// `vec![0; len]`, on huge pages where possible.
pub(crate) fn zeroed<T: Copy + Default>(len: usize, what: &str) -> Result<Vec<T>> {
    // `vec!` would ask the allocator for zeroed memory, unwritten until first use, but it
    // aborts when memory runs out; a fallible zeroed allocation needs `unsafe`, which
    // stays in the C skin. So the zeroes are written, after the advice.
    filled(len, T::default(), what)
}

/// `len` values of `f()`, for element types without `Clone` (atomics), on huge pages.
pub(crate) fn from_fn<T>(len: usize, f: impl FnMut() -> T, what: &str) -> Result<Vec<T>> {
    let mut v = with_capacity(len, what)?;
    v.extend(std::iter::repeat_with(f).take(len));
    Ok(v)
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
            let v = super::filled(len, 7u32, "v").unwrap();
            assert_eq!(v.len(), len);
            assert!(v.iter().all(|&x| x == 7));
            let w: Vec<u64> = super::with_capacity(len, "w").unwrap();
            assert!(w.is_empty() && w.capacity() >= len);
            let z: Vec<u64> = super::zeroed(len, "z").unwrap();
            assert!(z.len() == len && z.iter().all(|&x| x == 0));
            let a = super::from_fn(len, || std::sync::atomic::AtomicU32::new(3), "a").unwrap();
            assert!(
                a.len() == len
                    && a.iter()
                        .all(|x| x.load(std::sync::atomic::Ordering::Relaxed) == 3)
            );
        }
    }
}
