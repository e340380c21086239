//! Editing a built CHE: random sequences of every operation (valid and refused) on closed
//! meshes, meshes with boundary and damaged meshes, at every level. Every few steps the
//! mesh is valid, and after garbage collection every relation, the curves and the summary
//! equal those of a fresh build of the live triangles; a refused operation changes nothing.

mod che_common;

use che_common::Rng;
use glam::DVec3;
use topomesh::che::next;
use topomesh::generate::{Surface, grid, sphere, torus};
use topomesh::{BuildOptions, Che, NONE};

/// Everything an edit may write, as plain data, to compare before and after.
#[derive(Debug, PartialEq)]
struct Arrays {
    v: Vec<u32>,
    o: Option<Vec<u32>>,
    vh: Option<Vec<u32>>,
    eh: Option<Vec<u32>>,
    positions: Vec<DVec3>,
    vertex_origins: Option<Vec<u32>>,
    triangle_origins: Option<Vec<u32>>,
    flags: (Vec<u32>, Vec<u32>),
    counts: [usize; 6],
}

fn arrays(c: &Che) -> Arrays {
    Arrays {
        v: c.half_edge_vertices().to_vec(),
        o: c.opposites().map(<[u32]>::to_vec),
        vh: c.vertex_half_edges().map(<[u32]>::to_vec),
        eh: c.edge_half_edges().map(<[u32]>::to_vec),
        positions: c.positions().to_vec(),
        vertex_origins: c.vertex_origins().map(<[u32]>::to_vec),
        triangle_origins: c.triangle_origins().map(<[u32]>::to_vec),
        flags: (
            c.non_manifold_half_edges().to_vec(),
            c.seam_half_edges().to_vec(),
        ),
        counts: [
            c.num_vertices(),
            c.num_triangles(),
            c.num_edges(),
            c.num_live_vertices(),
            c.num_live_triangles(),
            c.num_live_edges(),
        ],
    }
}

/// The relations, curves and summary of a CHE, for comparing two of them.
#[derive(Debug, PartialEq)]
struct Relations {
    arrays: Arrays,
    vv: topomesh::che::Csr,
    ve: topomesh::che::Csr,
    vf: topomesh::che::Csr,
    ff: Vec<u32>,
    fe: Vec<u32>,
    ev: Vec<[u32; 2]>,
    curves: Vec<Vec<u32>>,
    curve_of: Vec<u32>,
    summary: topomesh::che::Summary,
}

fn relations(c: &Che) -> Relations {
    let starts = c.boundary_curve_starts().into_owned();
    Relations {
        arrays: arrays(c),
        vv: c.all_vertex_vertices().unwrap(),
        ve: c.all_vertex_edges().unwrap(),
        vf: c.all_vertex_triangles().unwrap(),
        ff: c.all_triangle_triangles().unwrap(),
        fe: c.all_triangle_edges().unwrap(),
        ev: (0..c.num_edges() as u32)
            .map(|e| c.edge_vertices(e))
            .collect(),
        curves: starts
            .iter()
            .map(|&s| c.boundary_curve(s).collect())
            .collect(),
        curve_of: (0..c.num_half_edges() as u32)
            .map(|h| c.curve_of(h))
            .collect(),
        summary: c.summary(),
    }
}

/// The live triangles through the collection's maps equal the collected mesh's, which
/// equals a fresh build of them in every relation; the summary before the collection is
/// already the fresh build's.
fn check_against_fresh(che: &Che) {
    che.validate().unwrap();
    let mut done = che.clone();
    let maps = done.garbage_collect().unwrap();
    done.validate().unwrap();
    for t in 0..che.num_triangles() as u32 {
        let nt = maps.triangles[t as usize];
        assert_eq!(nt == NONE, che.is_triangle_removed(t));
        if nt != NONE {
            let old = che.triangle_vertices(t).map(|x| maps.vertices[x as usize]);
            assert_eq!(done.triangle_vertices(nt), old, "triangle {t}");
        }
    }
    for h in 0..che.num_half_edges() as u32 {
        if !che.is_half_edge_removed(h) {
            let nh = 3 * maps.triangles[h as usize / 3] + h % 3;
            assert_eq!(done.edge_of(nh), maps.edges[che.edge_of(h) as usize]);
        }
    }
    let tris: Vec<u32> = done.half_edge_vertices().to_vec();
    let options = BuildOptions::level(che.level());
    let fresh = Che::from_flat(&tris, done.num_vertices(), done.positions(), options).unwrap();
    let (mut a, mut b) = (relations(&done), relations(&fresh));
    // Origins follow the input through the edits; the fresh build's are its own.
    (a.arrays.vertex_origins, a.arrays.triangle_origins) = (None, None);
    (b.arrays.vertex_origins, b.arrays.triangle_origins) = (None, None);
    assert_eq!(a, b);
    assert_eq!(che.summary(), fresh.summary());
}

