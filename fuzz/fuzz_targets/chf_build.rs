//! Arbitrary small tetrahedron soups: every level builds or errors; built meshes answer
//! the relations of every element, the same at every level.
#![no_main]

use libfuzzer_sys::fuzz_target;
use topomesh::{Chf, chf};

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
    let ids = &ids[..ids.len() / 4 * 4];
    let mut answers = Vec::new();
    for level in 0..=3 {
        let options = chf::BuildOptions {
            strict,
            ..chf::BuildOptions::level(level)
        };
        let chf = match Chf::from_flat(ids, n_vertices, &[], options) {
            Ok(chf) => chf,
            Err(_) => return,
        };
        let _ = chf.summary();
        let mut all = Vec::new();
        for v in 0..chf.num_vertices() as u32 {
            let mut vv: Vec<u32> = chf.vertex_vertices(v).collect();
            let mut vt: Vec<u32> = chf.vertex_tetrahedra(v).collect();
            vv.sort_unstable();
            vt.sort_unstable();
            all.push(vv);
            all.push(vt);
        }
        for e in 0..chf.num_edges() as u32 {
            all.push(chf.edge_vertices(e).to_vec());
            let mut et: Vec<u32> = chf.edge_tetrahedra(e).collect();
            et.sort_unstable();
            all.push(et);
        }
        for t in 0..chf.num_tetrahedra() as u32 {
            all.push(chf.tetrahedron_vertices(t).to_vec());
            all.push(chf.tetrahedron_tetrahedra(t).to_vec());
            all.push(chf.tetrahedron_edges(t).to_vec());
            all.push(chf.tetrahedron_faces(t).to_vec());
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
