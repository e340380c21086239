//! The arithmetic of half-faces, edge slots and half-edges. Nothing here reads a container
//! except [`radial`], which needs `V` and `O`.
//!
//! - Tetrahedron `t` owns half-faces `4t .. 4t+3`; half-face `hf = 4t + i` is the face
//!   opposite local vertex `i`, and `V[4t + i]` is vertex `i` of `t`.
//! - Face `i` lists its local vertices in [`FACE`]`[i]`, outward when
//!   `det(p1 - p0, p2 - p0, p3 - p0) > 0`.
//! - Edge slot `s = 6t + k` is local edge `k` of `t`, the local pair [`EDGE`]`[k]`.
//!   Slots are `u64`: `6T` may not fit in 32 bits even when `4T` does.
//! - **Half-edge encoding**: `he = 3 * hf + j` (a `u64`), the `j`-th edge of half-face
//!   `hf` in its vertex order: from local vertex `FACE[i][j]` to `FACE[i][(j + 1) % 3]`.
//!   Its **mate** ([`mate`]) is the same edge on the other face of the same tetrahedron,
//!   running the other way; its **radial** ([`radial`]) is the same edge on `O[hf]`,
//!   running the other way. [`NO_HALF_EDGE`] is "none".
//!
//! Walking `he, mate(he), radial(mate(he)), mate(...), ...` goes around an edge.

use crate::NONE;

/// Local vertices of face `i` (the face opposite local vertex `i`), outward order.
pub const FACE: [[u32; 3]; 4] = [[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]];

/// Local vertex pairs of the six edges of a tetrahedron.
pub const EDGE: [[u32; 2]; 6] = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];

/// A half-edge id: `3 * hf + j`.
pub type HalfEdge = u64;

/// "No half-edge" (the radial of a half-edge on a boundary half-face).
pub const NO_HALF_EDGE: HalfEdge = u64::MAX;

/// The tetrahedron of half-face `hf`.
#[inline]
pub fn tet(hf: u32) -> u32 {
    hf >> 2
}

/// The local index of half-face `hf` in its tetrahedron (the local vertex it is opposite).
#[inline]
pub fn local(hf: u32) -> u32 {
    hf & 3
}

/// The first half-face of tetrahedron `t`.
#[inline]
pub fn first(t: u32) -> u32 {
    4 * t
}

/// The half-face of the same tetrahedron `k` places further (`k` in 1..=3).
#[inline]
pub fn next(hf: u32, k: u32) -> u32 {
    (hf & !3) | ((hf + k) & 3)
}

/// The local edge index of local vertices `p != q`.
#[inline]
pub fn edge_index(p: u32, q: u32) -> u32 {
    EDGE_INDEX[p as usize][q as usize]
}

const EDGE_INDEX: [[u32; 4]; 4] = {
    let mut table = [[u32::MAX; 4]; 4];
    let mut k = 0;
    while k < 6 {
        let [p, q] = EDGE[k];
        table[p as usize][q as usize] = k as u32;
        table[q as usize][p as usize] = k as u32;
        k += 1;
    }
    table
};

/// Half-edge `j` of half-face `hf`.
#[inline]
pub fn half_edge(hf: u32, j: u32) -> HalfEdge {
    3 * hf as u64 + j as u64
}

/// The half-face a half-edge lies on.
#[inline]
pub fn he_face(he: HalfEdge) -> u32 {
    (he / 3) as u32
}

/// The position `j` of a half-edge in its half-face.
#[inline]
pub fn he_index(he: HalfEdge) -> u32 {
    (he % 3) as u32
}

/// The next half-edge in the same half-face (the one starting where `he` ends).
#[inline]
pub fn he_next(he: HalfEdge) -> HalfEdge {
    if he % 3 == 2 { he - 2 } else { he + 1 }
}

/// Local vertices `(from, to)` of a half-edge.
#[inline]
pub fn he_locals(he: HalfEdge) -> (u32, u32) {
    let f = &FACE[local(he_face(he)) as usize];
    let j = he_index(he) as usize;
    (f[j], f[(j + 1) % 3])
}

