//! The CHF exports called from Rust, as a C host would (the full C and C++ suites are in
//! `c-tests/`): relations, CSR rows and boundary maps agree with the core at every level.

use super::ChfMesh;
use super::build::*;
use super::csr::*;
use super::info::chf_mesh_validate;
use super::relations::*;
use super::surface::*;
use super::views::*;
use crate::NONE;
use crate::ffi::boundary::with_last_error;
use crate::ffi::che::{che_mesh_free, che_mesh_num_triangles};
use crate::ffi::status::Status;
use crate::ffi::tests::{Bulk, Relation, bulk, rows};
use std::ptr::null_mut;

/// Two tetrahedra sharing the face (1, 2, 3), both positive.
const PAIR: [u32; 8] = [0, 1, 2, 3, 4, 1, 3, 2];

fn build(tets: &[u32], n_vertices: usize, level: u32) -> *mut ChfMesh {
    crate::ffi::tests::build(chf_mesh_from_tetrahedra, tets, 4, n_vertices, level)
}

#[test]
fn relations_and_bulk_rows_agree_at_every_level() {
    let reference = build(&PAIR, 5, 2);
    for level in 0..=3 {
        let m = build(&PAIR, 5, level);
        // SAFETY: live meshes, freed below.
        unsafe {
            let (nv, ne, nt) = (
                chf_mesh_num_vertices(m),
                chf_mesh_num_edges(m),
                chf_mesh_num_tetrahedra(m),
            );
            assert_eq!((nv, ne, chf_mesh_num_faces(m), nt), (5, 9, 7, 2));
            let pairs: [(Relation<ChfMesh>, Bulk<ChfMesh>, usize); 6] = [
                (chf_vertex_vertices, chf_mesh_vertex_vertices_csr, nv),
                (chf_vertex_edges, chf_mesh_vertex_edges_csr, nv),
                (chf_vertex_faces, chf_mesh_vertex_faces_csr, nv),
                (chf_vertex_tetrahedra, chf_mesh_vertex_tetrahedra_csr, nv),
                (chf_edge_faces, chf_mesh_edge_faces_csr, ne),
                (chf_edge_tetrahedra, chf_mesh_edge_tetrahedra_csr, ne),
            ];
            for (one, all, n) in pairs {
                let want = rows(reference, one, n);
                assert_eq!(rows(m, one, n), want, "level {level}");
                assert_eq!(bulk(m, all), want, "level {level}");
            }
            assert_eq!(
                bulk(m, chf_mesh_tetrahedron_tetrahedra_csr),
                rows(reference, chf_tetrahedron_tetrahedra, nt)
            );
            assert_eq!(
                rows(m, chf_tetrahedron_tetrahedra, nt),
                [[1, NONE, NONE, NONE], [0, NONE, NONE, NONE]]
            );
            assert_eq!(chf_mesh_level(m), level, "bulk calls leave the level alone");
            assert_eq!(chf_mesh_opposites(m, null_mut()).is_null(), level < 1);
            assert_eq!(
                chf_mesh_boundary_half_faces(m, null_mut()).is_null(),
                level < 3
            );

            let mut che = null_mut();
            assert_eq!(chf_mesh_boundary(m, &mut che), Status::Ok);
            assert_eq!(che_mesh_num_triangles(che), 6);
            assert_eq!(chf_mesh_num_boundary_faces(m), 6);
            let (mut hf, mut k) = (0, 0);
            assert_eq!(chf_half_face_boundary_triangle(m, 0, &mut k), Status::Ok);
            assert_eq!(k, NONE, "half-face 0 is the shared face");
            assert_eq!(chf_boundary_triangle_half_face(m, 0, &mut hf), Status::Ok);
            assert_eq!(hf, 1);
            assert_eq!(
                chf_boundary_triangle_half_face(m, 6, &mut hf),
                Status::OutOfRange
            );
            assert!(with_last_error(|e| e.contains("boundary triangle 6")));
            che_mesh_free(che);
            chf_mesh_free(m);
        }
    }
    // SAFETY: freed once; NULL is a no-op.
    unsafe {
        chf_mesh_free(reference);
        chf_mesh_free(null_mut());
    }
}

#[test]
fn validate_passes_on_a_build_and_rejects_null() {
    let meshes = |level| vec![build(&PAIR, 5, level)];
    crate::ffi::tests::validates(meshes, chf_mesh_validate, chf_mesh_free);
}

#[test]
fn a_loaded_mesh_lends_the_reader_warnings() {
    let path =
        std::env::temp_dir().join(format!("topomesh-ffi-warnings-{}.mesh", std::process::id()));
    let text = "Dimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n\
                Triangles 1\n1 2 3 0\nTetrahedra 1\n1 2 3 4 0\nEnd\n";
    std::fs::write(&path, text).unwrap();
    let c_path = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
    let mut m = null_mut();
    // SAFETY: a valid path and out-pointer.
    let status = unsafe { chf_mesh_load(c_path.as_ptr(), 2, &mut m) };
    let _ = std::fs::remove_file(&path);
    assert_eq!(status, Status::Ok);
    let want = format!(
        "{}: 1 triangle beside the 1 tetrahedron ignored (a volume is built from its tetrahedra)",
        path.display()
    );
    let (mut buf, mut len) = ([0 as std::ffi::c_char; 256], 0usize);
    // SAFETY: `m` is live, the buffers valid for the sizes given.
    unsafe {
        assert_eq!(chf_mesh_num_warnings(m), 1);
        assert_eq!(
            chf_mesh_warning(m, 0, buf.as_mut_ptr(), 256, &mut len),
            Status::Ok
        );
        assert_eq!(len, want.len() + 1);
        let got = std::ffi::CStr::from_ptr(buf.as_ptr()).to_str().unwrap();
        assert_eq!(got, want);
        assert_eq!(
            chf_mesh_warning(m, 1, buf.as_mut_ptr(), 256, &mut len),
            Status::OutOfRange
        );
        assert_eq!(
            chf_mesh_warning(std::ptr::null(), 0, buf.as_mut_ptr(), 256, &mut len),
            Status::NullArgument
        );
        chf_mesh_free(m);
    }
    let built = build(&PAIR, 5, 1);
    // SAFETY: a live handle.
    unsafe {
        assert_eq!(chf_mesh_num_warnings(built), 0);
        chf_mesh_free(built);
    }
}
