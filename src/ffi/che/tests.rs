//! The exports called from Rust, as a C host would (the full C and C++ suites are in
//! `c-tests/`): the star iterator and the CSR calls agree with the core's iterators.

use super::*;
use crate::NONE;
use crate::che::{BuildOptions, Che};
use crate::ffi::boundary::with_last_error;
use crate::ffi::status::Status;
use std::ptr::null_mut;

const STRIP: [u32; 6] = [0, 1, 2, 1, 3, 2];

fn build(tris: &[u32], n_vertices: usize, level: u32) -> *mut CheMesh {
    crate::ffi::tests::build(che_mesh_from_triangles, tris, 3, n_vertices, level)
}

#[test]
fn star_iterator_matches_the_core_rotation() {
    let tetra = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3];
    for (tris, n) in [(&STRIP[..], 4), (&tetra[..], 4)] {
        for level in 0..=3 {
            let m = build(tris, n, level);
            // SAFETY: `m` is live until freed below.
            let che = unsafe { &(*m).che };
            for v in 0..n as u32 {
                let mut it = std::mem::MaybeUninit::<CheStarIter>::uninit();
                let mut step = CheStarStep::default();
                // SAFETY: live mesh, local iterator and step.
                assert_eq!(unsafe { che_star_begin(m, v, it.as_mut_ptr()) }, Status::Ok);
                let mut got = Vec::new();
                // SAFETY: the iterator was begun on a live mesh; `step` is a local.
                while unsafe { che_star_advance(it.as_mut_ptr(), &mut step) } {
                    got.push(step.0.vertex);
                }
                assert_eq!(
                    got,
                    che.vertex_vertices(v).collect::<Vec<_>>(),
                    "level {level} v {v}"
                );
            }
            // SAFETY: freed once.
            unsafe { che_mesh_free(m) };
        }
    }
}

#[test]
fn buffers_views_and_csr() {
    let m = build(&STRIP, 4, 1);
    let (mut buf, mut len) = ([0u32; 4], 0usize);
    // SAFETY: live mesh, local buffers of the stated sizes.
    unsafe {
        assert_eq!(
            che_vertex_vertices(m, 1, null_mut(), 0, &mut len),
            Status::Ok
        );
        assert_eq!(len, 3);
        assert_eq!(
            che_vertex_vertices(m, 1, buf.as_mut_ptr(), 2, &mut len),
            Status::BufferTooSmall
        );
        assert_eq!((len, &buf[..2]), (3, &[3, 2][..]));
        assert_eq!(
            che_triangle_triangles(m, 0, buf.as_mut_ptr(), 4, &mut len),
            Status::Ok
        );
        assert_eq!(&buf[..len], &[NONE, 1, NONE]);
        assert_eq!(
            che_vertex_vertices(m, 9, buf.as_mut_ptr(), 4, &mut len),
            Status::OutOfRange
        );
        assert!(with_last_error(|e| e.contains("vertex 9")));

        assert!(che_mesh_vertex_half_edges(m, &mut len).is_null() && len == 0);
        let o = che_mesh_opposites(m, &mut len);
        assert_eq!(
            std::slice::from_raw_parts(o, len),
            &[NONE, 5, NONE, NONE, NONE, 1]
        );

        let rows = crate::ffi::tests::bulk(m, che_mesh_vertex_vertices_csr);
        assert_eq!(rows, [vec![1, 2], vec![3, 2, 0], vec![0, 1, 3], vec![2, 1]]);
        assert_eq!(
            che_mesh_level(m),
            1,
            "the bulk call builds a copy, not the mesh"
        );
        che_mesh_free(m);
        che_mesh_free(null_mut());
    }
}

/// The arithmetic of `che_edge_of` (topomesh_inline.h) on the lent directory gives the
/// core's edge ids, at level 1 (computed here) and from level 2 (the core's own).
#[test]
fn edge_directory_gives_the_core_edge_ids() {
    // A strip of 40 triangles (120 half-edges: boundary and interior edges).
    let mut tris = Vec::new();
    for i in 0..40u32 {
        if i % 2 == 0 {
            tris.extend([i, i + 1, i + 2]);
        } else {
            tris.extend([i, i + 2, i + 1]);
        }
    }
    for level in 1..=3 {
        let mesh =
            CheMesh::from(Che::from_flat(&tris, 42, &[], BuildOptions::level(level)).unwrap());
        let o = mesh.che.opposites().unwrap();
        let d = mesh.che.edge_ranks().unwrap();
        assert_eq!(d.len(), o.len().div_ceil(32));
        for h in 0..o.len() as u32 {
            let g = o[h as usize];
            let c = if g != NONE && g < h { g } else { h } as usize;
            let entry = d[c / 32];
            let edge =
                (entry >> 32) as u32 + (entry as u32 & ((1u32 << (c % 32)) - 1)).count_ones();
            assert_eq!(edge, mesh.che.edge_of(h), "level {level} h {h}");
        }
    }
    let level0 = CheMesh::from(Che::from_flat(&tris, 42, &[], BuildOptions::level(0)).unwrap());
    assert!(level0.che.edge_ranks().is_none());
}

#[test]
fn validate_passes_at_every_level_and_names_a_null_handle() {
    let tetra = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3];
    let meshes = |level| vec![build(&STRIP, 4, level), build(&tetra, 4, level)];
    crate::ffi::tests::validates(meshes, che_mesh_validate, che_mesh_free);
}

