//! Shared by the CHF integration tests (included with `#[path]`): mesh generators and a
//! brute-force reference computed from the raw tetrahedron list.
#![allow(dead_code)]

use glam::DVec3;
use std::collections::{BTreeMap, BTreeSet};
use topomesh::NONE;
use topomesh::chf::{Chf, ChfBuildOptions};

/// A tetrahedral mesh as arrays.
#[derive(Clone, Debug)]
pub struct Mesh {
    pub tets: Vec<[u32; 4]>,
    pub positions: Vec<DVec3>,
}

impl Mesh {
    pub fn n(&self) -> usize {
        self.positions.len()
    }
    pub fn build(&self, level: u8, with_positions: bool) -> Chf {
        let pos: &[DVec3] = if with_positions { &self.positions } else { &[] };
        Chf::from_tetrahedra(&self.tets, self.n(), pos, ChfBuildOptions::level(level))
            .expect("build")
    }
}

pub fn det(p: &[DVec3], t: [u32; 4]) -> f64 {
    let [a, b, c, d] = t.map(|x| p[x as usize]);
    (b - a).dot((c - a).cross(d - a))
}

/// A box of `nx * ny * nz` unit cells, each split into 6 tetrahedra (Kuhn) or 5
/// (alternating, so that the face diagonals agree), all positively oriented.
pub fn cube(nx: u32, ny: u32, nz: u32, five: bool) -> Mesh {
    let id = |i: u32, j: u32, k: u32| i + (nx + 1) * (j + (ny + 1) * k);
    let mut positions = Vec::new();
    for k in 0..=nz {
        for j in 0..=ny {
            for i in 0..=nx {
                positions.push(DVec3::new(i as f64, j as f64, k as f64));
            }
        }
    }
    let mut tets = Vec::new();
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let c = |d: [u32; 3]| id(i + d[0], j + d[1], k + d[2]);
                let mut cell: Vec<[u32; 4]> = Vec::new();
                if five {
                    let even = (i + j + k) % 2 == 0;
                    let (center, corners): ([[u32; 3]; 4], [[u32; 3]; 4]) = if even {
                        (
                            [[0, 0, 0], [1, 1, 0], [1, 0, 1], [0, 1, 1]],
                            [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]],
                        )
                    } else {
                        (
                            [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]],
                            [[0, 0, 0], [1, 1, 0], [1, 0, 1], [0, 1, 1]],
                        )
                    };
                    cell.push(center.map(c));
                    for q in corners {
                        let nb = |axis: usize| {
                            let mut r = q;
                            r[axis] ^= 1;
                            r
                        };
                        cell.push([c(q), c(nb(0)), c(nb(1)), c(nb(2))]);
                    }
                } else {
                    for perm in [
                        [0, 1, 2],
                        [0, 2, 1],
                        [1, 0, 2],
                        [1, 2, 0],
                        [2, 0, 1],
                        [2, 1, 0],
                    ] {
                        let mut p = [0u32; 3];
                        let mut t = [c(p); 4];
                        for (s, &axis) in perm.iter().enumerate() {
                            p[axis] = 1;
                            t[s + 1] = c(p);
                        }
                        cell.push(t);
                    }
                }
                for mut t in cell {
                    if det(&positions, t) < 0.0 {
                        t.swap(1, 2);
                    }
                    assert!(det(&positions, t) > 0.0);
                    tets.push(t);
                }
            }
        }
    }
    Mesh { tets, positions }
}

/// splitmix64: a tiny deterministic generator for shuffles.
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
        (self.next_u64() % n as u64) as usize
    }
    pub fn shuffle<T>(&mut self, xs: &mut [T]) {
        for i in (1..xs.len()).rev() {
            xs.swap(i, self.below(i + 1));
        }
    }
}

