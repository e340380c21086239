//! Mesh generators: subdivided boxes, and a scrambler (subset, relabelling, shuffles).

use glam::DVec3;
use topomesh::chf::{self, Chf};

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
        Chf::from_tetrahedra(&self.tets, self.n(), pos, chf::BuildOptions::level(level))
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

/// Volumes with every kind of repair: closed and bounded boxes, a scrambled one, pinched
/// tetrahedra (an edge, a vertex) and a degenerate one.
pub fn volumes() -> Vec<Mesh> {
    let closed = cube(2, 2, 1, false);
    let mut out = vec![closed.clone(), cube(2, 1, 2, true)];
    out.push(scramble(&closed, 7, 70));
    // Two tetrahedra sharing only an edge, one sharing only a vertex, a degenerate one.
    let mut pinched = cube(1, 1, 1, true);
    let base = pinched.positions.len() as u32;
    pinched.positions.extend([
        DVec3::new(3.0, 0.0, 0.0),
        DVec3::new(3.0, 1.0, 0.0),
        DVec3::new(3.0, 0.0, 1.0),
    ]);
    pinched.tets.push([0, base, base + 1, base + 2]);
    pinched.tets.push([0, 0, base, base + 1]);
    out.push(pinched);
    out
}
