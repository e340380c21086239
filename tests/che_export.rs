//! Every export against an independent brute-force construction from the structure's
//! triangle list (maps and sorting, none of the crate's query code), at every level, on
//! clean, damaged and non-manifold meshes and on every real mesh of the differential tests
//! (in an optimised build); Betti numbers against Gaussian elimination over
//! Z/2 of the input complex and against known surfaces; strips decoded back.

mod che_common;

use che_common::{Rng, perturb};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use topomesh::che::{Assembled, CsrSlices, HalfEdgeOptions, MatrixKind, SparseMatrix};
use topomesh::generate::{grid, sphere, torus};
use topomesh::{BuildOptions, Che, NONE};

type Tris = Vec<[u32; 3]>;

fn tetrahedron(a: u32, b: u32, c: u32, d: u32) -> Tris {
    vec![[a, b, c], [a, d, b], [b, d, c], [a, c, d]]
}

/// A strip of `n` quads, its two ends glued with a half twist.
fn moebius(n: u32) -> Tris {
    let mut tris = Vec::new();
    for i in 0..n {
        let (t0, b0) = (i, n + i);
        let (t1, b1) = if i + 1 < n {
            (i + 1, n + i + 1)
        } else {
            (n, 0)
        };
        tris.push([t0, b0, b1]);
        tris.push([t0, b1, t1]);
    }
    tris
}

/// An `m` by `n` grid, rows glued straight and columns glued with a reflection.
fn klein(m: u32, n: u32) -> Tris {
    let id = |i: u32, j: u32| {
        if j == n {
            (m - i % m) % m
        } else {
            j * m + i % m
        }
    };
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    tris
}

/// `b` appended to `a` with its vertices after `a`'s `n` ones.
fn union(a: (Tris, usize), b: (Tris, usize)) -> (Tris, usize) {
    let mut t = a.0;
    t.extend(b.0.iter().map(|x| x.map(|v| v + a.1 as u32)));
    (t, a.1 + b.1)
}

fn mesh(s: topomesh::generate::Surface) -> (Tris, usize) {
    let n = s.positions.len();
    (s.triangles, n)
}

/// Two tori joined by a tube between two removed triangles: genus 2.
fn double_torus() -> (Tris, usize) {
    let (mut a, na) = mesh(torus(5, 4));
    let (b, nb) = mesh(torus(4, 5));
    let [p, q, r] = a.remove(0);
    let mut b: Tris = b.iter().map(|x| x.map(|v| v + na as u32)).collect();
    let [x, y, z] = b.remove(0);
    a.extend(b);
    for ((s, t), (u, w)) in [((p, q), (x, y)), ((q, r), (y, z)), ((r, p), (z, x))] {
        a.push([s, t, w]);
        a.push([s, w, u]);
    }
    (a, na + nb)
}

/// The fixtures: clean, with boundary, several components, non-manifold input the build
/// splits, seams, duplicates, isolated vertices, and damaged random meshes.
/// The synthetic meshes and every real mesh of the differential tests.
fn fixtures() -> Vec<(String, Tris, usize)> {
    let named = synthetic()
        .into_iter()
        .map(|(name, t, n)| (name.to_string(), t, n));
    named.chain(real_meshes().iter().cloned()).collect()
}

/// The real meshes of `c-tests/diff_surface/meshes.txt`, read once from where
/// `scripts/fetch-meshes.sh` puts them (each one not fetched is skipped with a line). Only
/// in an optimised build: the brute-force references take minutes on them unoptimised, so
/// `scripts/test.sh` runs this file again with `--release`.
fn real_meshes() -> &'static [(String, Tris, usize)] {
    static MESHES: OnceLock<Vec<(String, Tris, usize)>> = OnceLock::new();
    MESHES.get_or_init(|| {
        if cfg!(debug_assertions) {
            eprintln!("skipped: the real meshes (cargo test --release --test che_export)");
            return Vec::new();
        }
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let list = std::fs::read_to_string(root.join("c-tests/diff_surface/meshes.txt")).unwrap();
        let dir = std::env::var_os("TOPOMESH_MESH_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|| {
                let home = std::env::var_os("HOME").map(PathBuf::from);
                home.unwrap_or_default().join(".cache/topomesh/meshes")
            });
        let names = list
            .lines()
            .filter_map(|l| l.split('#').next()?.split_whitespace().next());
        let mut out = Vec::new();
        for name in names {
            let path = dir.join(format!("{name}.off"));
            if !path.is_file() {
                eprintln!(
                    "skipped: {} is not fetched (bash scripts/fetch-meshes.sh)",
                    path.display()
                );
                continue;
            }
            let data = topomesh::io::read(&path).unwrap();
            out.push((name.to_string(), data.triangles, data.positions.len()));
        }
        out
    })
}