/// The edge slot (`6t + k`) of a half-edge.
#[inline]
pub fn slot_of(he: HalfEdge) -> u64 {
    let (p, q) = he_locals(he);
    6 * tet(he_face(he)) as u64 + edge_index(p, q) as u64
}

/// The two half-edges of edge slot `s`, smaller id first: one on each face of the
/// tetrahedron that contains the edge, running opposite ways.
#[inline]
pub fn slot_half_edges(s: u64) -> [HalfEdge; 2] {
    let t = (s / 6) as u32;
    let [a, b] = SLOT_HALF_EDGES[(s % 6) as usize];
    [
        half_edge(first(t), 0) + a as u64,
        half_edge(first(t), 0) + b as u64,
    ]
}

/// Local half-edge `3i + j` (`i` the face, `j` its edge) as the pair of local vertices it
/// runs between.
const fn local_half_edge(h: usize) -> (u32, u32) {
    let face = FACE[h / 3];
    (face[h % 3], face[(h % 3 + 1) % 3])
}

/// Per local edge, the two local half-edges `3i + j` that lie on it, increasing.
const SLOT_HALF_EDGES: [[u32; 2]; 6] = {
    let mut table = [[u32::MAX; 2]; 6];
    let mut n = [0usize; 6];
    let mut h = 0;
    while h < 12 {
        let (p, q) = local_half_edge(h);
        let k = EDGE_INDEX[p as usize][q as usize] as usize;
        table[k][n[k]] = h as u32;
        n[k] += 1;
        h += 1;
    }
    table
};

/// Per local half-edge `3i + j`, its mate's local half-edge.
const MATE: [u32; 12] = {
    let mut table = [u32::MAX; 12];
    let mut h = 0;
    while h < 12 {
        let (p, q) = local_half_edge(h);
        // The other face holding edge {p, q} is opposite the fourth local vertex.
        let other = (6 - p - q) as usize - h / 3;
        let mut h2 = 3 * other;
        while h2 < 3 * other + 3 {
            let (p2, q2) = local_half_edge(h2);
            if p2 == q && q2 == p {
                table[h] = h2 as u32;
            }
            h2 += 1;
        }
        h += 1;
    }
    table
};

/// The same edge on the other face of the same tetrahedron, running the other way.
#[inline]
pub fn mate(he: HalfEdge) -> HalfEdge {
    let base = 12 * (he / 12);
    base + MATE[(he % 12) as usize] as u64
}

/// The vertex ids of half-face `hf`, in its (outward) order.
#[inline]
pub fn face_cycle(v: &[u32], hf: u32) -> [u32; 3] {
    let base = first(tet(hf)) as usize;
    FACE[local(hf) as usize].map(|l| v[base + l as usize])
}

/// The vertex a half-edge starts at.
#[inline]
pub fn he_origin(v: &[u32], he: HalfEdge) -> u32 {
    let (p, _) = he_locals(he);
    v[(first(tet(he_face(he))) + p) as usize]
}

/// The vertex a half-edge ends at.
#[inline]
pub fn he_target(v: &[u32], he: HalfEdge) -> u32 {
    let (_, q) = he_locals(he);
    v[(first(tet(he_face(he))) + q) as usize]
}

/// The same edge on the twin half-face `O[hf]`, running the other way; [`NO_HALF_EDGE`]
/// on a boundary half-face. Found by vertex id (3 comparisons): paired faces carry the
/// same ids in reverse order.
#[inline]
pub fn radial(v: &[u32], o: &[u32], he: HalfEdge) -> HalfEdge {
    let g = o[he_face(he) as usize];
    if g == NONE {
        return NO_HALF_EDGE;
    }
    // The next step reads `O` of the same tetrahedron: its line is fetched alongside
    // its corners rather than after them.
    crate::util::prefetch::prefetch(o, first(tet(g)) as usize);
    let y = he_target(v, he);
    let cycle = face_cycle(v, g);
    let j = if cycle[0] == y {
        0
    } else if cycle[1] == y {
        1
    } else {
        2
    };
    half_edge(g, j)
}