/// Keeps each tetrahedron with probability `keep_percent`, relabels the vertices, shuffles
/// the tetrahedra and permutes the local vertices of each at random.
pub fn scramble(mesh: &Mesh, seed: u64, keep_percent: u64) -> Mesh {
    let mut rng = Rng(seed);
    let mut tets: Vec<[u32; 4]> = mesh
        .tets
        .iter()
        .copied()
        .filter(|_| rng.next_u64() % 100 < keep_percent)
        .collect();
    let mut relabel: Vec<u32> = (0..mesh.n() as u32).collect();
    rng.shuffle(&mut relabel);
    let mut positions = vec![DVec3::ZERO; mesh.n()];
    for (old, &new) in relabel.iter().enumerate() {
        positions[new as usize] = mesh.positions[old];
    }
    for t in tets.iter_mut() {
        *t = t.map(|x| relabel[x as usize]);
        rng.shuffle(t);
    }
    rng.shuffle(&mut tets);
    Mesh { tets, positions }
}

pub fn sorted<const N: usize>(mut a: [u32; N]) -> [u32; N] {
    a.sort_unstable();
    a
}

/// A face of the reference: its vertex triple and its one or two tetrahedra (structure ids).
pub type FaceKey = ([u32; 3], Vec<u32>);
/// An edge of the reference: its vertex pair and the tetrahedra of its fan.
pub type EdgeKey = ([u32; 2], Vec<u32>);

/// The brute-force reference over the structure's tetrahedra (structure vertex ids), with
/// pairing decided from the raw input: two tetrahedra are glued along a face when its input
/// triple lies in exactly two kept input tetrahedra.
pub struct Reference {
    pub tv: Vec<[u32; 4]>,
    pub n_vertices: usize,
    pub faces: Vec<FaceKey>,
    pub edges: Vec<EdgeKey>,
}

fn combos3(t: [u32; 4]) -> [[u32; 3]; 4] {
    [0, 1, 2, 3].map(|i| {
        let mut f = [0; 3];
        let mut n = 0;
        for (j, &x) in t.iter().enumerate() {
            if j != i {
                f[n] = x;
                n += 1;
            }
        }
        sorted(f)
    })
}

fn pairs(t: [u32; 4]) -> [[u32; 2]; 6] {
    [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]].map(|[i, j]| sorted([t[i], t[j]]))
}

/// Connected components of `items` under `adjacent`, each sorted.
fn components(items: &[u32], adjacent: impl Fn(u32, u32) -> bool) -> Vec<Vec<u32>> {
    let mut seen = vec![false; items.len()];
    let mut out = Vec::new();
    for s in 0..items.len() {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        let mut comp = vec![items[s]];
        let mut stack = vec![s];
        while let Some(i) = stack.pop() {
            for j in 0..items.len() {
                if !seen[j] && adjacent(items[i], items[j]) {
                    seen[j] = true;
                    comp.push(items[j]);
                    stack.push(j);
                }
            }
        }
        comp.sort_unstable();
        out.push(comp);
    }
    out
}

/// Input triples (sorted) -> how many kept input tetrahedra hold them.
pub fn input_triple_counts(tets: &[[u32; 4]]) -> BTreeMap<[u32; 3], usize> {
    let mut counts = BTreeMap::new();
    for &t in tets.iter().filter(|t| !degenerate(**t)) {
        for f in combos3(t) {
            *counts.entry(f).or_insert(0) += 1;
        }
    }
    counts
}

pub fn degenerate(t: [u32; 4]) -> bool {
    let s = sorted(t);
    s[0] == s[1] || s[1] == s[2] || s[2] == s[3]
}

