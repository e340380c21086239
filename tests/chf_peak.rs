//! The build's heap peak stays within twice the heap the finished structure holds (issue 5:
//! "a build peak at most twice the final size"), at every level, on a mesh numbered at
//! random (every access a cache miss, as in tetgen's output): counted by a global
//! allocator wrapper, in a test binary of its own. The benchmark measures the same with
//! the resident set; this catches a change that raises the peak on any machine.

mod chf_common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

fn grow(n: usize) {
    let now = CURRENT.fetch_add(n, Ordering::Relaxed) + n;
    PEAK.fetch_max(now, Ordering::Relaxed);
}

// Sound: every call forwards to `System` with the caller's arguments; the counters only
// observe sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        grow(layout.size());
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        grow(layout.size());
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if new_size <= layout.size() {
            // A shrink happens in place.
            CURRENT.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
        } else {
            // Counted as the new block alongside the old one: a moving realloc holds both.
            grow(new_size);
            CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
        }
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn chf_build_peak_is_at_most_twice_the_structure() {
    let mesh = chf_common::scramble(&chf_common::cube(36, 36, 36, false), 7, 100);
    let flat: Vec<u32> = mesh.tets.iter().flatten().copied().collect();
    let n = mesh.n();
    for level in 0..=3u8 {
        let before = CURRENT.load(Ordering::Relaxed);
        PEAK.store(before, Ordering::Relaxed);
        let options = topomesh::ChfBuildOptions::level(level);
        let chf = topomesh::Chf::from_flat(&flat, n, &mesh.positions, options).unwrap();
        let held = CURRENT.load(Ordering::Relaxed) - before;
        let peak = PEAK.load(Ordering::Relaxed) - before;
        let ratio = peak as f64 / held as f64;
        println!(
            "level {level}: {} tetrahedra, peak {peak} B, held {held} B, ratio {ratio:.2}",
            chf.num_tetrahedra()
        );
        assert!(
            ratio <= 2.0,
            "level {level}: build peak {peak} B is {ratio:.2} times the {held} B held"
        );
        drop(chf);
    }
}
