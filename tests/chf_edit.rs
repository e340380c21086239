//! In-place editing of a CHF: seeded random sequences of operations (valid and refused)
//! on closed, bounded and damaged meshes at every level. Every few steps and at the end,
//! every relation, the boundary flags and the summary equal those of a fresh build of the
//! live tetrahedra (through the maps of `garbage_collect`), `validate()` passes, and a
//! refused operation leaves the structure as it was.

mod chf_common;

use chf_common::{Answers, Mesh, Rng, answers, cube, scramble};
use glam::DVec3;
use topomesh::chf::{self, Chf, GarbageMaps, NO_HALF_EDGE};
use topomesh::{ErrorKind, NONE};

/// The boundary of the 4-simplex: a closed 3-sphere of five tetrahedra, no positions.
fn four_simplex() -> Mesh {
    let tets = (0..5u32)
        .map(|skip| {
            let q: Vec<u32> = (0..5).filter(|&x| x != skip).collect();
            [q[0], q[1], q[2], q[3]]
        })
        .collect();
    Mesh {
        tets,
        positions: vec![DVec3::ZERO; 5],
    }
}

/// The boundary of the 4-dimensional cross-polytope: a closed 3-sphere, 16 tetrahedra.
fn cross_polytope() -> Mesh {
    let mut tets = Vec::new();
    for signs in 0..16u32 {
        let q = [0, 1, 2, 3].map(|axis| 2 * axis + ((signs >> axis) & 1));
        tets.push(q);
    }
    Mesh {
        tets,
        positions: vec![DVec3::ZERO; 8],
    }
}

/// The live tetrahedra of `chf` built afresh, with the maps `garbage_collect` gives.
fn fresh(chf: &Chf, full: bool) -> (Chf, GarbageMaps) {
    let mut gc = chf.clone();
    let maps = gc.garbage_collect().expect("garbage_collect");
    let mut tets = Vec::new();
    for t in 0..chf.num_tetrahedra() as u32 {
        if !chf.is_tetrahedron_removed(t) {
            assert_eq!(maps.tetrahedra[t as usize], tets.len() as u32);
            tets.push(
                chf.tetrahedron_vertices(t)
                    .map(|x| maps.vertices[x as usize]),
            );
        }
    }
    let n = maps.vertices.iter().filter(|&&x| x != NONE).count();
    let positions: Vec<DVec3> = if chf.positions().is_empty() {
        Vec::new()
    } else {
        (0..chf.num_vertices())
            .filter(|&x| maps.vertices[x] != NONE)
            .map(|x| chf.positions()[x])
            .collect()
    };
    // Ids and answers are the same at every level; level 2 answers fast.
    let options = chf::BuildOptions::level(chf.level().max(2));
    let built = Chf::from_tetrahedra(&tets, n, &positions, options).expect("fresh build");
    assert_eq!(gc.level(), chf.level());
    if full || chf.level() >= 2 {
        assert_eq!(
            answers(&gc),
            answers(&built),
            "garbage_collect is a fresh build"
        );
    }
    if chf.is_edited() {
        // An unedited mesh keeps what its own build reported (flips, splits).
        assert_eq!(gc.summary(), built.summary());
    }
    gc.validate().expect("the collected mesh is valid");
    (built, maps)
}

fn map_all(map: &[u32], xs: impl IntoIterator<Item = u32>) -> Vec<u32> {
    xs.into_iter()
        .map(|x| if x == NONE { NONE } else { map[x as usize] })
        .collect()
}

fn sorted(mut xs: Vec<u32>) -> Vec<u32> {
    xs.sort_unstable();
    xs
}