/// Small meshes made here: clean, with boundary, non-manifold, several components, damaged.
fn synthetic() -> Vec<(&'static str, Tris, usize)> {
    let mut out = vec![
        ("grid", mesh(grid(4, 3)).0, 20),
        ("sphere", mesh(sphere(5, 3)).0, mesh(sphere(5, 3)).1),
        ("torus", mesh(torus(5, 4)).0, 20),
        ("moebius", moebius(5), 10),
        ("klein", klein(4, 4), 16),
        ("bowtie", vec![[0, 1, 2], [0, 3, 4]], 5),
        ("three on an edge", vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]], 5),
        ("pillow", vec![[0, 1, 2], [0, 2, 1]], 3),
        ("duplicate", vec![[0, 1, 2], [0, 1, 2], [0, 2, 3]], 4),
        ("isolated vertex", vec![[0, 1, 2]], 4),
        ("empty", vec![], 0),
    ];
    let mut touching = tetrahedron(0, 1, 2, 3);
    touching.extend(tetrahedron(0, 4, 5, 6));
    out.push(("tetrahedra at a vertex", touching, 7));
    let mut edge = tetrahedron(0, 1, 2, 3);
    edge.extend(tetrahedron(0, 1, 4, 5));
    out.push(("tetrahedra on an edge", edge, 6));
    let (u, n) = union(mesh(sphere(4, 2)), mesh(torus(3, 3)));
    out.push(("sphere and torus", u, n));
    let mut rng = Rng(11);
    for (k, (tris, n)) in [mesh(torus(4, 4)), mesh(sphere(5, 3)), mesh(grid(3, 3))]
        .into_iter()
        .enumerate()
    {
        for _ in 0..4 {
            let mut t: Tris = tris.iter().copied().filter(|_| rng.chance(0.8)).collect();
            t.push([
                rng.below(n) as u32,
                rng.below(n) as u32,
                rng.below(n) as u32,
            ]);
            let name = ["damaged torus", "damaged sphere", "damaged grid"][k];
            out.push((name, perturb(&t, n, &mut rng, 0.3), n));
        }
    }
    out
}

/// The structure recomputed from `V` and the non-manifold flags alone.
struct Brute {
    v: Vec<u32>,
    nv: usize,
    twin: Vec<u32>,
    edge: Vec<u32>,
    /// The canonical half-edge of each edge.
    eh: Vec<u32>,
}

fn nxt(h: u32) -> u32 {
    3 * (h / 3) + (h + 1) % 3
}
fn prv(h: u32) -> u32 {
    3 * (h / 3) + (h + 2) % 3
}

impl Brute {
    fn new(che: &Che) -> Self {
        let v = che.half_edge_vertices().to_vec();
        let flagged: BTreeSet<u32> = che.non_manifold_half_edges().iter().copied().collect();
        let mut groups: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
        for h in 0..v.len() as u32 {
            let (a, b) = (v[h as usize], v[nxt(h) as usize]);
            groups.entry((a.min(b), a.max(b))).or_default().push(h);
        }
        let mut twin = vec![NONE; v.len()];
        for g in groups.values() {
            if let [h, k] = g[..] {
                let opposite = v[h as usize] == v[nxt(k) as usize];
                if opposite && !flagged.contains(&h) && !flagged.contains(&k) {
                    twin[h as usize] = k;
                    twin[k as usize] = h;
                }
            }
        }
        let (mut edge, mut eh) = (vec![NONE; v.len()], Vec::new());
        for h in 0..v.len() as u32 {
            let t = twin[h as usize];
            if t == NONE || h < t {
                edge[h as usize] = eh.len() as u32;
                if t != NONE {
                    edge[t as usize] = eh.len() as u32;
                }
                eh.push(h);
            }
        }
        Brute {
            v,
            nv: che.num_vertices(),
            twin,
            edge,
            eh,
        }
    }

