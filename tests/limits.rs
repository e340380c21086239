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

#[test]
fn counts_beyond_the_ids_or_the_used_vertices_are_refused_from_the_counts_alone() {
    use topomesh::che::{MAX_TRIANGLES, MAX_UNUSED_VERTICES};
    use topomesh::chf::MAX_TETRAHEDRA;
    use topomesh::{ErrorKind, che, chf};
    let too_large = |r: topomesh::error::Result<()>, needle: &str| {
        let e = r.unwrap_err();
        assert_eq!(e.kind, ErrorKind::TooLarge, "{e}");
        assert!(e.message.contains(needle), "{needle:?} not in {e}");
    };
    // Element counts whose half-edge (3t) or half-face (4t) ids, 0 to 3t - 1, would reach NONE.
    assert!(3 * MAX_TRIANGLES <= u32::MAX as usize && 3 * (MAX_TRIANGLES + 1) > u32::MAX as usize);
    assert!(
        4 * MAX_TETRAHEDRA <= u32::MAX as usize && 4 * (MAX_TETRAHEDRA + 1) > u32::MAX as usize
    );
    assert!(che::check_counts(MAX_TRIANGLES, 3).is_ok());
    too_large(
        che::check_counts(MAX_TRIANGLES + 1, 3),
        &format!("at most {MAX_TRIANGLES} triangles"),
    );
    assert!(chf::check_counts(MAX_TETRAHEDRA, 4).is_ok());
    too_large(
        chf::check_counts(MAX_TETRAHEDRA + 1, 4),
        &format!("at most {MAX_TETRAHEDRA} tetrahedra"),
    );
    too_large(che::check_counts(usize::MAX, 3), "half-edge ids");
    // Vertex ids that would reach NONE.
    too_large(che::check_counts(2, u32::MAX as usize), "below 2^32 - 1");
    too_large(chf::check_counts(2, usize::MAX), "below 2^32 - 1");
    // Vertices far beyond what the elements can name: the memory they would take holds nothing.
    let limit = format!("at most {MAX_UNUSED_VERTICES} vertices beyond");
    too_large(che::check_counts(2, u32::MAX as usize - 1), &limit);
    too_large(chf::check_counts(2, u32::MAX as usize - 1), &limit);
    assert!(che::check_counts(2, 6 + MAX_UNUSED_VERTICES).is_ok());
    too_large(che::check_counts(2, 7 + MAX_UNUSED_VERTICES), &limit);
    assert!(chf::check_counts(2, 8 + MAX_UNUSED_VERTICES).is_ok());
    too_large(chf::check_counts(2, 9 + MAX_UNUSED_VERTICES), &limit);
    // The builds check the counts first: two elements on 2^32 - 2 vertices fail at once,
    // without asking for the gigabytes that many vertices would take.
    let options = BuildOptions::default();
    let huge = u32::MAX as usize - 1;
    too_large(
        Che::from_triangles(&[[0, 1, 2], [0, 2, 3]], huge, &[], options).map(drop),
        &limit,
    );
    let tets = [[0, 1, 2, 3], [1, 2, 3, 4]];
    too_large(
        topomesh::Chf::from_tetrahedra(&tets, huge, &[], options).map(drop),
        &limit,
    );
}
