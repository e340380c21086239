//! At level 2 and up, queries do not allocate (stars of up to 64 tetrahedra): counted with
//! a global allocator wrapper, in a test binary of its own.

mod chf_common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn chf_level_2_queries_do_not_allocate() {
    let mesh = chf_common::scramble(&chf_common::cube(4, 3, 3, false), 3, 85);
    for level in [2, 3] {
        let chf = mesh.build(level, true);
        let before = ALLOCATIONS.load(Ordering::Relaxed);
        let mut sum = 0u64;
        for v in 0..chf.num_vertices() as u32 {
            sum += chf.vertex_vertices(v).map(u64::from).sum::<u64>();
            sum += chf.vertex_edges(v).map(u64::from).sum::<u64>();
            sum += chf.vertex_faces(v).map(u64::from).sum::<u64>();
            sum += chf.vertex_tetrahedra(v).map(u64::from).sum::<u64>();
            sum += chf.is_boundary_vertex(v) as u64;
        }
        for e in 0..chf.num_edges() as u32 {
            sum += chf.edge_vertices(e).iter().map(|&x| x as u64).sum::<u64>();
            sum += chf.edge_edges(e).map(u64::from).sum::<u64>();
            sum += chf.edge_faces(e).map(u64::from).sum::<u64>();
            sum += chf.edge_tetrahedra(e).map(u64::from).sum::<u64>();
            sum += chf.is_boundary_edge(e) as u64;
        }
        for f in 0..chf.num_faces() as u32 {
            sum += chf.face_vertices(f).iter().map(|&x| x as u64).sum::<u64>();
            sum += chf.face_edges(f).iter().map(|&x| x as u64).sum::<u64>();
            sum += chf.face_faces(f).iter().map(|&x| x as u64).sum::<u64>();
            sum += chf
                .face_tetrahedra(f)
                .iter()
                .map(|&x| x as u64)
                .sum::<u64>();
            sum += chf.is_boundary_face(f) as u64;
        }
        for t in 0..chf.num_tetrahedra() as u32 {
            sum += chf
                .tetrahedron_vertices(t)
                .iter()
                .map(|&x| x as u64)
                .sum::<u64>();
            sum += chf
                .tetrahedron_edges(t)
                .iter()
                .map(|&x| x as u64)
                .sum::<u64>();
            sum += chf
                .tetrahedron_faces(t)
                .iter()
                .map(|&x| x as u64)
                .sum::<u64>();
            sum += chf
                .tetrahedron_tetrahedra(t)
                .iter()
                .map(|&x| x as u64)
                .sum::<u64>();
        }
        let after = ALLOCATIONS.load(Ordering::Relaxed);
        assert!(sum > 0);
        assert_eq!(after - before, 0, "level {level} queries allocated");
    }
}