/// The answers of the edited mesh on its live elements, mapped to the fresh ids.
fn mapped_answers(chf: &Chf, f: &Chf, m: &GarbageMaps) -> Answers {
    let mut a = answers(f);
    let (mv, me, mf, mt) = (&m.vertices, &m.edges, &m.faces, &m.tetrahedra);
    let arr = |map: &[u32], x: &[u32]| map_all(map, x.iter().copied());
    for v in 0..chf.num_vertices() as u32 {
        let n = mv[v as usize];
        if n == NONE {
            assert!(chf.is_vertex_removed(v));
            continue;
        }
        a.vv[n as usize] = sorted(map_all(mv, chf.vertex_vertices(v)));
        a.ve[n as usize] = sorted(map_all(me, chf.vertex_edges(v)));
        a.vf[n as usize] = sorted(map_all(mf, chf.vertex_faces(v)));
        a.vt[n as usize] = sorted(map_all(mt, chf.vertex_tetrahedra(v)));
        a.boundary.0[n as usize] = chf.is_boundary_vertex(v);
    }
    for e in 0..chf.num_edges() as u32 {
        let n = me[e as usize];
        if n == NONE {
            assert!(chf.is_edge_removed(e));
            continue;
        }
        let ev = arr(mv, &chf.edge_vertices(e));
        a.ev[n as usize] = [ev[0], ev[1]];
        a.ee[n as usize] = map_all(me, chf.edge_edges(e));
        a.ef[n as usize] = map_all(mf, chf.edge_faces(e));
        a.et[n as usize] = map_all(mt, chf.edge_tetrahedra(e));
        a.boundary.1[n as usize] = chf.is_boundary_edge(e);
    }
    for face in 0..chf.num_faces() as u32 {
        let n = mf[face as usize];
        if n == NONE {
            assert!(chf.is_face_removed(face));
            continue;
        }
        let fv = arr(mv, &chf.face_vertices(face));
        a.fv[n as usize] = [fv[0], fv[1], fv[2]];
        let fe = arr(me, &chf.face_edges(face));
        a.fe[n as usize] = [fe[0], fe[1], fe[2]];
        a.ff[n as usize] = map_all(mf, chf.face_faces(face).to_vec());
        a.ft[n as usize] = map_all(mt, chf.face_tetrahedra(face).to_vec());
        a.boundary.2[n as usize] = chf.is_boundary_face(face);
    }
    for t in 0..chf.num_tetrahedra() as u32 {
        let n = mt[t as usize];
        if n == NONE {
            assert!(chf.is_tetrahedron_removed(t));
            continue;
        }
        let tv = arr(mv, &chf.tetrahedron_vertices(t));
        a.tv[n as usize] = [tv[0], tv[1], tv[2], tv[3]];
        let te = arr(me, &chf.tetrahedron_edges(t));
        a.te[n as usize] = [te[0], te[1], te[2], te[3], te[4], te[5]];
        let tf = arr(mf, &chf.tetrahedron_faces(t));
        a.tf[n as usize] = [tf[0], tf[1], tf[2], tf[3]];
        let tt = arr(mt, &chf.tetrahedron_tetrahedra(t));
        a.tt[n as usize] = [tt[0], tt[1], tt[2], tt[3]];
    }
    a
}

/// FF in a set order on both sides: the edited face ids map to fresh ids out of order.
fn normalise(mut a: Answers) -> Answers {
    for row in a.ff.iter_mut() {
        row.sort_unstable();
    }
    a
}

/// Every relation of a removed element answers `NONE` or nothing (no panic, no stale
/// id), at every level.
fn check_removed(chf: &Chf, at: &str) {
    let nothing = |what: &str, id: u32, ids: &[u32]| {
        assert!(
            ids.iter().all(|&x| x == NONE),
            "{at}: removed {what} {id} answers {ids:?}"
        );
    };
    for v in (0..chf.num_vertices() as u32).filter(|&v| chf.is_vertex_removed(v)) {
        nothing(
            "vertex (VV)",
            v,
            &chf.vertex_vertices(v).collect::<Vec<_>>(),
        );
        nothing("vertex (VE)", v, &chf.vertex_edges(v).collect::<Vec<_>>());
        nothing("vertex (VF)", v, &chf.vertex_faces(v).collect::<Vec<_>>());
        nothing(
            "vertex (VT)",
            v,
            &chf.vertex_tetrahedra(v).collect::<Vec<_>>(),
        );
        assert!(!chf.is_boundary_vertex(v), "{at}: removed vertex {v}");
    }
    for e in (0..chf.num_edges() as u32).filter(|&e| chf.is_edge_removed(e)) {
        assert_eq!(
            chf.edge_half_edge(e),
            NO_HALF_EDGE,
            "{at}: removed edge {e}"
        );
        nothing("edge (EV)", e, &chf.edge_vertices(e));
        nothing("edge (EE)", e, &chf.edge_edges(e).collect::<Vec<_>>());
        nothing("edge (EF)", e, &chf.edge_faces(e).collect::<Vec<_>>());
        nothing("edge (ET)", e, &chf.edge_tetrahedra(e).collect::<Vec<_>>());
        assert!(!chf.is_boundary_edge(e), "{at}: removed edge {e}");
    }
    for f in (0..chf.num_faces() as u32).filter(|&f| chf.is_face_removed(f)) {
        nothing("face (FH)", f, &[chf.face_half_face(f)]);
        nothing("face (FV)", f, &chf.face_vertices(f));
        nothing("face (FE)", f, &chf.face_edges(f));
        nothing("face (FF)", f, &chf.face_faces(f));
        nothing("face (FT)", f, &chf.face_tetrahedra(f));
        assert!(!chf.is_boundary_face(f), "{at}: removed face {f}");
    }
    for t in (0..chf.num_tetrahedra() as u32).filter(|&t| chf.is_tetrahedron_removed(t)) {
        nothing("tetrahedron (TE)", t, &chf.tetrahedron_edges(t));
        nothing("tetrahedron (TF)", t, &chf.tetrahedron_faces(t));
        nothing("tetrahedron (TT)", t, &chf.tetrahedron_tetrahedra(t));
    }
    // The live ids are the ids not removed, as many as the live counts say.
    assert_eq!(
        chf.live_tetrahedra().count(),
        chf.num_live_tetrahedra(),
        "{at}"
    );
    assert_eq!(chf.live_vertices().count(), chf.num_live_vertices(), "{at}");
    assert_eq!(chf.live_faces().count(), chf.num_live_faces(), "{at}");
    assert_eq!(chf.live_edges().count(), chf.num_live_edges(), "{at}");
    assert!(chf.live_faces().all(|f| !chf.is_face_removed(f)), "{at}");
}

