//! Arbitrary small triangle soups (ids a little past the vertex count included, so range
//! errors are exercised): every level builds or errors; built meshes answer every relation
//! of every element, the same at every level, and keep the Euler relation.
#![no_main]

use libfuzzer_sys::fuzz_target;
use topomesh::{BuildOptions, Che};

fuzz_target!(|data: &[u8]| {
    let Some((&head, rest)) = data.split_first() else {
        return;
    };
    let n_vertices = (head & 31) as usize + 1;
    let strict = head & 32 != 0;
    let ids: Vec<u32> = rest
        .iter()
        .map(|&b| u32::from(b) % (n_vertices as u32 + 2))
        .collect();
    let ids = &ids[..ids.len() / 3 * 3];
    let mut answers = Vec::new();
    for level in 0..=3 {
        let options = BuildOptions {
            level,
            strict,
            ..BuildOptions::default()
        };
        let che = match Che::from_flat(ids, n_vertices, &[], options) {
            Ok(che) => che,
            Err(_) => return,
        };
        let s = che.summary();
        assert_eq!(
            s.euler_characteristic,
            s.vertices as i64 - s.edges as i64 + s.triangles as i64
        );
        let mut all = Vec::new();
        for v in 0..che.num_vertices() as u32 {
            all.push(che.vertex_vertices(v).collect::<Vec<_>>());
            all.push(che.vertex_edges(v).collect());
            all.push(che.vertex_triangles(v).collect());
            all.push(vec![che.is_boundary_vertex(v) as u32]);
        }
        for e in 0..che.num_edges() as u32 {
            all.push(che.edge_vertices(e).to_vec());
            all.push(che.edge_triangles(e).iter().copied().collect());
            all.push(che.edge_edges(e).iter().copied().collect());
        }
        for t in 0..che.num_triangles() as u32 {
            all.push(che.triangle_vertices(t).to_vec());
            all.push(che.triangle_edges(t).to_vec());
            all.push(che.triangle_triangles(t).to_vec());
        }
        for c in 0..s.boundary_curves as u32 {
            all.push(che.boundary_curve_vertices(c).unwrap_or_default());
        }
        answers.push(all);
    }
    for level in 1..answers.len() {
        assert_eq!(
            answers[0], answers[level],
            "level {level} answers differ from level 0"
        );
    }
});
