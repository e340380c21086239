//! The brute-force reference, computed from the raw tetrahedron list: faces, edge fans,
//! every relation as sets, and what the build must report.

use super::mesh::sorted;
use std::collections::{BTreeMap, BTreeSet};
use topomesh::chf::Chf;

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