    fn ends(&self, e: usize) -> (u32, u32) {
        let h = self.eh[e];
        (self.v[h as usize], self.v[nxt(h) as usize])
    }
}

fn builds(tris: &Tris, n: usize) -> Vec<Che> {
    (0..=3)
        .map(|level| {
            let c = Che::from_triangles(tris, n, &[], BuildOptions::level(level)).unwrap();
            c.validate().unwrap();
            c
        })
        .collect()
}

#[test]
fn half_edge_arrays_marked() {
    for (name, tris, n) in fixtures() {
        for che in builds(&tris, n) {
            let b = Brute::new(&che);
            let a = che.half_edge_arrays(HalfEdgeOptions::default()).unwrap();
            let nh = b.v.len() as u32;
            let at = |x| format!("{name} level {}", x);
            assert_eq!(a.vertex, b.v, "{}", at(che.level()));
            assert_eq!(a.twin, b.twin, "{}", at(che.level()));
            assert_eq!(a.edge, b.edge, "{}", at(che.level()));
            assert_eq!(a.next, (0..nh).map(nxt).collect::<Vec<_>>());
            assert_eq!(a.prev, (0..nh).map(prv).collect::<Vec<_>>());
            assert_eq!(a.face, (0..nh).map(|h| h / 3).collect::<Vec<_>>());
            assert_eq!(
                a.face_half_edge,
                (0..nh / 3).map(|t| 3 * t).collect::<Vec<_>>()
            );
            check_vertex_half_edges(&b, &a.vertex_half_edge, |h| b.twin[h as usize] == NONE);
        }
    }
}

/// One outgoing half-edge per used vertex, the boundary one where there is one.
fn check_vertex_half_edges(b: &Brute, vh: &[u32], is_boundary: impl Fn(u32) -> bool) {
    assert_eq!(vh.len(), b.nv);
    let mut outgoing = vec![Vec::new(); b.nv];
    for (h, &v) in b.v.iter().enumerate() {
        outgoing[v as usize].push(h as u32);
    }
    for v in 0..b.nv as u32 {
        let out = &outgoing[v as usize];
        if out.is_empty() {
            assert_eq!(vh[v as usize], NONE);
            continue;
        }
        let h = vh[v as usize];
        let boundary = out.iter().any(|&h| b.twin[h as usize] == NONE);
        if h < b.v.len() as u32 {
            assert_eq!(b.v[h as usize], v);
        }
        assert_eq!(is_boundary(h), boundary, "vertex {v}");
    }
}

#[test]
fn half_edge_arrays_explicit_boundary() {
    for (name, tris, n) in fixtures() {
        for che in builds(&tris, n) {
            let b = Brute::new(&che);
            let a = che
                .half_edge_arrays(HalfEdgeOptions {
                    explicit_boundary: true,
                })
                .unwrap();
            let nh = b.v.len();
            let boundary: Vec<u32> = (0..nh as u32)
                .filter(|&h| b.twin[h as usize] == NONE)
                .collect();
            assert_eq!(a.next.len(), nh + boundary.len(), "{name}");
            for (k, &h) in boundary.iter().enumerate() {
                let x = (nh + k) as u32;
                assert_eq!(a.twin[h as usize], x);
                assert_eq!(a.twin[x as usize], h);
                assert_eq!(a.face[x as usize], NONE);
                assert_eq!(a.edge[x as usize], b.edge[h as usize]);
                assert_eq!(
                    a.vertex[x as usize],
                    b.v[nxt(h) as usize],
                    "tail of the outside twin"
                );
                // The loop continues where this one ends, outside the mesh.
                let y = a.next[x as usize];
                assert_eq!(a.vertex[y as usize], b.v[h as usize], "{name}");
                assert_eq!(a.face[y as usize], NONE);
                assert_eq!(a.prev[y as usize], x);
            }
            for h in 0..nh {
                if b.twin[h] != NONE {
                    assert_eq!(a.twin[h], b.twin[h]);
                }
            }
            check_vertex_half_edges(&b, &a.vertex_half_edge, |h| {
                h != NONE && a.face[h as usize] == NONE
            });
        }
    }
}