/// Every relation, flag and the summary of `chf` equal a fresh build's.
fn check(chf: &Chf, at: &str, full: bool) {
    if std::env::var_os("TOPOMESH_EDIT_TRACE").is_some() {
        eprintln!("{at}: {} live tetrahedra", chf.num_live_tetrahedra());
    }
    let trace = |what: &str| {
        if std::env::var_os("TOPOMESH_EDIT_TRACE").is_some() {
            eprintln!("  {what}");
        }
    };
    chf.validate().unwrap_or_else(|e| panic!("{at}: {e}"));
    trace("validated");
    check_removed(chf, at);
    let (f, maps) = fresh(chf, full);
    trace("fresh");
    let mine = normalise(mapped_answers(chf, &f, &maps));
    trace("mapped");
    let theirs = normalise(answers(&f));
    if mine != theirs {
        for (name, x, y) in [
            ("vv", format!("{:?}", mine.vv), format!("{:?}", theirs.vv)),
            ("ve", format!("{:?}", mine.ve), format!("{:?}", theirs.ve)),
            ("vf", format!("{:?}", mine.vf), format!("{:?}", theirs.vf)),
            ("ev", format!("{:?}", mine.ev), format!("{:?}", theirs.ev)),
            ("ee", format!("{:?}", mine.ee), format!("{:?}", theirs.ee)),
            ("ef", format!("{:?}", mine.ef), format!("{:?}", theirs.ef)),
            ("et", format!("{:?}", mine.et), format!("{:?}", theirs.et)),
            ("fv", format!("{:?}", mine.fv), format!("{:?}", theirs.fv)),
            ("fe", format!("{:?}", mine.fe), format!("{:?}", theirs.fe)),
            ("ft", format!("{:?}", mine.ft), format!("{:?}", theirs.ft)),
            ("te", format!("{:?}", mine.te), format!("{:?}", theirs.te)),
            ("tt", format!("{:?}", mine.tt), format!("{:?}", theirs.tt)),
            (
                "bd",
                format!("{:?}", mine.boundary),
                format!("{:?}", theirs.boundary),
            ),
        ] {
            assert_eq!(x, y, "{at}: {name}");
        }
        panic!("{at}: answers differ");
    }
    if chf.is_edited() {
        assert_eq!(chf.summary(), f.summary(), "{at}: summary");
    }
    check_boundary(chf, &f, &maps, at);
    assert_eq!(chf.num_live_tetrahedra(), f.num_tetrahedra(), "{at}");
    assert_eq!(chf.num_live_faces(), f.num_faces(), "{at}");
    assert_eq!(chf.num_live_edges(), f.num_edges(), "{at}");
    assert_eq!(chf.num_live_vertices(), f.num_vertices(), "{at}");
}

