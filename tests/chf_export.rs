//! The CHF exports against brute force from the raw tetrahedron list at every level:
//! half-face arrays, the dual graph, `d1 d2 == 0` and `d2 d3 == 0` over Z, and Betti
//! numbers against Gaussian elimination over Z/2 and known solids.

use std::collections::{BTreeMap, BTreeSet};
use topomesh::NONE;
use topomesh::che::SparseMatrix;
use topomesh::chf::{self, Chf, VolumeMatrixKind};

type Tets = Vec<[u32; 4]>;

/// `nx * ny * nz` unit cells, 6 tetrahedra each (Kuhn), corner `(i, j, k)` being vertex
/// `id(i, j, k)`.
fn kuhn(nx: u32, ny: u32, nz: u32, id: impl Fn(u32, u32, u32) -> u32) -> Tets {
    let mut out = Vec::new();
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let c = |d: u32| id(i + (d & 1), j + (d >> 1 & 1), k + (d >> 2 & 1));
                for (a, b) in [(1, 2), (2, 1), (1, 4), (4, 1), (2, 4), (4, 2)] {
                    out.push([c(0), c(a), c(a | b), c(7)]);
                }
            }
        }
    }
    out
}

/// A box of cells: a ball.
fn ball(n: u32) -> (Tets, usize) {
    let m = n + 1;
    (
        kuhn(n, n, n, |i, j, k| i + m * (j + m * k)),
        (m * m * m) as usize,
    )
}

/// A ring of `n` cells by 1 by 1, the last face glued to the first: a solid torus.
fn solid_torus(n: u32) -> (Tets, usize) {
    (
        kuhn(n, 1, 1, |i, j, k| i % n + n * (j + 2 * k)),
        (4 * n) as usize,
    )
}

fn builds(tets: &Tets, n: usize) -> Vec<Chf> {
    (0..=3)
        .map(|level| Chf::from_tetrahedra(tets, n, &[], chf::BuildOptions::level(level)).unwrap())
        .collect()
}

fn entries(m: &SparseMatrix) -> BTreeMap<(u32, u32), f64> {
    let mut out = BTreeMap::new();
    for r in 0..m.n_rows {
        let (cols, vals) = m.row(r);
        assert!(cols.windows(2).all(|w| w[0] < w[1]));
        for (&c, &x) in cols.iter().zip(vals) {
            out.insert((r as u32, c), x);
        }
    }
    out
}

fn product(a: &BTreeMap<(u32, u32), f64>, b: &BTreeMap<(u32, u32), f64>) -> usize {
    let mut out: BTreeMap<(u32, u32), f64> = BTreeMap::new();
    for (&(i, k), &x) in a {
        for (&(_, j), &y) in b.range((k, 0)..=(k, u32::MAX)) {
            *out.entry((i, j)).or_default() += x * y;
        }
    }
    out.values().filter(|&&x| x != 0.0).count()
}

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
        let pivot = m[rank].clone();
        for (i, row) in m.iter_mut().enumerate() {
            if i != rank && row[c / 64] >> (c % 64) & 1 == 1 {
                row.iter_mut().zip(&pivot).for_each(|(x, y)| *x ^= y);
            }
        }
        rank += 1;
    }
    rank as u64
}

/// Betti numbers over Z/2 of the complex of a manifold tetrahedron list, from maps.
fn brute_betti(tets: &Tets, n: usize) -> [u64; 4] {
    let mut edges: BTreeMap<[u32; 2], usize> = BTreeMap::new();
    let mut faces: BTreeMap<[u32; 3], usize> = BTreeMap::new();
    for t in tets {
        for (a, b) in [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)] {
            let mut k = [t[a], t[b]];
            k.sort_unstable();
            let l = edges.len();
            edges.entry(k).or_insert(l);
        }
        for skip in 0..4 {
            let mut k: Vec<u32> = (0..4).filter(|&i| i != skip).map(|i| t[i]).collect();
            k.sort_unstable();
            let l = faces.len();
            faces.entry([k[0], k[1], k[2]]).or_insert(l);
        }
    }
    let d1 = edges
        .keys()
        .map(|e| e.iter().map(|&x| x as usize).collect())
        .collect();
    let d2 = faces
        .keys()
        .map(|f| {
            [[f[0], f[1]], [f[0], f[2]], [f[1], f[2]]]
                .iter()
                .map(|e| edges[e])
                .collect()
        })
        .collect();
    let d3 = tets
        .iter()
        .map(|t| {
            (0..4)
                .map(|skip| {
                    let mut k: Vec<u32> = (0..4).filter(|&i| i != skip).map(|i| t[i]).collect();
                    k.sort_unstable();
                    faces[&[k[0], k[1], k[2]]]
                })
                .collect()
        })
        .collect();
    let (r1, r2, r3) = (
        rank_z2(d1, n),
        rank_z2(d2, edges.len()),
        rank_z2(d3, faces.len()),
    );
    let (e, f) = (edges.len() as u64, faces.len() as u64);
    [
        n as u64 - r1,
        e - r1 - r2,
        f - r2 - r3,
        tets.len() as u64 - r3,
    ]
}