impl Reference {
    pub fn new(chf: &Chf, input: &[[u32; 4]]) -> Reference {
        let counts = input_triple_counts(input);
        let tv: Vec<[u32; 4]> = (0..chf.num_tetrahedra() as u32)
            .map(|t| chf.tetrahedron_vertices(t))
            .collect();
        let origin = |f: [u32; 3]| sorted(f.map(|x| chf.vertex_origin(x)));
        // Faces the build could not glue without breaking the orientation (its choice).
        let seams: BTreeSet<[u32; 3]> = chf
            .seam_half_faces()
            .iter()
            .map(|&hf| origin(chf.half_face_vertices_of(hf)))
            .collect();
        let glued = |f: [u32; 3]| counts[&origin(f)] == 2 && !seams.contains(&origin(f));
        // Faces.
        let mut by_triple: BTreeMap<[u32; 3], Vec<u32>> = BTreeMap::new();
        for (t, &q) in tv.iter().enumerate() {
            for f in combos3(q) {
                by_triple.entry(f).or_default().push(t as u32);
            }
        }
        let mut faces = Vec::new();
        for (&f, ts) in &by_triple {
            if ts.len() == 2 && glued(f) {
                faces.push((f, ts.clone()));
            } else {
                for &t in ts {
                    faces.push((f, vec![t]));
                }
            }
        }
        // Edges: fans of the tetrahedra around each structure pair.
        let share_glued = |a: u32, b: u32, pair: [u32; 2]| {
            let fa = combos3(tv[a as usize]);
            let fb = combos3(tv[b as usize]);
            a != b
                && fa.iter().any(|f| {
                    fb.contains(f) && f.contains(&pair[0]) && f.contains(&pair[1]) && glued(*f)
                })
        };
        let mut by_pair: BTreeMap<[u32; 2], Vec<u32>> = BTreeMap::new();
        for (t, &q) in tv.iter().enumerate() {
            for p in pairs(q) {
                by_pair.entry(p).or_default().push(t as u32);
            }
        }
        let mut edges = Vec::new();
        for (&p, ts) in &by_pair {
            for fan in components(ts, |a, b| share_glued(a, b, p)) {
                edges.push((p, fan));
            }
        }
        Reference {
            tv,
            n_vertices: chf.num_vertices(),
            faces,
            edges,
        }
    }

    pub fn vt(&self, v: u32) -> BTreeSet<u32> {
        (0..self.tv.len() as u32)
            .filter(|&t| self.tv[t as usize].contains(&v))
            .collect()
    }
    pub fn vf(&self, v: u32) -> BTreeSet<FaceKey> {
        self.faces
            .iter()
            .filter(|f| f.0.contains(&v))
            .cloned()
            .collect()
    }
    pub fn ve(&self, v: u32) -> BTreeSet<EdgeKey> {
        self.edges
            .iter()
            .filter(|e| e.0.contains(&v))
            .cloned()
            .collect()
    }
    pub fn vv(&self, v: u32) -> BTreeSet<u32> {
        self.ve(v)
            .iter()
            .map(|e| if e.0[0] == v { e.0[1] } else { e.0[0] })
            .collect()
    }
    /// Faces of edge `e`: holding both ends, on a tetrahedron of its fan.
    pub fn ef(&self, e: &EdgeKey) -> BTreeSet<FaceKey> {
        self.faces
            .iter()
            .filter(|f| {
                f.0.contains(&e.0[0])
                    && f.0.contains(&e.0[1])
                    && f.1.iter().any(|t| e.1.contains(t))
            })
            .cloned()
            .collect()
    }
    /// Edges of face `f`.
    pub fn fe(&self, f: &FaceKey) -> BTreeSet<EdgeKey> {
        self.edges
            .iter()
            .filter(|e| {
                f.0.contains(&e.0[0])
                    && f.0.contains(&e.0[1])
                    && f.1.iter().any(|t| e.1.contains(t))
            })
            .cloned()
            .collect()
    }
    pub fn ee(&self, e: &EdgeKey) -> BTreeSet<EdgeKey> {
        let mut out = BTreeSet::new();
        for f in self.ef(e) {
            out.extend(self.fe(&f));
        }
        out.remove(e);
        out
    }
    pub fn ff(&self, f: &FaceKey) -> BTreeSet<FaceKey> {
        self.faces
            .iter()
            .filter(|g| *g != f && g.1.iter().any(|t| f.1.contains(t)))
            .cloned()
            .collect()
    }
    pub fn te(&self, t: u32) -> BTreeSet<EdgeKey> {
        self.edges
            .iter()
            .filter(|e| e.1.contains(&t))
            .cloned()
            .collect()
    }
    pub fn tf(&self, t: u32) -> BTreeSet<FaceKey> {
        self.faces
            .iter()
            .filter(|f| f.1.contains(&t))
            .cloned()
            .collect()
    }
    pub fn tt(&self, t: u32) -> BTreeSet<u32> {
        self.tf(t)
            .iter()
            .flat_map(|f| f.1.iter().copied())
            .filter(|&u| u != t)
            .collect()
    }
    pub fn boundary_face(f: &FaceKey) -> bool {
        f.1.len() == 1
    }
}

