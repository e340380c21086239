//! Random edit sequences on small built tetrahedral meshes (damaged ones included, with or
//! without positions on a coarse grid, level changes between edits): every operation
//! succeeds or is refused without changing the arrays; the mesh stays valid after each,
//! and after garbage collection.
#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;
use topomesh::{Chf, chf};

/// The arrays a refused operation must leave as they were.
fn arrays(chf: &Chf) -> (Vec<u32>, Option<Vec<u32>>, Option<Vec<u32>>, usize, usize) {
    (
        chf.half_face_vertices().to_vec(),
        chf.opposites().map(<[u32]>::to_vec),
        chf.vertex_half_faces().map(<[u32]>::to_vec),
        chf.num_live_tetrahedra(),
        chf.num_live_vertices(),
    )
}

fuzz_target!(|data: &[u8]| {
    let [head, n_tets, rest @ ..] = data else {
        return;
    };
    let n_vertices = (head & 31) as usize + 4;
    let level = (head >> 5) & 3;
    let n_ids = (*n_tets as usize % 16) * 4;
    if rest.len() < n_ids {
        return;
    }
    let (ids, rest) = rest.split_at(n_ids);
    let Some((positions, ops)) = common::grid_points(*head, n_vertices, rest) else {
        return;
    };
    let ids: Vec<u32> = ids
        .iter()
        .map(|&b| u32::from(b) % n_vertices as u32)
        .collect();
    let Ok(mut chf) = Chf::from_flat(
        &ids,
        n_vertices,
        &positions,
        chf::BuildOptions::level(level),
    ) else {
        return;
    };
    for op in ops.chunks_exact(2) {
        let before = arrays(&chf);
        // Ids a little past the counts, so range errors are exercised too.
        let id = |n: usize| u32::from(op[1]) % (n as u32 + 2);
        let (nv, nt, nf, ne) = (
            chf.num_vertices(),
            chf.num_tetrahedra(),
            chf.num_faces(),
            chf.num_edges(),
        );
        let he = u64::from(op[1]) % (12 * nt as u64 + 2);
        let point = (!positions.is_empty()).then(|| common::grid_point([op[1], op[0], op[1] / 5]));
        let at = point.filter(|_| op[1] & 1 == 1);
        let r = match op[0] % 13 {
            0 => chf.add_vertex(point).map(drop),
            1 => {
                let a = id(nv);
                let m = (nv as u32).max(1);
                chf.add_tetrahedron([a, (a + 1) % m, (a + 2) % m, (a + 3) % m])
                    .map(drop)
            }
            2 => chf.remove_tetrahedron(id(nt)),
            3 => chf.remove_vertex(id(nv)),
            4 => chf.split_tetrahedron(id(nt), at).map(drop),
            5 => chf.split_face(id(nf), at).map(drop),
            6 => chf.split_edge(id(ne), at).map(drop),
            7 => chf.flip_23(id(nf)).map(drop),
            8 => chf.flip_32(id(ne)).map(drop),
            9 => chf.collapse_edge(he).map(drop),
            10 => chf.check_collapse_edge(he),
            11 => chf.garbage_collect().map(drop),
            // A level change is no edit: it keeps the mesh, or fails without a change.
            _ => chf.build_level(op[1] % 4),
        };
        if r.is_err() {
            assert!(
                before == arrays(&chf),
                "a refused operation changed the mesh"
            );
        }
        chf.validate().unwrap();
    }
    chf.garbage_collect().unwrap();
    chf.validate().unwrap();
    let s = chf.summary();
    assert_eq!(s.tetrahedra as usize, chf.num_tetrahedra());
});