fn union(a: (Tets, usize), b: (Tets, usize)) -> (Tets, usize) {
    let mut t = a.0;
    t.extend(b.0.iter().map(|x| x.map(|v| v + a.1 as u32)));
    (t, a.1 + b.1)
}

#[test]
fn betti_numbers_of_known_solids() {
    let cases: Vec<(&str, (Tets, usize), [u64; 4])> = vec![
        ("one tetrahedron", (vec![[0, 1, 2, 3]], 4), [1, 0, 0, 0]),
        ("ball", ball(2), [1, 0, 0, 0]),
        ("solid torus", solid_torus(4), [1, 1, 0, 0]),
        (
            "ball and solid torus",
            union(ball(1), solid_torus(3)),
            [2, 1, 0, 0],
        ),
    ];
    for (name, (tets, n), want) in cases {
        assert_eq!(brute_betti(&tets, n), want, "{name}: the reference");
        for chf in builds(&tets, n) {
            assert_eq!(
                chf.betti_numbers().unwrap(),
                want,
                "{name} level {}",
                chf.level()
            );
            let b = want.map(|x| x as i64);
            assert_eq!(
                b[0] - b[1] + b[2] - b[3],
                chf.summary().euler_characteristic,
                "{name}"
            );
        }
    }
}

#[test]
fn boundary_of_boundary_and_arrays() {
    for (name, (tets, n)) in [
        ("ball", ball(2)),
        ("solid torus", solid_torus(3)),
        ("one", (vec![[0, 2, 1, 3]], 4)),
    ] {
        for chf in builds(&tets, n) {
            let m = |k| entries(&chf.volume_matrix(k).unwrap());
            let (d1, d2, d3) = (
                m(VolumeMatrixKind::D1),
                m(VolumeMatrixKind::D2),
                m(VolumeMatrixKind::D3),
            );
            assert_eq!(product(&d1, &d2), 0, "{name}: d1 d2");
            assert_eq!(product(&d2, &d3), 0, "{name}: d2 d3");
            assert_eq!(d3.len(), 4 * chf.num_tetrahedra());
            // Half-faces against the tetrahedra's vertices: each the three others, twins
            // on the same vertices in reverse, faces the same on twins.
            let a = chf.half_face_arrays().unwrap();
            let v: Vec<[u32; 4]> = (0..chf.num_tetrahedra() as u32)
                .map(|t| chf.tetrahedron_vertices(t))
                .collect();
            let dual = chf.tetrahedron_dual_graph().unwrap();
            let adjacency = m(VolumeMatrixKind::DualAdjacency);
            for (hf, &across) in dual.iter().enumerate() {
                let (t, i) = (hf / 4, hf % 4);
                let mut got = a.vertices[3 * hf..3 * hf + 3].to_vec();
                let mut want: Vec<u32> = (0..4).filter(|&k| k != i).map(|k| v[t][k]).collect();
                got.sort_unstable();
                want.sort_unstable();
                assert_eq!(got, want);
                let g = a.twin[hf];
                if g == NONE {
                    assert_eq!(across, NONE);
                    continue;
                }
                let g = g as usize;
                assert_eq!(a.twin[g], hf as u32);
                assert_eq!(a.face[g], a.face[hf]);
                let (x, y) = (
                    &a.vertices[3 * hf..3 * hf + 3],
                    &a.vertices[3 * g..3 * g + 3],
                );
                assert!(
                    (0..3).any(|r| (0..3).all(|k| x[k] == y[(r + 3 - k) % 3])),
                    "reversed"
                );
                assert_eq!(across, (g / 4) as u32);
                assert_eq!(adjacency.get(&(t as u32, (g / 4) as u32)), Some(&1.0));
            }
        }
    }
}