/// Every relation of every element, as the structure answers it (ids, in its order).
#[derive(Debug, PartialEq, Eq)]
pub struct Answers {
    pub vv: Vec<Vec<u32>>,
    pub ve: Vec<Vec<u32>>,
    pub vf: Vec<Vec<u32>>,
    pub vt: Vec<Vec<u32>>,
    pub ev: Vec<[u32; 2]>,
    pub ee: Vec<Vec<u32>>,
    pub ef: Vec<Vec<u32>>,
    pub et: Vec<Vec<u32>>,
    pub fv: Vec<[u32; 3]>,
    pub fe: Vec<[u32; 3]>,
    pub ff: Vec<Vec<u32>>,
    pub ft: Vec<Vec<u32>>,
    pub tv: Vec<[u32; 4]>,
    pub te: Vec<[u32; 6]>,
    pub tf: Vec<[u32; 4]>,
    pub tt: Vec<[u32; 4]>,
    pub boundary: (Vec<bool>, Vec<bool>, Vec<bool>),
}

pub fn answers(chf: &Chf) -> Answers {
    let nv = chf.num_vertices() as u32;
    let ne = chf.num_edges() as u32;
    let nf = chf.num_faces() as u32;
    let nt = chf.num_tetrahedra() as u32;
    Answers {
        vv: (0..nv).map(|v| chf.vertex_vertices(v).collect()).collect(),
        ve: (0..nv).map(|v| chf.vertex_edges(v).collect()).collect(),
        vf: (0..nv).map(|v| chf.vertex_faces(v).collect()).collect(),
        vt: (0..nv)
            .map(|v| chf.vertex_tetrahedra(v).collect())
            .collect(),
        ev: (0..ne).map(|e| chf.edge_vertices(e)).collect(),
        ee: (0..ne).map(|e| chf.edge_edges(e).collect()).collect(),
        ef: (0..ne).map(|e| chf.edge_faces(e).collect()).collect(),
        et: (0..ne).map(|e| chf.edge_tetrahedra(e).collect()).collect(),
        fv: (0..nf).map(|f| chf.face_vertices(f)).collect(),
        fe: (0..nf).map(|f| chf.face_edges(f)).collect(),
        ff: (0..nf).map(|f| chf.face_faces(f).to_vec()).collect(),
        ft: (0..nf).map(|f| chf.face_tetrahedra(f).to_vec()).collect(),
        tv: (0..nt).map(|t| chf.tetrahedron_vertices(t)).collect(),
        te: (0..nt).map(|t| chf.tetrahedron_edges(t)).collect(),
        tf: (0..nt).map(|t| chf.tetrahedron_faces(t)).collect(),
        tt: (0..nt).map(|t| chf.tetrahedron_tetrahedra(t)).collect(),
        boundary: (
            (0..nv).map(|v| chf.is_boundary_vertex(v)).collect(),
            (0..ne).map(|e| chf.is_boundary_edge(e)).collect(),
            (0..nf).map(|f| chf.is_boundary_face(f)).collect(),
        ),
    }
}

fn set<T: Ord + Clone>(xs: impl IntoIterator<Item = T>) -> BTreeSet<T> {
    xs.into_iter().collect()
}

fn once<T: Ord + Clone + std::fmt::Debug>(xs: &[T], what: &str) -> BTreeSet<T> {
    let s = set(xs.iter().cloned());
    assert_eq!(s.len(), xs.len(), "{what}: repeated ids in {xs:?}");
    s
}

