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

/// Every relation of a removed element answers `NONE` or nothing (no panic, no stale
/// id), at every level.
fn check_removed(che: &Che) {
    let nothing = |what: &str, id: u32, ids: &[u32]| {
        assert!(
            ids.iter().all(|&x| x == NONE),
            "removed {what} {id} answers {ids:?}"
        );
    };
    for v in (0..che.num_vertices() as u32).filter(|&v| che.is_vertex_removed(v)) {
        nothing(
            "vertex (VV)",
            v,
            &che.vertex_vertices(v).collect::<Vec<_>>(),
        );
        nothing("vertex (VE)", v, &che.vertex_edges(v).collect::<Vec<_>>());
        nothing(
            "vertex (VF)",
            v,
            &che.vertex_triangles(v).collect::<Vec<_>>(),
        );
    }
    for e in (0..che.num_edges() as u32).filter(|&e| che.is_edge_removed(e)) {
        nothing("edge (EH)", e, &[che.edge_half_edge(e)]);
        nothing("edge (EV)", e, &che.edge_vertices(e));
        nothing("edge (EE)", e, &che.edge_edges(e));
        nothing("edge (EF)", e, &che.edge_triangles(e));
        assert!(!che.is_boundary_edge(e), "removed edge {e}");
    }
    for t in (0..che.num_triangles() as u32).filter(|&t| che.is_triangle_removed(t)) {
        nothing("triangle (FV)", t, &che.triangle_vertices(t));
        nothing("triangle (FE)", t, &che.triangle_edges(t));
        nothing("triangle (FF)", t, &che.triangle_triangles(t));
        let half_edges = [0, 1, 2].map(|i| che.edge_of(3 * t + i));
        nothing("triangle (half-edge edges)", t, &half_edges);
    }
    // The live ids are the ids not removed, as many as the live counts say.
    assert_eq!(che.live_vertices().count(), che.num_live_vertices());
    assert_eq!(che.live_triangles().count(), che.num_live_triangles());
    assert_eq!(che.live_edges().count(), che.num_live_edges());
    assert!(che.live_triangles().all(|t| !che.is_triangle_removed(t)));
}

/// Each vertex's relations one at a time are the rows of the bulk ones, in the same
/// order, before the collection (below level 2 both start the rotation at the `VH` the
/// edits keep), and edge ids and their half-edges agree.
fn check_stars_against_bulk(che: &Che) {
    let (vv, ve, vf) = (
        che.all_vertex_vertices().unwrap(),
        che.all_vertex_edges().unwrap(),
        che.all_vertex_triangles().unwrap(),
    );
    for v in 0..che.num_vertices() as u32 {
        let i = v as usize;
        let one: Vec<u32> = che.vertex_vertices(v).collect();
        assert_eq!(one, vv.row(i), "VV of vertex {v}");
        let one: Vec<u32> = che.vertex_edges(v).collect();
        assert_eq!(one, ve.row(i), "VE of vertex {v}");
        let one: Vec<u32> = che.vertex_triangles(v).collect();
        assert_eq!(one, vf.row(i), "VF of vertex {v}");
    }
    // Each live half-edge's edge names its canonical half-edge back.
    for h in (0..che.num_half_edges() as u32).filter(|&h| !che.is_half_edge_removed(h)) {
        let e = che.edge_of(h);
        let canonical = h.min(che.opposite(h));
        assert_eq!(che.edge_half_edge(e), canonical, "half-edge {h}, edge {e}");
    }
}