#[test]
fn winged_edges_corner_table_and_lists() {
    for (name, tris, n) in fixtures() {
        for che in builds(&tris, n) {
            let b = Brute::new(&che);
            let w = che.winged_edges().unwrap();
            let (mut verts, mut faces, mut wings) = (vec![], vec![], vec![]);
            for (e, &h) in b.eh.iter().enumerate() {
                let (x, y) = b.ends(e);
                verts.extend([x, y]);
                let g = b.twin[h as usize];
                let ed = |k: u32| b.edge[k as usize];
                wings.extend([ed(prv(h)), ed(nxt(h))]);
                if g == NONE {
                    faces.extend([h / 3, NONE]);
                    wings.extend([NONE, NONE]);
                } else {
                    faces.extend([h / 3, g / 3]);
                    wings.extend([ed(prv(g)), ed(nxt(g))]);
                }
            }
            assert_eq!(
                (&w.vertices, &w.faces, &w.wings),
                (&verts, &faces, &wings),
                "{name}"
            );
            let fe: Vec<u32> = (0..b.v.len() / 3).map(|t| b.edge[3 * t]).collect();
            assert_eq!(w.face_edge, fe);
            for (v, &e) in w.vertex_edge.iter().enumerate() {
                if e != NONE {
                    let (x, y) = b.ends(e as usize);
                    assert!(x == v as u32 || y == v as u32);
                }
            }
            assert_eq!(che.edge_list().unwrap(), verts, "{name}: edge list");

            let c = che.corner_table().unwrap();
            assert_eq!(c.v, &b.v[..]);
            for corner in 0..b.v.len() as u32 {
                // The corner across the edge facing `corner`: the one of the other
                // triangle on that edge that is not on it.
                let g = b.twin[nxt(corner) as usize];
                let want = if g == NONE {
                    NONE
                } else {
                    (3 * (g / 3)..3 * (g / 3) + 3)
                        .find(|&k| k != g && k != nxt(g))
                        .unwrap()
                };
                assert_eq!(c.o[corner as usize], want, "{name}: corner {corner}");
            }
        }
    }
}

/// A matrix as a map from (row, column) to value, checking the CSR invariants.
fn entries(m: &SparseMatrix) -> BTreeMap<(u32, u32), f64> {
    assert_eq!(m.offsets.len(), m.n_rows + 1);
    assert_eq!(m.offsets[0], 0);
    let mut out = BTreeMap::new();
    for r in 0..m.n_rows {
        let (cols, vals) = m.row(r);
        assert!(cols.windows(2).all(|w| w[0] < w[1]), "sorted columns");
        for (&c, &x) in cols.iter().zip(vals) {
            assert!((c as usize) < m.n_cols);
            out.insert((r as u32, c), x);
        }
    }
    out
}