/// Checks every relation of `a` (answers of `chf`) against the reference, as sets, plus
/// the rotation order around every edge.
pub fn check_against_reference(chf: &Chf, a: &Answers, r: &Reference) {
    let edge_key = |e: u32| -> EdgeKey {
        let mut ts = a.et[e as usize].clone();
        ts.sort_unstable();
        (sorted(a.ev[e as usize]), ts)
    };
    let face_key = |f: u32| -> FaceKey {
        let mut ts = a.ft[f as usize].clone();
        ts.sort_unstable();
        (sorted(a.fv[f as usize]), ts)
    };
    // Ids name the reference's edges and faces one-to-one.
    let edges: Vec<EdgeKey> = (0..chf.num_edges() as u32).map(edge_key).collect();
    let faces: Vec<FaceKey> = (0..chf.num_faces() as u32).map(face_key).collect();
    assert_eq!(once(&edges, "edges"), set(r.edges.iter().cloned()));
    assert_eq!(once(&faces, "faces"), set(r.faces.iter().cloned()));
    let ek = |ids: &[u32]| {
        ids.iter()
            .map(|&e| edges[e as usize].clone())
            .collect::<Vec<_>>()
    };
    let fk = |ids: &[u32]| {
        ids.iter()
            .map(|&f| faces[f as usize].clone())
            .collect::<Vec<_>>()
    };

    for v in 0..chf.num_vertices() as u32 {
        let i = v as usize;
        assert_eq!(once(&a.vt[i], "VT"), r.vt(v), "VT({v})");
        assert_eq!(once(&a.vv[i], "VV"), r.vv(v), "VV({v})");
        assert_eq!(once(&ek(&a.ve[i]), "VE"), r.ve(v), "VE({v})");
        assert_eq!(once(&fk(&a.vf[i]), "VF"), r.vf(v), "VF({v})");
        let on_boundary = r.vf(v).iter().any(Reference::boundary_face);
        assert_eq!(a.boundary.0[i], on_boundary, "boundary vertex {v}");
    }
    for e in 0..chf.num_edges() as u32 {
        let i = e as usize;
        let key = &edges[i];
        let ef = r.ef(key);
        assert_eq!(once(&fk(&a.ef[i]), "EF"), ef, "EF({e})");
        assert_eq!(once(&ek(&a.ee[i]), "EE"), r.ee(key), "EE({e})");
        once(&a.et[i], "ET");
        let open = ef.iter().any(Reference::boundary_face);
        assert_eq!(a.boundary.1[i], open, "boundary edge {e}");
        check_rotation(&a.et[i], &fk(&a.ef[i]), open, key);
    }
    for f in 0..chf.num_faces() as u32 {
        let i = f as usize;
        let key = &faces[i];
        assert_eq!(once(&ek(&a.fe[i]), "FE"), r.fe(key), "FE({f})");
        assert_eq!(once(&fk(&a.ff[i]), "FF"), r.ff(key), "FF({f})");
        assert_eq!(a.boundary.2[i], Reference::boundary_face(key));
        // FE: edge j runs from vertex j to vertex j + 1.
        for j in 0..3 {
            let pair = sorted([a.fv[i][j], a.fv[i][(j + 1) % 3]]);
            assert_eq!(edges[a.fe[i][j] as usize].0, pair, "FE({f}) order");
        }
    }
    for t in 0..chf.num_tetrahedra() as u32 {
        let i = t as usize;
        assert_eq!(a.tv[i], r.tv[i]);
        assert_eq!(once(&ek(&a.te[i]), "TE"), r.te(t), "TE({t})");
        assert_eq!(once(&fk(&a.tf[i]), "TF"), r.tf(t), "TF({t})");
        let tt: Vec<u32> = a.tt[i].iter().copied().filter(|&u| u != NONE).collect();
        assert_eq!(set(tt), r.tt(t), "TT({t})");
        for k in 0..4 {
            // Face k is opposite vertex k; its neighbour is across it.
            let f = &faces[a.tf[i][k] as usize];
            assert!(!f.0.contains(&a.tv[i][k]));
            let across = f.1.iter().copied().find(|&u| u != t).unwrap_or(NONE);
            assert_eq!(a.tt[i][k], across);
        }
    }
}

