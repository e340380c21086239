//! Limits on the inputs: thread counts, element counts, and the cost of the queries at
//! every level.

use topomesh::che::BuildOptions;
use topomesh::{Che, planned_threads};

/// Everything a build stores, as text.
fn fingerprint(che: &Che) -> String {
    format!(
        "{:?}",
        (
            (
                che.half_edge_vertices(),
                che.opposites(),
                che.vertex_half_edges()
            ),
            (che.edge_half_edges(), che.curve_half_edges()),
            (che.num_vertices(), che.num_edges()),
            (che.vertex_origins(), che.triangle_origins()),
            che.report(),
        )
    )
}

#[test]
fn a_huge_thread_count_builds_the_single_threaded_mesh_on_the_machine_s_threads() {
    let s = topomesh::generate::grid(250, 200);
    let n = s.triangles.len();
    let available = std::thread::available_parallelism().map_or(1, |n| n.get());
    assert!(planned_threads(100_000, n) <= available);
    assert!(planned_threads(0, n) <= available);
    assert_eq!(planned_threads(100_000, 10), 1);
    for level in [0, 3] {
        let build = |threads| {
            let options = BuildOptions {
                level,
                threads,
                ..BuildOptions::default()
            };
            Che::from_triangles(&s.triangles, s.positions.len(), &s.positions, options).unwrap()
        };
        assert!(
            fingerprint(&build(100_000)) == fingerprint(&build(1)),
            "level {level}"
        );
    }
}