/// One random operation; its result or refusal is checked against the arrays before.
fn random_op(che: &mut Che, rng: &mut Rng) {
    let before = arrays(che);
    let (nv, nt, ne, nh) = (
        che.num_vertices() as u32,
        che.num_triangles() as u32,
        che.num_edges() as u32,
        che.num_half_edges() as u32,
    );
    // Ids mostly in range, sometimes out of it or NONE.
    let id = |n: u32, rng: &mut Rng| match rng.below(20) {
        0 => NONE,
        1 => n + rng.below(3) as u32,
        _ => rng.below(n as usize) as u32,
    };
    let has_positions = !che.positions().is_empty();
    let p = has_positions.then(|| DVec3::new(rng.below(9) as f64, 1.0, 2.0));
    let kind = rng.below(10);
    let r: Result<(), topomesh::Error> = match kind {
        0 => che.add_vertex(p).map(drop),
        1 => {
            let [a, b, c] = ear(che, rng).unwrap_or([id(nv, rng), id(nv, rng), id(nv, rng)]);
            che.add_triangle(a, b, c).map(drop)
        }
        2 => che.remove_triangle(id(nt, rng)),
        3 if rng.chance(0.3) => che.remove_vertex(id(nv, rng)),
        4 => {
            let e = id(ne, rng);
            let ok = che.is_flip_ok(e);
            let r = che.flip_edge(e);
            assert_eq!(
                ok.unwrap_or(false),
                r.is_ok(),
                "is_flip_ok({e}) against flip_edge"
            );
            r
        }
        5 => che.split_edge(id(ne, rng), None).map(drop),
        6 | 7 => {
            let h = id(nh, rng);
            let ok = che.is_collapse_ok(h);
            let r = che.collapse_edge(h).map(drop);
            assert_eq!(ok.unwrap_or(false), r.is_ok(), "is_collapse_ok({h})");
            r
        }
        8 => che.split_triangle(id(nt, rng), None).map(drop),
        _ => che.flip_edge(id(ne, rng)),
    };
    if std::env::var("EDIT_DEBUG").is_ok()
        && let Err(e) = che.validate()
    {
        panic!("op {kind} -> {r:?} broke the mesh: {e:?}");
    }
    match r {
        Ok(()) => {}
        Err(e) => {
            assert!(!e.message.is_empty());
            assert_eq!(
                arrays(che),
                before,
                "refused op {kind} changed the mesh: {e:?}"
            );
        }
    }
}

/// A triangle that closes a boundary corner `a -> b -> c` (two boundary half-edges in a
/// row), so that add_triangle has valid work too.
fn ear(che: &Che, rng: &mut Rng) -> Option<[u32; 3]> {
    let nh = che.num_half_edges();
    for _ in 0..20 {
        let h = rng.below(nh) as u32;
        if che.is_half_edge_removed(h) || che.opposite(h) != NONE {
            continue;
        }
        let (a, b) = (che.origin(h), che.target(h));
        let g = (0..nh as u32).find(|&g| {
            !che.is_half_edge_removed(g) && che.opposite(g) == NONE && che.origin(g) == b
        })?;
        let c = che.half_edge_vertices()[next(g) as usize];
        return Some([b, a, c]);
    }
    None
}

fn built(s: &Surface, level: u8) -> Che {
    Che::from_triangles(
        &s.triangles,
        s.positions.len(),
        &s.positions,
        BuildOptions::level(level),
    )
    .unwrap()
}

fn run(mut che: Che, seed: u64, steps: usize, every: usize) -> Che {
    let mut rng = Rng(seed);
    for step in 0..steps {
        random_op(&mut che, &mut rng);
        if step % every == every - 1 {
            check_against_fresh(&che);
        }
    }
    check_against_fresh(&che);
    che
}

#[test]
fn random_edits_on_a_closed_mesh_at_every_level() {
    for level in 0..=3 {
        run(built(&sphere(8, 6), level), 7 + level as u64, 1500, 250);
        run(built(&torus(6, 5), level), 70 + level as u64, 800, 200);
    }
}

#[test]
fn random_edits_on_a_mesh_with_boundary_at_every_level() {
    for level in 0..=3 {
        run(built(&grid(7, 6), level), 17 + level as u64, 1500, 250);
    }
}

#[test]
fn random_edits_on_a_damaged_mesh_stay_valid() {
    // Three triangles on edge 0-1, a bowtie at vertex 5, a degenerate and a duplicate.
    let tris = [
        [0, 1, 2],
        [1, 0, 3],
        [0, 1, 4],
        [5, 6, 7],
        [5, 8, 9],
        [2, 2, 3],
        [5, 6, 7],
        [1, 2, 10],
        [2, 11, 10],
    ];
    for level in 0..=3 {
        let mut che = Che::from_triangles(&tris, 12, &[], BuildOptions::level(level)).unwrap();
        let mut rng = Rng(99 + level as u64);
        for step in 0..600 {
            random_op(&mut che, &mut rng);
            if step % 25 == 0 {
                che.validate().unwrap();
                let mut done = che.clone();
                done.garbage_collect().unwrap();
                done.validate().unwrap();
            }
        }
    }
}