/// The live triangles through the collection's maps equal the collected mesh's, which
/// equals a fresh build of them in every relation; the summary before the collection is
/// already the fresh build's.
fn check_against_fresh(che: &Che) {
    che.validate().unwrap();
    check_removed(che);
    check_stars_against_bulk(che);
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
    // A build flags the half-edges of a non-manifold edge of its input, then its vertex
    // split may leave one alone on its vertex pair: a rebuild sees a boundary half-edge.
    let pair = |h: u32| {
        let (x, y) = (done.origin(h), done.target(h));
        (x.min(y), x.max(y))
    };
    a.arrays
        .flags
        .0
        .retain(|&h| (0..done.num_half_edges() as u32).any(|g| g != h && pair(g) == pair(h)));
    // Origins follow the input through the edits; the fresh build's are its own.
    (a.arrays.vertex_origins, a.arrays.triangle_origins) = (None, None);
    (b.arrays.vertex_origins, b.arrays.triangle_origins) = (None, None);
    if a != b
        && let Ok(dir) = std::env::var("EDIT_DUMP")
    {
        std::fs::write(format!("{dir}/edited.txt"), format!("{a:#?}")).unwrap();
        std::fs::write(format!("{dir}/fresh.txt"), format!("{b:#?}")).unwrap();
    }
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

/// Built strict: every operation kind, the refusals of `add_triangle` included.
fn built(s: &Surface, level: u8) -> Che {
    built_with(s, level, true)
}

fn built_with(s: &Surface, level: u8, strict: bool) -> Che {
    let options = BuildOptions {
        strict,
        ..BuildOptions::level(level)
    };
    let che = Che::from_triangles(&s.triangles, s.positions.len(), &s.positions, options);
    let che = che.unwrap();
    assert_eq!(che.is_strict(), strict);
    che
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
    for level in 0..=3 {
        let mut che = Che::from_triangles(&DAMAGED, 12, &[], BuildOptions::level(level)).unwrap();
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

/// A live vertex, or a new one.
fn some_vertex(che: &mut Che, rng: &mut Rng) -> u32 {
    for _ in 0..20 {
        let x = rng.below(che.num_vertices().max(1)) as u32;
        if (x as usize) < che.num_vertices() && !che.is_vertex_removed(x) {
            return x;
        }
    }
    let p = (!che.positions().is_empty()).then_some(DVec3::new(rng.below(9) as f64, 1.0, 3.0));
    che.add_vertex(p).unwrap()
}

/// One random `add_triangle` on a non-strict CHE, of every kind its repairs cover: ears,
/// triangles across an existing edge either way (a flip, or a third triangle on the edge),
/// duplicates either way, triangles on new vertices and random triples (a new fan at
/// each corner). A refusal (degenerate) changes nothing; an accepted triangle has the
/// corners asked for, or copies of them, in some orientation.
fn random_add(che: &mut Che, rng: &mut Rng) {
    let nh = che.num_half_edges();
    let live_h = (0..20)
        .map(|_| rng.below(nh.max(1)) as u32)
        .find(|&h| (h as usize) < nh && !che.is_half_edge_removed(h));
    let corners = match (rng.below(6), live_h) {
        (0, _) => ear(che, rng),
        (1 | 2, Some(h)) => {
            let (a, b) = (che.origin(h), che.target(h));
            let c = some_vertex(che, rng);
            Some(if rng.chance(0.5) {
                [a, b, c]
            } else {
                [b, a, c]
            })
        }
        (3, Some(h)) => {
            let [a, b, c] = che.triangle_vertices(h / 3);
            Some(if rng.chance(0.5) {
                [a, b, c]
            } else {
                [a, c, b]
            })
        }
        _ => None,
    };
    let [a, b, c] = corners.unwrap_or_else(|| [0; 3].map(|_| some_vertex(che, rng)));
    let before = arrays(che);
    match che.add_triangle(a, b, c) {
        Ok(t) => {
            let origin = |x: u32| che.vertex_origin(x);
            let mut got = che.triangle_vertices(t).map(origin);
            let mut asked = [a, b, c].map(origin);
            got.sort_unstable();
            asked.sort_unstable();
            assert_eq!(got, asked, "add_triangle({a}, {b}, {c}) gave triangle {t}");
        }
        Err(e) => {
            assert!(e.message.contains("degenerate"), "{e:?}");
            assert_eq!(arrays(che), before, "refused add_triangle changed the mesh");
        }
    }
}

/// Three triangles on edge 0-1, a bowtie at vertex 5, a degenerate and a duplicate.
const DAMAGED: [[u32; 3]; 9] = [
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

/// [`check_against_fresh`] while the surface is orientable. Where an added triangle makes
/// it non-orientable, where the build leaves its seams depends on the order its traversal
/// meets the triangles, which a rebuild of the repaired surface need not repeat: then
/// the CHE must still be valid and its summary say non-orientable.
fn check_non_strict(che: &Che) {
    if che.seam_half_edges().is_empty() {
        check_against_fresh(che);
    } else {
        che.validate().unwrap();
        assert!(!che.summary().orientable);
    }
}

/// Random `add_triangle` sequences on non-strict CHEs, closed, with boundary and damaged,
/// at every level: every few steps every relation, the flags and the summary equal those
/// of a fresh non-strict build of the live triangles.
#[test]
fn non_strict_add_triangle_repairs_as_a_fresh_build() {
    for level in 0..=3 {
        let damaged = Che::from_triangles(&DAMAGED, 12, &[], BuildOptions::level(level));
        let meshes = [
            built_with(&sphere(6, 5), level, false),
            built_with(&torus(5, 4), level, false),
            built_with(&grid(5, 4), level, false),
            damaged.unwrap(),
        ];
        for (k, mut che) in meshes.into_iter().enumerate() {
            let mut rng = Rng(1000 + 10 * level as u64 + k as u64);
            for step in 0..150 {
                random_add(&mut che, &mut rng);
                if step % 25 == 24 {
                    check_non_strict(&che);
                }
            }
            check_non_strict(&che);
            let r = che.report();
            assert!(r.non_manifold_edges > 0 && r.split_vertices > 0 && r.flipped_triangles > 0);
        }
    }
}

/// The same four additions on a strict and a non-strict grid: the strict one refuses each
/// with the reason (and changes nothing), the non-strict one repairs it as its build
/// would, counts it in the report, and equals a fresh build of its triangles.
#[test]
fn strict_meshes_refuse_what_non_strict_ones_repair() {
    for level in 0..=3 {
        let mut strict = built_with(&grid(3, 3), level, true);
        let mut loose = built_with(&grid(3, 3), level, false);
        let n = strict.num_half_edges() as u32;
        let boundary = (0..n).find(|&h| strict.opposite(h) == NONE).unwrap();
        let interior = (0..n).find(|&h| strict.opposite(h) != NONE).unwrap();
        let (a, b) = (strict.origin(boundary), strict.target(boundary));
        let (c, d) = (strict.origin(interior), strict.target(interior));
        let x = strict.triangle_vertices(4)[0];
        let dup = strict.triangle_vertices(1);
        type Count = fn(&topomesh::BuildReport) -> usize;
        let cases: [(&str, Count, [u32; 3], bool); 4] = [
            ("orientation", |r| r.flipped_triangles, [a, b, NONE], true),
            // An interior edge has a triangle on either side: the strict refusal says so.
            (
                "already has a triangle",
                |r| r.non_manifold_edges,
                [d, c, NONE],
                true,
            ),
            ("second fan", |r| r.split_vertices, [x, NONE, NONE], true),
            ("duplicates", |r| r.duplicate_triangles, dup, false),
        ];
        for (why, count, corners, new_vertices) in cases {
            let fill = |che: &mut Che| {
                let mut v = corners;
                for y in v.iter_mut().filter(|y| **y == NONE) {
                    *y = che.add_vertex(Some(DVec3::new(9.0, 9.0, 9.0))).unwrap();
                }
                assert!(new_vertices || v == corners);
                v
            };
            let [p, q, r] = fill(&mut strict);
            let before = arrays(&strict);
            let err = strict.add_triangle(p, q, r).unwrap_err();
            assert!(err.message.contains(why), "{why}: {}", err.message);
            assert_eq!(arrays(&strict), before);
            let [p, q, r] = fill(&mut loose);
            let was = count(loose.report());
            let t = loose.add_triangle(p, q, r).unwrap();
            assert_eq!(count(loose.report()), was + 1, "{why} at level {level}");
            let mut got = loose.triangle_vertices(t).map(|y| loose.vertex_origin(y));
            let mut asked = [p, q, r].map(|y| loose.vertex_origin(y));
            got.sort_unstable();
            asked.sort_unstable();
            assert_eq!(got, asked);
            check_against_fresh(&loose);
        }
        assert!(strict.is_strict() && !loose.is_strict());
    }
}

/// A level file keeps whether the CHE was built strict (header flag bit 1).
#[test]
fn level_files_keep_the_strict_flag() {
    let dir = std::env::temp_dir().join(format!("topomesh-strict-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for strict in [false, true] {
        let che = built_with(&grid(3, 3), 2, strict);
        let path = dir.join("g.che");
        che.save(&path).unwrap();
        let mut back = Che::open(&path, Default::default()).unwrap();
        assert_eq!(back.is_strict(), strict);
        let [a, b, _] = back.triangle_vertices(0);
        let w = back.add_vertex(Some(DVec3::ZERO)).unwrap();
        assert_eq!(back.add_triangle(a, b, w).is_err(), strict);
    }
    let _ = std::fs::remove_dir_all(&dir);
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

/// From the first edit the edge ids are explicit, and the edge directory whose ranks
/// they replace is let go: an edited mesh holds `EH`, an id per half-edge and a bit per
/// vertex (in 64-bit words) for its edges, and `garbage_collect` brings the directory back
/// (the ranks are the ids again).
#[test]
fn edit_ids_replace_the_edge_directory() {
    for level in [2, 3] {
        let mut che = built(&sphere(8, 6), level);
        let built_edges = che.memory_bytes().edges;
        let e = first_allowed(che.num_edges(), |e| che.is_flip_ok(e).unwrap());
        che.flip_edge(e).unwrap();
        let flags = 8 * che.num_vertices().div_ceil(64);
        let explicit = 4 * (che.num_edges() + 3 * che.num_triangles()) + flags;
        assert_eq!(che.memory_bytes().edges, explicit, "level {level}");
        che.garbage_collect().unwrap();
        // The directory again, beside the flags the edit state keeps.
        assert_eq!(
            che.memory_bytes().edges,
            built_edges + flags,
            "level {level}"
        );
        assert!(che.edge_rank_directory().is_some());
        che.validate().unwrap();
    }
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

/// A level file holds the tables of the build's rules (edge ranks, curves), which an edit
/// that removes nothing (a flip) changes too: saving waits for garbage collection, and the
/// file written after it opens to the same mesh.
#[test]
fn a_level_file_waits_for_garbage_collection_after_any_edit() {
    let dir = std::env::temp_dir().join(format!("topomesh-edit-saved-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for level in 0..=3 {
        let mut che = built(&grid(5, 4), level);
        let e = (0..che.num_edges() as u32).find(|&e| che.flip_edge(e).is_ok());
        assert!(e.is_some(), "level {level}: some edge flips");
        let err = che.save(dir.join("s.che")).unwrap_err();
        assert!(err.to_string().contains("garbage_collect"), "{err}");
        che.garbage_collect().unwrap();
        che.save(dir.join("s.che")).unwrap();
        let opened = Che::open(dir.join("s.che"), Default::default()).unwrap();
        assert_eq!(opened.summary(), che.summary(), "level {level}");
        for v in 0..che.num_vertices() as u32 {
            assert_eq!(
                opened.vertex_vertices(v).collect::<Vec<_>>(),
                che.vertex_vertices(v).collect::<Vec<_>>()
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The checks never modify: after every flip and collapse check of a mesh, at every
/// level, its arrays, counts and memory are as before, and it saves as a mesh never
/// edited (no garbage collection asked).
#[test]
fn checks_leave_the_mesh_as_it_was() {
    let dir = std::env::temp_dir().join(format!("topomesh-checks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for level in 0..=3 {
        for s in [grid(5, 4), torus(6, 5)] {
            let mut che = built(&s, level);
            let (before, memory) = (arrays(&che), che.memory_bytes());
            let (mut flips, mut collapses) = (0, 0);
            for e in 0..che.num_edges() as u32 {
                flips += che.is_flip_ok(e).unwrap() as usize;
            }
            for h in 0..che.num_half_edges() as u32 {
                collapses += che.is_collapse_ok(h).unwrap() as usize;
            }
            assert!(
                flips > 0 && collapses > 0,
                "level {level}: some checks pass"
            );
            assert_eq!(arrays(&che), before, "level {level}");
            if level >= 2 {
                assert_eq!(che.memory_bytes(), memory, "level {level}: no edit state");
            }
            che.save(dir.join("c.che")).unwrap();
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The first id below `n` that `allowed` accepts (the mark tests start from one).
fn first_allowed(n: usize, mut allowed: impl FnMut(u32) -> bool) -> u32 {
    (0..n as u32)
        .find(|&x| allowed(x))
        .expect("an id the check allows")
}

/// A flip right after its check skips repeating it; anything in between (here the removal
/// of one of the edge's triangles, which puts it on the boundary) makes it check again.
#[test]
fn a_flip_checks_again_after_any_other_call() {
    for level in 0..=3 {
        let mut che = built(&torus(6, 5), level);
        let e = (0..che.num_edges() as u32)
            .find(|&e| che.is_flip_ok(e).unwrap())
            .unwrap();
        let t = che.edge_triangles(e)[0];
        che.remove_triangle(t).unwrap();
        let err = che.flip_edge(e).unwrap_err();
        assert!(err.to_string().contains("boundary"), "level {level}: {err}");
        assert!(che.is_flip_ok(e).is_ok_and(|ok| !ok), "level {level}");
        che.validate().unwrap();
    }
}

/// A collapse right after its check skips repeating it; anything in between makes it check
/// again: here a triangle at each end of the edge, neither on it, is removed, which puts both
/// ends on the boundary and the edge between them inside.
#[test]
fn a_collapse_checks_again_after_any_other_call() {
    for level in 0..=3 {
        let mut che = built(&torus(6, 5), level);
        let h = first_allowed(che.num_half_edges(), |h| che.is_collapse_ok(h).unwrap());
        let (a, b) = (che.origin(h), che.target(h));
        let off_the_edge = |che: &Che, x: u32| {
            che.vertex_triangles(x)
                .find(|&t| {
                    !che.triangle_vertices(t).contains(&a) || !che.triangle_vertices(t).contains(&b)
                })
                .unwrap()
        };
        let ta = off_the_edge(&che, a);
        assert!(che.is_collapse_ok(h).unwrap(), "level {level}");
        che.remove_triangle(ta).unwrap();
        let tb = off_the_edge(&che, b);
        che.remove_triangle(tb).unwrap();
        let err = che.collapse_edge(h).unwrap_err();
        assert!(
            err.to_string().contains("two boundary vertices"),
            "level {level}: {err}"
        );
        assert!(che.is_collapse_ok(h).is_ok_and(|ok| !ok), "level {level}");
        che.validate().unwrap();
    }
}

/// At level 3 an edit notes the half-edges it unpairs, for the next curve computation: the
/// notes stay within the boundary plus a constant however many edits run without a curve
/// query, so level 3 costs no more memory while editing than level 2.
#[test]
fn level3_edits_keep_their_boundary_notes_short() {
    let s = grid(40, 40);
    let (mut two, mut three) = (built(&s, 2), built(&s, 3));
    for e in 0..3000 {
        assert_eq!(
            two.split_edge(e, None).is_ok(),
            three.split_edge(e, None).is_ok()
        );
    }
    // The level-3 tables as built stay until garbage collection; what the edits add to
    // `curves` is the log of boundary half-edges, which must stay near the boundary's size.
    let tables = built(&s, 3).memory_bytes().curves;
    let (m2, m3) = (two.memory_bytes(), three.memory_bytes());
    assert_eq!(m3.edges, m2.edges);
    let log = m3.curves - tables;
    assert!(log <= 3 * tables + 8 * 1100, "{log} bytes of boundary log");
    three.validate().unwrap();
    assert_eq!(three.summary(), two.summary());
}

/// Curves after a level change of an edited CHE, with curve queries (`validate`) between
/// the edits, and after a garbage collection: each time those of a fresh build.
#[test]
fn curves_follow_edits_across_level_changes() {
    for s in [grid(12, 9), sphere(8, 6)] {
        let mut che = built(&s, 2);
        let mut rng = Rng(5);
        for round in 0..4 {
            for _ in 0..150 {
                random_op(&mut che, &mut rng);
            }
            che.build_level(if round % 2 == 0 { 3 } else { 2 }).unwrap();
            // Curves computed right after the change (by a scan), then an edit that
            // unpairs half-edges: the next computation must see them.
            che.validate().unwrap();
            let t = (0..che.num_triangles() as u32).find(|&t| !che.is_triangle_removed(t));
            che.remove_triangle(t.unwrap()).unwrap();
            for i in 0..150 {
                random_op(&mut che, &mut rng);
                if i % 50 == 0 {
                    che.validate().unwrap();
                }
            }
            check_against_fresh(&che);
            if round == 2 {
                che.garbage_collect().unwrap();
            }
        }
    }
}