/// Do two half-faces on the same vertex triple run the same way round?
#[inline]
pub fn same_direction(v: &[u32], h: u32, g: u32) -> bool {
    let a = face_cycle(v, h);
    let b = face_cycle(v, g);
    let k = if b[0] == a[0] {
        0
    } else if b[1] == a[0] {
        1
    } else {
        2
    };
    b[(k + 1) % 3] == a[1]
}

/// The vertex triple of half-face `hf`, sorted.
#[inline]
pub fn sorted_triple(v: &[u32], hf: u32) -> [u32; 3] {
    let mut t = face_cycle(v, hf);
    if t[0] > t[1] {
        t.swap(0, 1);
    }
    if t[1] > t[2] {
        t.swap(1, 2);
    }
    if t[0] > t[1] {
        t.swap(0, 1);
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_are_outward_for_a_positive_tetrahedron() {
        // p0 = 0, p1 = x, p2 = y, p3 = z: det = +1. The outward normal of face i points
        // away from vertex i.
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0f64],
        ];
        let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        for (i, f) in FACE.iter().enumerate() {
            let [a, b, c] = f.map(|l| p[l as usize]);
            let n = cross(sub(b, a), sub(c, a));
            assert!(dot(n, sub(p[i], a)) < 0.0, "face {i} points inward");
            assert!(!f.contains(&(i as u32)));
        }
    }

    #[test]
    fn mates_pair_up_and_reverse() {
        let v = [10, 11, 12, 13, 20, 21, 22, 23];
        for he in 0..24u64 {
            let m = mate(he);
            assert_eq!(mate(m), he);
            assert_ne!(he_face(m), he_face(he));
            assert_eq!(tet(he_face(m)), tet(he_face(he)));
            assert_eq!(he_origin(&v, m), he_target(&v, he));
            assert_eq!(he_target(&v, m), he_origin(&v, he));
            assert_eq!(slot_of(m), slot_of(he));
            let pair = slot_half_edges(slot_of(he));
            assert!(pair.contains(&he) && pair.contains(&m) && pair[0] < pair[1]);
        }
    }

    #[test]
    fn half_edges_follow_the_face_order() {
        let v = [10, 11, 12, 13];
        for hf in 0..4 {
            let c = face_cycle(&v, hf);
            for j in 0..3 {
                let he = half_edge(hf, j);
                assert_eq!(he_origin(&v, he), c[j as usize]);
                assert_eq!(he_target(&v, he), c[(j as usize + 1) % 3]);
                assert_eq!(he_origin(&v, he_next(he)), c[(j as usize + 1) % 3]);
            }
        }
        assert_eq!(next(5, 1), 6);
        assert_eq!(next(7, 1), 4);
        assert_eq!(next(7, 3), 6);
    }

    #[test]
    fn radial_crosses_a_shared_face() {
        // t0 = (0,1,2,3) positive; t1 = (1,2,3,4) shares face (1,2,3) = half-face 0 of t0
        // and must hold it in reverse: t1 = (4,1,3,2) puts face 0 of t1 = (1,3,2).
        let v = [0, 1, 2, 3, 4, 1, 3, 2];
        let mut o = vec![NONE; 8];
        o[0] = 4;
        o[4] = 0;
        assert!(!same_direction(&v, 0, 4));
        for j in 0..3 {
            let he = half_edge(0, j);
            let r = radial(&v, &o, he);
            assert_eq!(he_face(r), 4);
            assert_eq!(he_origin(&v, r), he_target(&v, he));
            assert_eq!(he_target(&v, r), he_origin(&v, he));
            assert_eq!(radial(&v, &o, r), he);
        }
        assert_eq!(radial(&v, &o, half_edge(1, 0)), NO_HALF_EDGE);
        assert_eq!(sorted_triple(&v, 4), [1, 2, 3]);
    }
}
