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

/// The queries below level 2 on a mesh of about 200k triangles answer as level 3 does, in
/// O(T) each: the test runs tens of them at levels 0 and 1, which a query quadratic in T
/// (a scan of `V` per step of a walk) would not finish in the test's time.
#[test]
fn queries_below_level_2_are_linear_on_a_large_mesh() {
    let s = topomesh::generate::grid(300, 330);
    assert!(s.triangles.len() > 190_000);
    let build = |level| {
        Che::from_triangles(
            &s.triangles,
            s.positions.len(),
            &s.positions,
            BuildOptions::level(level),
        )
        .unwrap()
    };
    let top = build(3);
    let n_half_edges = 3 * top.num_triangles() as u32;
    let boundary: Vec<u32> = (0..n_half_edges)
        .filter(|&h| top.opposite(h) == topomesh::NONE)
        .step_by(300)
        .collect();
    let vertices = [0, 301, 45_000, s.positions.len() as u32 - 1];
    for level in [0, 1, 2] {
        let che = build(level);
        let curve = che.boundary_curve_vertices(0).unwrap();
        assert!(
            curve.len() == 2 * (300 + 330),
            "level {level}: {}",
            curve.len()
        );
        assert_eq!(
            curve,
            top.boundary_curve_vertices(0).unwrap(),
            "level {level}"
        );
        assert_eq!(che.num_boundary_curves(), 1);
        for &h in &boundary {
            assert_eq!(che.curve_of(h), 0, "level {level}, half-edge {h}");
        }
        for &v in &vertices {
            let same = |a: Vec<u32>, b: Vec<u32>| assert_eq!(a, b, "level {level}, vertex {v}");
            same(
                che.vertex_vertices(v).collect(),
                top.vertex_vertices(v).collect(),
            );
            same(che.vertex_edges(v).collect(), top.vertex_edges(v).collect());
            same(
                che.vertex_triangles(v).collect(),
                top.vertex_triangles(v).collect(),
            );
            assert_eq!(che.vertex_half_edge(v), top.vertex_half_edge(v));
            assert_eq!(che.is_boundary_vertex(v), top.is_boundary_vertex(v));
        }
        for e in [7, top.num_edges() as u32 - 1] {
            assert_eq!(
                che.edge_edges(e),
                top.edge_edges(e),
                "level {level}, edge {e}"
            );
        }
        for t in [99, top.num_triangles() as u32 - 1] {
            assert_eq!(
                che.triangle_edges(t),
                top.triangle_edges(t),
                "level {level}"
            );
        }
    }
}
