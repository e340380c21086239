//! Shared by the CHE tests: a small deterministic RNG, mesh perturbations, and a checker
//! that compares every relation at every level with a brute-force reference computed from
//! the raw input triangle list.
#![allow(dead_code)]

use glam::DVec3;
use std::collections::{BTreeMap, BTreeSet};
use topomesh::che::{StarStep, next, prev, tri};
use topomesh::generate::{grid, sphere, torus};
use topomesh::{BuildOptions, Che, NONE};

pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
    pub fn chance(&mut self, p: f64) -> bool {
        ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64) < p
    }
    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            v.swap(i, self.below(i + 1));
        }
    }
}

/// Relabels vertices, shuffles triangles, rotates corners, flips some triangles.
pub fn perturb(tris: &[[u32; 3]], n: usize, rng: &mut Rng, flip_p: f64) -> Vec<[u32; 3]> {
    let mut perm: Vec<u32> = (0..n as u32).collect();
    rng.shuffle(&mut perm);
    let mut out: Vec<[u32; 3]> = tris
        .iter()
        .map(|t| {
            let mut t = t.map(|x| perm[x as usize]);
            t.rotate_left(rng.below(3));
            if rng.chance(flip_p) {
                t.swap(1, 2);
            }
            t
        })
        .collect();
    rng.shuffle(&mut out);
    out
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The input complex, brute force: kept triangles (input ids), edges with their triangles.
pub struct Reference {
    pub n: usize,
    pub kept: Vec<u32>,
    pub edges: BTreeMap<(u32, u32), Vec<u32>>,
}

impl Reference {
    pub fn new(tris: &[[u32; 3]], n: usize) -> Self {
        let mut kept = Vec::new();
        let mut edges: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
        for (t, &[a, b, c]) in tris.iter().enumerate() {
            if a == b || b == c || a == c {
                continue;
            }
            kept.push(t as u32);
            for (x, y) in [(a, b), (b, c), (c, a)] {
                edges.entry(key(x, y)).or_default().push(t as u32);
            }
        }
        Reference { n, kept, edges }
    }
    pub fn neighbours(&self, x: u32) -> BTreeSet<u32> {
        self.edges
            .keys()
            .filter_map(|&(a, b)| {
                if a == x {
                    Some(b)
                } else if b == x {
                    Some(a)
                } else {
                    None
                }
            })
            .collect()
    }
}

/// Everything the structure answers, mapped to input ids, for comparison across levels.
#[derive(Debug, PartialEq)]
pub struct Answers {
    vv: Vec<Vec<u32>>,
    ve: Vec<Vec<u32>>,
    vf: Vec<Vec<u32>>,
    ev: Vec<[u32; 2]>,
    ee: Vec<Vec<u32>>,
    ef: Vec<Vec<u32>>,
    fe: Vec<[u32; 3]>,
    ff: Vec<[u32; 3]>,
    vb: Vec<bool>,
    eb: Vec<bool>,
    curves: Vec<Vec<u32>>,
    summary: topomesh::Summary,
}

pub fn answers(che: &Che) -> Answers {
    let nv = che.num_vertices() as u32;
    let ne = che.num_edges() as u32;
    let nt = che.num_triangles() as u32;
    Answers {
        vv: (0..nv).map(|v| che.vertex_vertices(v).collect()).collect(),
        ve: (0..nv).map(|v| che.vertex_edges(v).collect()).collect(),
        vf: (0..nv).map(|v| che.vertex_triangles(v).collect()).collect(),
        ev: (0..ne).map(|e| che.edge_vertices(e)).collect(),
        ee: (0..ne).map(|e| che.edge_edges(e).to_vec()).collect(),
        ef: (0..ne).map(|e| che.edge_triangles(e).to_vec()).collect(),
        fe: (0..nt).map(|t| che.triangle_edges(t)).collect(),
        ff: (0..nt).map(|t| che.triangle_triangles(t)).collect(),
        vb: (0..nv).map(|v| che.is_boundary_vertex(v)).collect(),
        eb: (0..ne).map(|e| che.is_boundary_edge(e)).collect(),
        curves: (0..che.num_boundary_curves() as u32)
            .map(|c| che.boundary_curve_vertices(c).unwrap())
            .collect(),
        summary: che.summary(),
    }
}

/// Builds `tris` at every level in `levels` and checks the structure and every relation
/// against brute force and against each other. Returns the level-3 mesh.
pub fn check_all(tris: &[[u32; 3]], n: usize, levels: &[u8]) -> Che {
    let reference = Reference::new(tris, n);
    let top = Che::from_triangles(tris, n, &[], BuildOptions::level(3)).expect("build");
    top.validate().expect("level 3 invariants");
    check_structure(&top, tris, &reference);
    let expected = answers(&top);
    for &level in levels {
        let che = Che::from_triangles(tris, n, &[], BuildOptions::level(level)).expect("build");
        assert_eq!(che.level(), level);
        che.validate()
            .unwrap_or_else(|e| panic!("level {level} invariants: {e:?}"));
        assert_eq!(
            che.half_edge_vertices(),
            top.half_edge_vertices(),
            "level {level}: V"
        );
        let got = answers(&che);
        assert_eq!(got, expected, "level {level} answers differ from level 3");
        check_bulk(&che, &got);
        // Raising the level in place gives the same structure as building it directly.
        let mut raised = che.clone();
        raised.build_level(3).unwrap();
        raised.validate().expect("raised to level 3");
        assert_eq!(
            raised.opposites(),
            top.opposites(),
            "raised from {level}: O"
        );
        assert_eq!(raised.vertex_half_edges(), top.vertex_half_edges());
        assert_eq!(raised.curve_half_edges(), top.curve_half_edges());
    }
    top
}

/// The CSR sweeps give the per-element answers.
fn check_bulk(che: &Che, a: &Answers) {
    let as_lists = |csr: &topomesh::che::Csr| {
        (0..csr.len())
            .map(|i| csr.get(i).to_vec())
            .collect::<Vec<_>>()
    };
    assert_eq!(
        as_lists(&che.all_vertex_vertices().unwrap()),
        a.vv,
        "bulk VV"
    );
    assert_eq!(as_lists(&che.all_vertex_edges().unwrap()), a.ve, "bulk VE");
    assert_eq!(
        as_lists(&che.all_vertex_triangles().unwrap()),
        a.vf,
        "bulk VF"
    );
    let triples =
        |x: Vec<u32>| -> Vec<[u32; 3]> { x.chunks(3).map(|c| [c[0], c[1], c[2]]).collect() };
    assert_eq!(
        triples(che.all_triangle_triangles().unwrap()),
        a.ff,
        "bulk FF"
    );
    assert_eq!(triples(che.all_triangle_edges().unwrap()), a.fe, "bulk FE");
}

/// Structural invariants plus the relations against the input complex.
pub fn check_structure(che: &Che, tris: &[[u32; 3]], r: &Reference) {
    let v = che.half_edge_vertices();
    let o = che.opposites().unwrap();
    let vh = che.vertex_half_edges().unwrap();
    let nh = v.len() as u32;
    let org = |x: u32| che.vertex_origin(x);

    // Nothing disappears: each kept input triangle is a structure triangle, in order, with
    // the same vertices in the same or the reversed cyclic order.
    assert_eq!(che.num_triangles(), r.kept.len());
    for t in 0..che.num_triangles() as u32 {
        let input = tris[che.triangle_origin(t) as usize];
        assert_eq!(che.triangle_origin(t), r.kept[t as usize]);
        let got = che.triangle_vertices(t).map(org);
        let rotations = |x: [u32; 3]| [x, [x[1], x[2], x[0]], [x[2], x[0], x[1]]];
        let reversed = [input[0], input[2], input[1]];
        assert!(
            rotations(input).contains(&got) || rotations(reversed).contains(&got),
            "triangle {t}: {got:?} is not input {input:?}"
        );
    }
    assert_eq!(
        che.report().dropped_degenerate + r.kept.len(),
        tris.len(),
        "every input triangle is kept or reported dropped"
    );

    // O: an involution between half-edges running opposite ways, exactly the brute rule.
    let mut by_pair: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    for h in 0..nh {
        by_pair
            .entry(key(v[h as usize], v[next(h) as usize]))
            .or_default()
            .push(h);
    }
    let nm: BTreeSet<u32> = che.non_manifold_half_edges().iter().copied().collect();
    for h in 0..nh {
        let g = o[h as usize];
        let group = &by_pair[&key(v[h as usize], v[next(h) as usize])];
        let expected = if group.len() == 2 && !nm.contains(&h) {
            let other = if group[0] == h { group[1] } else { group[0] };
            if v[other as usize] != v[h as usize] {
                other
            } else {
                NONE
            }
        } else {
            NONE
        };
        // The involution and the vertex pairs are `Che::validate`'s; here the rule.
        assert_eq!(g, expected, "O[{h}]");
        // An input edge with exactly two triangles that is not a seam is paired.
        let input_edge = &r.edges[&key(org(v[h as usize]), org(v[next(h) as usize]))];
        if input_edge.len() == 2 && che.seam_half_edges().binary_search(&h).is_err() {
            assert_ne!(
                g, NONE,
                "input edge with two triangles left unpaired at {h}"
            );
        }
        if input_edge.len() != 2 {
            assert_eq!(g, NONE, "boundary or non-manifold input edge paired at {h}");
        }
    }

    // VH, the boundary rule and one fan per vertex are `Che::validate`'s; here the rotation
    // order and its closing step.
    for x in 0..che.num_vertices() as u32 {
        if vh[x as usize] == NONE {
            assert!(che.is_isolated_vertex(x));
            continue;
        }
        let star: Vec<StarStep> = che.vertex_star(x).collect();
        let outs: Vec<u32> = star
            .iter()
            .filter_map(|s| {
                if let StarStep::Out(h) = s {
                    Some(*h)
                } else {
                    None
                }
            })
            .collect();
        // Counter-clockwise: each step crosses the previous corner's edge.
        for w in outs.windows(2) {
            assert_eq!(o[prev(w[0]) as usize], w[1]);
        }
        match star.last() {
            Some(StarStep::LastIn(p)) => {
                assert_eq!(o[*p as usize], NONE);
                assert_eq!(*p, prev(*outs.last().unwrap()));
                assert!(che.is_boundary_vertex(x));
            }
            _ => assert!(!che.is_boundary_vertex(x)),
        }
    }

    // VV, VF, VE against the input complex (union over the copies of a split vertex).
    let mut vv: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    let mut vf: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    let mut ve: BTreeMap<u32, BTreeSet<(u32, u32)>> = BTreeMap::new();
    for x in 0..che.num_vertices() as u32 {
        let ring: Vec<u32> = che.vertex_vertices(x).collect();
        let edges: Vec<u32> = che.vertex_edges(x).collect();
        assert_eq!(ring.len(), edges.len());
        for (&w, &e) in ring.iter().zip(&edges) {
            let [a, b] = che.edge_vertices(e);
            assert_eq!(key(a, b), key(x, w), "VE and VV agree at {x}");
        }
        vv.entry(org(x))
            .or_default()
            .extend(ring.iter().map(|&w| org(w)));
        vf.entry(org(x))
            .or_default()
            .extend(che.vertex_triangles(x).map(|t| che.triangle_origin(t)));
        ve.entry(org(x)).or_default().extend(edges.iter().map(|&e| {
            let [a, b] = che.edge_vertices(e);
            key(org(a), org(b))
        }));
    }
    for x in 0..r.n as u32 {
        let expected = r.neighbours(x);
        assert_eq!(
            vv.get(&x).cloned().unwrap_or_default(),
            expected,
            "VV of input vertex {x}"
        );
        let expected_edges: BTreeSet<(u32, u32)> = expected.iter().map(|&w| key(x, w)).collect();
        assert_eq!(
            ve.get(&x).cloned().unwrap_or_default(),
            expected_edges,
            "VE of {x}"
        );
        let mut got = vf.get(&x).cloned().unwrap_or_default();
        got.sort_unstable();
        let mut want: Vec<u32> = r
            .kept
            .iter()
            .copied()
            .filter(|&t| tris[t as usize].contains(&x))
            .collect();
        want.sort_unstable();
        assert_eq!(got, want, "VF of input vertex {x}");
    }

    // Edges: ids cover every canonical half-edge once; EV, EF, EE, FE, FF consistent.
    assert_eq!(
        che.num_edges(),
        (0..nh)
            .filter(|&h| o[h as usize] == NONE || h < o[h as usize])
            .count()
    );
    let mut ef_union: BTreeMap<(u32, u32), BTreeSet<u32>> = BTreeMap::new();
    for e in 0..che.num_edges() as u32 {
        let h = che.edge_half_edge(e);
        assert_eq!(che.edge_of(h), e);
        if o[h as usize] != NONE {
            assert_eq!(che.edge_of(o[h as usize]), e);
            assert!(h < o[h as usize]);
        }
        let [a, b] = che.edge_vertices(e);
        let k = key(org(a), org(b));
        let tris_of_edge = che.edge_triangles(e);
        assert_eq!(che.is_boundary_edge(e), tris_of_edge.len() == 1);
        ef_union
            .entry(k)
            .or_default()
            .extend(tris_of_edge.iter().map(|&t| che.triangle_origin(t)));
        let wings = che.edge_edges(e);
        assert_eq!(wings.len(), 2 * tris_of_edge.len());
        for &w in wings.iter() {
            let [c, d] = che.edge_vertices(w);
            assert!(
                c == a || c == b || d == a || d == b,
                "wing {w} of {e} touches it"
            );
        }
    }
    for (k, ts) in &r.edges {
        let want: BTreeSet<u32> = ts.iter().copied().collect();
        assert_eq!(ef_union.get(k), Some(&want), "EF of input edge {k:?}");
    }
    for t in 0..che.num_triangles() as u32 {
        let fv = che.triangle_vertices(t);
        let fe = che.triangle_edges(t);
        let ff = che.triangle_triangles(t);
        for i in 0..3 {
            let [a, b] = che.edge_vertices(fe[i]);
            assert_eq!(key(a, b), key(fv[i], fv[(i + 1) % 3]));
            let k = key(org(fv[i]), org(fv[(i + 1) % 3]));
            let input = &r.edges[&k];
            let h = 3 * t + i as u32;
            if ff[i] == NONE {
                assert_eq!(o[h as usize], NONE);
            } else {
                assert_eq!(input.len(), 2);
                assert!(input.contains(&che.triangle_origin(ff[i])));
                assert_ne!(ff[i], t);
                assert_eq!(tri(o[h as usize]), ff[i]);
            }
        }
    }

    // Boundary curves: every boundary half-edge in exactly one curve, walked in order.
    let starts = che.boundary_curve_starts();
    let mut seen = vec![false; nh as usize];
    for (c, &s) in starts.iter().enumerate() {
        let walk: Vec<u32> = che.boundary_curve(s).collect();
        for (i, &h) in walk.iter().enumerate() {
            assert_eq!(o[h as usize], NONE);
            assert!(!seen[h as usize], "half-edge {h} in two curves");
            seen[h as usize] = true;
            assert_eq!(che.curve_of(h), c as u32);
            let following = walk[(i + 1) % walk.len()];
            assert_eq!(
                v[next(h) as usize],
                v[following as usize],
                "curve {c} is a chain"
            );
        }
    }
    for h in 0..nh {
        assert_eq!(
            seen[h as usize],
            o[h as usize] == NONE,
            "boundary half-edge {h} in a curve"
        );
    }

    // Summary against the input complex.
    let s = che.summary();
    let used: BTreeSet<u32> = r.kept.iter().flat_map(|&t| tris[t as usize]).collect();
    assert_eq!(s.vertices as usize, r.n);
    assert_eq!(s.edges as usize, r.edges.len());
    assert_eq!(s.triangles as usize, r.kept.len());
    assert_eq!(
        s.boundary_edges as usize,
        r.edges.values().filter(|t| t.len() == 1).count()
    );
    assert_eq!(
        s.non_manifold_edges as usize,
        r.edges.values().filter(|t| t.len() > 2).count()
    );
    assert_eq!(s.isolated_vertices as usize, r.n - used.len());
    assert_eq!(
        s.euler_characteristic,
        r.n as i64 - r.edges.len() as i64 + r.kept.len() as i64
    );
}

/// Surfaces with every kind of repair: closed, with boundary, perturbed (flips, splits,
/// non-manifold edges, degenerate and duplicate triangles), a Möbius strip.
pub fn surfaces() -> Vec<(Vec<[u32; 3]>, Vec<DVec3>)> {
    let mut out = Vec::new();
    for s in [grid(3, 2), torus(4, 3), sphere(4, 3)] {
        out.push((s.triangles.clone(), s.positions.clone()));
        let n = s.positions.len();
        let mut rng = Rng(n as u64);
        out.push((perturb(&s.triangles, n, &mut rng, 0.4), Vec::new()));
    }
    let moebius: Vec<[u32; 3]> = (0..6u32)
        .flat_map(|i| {
            let (t0, b0) = (i, 6 + i);
            let (t1, b1) = if i < 5 { (i + 1, 7 + i) } else { (6, 0) };
            [[t0, b0, b1], [t0, b1, t1]]
        })
        .collect();
    out.push((moebius, Vec::new()));
    let pinch = vec![
        [0, 1, 2],
        [0, 1, 3],
        [0, 1, 4],
        [2, 2, 5],
        [0, 5, 6],
        [0, 6, 5],
    ];
    out.push((pinch, Vec::new()));
    out
}

/// The vertex count of a test surface: its positions, or one past its largest id.
pub fn che_n(tris: &[[u32; 3]], positions: &[DVec3]) -> usize {
    positions.len().max(
        tris.iter()
            .flatten()
            .map(|&x| x as usize + 1)
            .max()
            .unwrap_or(0),
    )
}