fn brute_matrix(b: &Brute, kind: MatrixKind) -> BTreeMap<(u32, u32), f64> {
    let mut m = BTreeMap::new();
    let adjacency = |m: &mut BTreeMap<(u32, u32), f64>| {
        for e in 0..b.eh.len() {
            let (x, y) = b.ends(e);
            m.insert((x, y), 1.0);
            m.insert((y, x), 1.0);
        }
    };
    match kind {
        MatrixKind::VertexAdjacency => adjacency(&mut m),
        MatrixKind::Laplacian => {
            adjacency(&mut m);
            let mut degree = vec![0.0; b.nv];
            for x in m.values_mut() {
                *x = -1.0;
            }
            m.keys().for_each(|&(r, _)| degree[r as usize] += 1.0);
            for (v, d) in degree.into_iter().enumerate() {
                m.insert((v as u32, v as u32), d);
            }
        }
        MatrixKind::EdgeAdjacency => {
            // Two edges meet where they share an end: every pair among a vertex's edges.
            let mut at: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
            for e in 0..b.eh.len() {
                let (x, y) = b.ends(e);
                at.entry(x).or_default().push(e as u32);
                at.entry(y).or_default().push(e as u32);
            }
            for edges in at.values() {
                for &e in edges {
                    edges.iter().filter(|&&f| f != e).for_each(|&f| {
                        m.insert((e, f), 1.0);
                    });
                }
            }
        }
        MatrixKind::D1 => {
            for e in 0..b.eh.len() {
                let (x, y) = b.ends(e);
                m.insert((x, e as u32), -1.0);
                m.insert((y, e as u32), 1.0);
            }
        }
        MatrixKind::D2 => {
            for h in 0..b.v.len() {
                let sign = if b.eh[b.edge[h] as usize] == h as u32 {
                    1.0
                } else {
                    -1.0
                };
                m.insert((b.edge[h], h as u32 / 3), sign);
            }
        }
        MatrixKind::DualAdjacency => {
            for h in 0..b.v.len() {
                if b.twin[h] != NONE {
                    m.insert((h as u32 / 3, b.twin[h] / 3), 1.0);
                }
            }
        }
    }
    m
}

/// The product of two matrices given as maps, zeros dropped.
fn product(
    a: &BTreeMap<(u32, u32), f64>, b: &BTreeMap<(u32, u32), f64>,
) -> BTreeMap<(u32, u32), f64> {
    let mut out: BTreeMap<(u32, u32), f64> = BTreeMap::new();
    for (&(i, k), &x) in a {
        for (&(_, j), &y) in b.range((k, 0)..=(k, u32::MAX)) {
            *out.entry((i, j)).or_default() += x * y;
        }
    }
    out.retain(|_, x| *x != 0.0);
    out
}

#[test]
fn matrices_and_boundary_of_boundary() {
    let mut written = 0;
    for (name, tris, n) in fixtures() {
        for che in builds(&tris, n) {
            let b = Brute::new(&che);
            for kind in MatrixKind::ALL {
                let m = che.matrix(kind).unwrap();
                assert_eq!(
                    entries(&m),
                    brute_matrix(&b, kind),
                    "{name} level {}: {kind:?}",
                    che.level()
                );
                written += usize::from(into_storage_is_the_same(&che, kind, &m));
            }
            // d1 d2 = 0 over Z: a built CHE is oriented and its edges are its own.
            let d1 = entries(&che.matrix(MatrixKind::D1).unwrap());
            let d2 = entries(&che.matrix(MatrixKind::D2).unwrap());
            assert!(product(&d1, &d2).is_empty(), "{name}: d1 d2 over Z");
            let mod2 = |m: BTreeMap<(u32, u32), f64>| -> Vec<(u32, u32)> {
                m.into_iter()
                    .filter(|(_, x)| (*x as i64) % 2 != 0)
                    .map(|(k, _)| k)
                    .collect()
            };
            assert!(mod2(product(&d1, &d2)).is_empty(), "{name}: d1 d2 over Z/2");
            let l = che.matrix(MatrixKind::Laplacian).unwrap();
            for r in 0..l.n_rows {
                assert_eq!(
                    l.row(r).1.iter().sum::<f64>(),
                    0.0,
                    "Laplacian rows sum to 0"
                );
            }
        }
    }
    assert!(
        written > 100,
        "only {written} matrices went to the storage offered"
    );
}

/// `matrix_into` with storage of twice the entries (stale values in it) gives `m`, in that
/// storage when it had room for every entry given; says whether it went there.
fn into_storage_is_the_same(che: &Che, kind: MatrixKind, m: &SparseMatrix) -> bool {
    let cap = 2 * m.nnz() + 8;
    let (mut o, mut c, mut v) = (vec![7; m.n_rows + 1], vec![7; cap], vec![7.0; cap]);
    let mut slices = Some(CsrSlices {
        offsets: &mut o,
        columns: &mut c,
        values: &mut v,
    });
    let mut asked = (0, 0);
    let got = che.matrix_into(kind, &mut |rows, n| {
        asked = (rows, n);
        slices.take()
    });
    match got.unwrap() {
        Assembled::Written {
            n_offsets,
            n_entries,
        } => {
            assert!(
                asked.1 <= cap && n_offsets == m.n_rows + 1,
                "{kind:?}: {asked:?}"
            );
            assert_eq!(o, m.offsets, "{kind:?}");
            assert_eq!(
                (&c[..n_entries], &v[..n_entries]),
                (&m.columns[..], &m.values[..])
            );
            true
        }
        Assembled::Owned(got) => {
            assert!(asked.1 > cap, "{kind:?}: room for {cap}, {asked:?} asked");
            assert_eq!(&got, m, "{kind:?}");
            false
        }
    }
}