/// The level-3 boundary surface of `chf` equals a fresh build's. Collection keeps the
/// order of the live tetrahedra and vertices, so boundary triangle `k` and boundary vertex
/// `b` keep their ranks: every list is compared element by element through the maps.
fn check_boundary(chf: &Chf, f: &Chf, m: &GarbageMaps, at: &str) {
    if chf.level() < 3 {
        return;
    }
    let (mt, mv) = (&m.tetrahedra, &m.vertices);
    let hf_map = |h: u32| 4 * mt[(h / 4) as usize] + h % 4;
    let mine: Vec<u32> = chf
        .boundary_half_faces()
        .iter()
        .map(|&h| hf_map(h))
        .collect();
    assert_eq!(
        mine,
        &f.boundary_half_faces()[..],
        "{at}: boundary half-faces"
    );
    let mine = map_all(mv, chf.boundary_vertices().iter().copied());
    assert_eq!(mine, &f.boundary_vertices()[..], "{at}: boundary vertices");
    assert_eq!(
        chf.boundary_vertex_components(),
        f.boundary_vertex_components(),
        "{at}: boundary components"
    );
    let counts = |c: &Chf| {
        [
            c.num_boundary_triangles(),
            c.num_boundary_faces(),
            c.num_boundary_vertices(),
            c.num_boundary_components(),
        ]
    };
    assert_eq!(counts(chf), counts(f), "{at}: boundary counts");
    let (a, b) = (
        chf.boundary().expect("level 3"),
        f.boundary().expect("level 3"),
    );
    assert_eq!(a.summary(), b.summary(), "{at}: boundary surface summary");
    assert_eq!(a.num_vertices(), b.num_vertices(), "{at}: surface vertices");
    for k in 0..a.num_triangles() as u32 {
        let volume = |c: &Chf, s: &topomesh::che::Che| {
            s.triangle_vertices(k)
                .map(|x| c.boundary_vertex_volume_vertex(x))
        };
        let mapped = volume(chf, a).map(|x| mv[x as usize]);
        assert_eq!(mapped, volume(f, b), "{at}: boundary triangle {k}");
        assert_eq!(a.triangle_vertices(k), b.triangle_vertices(k), "{at}: {k}");
    }
    for hf in 0..chf.num_half_faces() as u32 {
        if !chf.is_tetrahedron_removed(hf / 4) {
            let (x, y) = (chf.boundary_triangle(hf), f.boundary_triangle(hf_map(hf)));
            assert_eq!(x, y, "{at}: boundary triangle of half-face {hf}");
        }
    }
    for v in 0..chf.num_vertices() as u32 {
        if mv[v as usize] != NONE {
            let y = f.boundary_vertex(mv[v as usize]);
            assert_eq!(chf.boundary_vertex(v), y, "{at}: boundary vertex of {v}");
        }
    }
    assert_eq!(
        chf.boundary_surface().expect("surface").summary(),
        b.summary(),
        "{at}: boundary_surface"
    );
}

/// A random id below `n`, live by `live` when it can find one, else anything (maybe
/// removed, out of range or `NONE`: the refusals are tested too).
fn pick(rng: &mut Rng, n: usize, live: impl Fn(u32) -> bool) -> u32 {
    match rng.below(20) {
        0 => return NONE,
        1 => return n as u32 + rng.below(3) as u32,
        _ => {}
    }
    for _ in 0..20 {
        let x = rng.below(n.max(1)) as u32;
        if live(x) {
            return x;
        }
    }
    rng.below(n.max(1)) as u32
}

/// One random operation; whether it was accepted.
/// The yes-or-no question agrees with the check: true when it passes, false for a refusal,
/// the check's own error otherwise.
fn agrees(question: topomesh::error::Result<bool>, check: topomesh::error::Result<()>) {
    match check {
        Ok(()) => assert_eq!(question, Ok(true)),
        Err(e) if matches!(e.kind, ErrorKind::InvalidInput | ErrorKind::NonManifold) => {
            assert_eq!(question, Ok(false), "{e}")
        }
        Err(e) => assert_eq!(question, Err(e)),
    }
}

fn step(chf: &mut Chf, rng: &mut Rng, removed: &mut Vec<[u32; 4]>) -> bool {
    let nt = chf.num_tetrahedra();
    let t = pick(rng, nt, |t| !chf.is_tetrahedron_removed(t));
    let positions = !chf.positions().is_empty();
    let r = match rng.below(12) {
        0 | 1 => chf.split_tetrahedron(t, None).map(|_| ()),
        2 => {
            let f = pick(rng, chf.num_faces(), |f| !chf.is_face_removed(f));
            chf.split_face(f, None).map(|_| ())
        }
        3 => {
            let e = pick(rng, chf.num_edges(), |e| !chf.is_edge_removed(e));
            chf.split_edge(e, None).map(|_| ())
        }
        4 | 5 => {
            let f = pick(rng, chf.num_faces(), |f| !chf.is_face_removed(f));
            agrees(chf.is_flip_23_ok(f), chf.check_flip_23(f));
            chf.flip_23(f).map(|_| ())
        }
        6 => {
            let e = pick(rng, chf.num_edges(), |e| !chf.is_edge_removed(e));
            agrees(chf.is_flip_32_ok(e), chf.check_flip_32(e));
            chf.flip_32(e).map(|_| ())
        }
        7 => {
            let he = 12 * t as u64 + rng.below(12) as u64;
            agrees(chf.is_collapse_ok(he), chf.check_collapse_edge(he));
            chf.collapse_edge(he).map(|_| ())
        }
        8 => {
            let q = if t < nt as u32 && !chf.is_tetrahedron_removed(t) {
                Some(chf.tetrahedron_vertices(t))
            } else {
                None
            };
            let r = chf.remove_tetrahedron(t);
            if let (Ok(()), Some(q)) = (&r, q) {
                removed.push(q);
            }
            r
        }
        9 => match removed.pop() {
            Some(q) => chf.add_tetrahedron(q).map(|_| ()),
            None => {
                let q = [0, 1, 2, 3].map(|_| rng.below(chf.num_vertices()) as u32);
                chf.add_tetrahedron(q).map(|_| ())
            }
        },
        10 => {
            let v = pick(rng, chf.num_vertices(), |v| !chf.is_vertex_removed(v));
            chf.remove_vertex(v)
        }
        _ => {
            let p = positions.then(|| DVec3::new(rng.below(100) as f64, 0.5, 7.0));
            chf.add_vertex(p).map(|_| ())
        }
    };
    r.is_ok()
}

