//! Checks of a build against its raw input and of the structure's invariants.

use super::mesh::{det, sorted};
use super::reference::{degenerate, expected};
use glam::DVec3;
use std::collections::BTreeSet;
use topomesh::NONE;
use topomesh::chf::Chf;

/// Checks the build against the raw input: nothing disappears, the split follows the
/// pieces of every input star, the orientation, `O` and `VH` invariants, the summary, and
/// the boundary surface at level 3. `geometry` holds the generator's positions (whether or
/// not the build was given them).
pub fn check_build(chf: &Chf, input: &[[u32; 4]], geometry: &[DVec3], given_positions: bool) {
    let n = geometry.len();
    let x = expected(input, n);
    let r = chf.report();
    // Nothing disappears: every kept tetrahedron is there, with its vertices, in order.
    assert_eq!(chf.num_tetrahedra(), x.kept);
    assert_eq!(r.dropped_degenerate, x.dropped);
    let mut present = vec![false; input.len()];
    let mut last = None;
    for t in 0..chf.num_tetrahedra() as u32 {
        let o = chf.tetrahedron_origin(t);
        assert!(last.is_none_or(|l| l < o), "tetrahedron order kept");
        last = Some(o);
        present[o as usize] = true;
        let back = chf.tetrahedron_vertices(t).map(|v| chf.vertex_origin(v));
        assert_eq!(
            sorted(back),
            sorted(input[o as usize]),
            "tetrahedron {t} from input {o}"
        );
    }
    let dropped: Vec<u32> = (0..input.len() as u32)
        .filter(|&i| !present[i as usize])
        .collect();
    assert!(dropped.iter().all(|&i| degenerate(input[i as usize])));
    assert_eq!(
        r.degenerate_examples,
        dropped
            .iter()
            .copied()
            .take(topomesh::REPORT_EXAMPLES)
            .collect::<Vec<_>>()
    );
    // The split: one structure vertex per piece of each input star.
    let mut structure_of_input_tet = vec![NONE; input.len()];
    for t in 0..chf.num_tetrahedra() as u32 {
        structure_of_input_tet[chf.tetrahedron_origin(t) as usize] = t;
    }
    let mut ids_used = BTreeSet::new();
    for (xv, pieces) in x.pieces.iter().enumerate() {
        for piece in pieces {
            let ids: BTreeSet<u32> = piece
                .iter()
                .map(|&i| {
                    let t = structure_of_input_tet[i as usize];
                    *chf.tetrahedron_vertices(t)
                        .iter()
                        .find(|&&v| chf.vertex_origin(v) == xv as u32)
                        .unwrap()
                })
                .collect();
            assert_eq!(ids.len(), 1, "one id per piece of vertex {xv}");
            assert!(
                ids_used.insert(*ids.first().unwrap()),
                "pieces of {xv} share an id"
            );
        }
    }
    let pieces: usize = x.pieces.iter().map(|p| p.len()).sum();
    assert_eq!(chf.num_vertices(), n + pieces - (n - x.isolated));
    assert_eq!(r.added_vertices, chf.num_vertices() - n);
    assert_eq!(r.split_vertices, x.split_vertices);
    assert_eq!(r.non_manifold_faces, x.non_manifold_faces);
    assert_eq!(r.non_manifold_edges, x.non_manifold_edges);
    assert_eq!(r.non_orientable_components, 0);
    // Orientation.
    let pos: Vec<DVec3> = (0..chf.num_vertices() as u32)
        .map(|v| geometry[chf.vertex_origin(v) as usize])
        .collect();
    let negative = (0..chf.num_tetrahedra() as u32)
        .filter(|&t| det(&pos, chf.tetrahedron_vertices(t)) < 0.0)
        .count();
    if given_positions {
        assert_eq!(negative, r.inverted_tetrahedra);
        if r.duplicate_tetrahedra + r.zero_volume + r.inverted_tetrahedra == 0 {
            let flips = dropped_free(input)
                .filter(|t| det(geometry, *t) < 0.0)
                .count();
            assert_eq!(r.flipped_tetrahedra, flips);
        }
    }
    check_invariants(chf);
    // Summary.
    let s = chf.summary();
    assert_eq!(
        (
            s.vertices as usize,
            s.edges as usize,
            s.faces as usize,
            s.tetrahedra as usize
        ),
        (n, x.edges, x.faces, x.kept)
    );
    assert_eq!(
        (
            s.boundary_faces as usize,
            s.boundary_edges as usize,
            s.boundary_vertices as usize
        ),
        (x.boundary_faces, x.boundary_edges, x.boundary_vertices)
    );
    assert_eq!(s.boundary_components as usize, x.boundary_components);
    assert_eq!(s.components as usize, x.components);
    assert_eq!(s.isolated_vertices as usize, x.isolated);
    assert_eq!(s.euler_characteristic, x.euler);
    assert_eq!(
        s.manifold,
        x.non_manifold_faces == 0 && x.non_manifold_edges == 0 && x.split_vertices == 0
    );
}

fn dropped_free(input: &[[u32; 4]]) -> impl Iterator<Item = [u32; 4]> + '_ {
    input.iter().copied().filter(|t| !degenerate(*t))
}

/// The structure's invariants (`Chf::validate`), and at level 3 the boundary maps'
/// answers below level 3 (computed for the call) against the stored ones.
pub fn check_invariants(chf: &Chf) {
    if let Err(e) = chf.validate() {
        panic!("{}", e.message);
    }
    if let Some(che) = chf.boundary() {
        let bv = chf.boundary_vertices();
        // The same answers below level 3, computed for the call.
        let mut low = chf.clone();
        low.build_level(1).unwrap();
        assert_eq!(low.num_boundary_faces(), chf.num_boundary_faces());
        assert_eq!(low.num_boundary_triangles(), chf.num_boundary_triangles());
        assert_eq!(low.num_boundary_vertices(), bv.len());
        assert_eq!(&low.boundary_vertices()[..], &bv[..]);
        assert_eq!(low.num_boundary_components(), chf.num_boundary_components());
        for v in 0..chf.num_vertices().min(50) as u32 {
            assert_eq!(low.boundary_vertex(v), chf.boundary_vertex(v));
            assert_eq!(low.boundary_component(v), chf.boundary_component(v));
        }
        for c in 0..che.num_vertices().min(50) as u32 {
            assert_eq!(
                low.boundary_vertex_volume_vertex(c),
                chf.boundary_vertex_volume_vertex(c)
            );
        }
    }
}