/// The rank over Z/2 of rows given as sets of columns, by dense Gaussian elimination.
fn rank_z2(rows: Vec<BTreeSet<usize>>, n_cols: usize) -> u64 {
    let words = n_cols.div_ceil(64).max(1);
    let mut m: Vec<Vec<u64>> = rows
        .into_iter()
        .map(|r| {
            let mut bits = vec![0u64; words];
            r.into_iter().for_each(|c| bits[c / 64] ^= 1 << (c % 64));
            bits
        })
        .collect();
    let mut rank = 0;
    for c in 0..n_cols {
        let Some(p) = (rank..m.len()).find(|&i| m[i][c / 64] >> (c % 64) & 1 == 1) else {
            continue;
        };
        m.swap(rank, p);
        for i in 0..m.len() {
            if i != rank && m[i][c / 64] >> (c % 64) & 1 == 1 {
                let pivot = m[rank].clone();
                m[i].iter_mut().zip(pivot).for_each(|(x, y)| *x ^= y);
            }
        }
        rank += 1;
    }
    rank as u64
}

/// Betti numbers over Z/2 of the input complex, from the raw triangle list.
fn brute_betti(tris: &Tris, n: usize) -> [u64; 3] {
    let kept: Vec<[u32; 3]> = tris
        .iter()
        .copied()
        .filter(|&[a, b, c]| a != b && b != c && a != c)
        .collect();
    let mut edges: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for t in &kept {
        for (x, y) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let k = edges.len();
            edges.entry((x.min(y), x.max(y))).or_insert(k);
        }
    }
    let d1: Vec<BTreeSet<usize>> = edges
        .keys()
        .map(|&(a, b)| [a as usize, b as usize].into())
        .collect();
    let d2: Vec<BTreeSet<usize>> = kept
        .iter()
        .map(|t| {
            [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
                .map(|(x, y)| edges[&(x.min(y), x.max(y))])
                .into()
        })
        .collect();
    let (r1, r2) = (rank_z2(d1, n), rank_z2(d2, edges.len()));
    [
        n as u64 - r1,
        edges.len() as u64 - r1 - r2,
        kept.len() as u64 - r2,
    ]
}

#[test]
fn betti_numbers_against_elimination() {
    // Dense elimination: the small meshes only; the real ones are checked below.
    for (name, tris, n) in synthetic() {
        let want = brute_betti(&tris, n);
        for che in builds(&tris, n) {
            let b = che.betti_numbers().unwrap();
            assert_eq!(b, want, "{name} level {}", che.level());
            let chi = che.summary().euler_characteristic;
            assert_eq!(
                b[0] as i64 - b[1] as i64 + b[2] as i64,
                chi,
                "{name}: Euler"
            );
        }
    }
}

#[test]
fn betti_numbers_of_real_meshes_agree_with_the_summary() {
    for (name, tris, n) in real_meshes() {
        for che in builds(tris, *n) {
            let [b0, b1, b2] = che.betti_numbers().unwrap();
            let s = che.summary();
            let at = format!("{name} level {}", che.level());
            assert_eq!(b0, s.components + s.isolated_vertices, "{at}: b0");
            let chi = b0 as i64 - b1 as i64 + b2 as i64;
            assert_eq!(chi, s.euler_characteristic, "{at}: Euler");
            if s.boundary_edges == 0 {
                // Every closed component carries one 2-cycle over Z/2.
                assert_eq!(b2, s.components, "{at}: b2");
            }
        }
    }
}