/// `steps` random operations on `mesh` at `level`, checked every `every` steps.
fn run(
    name: &str, mesh: &Mesh, with_positions: bool, level: u8, seed: u64, steps: usize, every: usize,
) {
    let mut chf = mesh.build(level, with_positions);
    let mut rng = Rng(seed);
    let mut removed = Vec::new();
    let (mut ok, mut refused) = (0, 0);
    check(&chf, name, false);
    for i in 0..steps {
        let before = (i % 7 == 0).then(|| format!("{chf:?}"));
        if std::env::var_os("TOPOMESH_EDIT_TRACE").is_some() {
            eprintln!("step {i}");
        }
        if step(&mut chf, &mut rng, &mut removed) {
            ok += 1;
        } else {
            refused += 1;
            if let Some(before) = before {
                assert_eq!(
                    before,
                    format!("{chf:?}"),
                    "{name}: a refusal changed the mesh"
                );
            }
        }
        if (i + 1) % every == 0 {
            check(&chf, &format!("{name} level {level} step {i}"), false);
        }
    }
    check(&chf, &format!("{name} level {level} end"), true);
    assert!(
        ok > steps / 10 && refused > 0,
        "{name}: {ok} accepted, {refused} refused"
    );
}

#[test]
fn closed_meshes_at_every_level() {
    for level in 0..=3 {
        run(
            "4-simplex",
            &four_simplex(),
            false,
            level,
            11 + level as u64,
            300,
            50,
        );
        run(
            "cross-polytope",
            &cross_polytope(),
            false,
            level,
            17 + level as u64,
            200,
            50,
        );
    }
}

#[test]
fn bounded_meshes_with_positions_at_every_level() {
    for level in 0..=3 {
        run(
            "cube",
            &cube(2, 2, 2, false),
            true,
            level,
            23 + level as u64,
            300,
            60,
        );
        run(
            "cube5",
            &cube(2, 2, 1, true),
            true,
            level,
            29 + level as u64,
            200,
            50,
        );
    }
}

#[test]
fn bounded_meshes_without_positions() {
    for level in [0, 2, 3] {
        run(
            "cube-nopos",
            &cube(2, 2, 2, false),
            false,
            level,
            31 + level as u64,
            300,
            60,
        );
    }
}

#[test]
fn damaged_meshes() {
    for (level, seed) in [(0u8, 1u64), (1, 2), (2, 3), (3, 4)] {
        let mesh = scramble(&cube(3, 3, 2, false), seed, 70);
        run("damaged", &mesh, true, level, 37 + seed, 200, 50);
        run("damaged-nopos", &mesh, false, level, 41 + seed, 200, 50);
    }
}

#[test]
fn each_operation_on_a_cube() {
    let mut chf = cube(1, 1, 1, false).build(2, true);
    let q = chf.tetrahedron_vertices(0);
    let n = chf.num_tetrahedra() as u32;
    let x = chf.split_tetrahedron(0, None).unwrap();
    assert_eq!(x as usize, chf.num_vertices() - 1);
    // Tetrahedron 0 keeps its id, its vertex 0 replaced; the other pieces are appended.
    assert!(!chf.is_tetrahedron_removed(0));
    assert_eq!(chf.num_tetrahedra() as u32, n + 3);
    for (k, t) in [0, n, n + 1, n + 2].into_iter().enumerate() {
        let mut piece = q;
        piece[k] = x;
        assert_eq!(chf.tetrahedron_vertices(t), piece, "piece {k}");
    }
    check(&chf, "1-4", true);
    let interior = (0..chf.num_faces() as u32)
        .find(|&f| {
            !chf.is_face_removed(f) && !chf.is_boundary_face(f) && chf.check_flip_23(f).is_ok()
        })
        .expect("a flippable face");
    let gone = chf.face_tetrahedra(interior)[0];
    let new = chf.flip_23(interior).unwrap();
    check(&chf, "2-3", true);
    let e = chf
        .tetrahedron_edges(new[0])
        .into_iter()
        .find(|&e| chf.check_flip_32(e).is_ok())
        .expect("the new edge");
    chf.flip_32(e).unwrap();
    check(&chf, "3-2", true);
    let err = chf.remove_tetrahedron(gone).unwrap_err();
    assert!(err.message.contains("removed"), "{err}");
    let err = chf.split_tetrahedron(NONE, None).unwrap_err();
    assert_eq!(err.kind, topomesh::ErrorKind::OutOfRange);
    let maps = chf.garbage_collect().unwrap();
    assert_eq!(maps.tetrahedra[gone as usize], NONE);
    chf.validate().unwrap();
    assert!(!chf.is_edited());
}