#[test]
fn collecting_after_removing_everything_leaves_isolated_vertices() {
    for level in 0..=3 {
        let mut che = built(&sphere(5, 4), level);
        for t in 0..che.num_triangles() as u32 {
            che.remove_triangle(t).unwrap();
        }
        assert_eq!(che.num_live_triangles(), 0);
        assert_eq!(che.summary().isolated_vertices, che.num_vertices() as u64);
        let maps = che.garbage_collect().unwrap();
        che.validate().unwrap();
        assert!(maps.triangles.iter().all(|&t| t == NONE));
        assert!(maps.edges.iter().all(|&e| e == NONE));
        assert_eq!(che.num_triangles(), 0);
        for x in 0..che.num_vertices() as u32 {
            che.remove_vertex(x).unwrap();
        }
        let maps = che.garbage_collect().unwrap();
        assert!(maps.vertices.iter().all(|&x| x == NONE));
        assert_eq!(che.num_vertices(), 0);
        che.validate().unwrap();
    }
}

#[test]
fn stable_edge_ids_and_refusals_name_the_problem() {
    let mut che = built(&grid(3, 3), 2);
    let e = che.edge_of(4);
    let ends = che.edge_vertices(e);
    let far = che.num_edges() as u32 - 1;
    let far_ends = che.edge_vertices(far);
    let t = che.triangles_of_edge_for_test(e);
    che.remove_triangle(t).unwrap();
    // Untouched edges keep their ids; a new edge gets a new id.
    assert_eq!(che.edge_vertices(far), far_ends);
    let m = che.split_triangle(0, None).unwrap();
    let new_edge = che.edge_of(3 * (che.num_triangles() as u32 - 1) + 1);
    assert!(new_edge as usize >= che.num_edges() - 3);
    assert!(che.vertex_vertices(m).count() == 3);
    let _ = ends;
    let err = che.remove_triangle(t).unwrap_err();
    assert!(err.message.contains("removed"), "{}", err.message);
    let err = che.flip_edge(NONE).unwrap_err();
    assert!(err.message.contains("out of range"), "{}", err.message);
    let b =
        (0..che.num_edges() as u32).find(|&e| !che.is_edge_removed(e) && che.is_boundary_edge(e));
    let err = che.flip_edge(b.unwrap()).unwrap_err();
    assert!(err.message.contains("boundary"), "{}", err.message);
    let err = che.add_triangle(0, 1, 0).unwrap_err();
    assert!(err.message.contains("degenerate"), "{}", err.message);
    let live = (0..che.num_triangles() as u32).find(|&t| !che.is_triangle_removed(t));
    let [a, b2, c] = che.triangle_vertices(live.unwrap());
    let err = che.add_triangle(a, b2, c).unwrap_err();
    assert!(err.message.contains("duplicates"), "{}", err.message);
    let [p, q, _] = che.triangle_vertices(live.unwrap());
    let w = che.add_vertex(Some(DVec3::ZERO)).unwrap();
    assert!(che.add_vertex(None).is_err());
    let err = che.add_triangle(p, q, w).unwrap_err();
    assert!(err.message.contains("orientation"), "{}", err.message);
}

trait ForTest {
    fn triangles_of_edge_for_test(&self, e: u32) -> u32;
}
impl ForTest for Che {
    fn triangles_of_edge_for_test(&self, e: u32) -> u32 {
        self.edge_triangles(e)[0]
    }
}

#[test]
fn a_never_edited_mesh_keeps_its_memory_and_identity_maps() {
    let mut che = built(&sphere(8, 6), 3);
    let memory = che.memory_bytes();
    let dir = che.edge_rank_directory().map(<[u64]>::to_vec);
    let maps = che.garbage_collect().unwrap();
    assert_eq!(che.memory_bytes(), memory);
    assert_eq!(che.edge_rank_directory().map(<[u64]>::to_vec), dir);
    assert!(
        maps.vertices
            .iter()
            .enumerate()
            .all(|(i, &x)| x == i as u32)
    );
    assert!(maps.edges.iter().enumerate().all(|(i, &x)| x == i as u32));
}

/// Exports, writers and level files lay ids out without holes: while removed elements
/// wait for garbage collection they are refused with an error saying so (never a panic or
/// an answer with holes), and they work again after it.
#[test]
fn exports_and_files_wait_for_garbage_collection() {
    let dir = std::env::temp_dir().join(format!("topomesh-edit-files-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for level in 0..=3 {
        let mut che = built(&torus(6, 5), level);
        che.remove_triangle(4).unwrap();
        let refusals = [
            che.edge_list().err(),
            che.corner_table().err(),
            che.winged_edges().err(),
            che.triangle_strips().err(),
            che.betti_numbers().err(),
            che.save(dir.join("t.che")).err(),
            che.write(&dir.join("t.off")).err(),
        ];
        for e in refusals {
            let e = e.expect("refused before garbage collection");
            assert!(e.to_string().contains("garbage_collect"), "{e}");
        }
        che.garbage_collect().unwrap();
        che.edge_list().unwrap();
        che.corner_table().unwrap();
        assert_eq!(che.betti_numbers().unwrap(), [1, 2, 0]);
        che.save(dir.join("t.che")).unwrap();
        che.write(&dir.join("t.off")).unwrap();
    }
    let _ = std::fs::remove_dir_all(&dir);
}