/// ET walks around the edge: consecutive tetrahedra share a glued face holding it (the last
/// and the first too when closed); EF lists the faces crossed, starting and ending on the
/// boundary when open.
fn check_rotation(et: &[u32], ef: &[FaceKey], open: bool, edge: &EdgeKey) {
    assert!(!et.is_empty());
    let k = et.len();
    assert_eq!(
        ef.len(),
        if open { k + 1 } else { k },
        "EF size of {edge:?}"
    );
    if open {
        assert!(ef[0].1.len() == 1 && ef[0].1[0] == et[0]);
        assert!(ef[k].1.len() == 1 && ef[k].1[0] == et[k - 1]);
    }
    for i in 0..k {
        // Face i + 1 (open) or i + 1 mod k (closed) is between et[i] and the next.
        let f = &ef[(i + 1) % ef.len()];
        assert!(f.1.contains(&et[i]), "rotation of {edge:?}");
        if open && i + 1 == k {
            continue;
        }
        let next = et[(i + 1) % k];
        assert!(
            f.1.contains(&next) && f.1.len() == 2,
            "rotation of {edge:?}"
        );
    }
}

/// Union-find for the brute-force summaries.
pub struct Dsu(Vec<usize>);

impl Dsu {
    pub fn new(n: usize) -> Self {
        Dsu((0..n).collect())
    }
    pub fn find(&mut self, mut x: usize) -> usize {
        while self.0[x] != x {
            x = self.0[x];
        }
        x
    }
    pub fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        self.0[ra] = rb;
    }
}

/// What the build must report, from the raw input alone.
#[derive(Debug, PartialEq, Eq)]
pub struct Expected {
    pub kept: usize,
    pub dropped: usize,
    pub edges: usize,
    pub faces: usize,
    pub boundary_faces: usize,
    pub boundary_edges: usize,
    pub boundary_vertices: usize,
    pub boundary_components: usize,
    pub components: usize,
    pub isolated: usize,
    pub euler: i64,
    pub non_manifold_faces: usize,
    pub non_manifold_edges: usize,
    pub split_vertices: usize,
    /// Pieces of each input vertex star (0 for isolated vertices).
    pub pieces: Vec<Vec<Vec<u32>>>,
}

pub fn expected(input: &[[u32; 4]], n: usize) -> Expected {
    let kept: Vec<(u32, [u32; 4])> = input
        .iter()
        .enumerate()
        .filter(|(_, t)| !degenerate(**t))
        .map(|(i, &t)| (i as u32, t))
        .collect();
    let counts = input_triple_counts(input);
    let mut pair_set = BTreeSet::new();
    for (_, t) in &kept {
        pair_set.extend(pairs(*t));
    }
    let boundary: Vec<[u32; 3]> = counts
        .iter()
        .filter(|(_, c)| **c == 1)
        .map(|(f, _)| *f)
        .collect();
    let mut bpairs = BTreeSet::new();
    let mut bverts = BTreeSet::new();
    let mut dsu = Dsu::new(n);
    for f in &boundary {
        bpairs.extend([[f[0], f[1]], [f[0], f[2]], [f[1], f[2]]]);
        bverts.extend(f.iter().copied());
        dsu.union(f[0] as usize, f[1] as usize);
        dsu.union(f[0] as usize, f[2] as usize);
    }
    let boundary_components = bverts
        .iter()
        .map(|&x| dsu.find(x as usize))
        .collect::<BTreeSet<_>>()
        .len();
    let mut used = vec![false; n];
    let mut dsu = Dsu::new(n);
    for (_, t) in &kept {
        for &x in t {
            used[x as usize] = true;
            dsu.union(t[0] as usize, x as usize);
        }
    }
    let n_components = (0..n)
        .filter(|&x| used[x])
        .map(|x| dsu.find(x))
        .collect::<BTreeSet<_>>()
        .len();
    // Glued: sharing a face that lies in exactly two tetrahedra.
    let tet_of = |i: u32| kept.iter().find(|k| k.0 == i).unwrap().1;
    let glued_holding = |a: u32, b: u32, must: &[u32]| {
        let (fa, fb) = (combos3(tet_of(a)), combos3(tet_of(b)));
        a != b
            && fa
                .iter()
                .any(|f| fb.contains(f) && counts[f] == 2 && must.iter().all(|x| f.contains(x)))
    };
    let ids: Vec<u32> = kept.iter().map(|k| k.0).collect();
    let mut pieces = vec![Vec::new(); n];
    for x in 0..n as u32 {
        let star: Vec<u32> = ids
            .iter()
            .copied()
            .filter(|&i| tet_of(i).contains(&x))
            .collect();
        pieces[x as usize] = components(&star, |a, b| glued_holding(a, b, &[x]));
    }
    let non_manifold_edges = pair_set
        .iter()
        .filter(|p| {
            let around: Vec<u32> = ids
                .iter()
                .copied()
                .filter(|&i| tet_of(i).contains(&p[0]) && tet_of(i).contains(&p[1]))
                .collect();
            components(&around, |a, b| glued_holding(a, b, &p[..])).len() > 1
        })
        .count();
    let isolated = used.iter().filter(|u| !**u).count();
    Expected {
        kept: kept.len(),
        dropped: input.len() - kept.len(),
        edges: pair_set.len(),
        faces: counts.len(),
        boundary_faces: boundary.len(),
        boundary_edges: bpairs.len(),
        boundary_vertices: bverts.len(),
        boundary_components,
        components: n_components,
        isolated,
        euler: n as i64 - pair_set.len() as i64 + counts.len() as i64 - kept.len() as i64,
        non_manifold_faces: counts.values().filter(|&&c| c >= 3).count(),
        non_manifold_edges,
        split_vertices: pieces.iter().filter(|p| p.len() > 1).count(),
        pieces,
    }
}

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