#[test]
fn write_checks_the_handle_the_flags_and_the_positions() {
    let m = build(&STRIP, 4, 2);
    let path = c"/nonexistent-topomesh-folder/strip.off";
    let detail = |words: &str| with_last_error(|e| assert!(e.contains(words), "{e}"));
    // SAFETY: `m` is live until freed; the path is NUL-terminated.
    unsafe {
        assert_eq!(
            che_mesh_write(std::ptr::null(), path.as_ptr(), 0),
            Status::NullArgument
        );
        assert_eq!(che_mesh_write(m, std::ptr::null(), 0), Status::NullArgument);
        detail("'path'");
        assert_eq!(che_mesh_write(m, path.as_ptr(), 4), Status::InvalidInput);
        detail("unknown bits 0x4");
        assert_eq!(che_mesh_write(m, path.as_ptr(), 0), Status::InvalidInput);
        detail("no positions");
        che_mesh_free(m);
    }
}

#[test]
fn a_loaded_mesh_lends_the_reader_warnings() {
    let path =
        std::env::temp_dir().join(format!("topomesh-ffi-warnings-{}.off", std::process::id()));
    std::fs::write(&path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n").unwrap();
    let c_path = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
    let mut m = null_mut();
    // SAFETY: a valid path and out-pointer.
    let status = unsafe { che_mesh_load(c_path.as_ptr(), 2, &mut m) };
    let _ = std::fs::remove_file(&path);
    assert_eq!(status, Status::Ok);
    let want = format!(
        "{}:7: 1 face line after the 1 declared (ignored)",
        path.display()
    );
    let (mut buf, mut len) = ([0 as std::ffi::c_char; 256], 0usize);
    // SAFETY: `m` is live, the buffers valid for the sizes given.
    unsafe {
        assert_eq!(che_mesh_num_warnings(m), 1);
        assert_eq!(che_mesh_warning(m, 0, null_mut(), 0, &mut len), Status::Ok);
        assert_eq!(len, want.len() + 1);
        assert_eq!(
            che_mesh_warning(m, 0, buf.as_mut_ptr(), 256, &mut len),
            Status::Ok
        );
        let text = std::ffi::CStr::from_ptr(buf.as_ptr()).to_str().unwrap();
        assert_eq!(text, want);
        assert_eq!(
            che_mesh_warning(m, 0, buf.as_mut_ptr(), 5, &mut len),
            Status::BufferTooSmall
        );
        assert_eq!(
            std::ffi::CStr::from_ptr(buf.as_ptr()).to_bytes(),
            &want.as_bytes()[..4]
        );
        assert_eq!(
            che_mesh_warning(m, 1, buf.as_mut_ptr(), 256, &mut len),
            Status::OutOfRange
        );
        with_last_error(|e| assert_eq!(e, "warning 1 out of range (the mesh has 1 warnings)"));
        assert_eq!(
            che_mesh_warning(m, 0, null_mut(), 8, &mut len),
            Status::NullArgument
        );
        assert_eq!(che_mesh_num_warnings(std::ptr::null()), 0);
        che_mesh_free(m);
    }
    let built = build(&STRIP, 4, 2);
    // SAFETY: a live handle.
    unsafe {
        assert_eq!(che_mesh_num_warnings(built), 0);
        che_mesh_free(built);
    }
}

/// `che_mesh_views` gives at once what the single views and counts give, at every level,
/// and NULL_ARGUMENT for a NULL handle or out.
#[test]
fn views_at_once_match_the_single_views() {
    let positions = [0.0f64; 12];
    for level in 0..=3 {
        let m = build(&STRIP, 4, level);
        let mut p = null_mut();
        // SAFETY: live arrays of the stated sizes, a local out.
        let s = unsafe {
            che_mesh_from_triangles(STRIP.as_ptr(), 2, 4, positions.as_ptr(), level, &mut p)
        };
        assert_eq!(s, Status::Ok);
        for (m, with_positions) in [(m, false), (p, true)] {
            let mut v = std::mem::MaybeUninit::<CheViews>::uninit();
            // SAFETY: live mesh, a local out; NULL `len` is allowed.
            unsafe {
                assert_eq!(che_mesh_views(m, v.as_mut_ptr()), Status::Ok);
                let v = v.assume_init();
                let null = null_mut();
                assert_eq!(v.half_edge_vertices, che_mesh_half_edge_vertices(m, null));
                assert_eq!(v.opposites, che_mesh_opposites(m, null));
                assert_eq!(v.vertex_half_edges, che_mesh_vertex_half_edges(m, null));
                assert_eq!(v.edge_half_edges, che_mesh_edge_half_edges(m, null));
                assert_eq!(v.positions, che_mesh_positions(m, null));
                assert_eq!(v.positions.is_null(), !with_positions);
                assert_eq!(v.opposites.is_null(), level < 1);
                assert_eq!(v.edge_half_edges.is_null(), level < 2);
                let counts = (v.num_vertices, v.num_triangles, v.num_edges);
                let single = (
                    che_mesh_num_vertices(m),
                    che_mesh_num_triangles(m),
                    che_mesh_num_edges(m),
                );
                assert_eq!(counts, single);
                assert_eq!(counts, (4, 2, 5));
                assert_eq!(che_mesh_views(m, null_mut()), Status::NullArgument);
                che_mesh_free(m);
            }
        }
    }
    let mut v = std::mem::MaybeUninit::<CheViews>::uninit();
    // SAFETY: a NULL handle is allowed.
    assert_eq!(
        unsafe { che_mesh_views(std::ptr::null(), v.as_mut_ptr()) },
        Status::NullArgument
    );
}
