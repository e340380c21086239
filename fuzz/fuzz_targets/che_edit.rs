//! Random edit sequences on small built surfaces (damaged ones included, with or without
//! positions on a coarse grid, level changes between edits): every operation succeeds or
//! is refused without changing the arrays; the mesh stays valid after each, and after
//! garbage collection.
#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;
use topomesh::{BuildOptions, Che};

fuzz_target!(|data: &[u8]| {
    let [head, n_tris, rest @ ..] = data else {
        return;
    };
    let n_vertices = (head & 31) as usize + 3;
    let level = (head >> 5) & 3;
    let n_ids = (*n_tris as usize % 24) * 3;
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
    let options = BuildOptions::level(level);
    let Ok(mut che) = Che::from_flat(&ids, n_vertices, &positions, options) else {
        return;
    };
    for op in ops.chunks_exact(2) {
        let before = (
            che.half_edge_vertices().to_vec(),
            che.opposites().map(<[u32]>::to_vec),
            che.vertex_half_edges().map(<[u32]>::to_vec),
            che.edge_half_edges().map(<[u32]>::to_vec),
        );
        // Ids a little past the counts, so range errors are exercised too.
        let id = |n: usize| u32::from(op[1]) % (n as u32 + 2);
        let (nv, nt, ne, nh) = (
            che.num_vertices(),
            che.num_triangles(),
            che.num_edges(),
            che.num_half_edges(),
        );
        let point = (!positions.is_empty()).then(|| common::grid_point([op[1], op[0], op[1] / 5]));
        let at = point.filter(|_| op[1] & 1 == 1);
        let r = match op[0] % 11 {
            0 => che.add_vertex(point).map(drop),
            1 => {
                let (a, b) = (id(nv), id(nv) / 2);
                che.add_triangle(a, b, (a + 1) % (nv as u32).max(1))
                    .map(drop)
            }
            2 => che.remove_triangle(id(nt)),
            3 => che.remove_vertex(id(nv)),
            4 => che.flip_edge(id(ne)),
            5 => che.split_edge(id(ne), at).map(drop),
            6 => che.collapse_edge(id(nh)).map(drop),
            7 => che.split_triangle(id(nt), at).map(drop),
            8 => che.is_flip_ok(id(ne)).map(drop),
            9 => che.garbage_collect().map(drop),
            // A level change is no edit: it keeps the mesh, or fails without a change.
            _ => che.build_level(op[1] % 4),
        };
        if r.is_err() {
            let after = (
                che.half_edge_vertices().to_vec(),
                che.opposites().map(<[u32]>::to_vec),
                che.vertex_half_edges().map(<[u32]>::to_vec),
                che.edge_half_edges().map(<[u32]>::to_vec),
            );
            assert_eq!(before, after, "a refused operation changed the mesh");
        }
        che.validate().unwrap();
        let s = che.summary();
        assert_eq!(
            s.euler_characteristic,
            s.vertices as i64 - s.edges as i64 + s.triangles as i64
        );
    }
    che.garbage_collect().unwrap();
    che.validate().unwrap();
});