/// `O` pairs reversed faces; `VH` holds its vertex and is a boundary half-face exactly on
/// boundary vertices; the level-3 boundary surface is the boundary half-faces.
pub fn check_invariants(chf: &Chf) {
    if let Some(o) = chf.opposites() {
        for (hf, &g) in o.iter().enumerate() {
            if g == NONE {
                continue;
            }
            assert_eq!(o[g as usize], hf as u32);
            let a = chf.half_face_vertices_of(hf as u32);
            let b = chf.half_face_vertices_of(g);
            let k = b.iter().position(|&y| y == a[0]).expect("same triple");
            assert_eq!(b[(k + 2) % 3], a[1], "twins run opposite ways");
            assert_eq!(b[(k + 1) % 3], a[2], "twins run opposite ways");
        }
    }
    if let Some(vh) = chf.vertex_half_faces() {
        for (v, &hf) in vh.iter().enumerate() {
            if hf == NONE {
                assert_eq!(chf.vertex_tetrahedra(v as u32).count(), 0);
                continue;
            }
            assert!(chf.half_face_vertices_of(hf).contains(&(v as u32)));
            let boundary = chf.vertex_faces(v as u32).any(|f| chf.is_boundary_face(f));
            assert_eq!(chf.opposites().unwrap()[hf as usize] == NONE, boundary);
        }
    }
    if let Some(che) = chf.boundary() {
        let hfs = chf.boundary_half_faces();
        assert_eq!(che.num_triangles(), hfs.len());
        for (k, &hf) in hfs.iter().enumerate() {
            assert_eq!(chf.opposite(hf), NONE);
            assert_eq!(chf.boundary_triangle(hf), k as u32);
            assert_eq!(chf.boundary_triangle_half_face(k as u32), hf);
            let tri = che
                .triangle_vertices(k as u32)
                .map(|v| che.vertex_origin(v));
            assert_eq!(
                tri,
                chf.half_face_vertices_of(hf),
                "triangle {k} is half-face {hf}"
            );
            let comp = chf.boundary_component(tri[0]);
            assert_ne!(comp, NONE);
            assert!(tri.iter().all(|&v| chf.boundary_component(v) == comp));
        }
        for v in 0..chf.num_vertices() as u32 {
            assert_eq!(chf.boundary_component(v) != NONE, chf.is_boundary_vertex(v));
        }
    }
}