#[test]
fn betti_numbers_of_known_surfaces() {
    let cases: Vec<(&str, (Tris, usize), [u64; 3])> = vec![
        ("sphere", mesh(sphere(6, 4)), [1, 0, 1]),
        ("torus", mesh(torus(6, 5)), [1, 2, 1]),
        ("double torus", double_torus(), [1, 4, 1]),
        ("moebius", (moebius(6), 12), [1, 1, 0]),
        ("klein", (klein(5, 4), 20), [1, 2, 1]),
        ("disk", mesh(grid(3, 3)), [1, 0, 0]),
        (
            "sphere + torus + torus",
            union(
                union(mesh(sphere(4, 3)), mesh(torus(3, 3))),
                mesh(torus(4, 3)),
            ),
            [3, 4, 3],
        ),
        (
            "klein + moebius",
            union((klein(4, 4), 16), (moebius(5), 10)),
            [2, 3, 1],
        ),
    ];
    for (name, (tris, n), want) in cases {
        assert_eq!(brute_betti(&tris, n), want, "{name}: the reference");
        for che in builds(&tris, n) {
            assert_eq!(
                che.betti_numbers().unwrap(),
                want,
                "{name} level {}",
                che.level()
            );
            // b0 counts the components; on one closed orientable surface b1 = 2g.
            let s = che.summary();
            assert_eq!(
                want[0],
                s.components + s.isolated_vertices,
                "{name}: components"
            );
            if s.components == 1 && s.orientable && s.boundary_edges == 0 {
                assert_eq!(want[1] as i64, 2 * s.genus, "{name}: genus");
            }
        }
    }
}

/// The triangles a strip stands for, degenerate ones dropped, each rotated to start at
/// its smallest vertex (orientation kept).
fn decode(strip: &[u32]) -> Vec<[u32; 3]> {
    let mut out = Vec::new();
    for i in 0..strip.len().saturating_sub(2) {
        let t = if i % 2 == 0 {
            [strip[i], strip[i + 1], strip[i + 2]]
        } else {
            [strip[i + 1], strip[i], strip[i + 2]]
        };
        if t[0] != t[1] && t[1] != t[2] && t[0] != t[2] {
            out.push(rotated(t));
        }
    }
    out
}

fn rotated(t: [u32; 3]) -> [u32; 3] {
    let k = (0..3).min_by_key(|&i| t[i]).unwrap();
    [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
}

#[test]
fn strips_cover_every_triangle_once_with_its_orientation() {
    for (name, tris, n) in fixtures() {
        for che in builds(&tris, n) {
            let mut want: Vec<[u32; 3]> = che
                .half_edge_vertices()
                .chunks(3)
                .map(|c| rotated([c[0], c[1], c[2]]))
                .collect();
            want.sort_unstable();
            let s = che.triangle_strips().unwrap();
            let mut got: Vec<[u32; 3]> = (0..s.len()).flat_map(|k| decode(s.strip(k))).collect();
            // No strip holds a degenerate triangle of its own.
            let inner: usize = (0..s.len()).map(|k| s.strip(k).len() - 2).sum();
            assert_eq!(inner, got.len(), "{name}");
            got.sort_unstable();
            assert_eq!(got, want, "{name} level {}", che.level());
            let restarts = s.with_restarts().unwrap();
            let mut again: Vec<[u32; 3]> = restarts
                .split(|&x| x == u32::MAX)
                .flat_map(decode)
                .collect();
            again.sort_unstable();
            assert_eq!(again, want, "{name}: with restarts");
            let mut joined = decode(&s.joined().unwrap());
            joined.sort_unstable();
            assert_eq!(joined, want, "{name}: joined by degenerate triangles");
        }
    }
}

#[test]
fn strips_are_long_on_a_clean_grid() {
    // A strip follows a row of quads: far fewer strips than triangles.
    let (tris, n) = mesh(grid(8, 8));
    let che = Che::from_triangles(&tris, n, &[], BuildOptions::level(2)).unwrap();
    let s = che.triangle_strips().unwrap();
    assert!(
        s.len() * 4 <= che.num_triangles(),
        "{} strips for {} triangles",
        s.len(),
        che.num_triangles()
    );
}