#[test]
fn an_unedited_mesh_has_no_edit_state_and_answers_as_built() {
    let mesh = cube(2, 1, 1, false);
    let chf = mesh.build(2, true);
    assert!(!chf.is_edited());
    let mut probe = chf.clone();
    assert!(probe.check_split_tetrahedron(0, None).is_ok());
    assert!(!probe.is_edited(), "a check changes nothing");
    assert!(probe.flip_32(NONE).is_err());
    assert_eq!(answers(&probe), answers(&chf));
    let f = (0..chf.num_faces() as u32)
        .find(|&f| chf.is_boundary_face(f))
        .unwrap();
    let err = probe.flip_23(f).unwrap_err();
    assert!(err.message.contains("boundary"), "{err}");
    assert!(!probe.is_edited());
}

/// Exports and level files lay ids out without holes: refused, saying why, until
/// garbage collection; fine after it.
#[test]
fn exports_and_files_wait_for_garbage_collection() {
    let dir = std::env::temp_dir().join(format!("topomesh-chf-files-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for level in 0..=3 {
        let mut chf = cube(2, 2, 2, true).build(level, true);
        let removable =
            (0..chf.num_tetrahedra() as u32).find(|&t| chf.remove_tetrahedron(t).is_ok());
        assert!(
            removable.is_some(),
            "level {level}: some tetrahedron can go"
        );
        let refusals = [
            chf.half_face_arrays().err(),
            chf.tetrahedron_dual_graph().err(),
            chf.betti_numbers().err(),
            chf.save(dir.join("c.chf")).err(),
        ];
        for e in refusals {
            let e = e.expect("refused before garbage collection");
            assert!(e.to_string().contains("garbage_collect"), "{e}");
        }
        chf.garbage_collect().unwrap();
        chf.half_face_arrays().unwrap();
        assert_eq!(chf.betti_numbers().unwrap()[0], 1);
        chf.save(dir.join("c.chf")).unwrap();
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A removed vertex is refused by every operation naming a vertex, at every level, in
/// every position of a new tetrahedron: an out-of-range status naming it, the mesh as it
/// was.
#[test]
fn a_removed_vertex_is_refused_by_every_operation_taking_one() {
    for level in 0..=3 {
        let mut chf = cube(2, 1, 1, false).build(level, true);
        let s = (0..chf.num_vertices() as u32)
            .find(|&v| chf.remove_vertex(v).is_ok())
            .expect("a removable vertex");
        assert!(chf.is_vertex_removed(s));
        let t = (0..chf.num_tetrahedra() as u32)
            .find(|&t| !chf.is_tetrahedron_removed(t))
            .expect("a live tetrahedron");
        let live = chf.tetrahedron_vertices(t);
        let before = format!("{chf:?}");
        let refused = |r: Result<(), topomesh::Error>, what: &str| {
            let err = r.expect_err(what);
            assert_eq!(err.kind, topomesh::ErrorKind::OutOfRange, "{what}: {err}");
            assert!(
                err.message.contains(&format!("vertex {s} is removed")),
                "{what}: {err}"
            );
        };
        for i in 0..4 {
            let mut q = live;
            q[i] = s;
            refused(chf.check_add_tetrahedron(q), "check_add_tetrahedron");
            refused(chf.add_tetrahedron(q).map(|_| ()), "add_tetrahedron");
        }
        refused(chf.check_remove_vertex(s), "check_remove_vertex");
        refused(chf.remove_vertex(s), "remove_vertex");
        refused(chf.check_live_vertex(s), "check_live_vertex");
        assert_eq!(
            before,
            format!("{chf:?}"),
            "level {level}: a refusal changed the mesh"
        );
        chf.validate().unwrap();
    }
}

/// Without positions, a new tetrahedron is turned over when only that makes its faces run
/// opposite to their neighbours', kept as given when it fits, and a refusal for another
/// reason is the refusal of the order given.
#[test]
fn add_tetrahedron_without_positions_turns_over_to_fit() {
    for level in 0..=3 {
        let mut chf = cube(2, 1, 1, false).build(level, false);
        let t = (0..chf.num_tetrahedra() as u32)
            .find(|&t| chf.check_remove_tetrahedron(t).is_ok())
            .expect("a removable tetrahedron");
        let [a, b, c, d] = chf.tetrahedron_vertices(t);
        chf.remove_tetrahedron(t).unwrap();
        let n = chf.add_tetrahedron([a, b, d, c]).unwrap();
        assert_eq!(chf.tetrahedron_vertices(n), [a, b, c, d], "level {level}");
        check(&chf, &format!("turned over at level {level}"), false);
        let err = chf.add_tetrahedron([a, b, d, c]).unwrap_err();
        assert!(err.message.contains("already exists"), "{err}");
        chf.remove_tetrahedron(n).unwrap();
        let n = chf.add_tetrahedron([b, a, d, c]).unwrap();
        assert_eq!(
            chf.tetrahedron_vertices(n),
            [b, a, d, c],
            "level {level}: as given"
        );
        check(&chf, &format!("as given at level {level}"), false);
    }
}

/// A level file holds the tables of the build's rules, which an edit that removes nothing
/// (a 1-4 split) leaves behind too: saving waits for garbage collection, and the file
/// written after it opens to the same mesh.
#[test]
fn a_level_file_waits_for_garbage_collection_after_any_edit() {
    let dir = std::env::temp_dir().join(format!("topomesh-chf-saved-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let m = cube(2, 2, 2, true);
    for level in 0..=3 {
        let mut chf = m.build(level, true);
        let q = chf.tetrahedron_vertices(0);
        let centroid = q.iter().map(|&x| m.positions[x as usize]).sum::<DVec3>() / 4.0;
        chf.split_tetrahedron(0, Some(centroid)).unwrap();
        let e = chf.save(dir.join("s.chf")).unwrap_err();
        assert!(e.to_string().contains("garbage_collect"), "{e}");
        chf.garbage_collect().unwrap();
        chf.save(dir.join("s.chf")).unwrap();
        let opened = Chf::open(dir.join("s.chf"), Default::default()).unwrap();
        assert_eq!(opened.summary(), chf.summary(), "level {level}");
        assert_eq!(opened.num_tetrahedra(), m.tets.len() + 3);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Two copies of a tetrahedron and a third one on a face of both: the build keeps the
/// three half-faces of that face unpaired (non-manifold) after splitting the third's
/// vertices off, where a build of the same arrays pairs the copies' two. An edit must
/// not call the mesh invalid for it (a long fuzz run of `chf_edit` found this).
#[test]
fn an_edited_mesh_with_a_kept_non_manifold_face_stays_valid() {
    let tets = [[5, 1, 3, 2], [5, 4, 3, 1], [1, 3, 2, 5]];
    let mut chf = Chf::from_tetrahedra(&tets, 7, &[], chf::BuildOptions::level(2)).unwrap();
    assert_eq!(chf.report().non_manifold_faces, 1);
    let x = chf.add_vertex(None).unwrap();
    chf.validate().unwrap();
    // Tetrahedron 1 holds the non-manifold face (its vertices 7, 8, 9): refused.
    assert_eq!(chf.tetrahedron_vertices(1), [7, 4, 8, 9]);
    assert!(chf.split_tetrahedron(1, None).is_err());
    chf.add_tetrahedron([4, 7, 8, x]).unwrap();
    chf.validate().unwrap();
    chf.garbage_collect().unwrap();
    chf.validate().unwrap();
}

/// The first edit replaces the rank directories of faces and edges with explicit ids:
/// they are freed, the answers still come (from the ids), and the memory counts the ids
/// and the removed marks in their place.
#[test]
fn the_first_edit_frees_the_rank_directories() {
    let g = topomesh::generate::cube_grid(3);
    let p = &g.positions;
    let mut chf =
        Chf::from_tetrahedra(&g.tetrahedra, p.len(), p, chf::BuildOptions::level(2)).unwrap();
    let before = chf.memory_bytes();
    assert!(before.faces > 0 && before.edges > 0);
    let faces = chf.tetrahedron_faces(5);
    chf.split_tetrahedron(0, None).unwrap();
    let after = chf.memory_bytes();
    let (t, v) = (chf.num_tetrahedra(), chf.num_vertices());
    let face_ids = 4 * (4 * t + chf.num_faces());
    // The removed marks: a bit per tetrahedron and per vertex, in 64-bit words.
    let marks = 8 * (t.div_ceil(64) + v.div_ceil(64));
    let edge_ids = 4 * 6 * t + 8 * chf.num_edges() + marks;
    assert_eq!((after.faces, after.edges), (face_ids, edge_ids));
    assert_eq!(chf.tetrahedron_faces(5), faces);
    chf.validate().unwrap();
}

/// Garbage collection, checking that each map takes a live face or edge to one on the same
/// vertices (mapped) and a removed one to `NONE`, and that the result validates.
fn collect_checking_maps(chf: &mut Chf) -> GarbageMaps {
    let sets = |n: usize, removed: &dyn Fn(u32) -> bool, ends: &dyn Fn(u32) -> Vec<u32>| {
        (0..n as u32)
            .map(|x| (!removed(x)).then(|| sorted(ends(x))))
            .collect::<Vec<_>>()
    };
    let faces = sets(chf.num_faces(), &|f| chf.is_face_removed(f), &|f| {
        chf.face_vertices(f).to_vec()
    });
    let edges = sets(chf.num_edges(), &|e| chf.is_edge_removed(e), &|e| {
        chf.edge_vertices(e).to_vec()
    });
    let m = chf.garbage_collect().unwrap();
    chf.validate().unwrap();
    let check =
        |what: &str, old: Vec<Option<Vec<u32>>>, map: &[u32], ends: &dyn Fn(u32) -> Vec<u32>| {
            for (x, old) in old.into_iter().enumerate() {
                assert_eq!(old.is_some(), map[x] != NONE, "{what} {x}");
                if let Some(old) = old {
                    assert_eq!(
                        sorted(ends(map[x])),
                        sorted(map_all(&m.vertices, old)),
                        "{what} {x}"
                    );
                }
            }
        };
    check("face", faces, &m.faces, &|f| chf.face_vertices(f).to_vec());
    check("edge", edges, &m.edges, &|e| chf.edge_vertices(e).to_vec());
    m
}

/// Soups of random tetrahedra, non-orientable ones among them (their seams unpaired), with
/// some tetrahedra removed: the maps of the garbage collection name the same faces and
/// edges.
#[test]
fn garbage_collection_maps_of_damaged_soups() {
    let (mut seams, mut removed) = (0, 0);
    for seed in 0..60 {
        let mut rng = Rng(seed);
        let tets: Vec<[u32; 4]> = (0..40)
            .map(|_| [0; 4].map(|_| rng.below(9) as u32))
            .collect();
        let mut chf = Chf::from_tetrahedra(&tets, 9, &[], chf::BuildOptions::level(2)).unwrap();
        seams += chf.report().seam_faces;
        for _ in 0..10 {
            let t = rng.below(chf.num_tetrahedra()) as u32;
            removed += usize::from(chf.remove_tetrahedron(t).is_ok());
        }
        collect_checking_maps(&mut chf);
    }
    assert!(seams > 0 && removed > 0, "{seams} seams, {removed} removed");
}

/// A fold: tetrahedron 0 has a negative determinant, 1 none (flat), 2 a positive one, and
/// the build keeps the input's side on the tie. Once 2 is removed, a build from scratch
/// would turn the rest over (its determinants say so); validation and garbage collection
/// keep the edited side, and the face and edge maps still name the same vertex sets.
#[test]
fn garbage_collection_keeps_a_folded_components_side() {
    let p = DVec3::new;
    let positions = [
        p(0.5, 0.0, 1.0),
        p(0.5, 0.0, 0.0),
        p(1.5, 1.5, 0.5),
        p(1.0, 1.0, 1.0),
        p(1.5, 0.5, 1.5),
        p(0.0, 1.0, 1.0),
        p(f64::NAN, 0.0, 0.0),
    ];
    let tets = [[5, 1, 3, 2], [5, 4, 3, 2], [5, 1, 2, 0]];
    for level in 0..=3 {
        let options = chf::BuildOptions::level(level);
        let mut chf = Chf::from_tetrahedra(&tets, 7, &positions, options).unwrap();
        assert_eq!(chf.report().inverted_tetrahedra, 1, "level {level}");
        chf.remove_tetrahedron(2).unwrap();
        chf.validate().unwrap();
        let kept = [0, 1].map(|t| chf.tetrahedron_vertices(t));
        let m = collect_checking_maps(&mut chf);
        let new = |x: u32| m.vertices[x as usize];
        assert_eq!(
            [0, 1].map(|t| chf.tetrahedron_vertices(t)),
            kept.map(|q| q.map(new))
        );
        assert_eq!(chf.report().inverted_tetrahedra, 1, "level {level}");
        assert_eq!(chf.report().zero_volume, 1, "level {level}");
    }
}
