//! The work on one vertex star, from its records alone (see `stars.rs`): the star of `x`
//! is its tetrahedra; its **link** is the surface of their faces opposite `x` (one
//! triangle per tetrahedron). A face `(x, y, z)` is the link edge `(y, z)`, so:
//!
//! - matching the link edges of the star matches the faces holding `x` (each face is
//!   matched in the star of each of its three vertices; its pair is recorded from its
//!   smallest one), with the rule of `O`: exactly two tetrahedra, running opposite ways,
//!   neither half-face flagged;
//! - the star is one piece when its triangles are connected through matched link edges;
//! - the fans of the edge `(x, y)` are the triangles around the link vertex `y`.
//!
//! Edges without walking: the link, cut at its unmatched edges and with each fan made a
//! vertex of its own, is a surface; when the star is one piece it is connected, so its
//! Euler characteristic is at most 2 (at most 1 with a boundary). Counting each vertex id
//! once instead of each fan can only lower it; so when that count already reaches 2 (or 1)
//! no vertex id carries two fans, and the canonical slot of each fan (see `edges.rs`) is
//! in its smallest tetrahedron (closed fan) or its smallest end tetrahedron (open fan): a
//! minimum over the link's corners. Otherwise (a pinched link) the fans are walked.

use super::edges::MultiFan;
use super::ids::{FACE, edge_index};
use super::report::push_example;
use crate::NONE;

/// `[occurrence 4t + i, vertex x, the three other vertices of t in local order]`.
pub(crate) type Record = [u32; 5];

/// Local indices other than `i`, increasing: corner `s` of a record is local
/// `OTHERS[i][s]`.
pub(crate) const OTHERS: [[u32; 3]; 4] = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];

/// Per (local of `x`, corner `s`): the corners `(a, b)` of the face opposite corner `s`,
/// in the face's cycle starting at `x` (so the face runs `x -> a -> b`).
const CYCLE: [[[u8; 2]; 3]; 4] = {
    let mut table = [[[0u8; 2]; 3]; 4];
    let mut i = 0;
    while i < 4 {
        let mut s = 0;
        while s < 3 {
            let j = OTHERS[i][s] as usize;
            let f = FACE[j];
            let mut r = 0;
            while f[r] != i as u32 {
                r += 1;
            }
            let (la, lb) = (f[(r + 1) % 3], f[(r + 2) % 3]);
            table[i][s] = [
                (la - (la > i as u32) as u32) as u8,
                (lb - (lb > i as u32) as u32) as u8,
            ];
            s += 1;
        }
        i += 1;
    }
    table
};

/// Faces found from their smallest vertex, for `O` and the build report.
#[derive(Default)]
pub(crate) struct FaceCensus {
    pub input_faces: usize,
    pub boundary_faces: usize,
    pub non_manifold_faces: usize,
    pub non_manifold_face_examples: Vec<[u32; 3]>,
    /// Half-faces of non-manifold faces, unsorted.
    pub non_manifold: Vec<u32>,
    pub duplicates: usize,
    /// Tetrahedra (structure ids) of the first duplicate pairs, in the order of their
    /// triples.
    pub duplicate_examples: Vec<[u32; 2]>,
    /// Some pair runs the same way round.
    pub same_direction: bool,
}

/// What the star of every vertex adds up to.
pub(crate) struct Sums<'a> {
    /// Half-faces never paired (sorted): non-manifold faces and seams of the build, when
    /// `V` has been split or oriented since.
    pub flagged: &'a [u32],
    /// Record the faces and their pairs (only right on the build's first pass, before any
    /// split).
    pub faces: Option<(&'a mut FaceCensus, &'a mut super::pairs::Opposites)>,
    /// Pair every face of two half-faces (else only the mates).
    pub partners: bool,
    pub split_needed: bool,
    pub vh: Vec<u32>,
    /// Canonical edge slots, in no order.
    pub edge_slots: Vec<u64>,
    pub input_edges: usize,
    pub non_manifold_edges: usize,
    pub non_manifold_edge_examples: Vec<[u32; 2]>,
    pub multi_fan: Vec<MultiFan>,
}

/// Scratch reused from vertex to vertex.
pub(crate) struct Link {
    n_vertices: usize,
    /// Per vertex id: `(x + 1) << 8 | local id` when last seen in the star of `x` (while
    /// vertex ids fit in 24 bits), so that naming the vertices of a star is one branch-free
    /// lookup each, against a hash table's mispredicted probes; 4 bytes per vertex, to
    /// stay in the L2 cache as much as it can.
    stamp_compact: Vec<u32>,
    /// The same, `(x + 1) << 32 | local id`, for larger meshes and stars (made on demand).
    stamp: Vec<u64>,
    /// Per record: the local ids of its three other vertices, the link edge (face) opposite
    /// each corner as a cell, each corner's mate (the corner across that face, `3q + s`)
    /// or `NONE`, and the directions of its three faces (bit `s`: the face opposite corner
    /// `s` runs `x -> a -> b` with `a < b`).
    ids: Vec<[u32; 3]>,
    cells: Vec<[u32; 3]>,
    mates: Vec<[u32; 3]>,
    dirs: Vec<u8>,
    /// Per record (stars of up to 64): its neighbours across matched faces, as bits.
    near: Vec<u64>,
    /// Local id -> vertex id (one spare entry: written before it is known to be new).
    verts: Vec<u32>,
    /// Per cell: arrivals, and the first two corners.
    count: Vec<u16>,
    arrivals: Vec<u32>,
    /// Per local id: the smallest corner holding it, the smallest end corner.
    best: Vec<u32>,
    best_end: Vec<u32>,
    queue: Vec<u32>,
    seen: Vec<bool>,
    walked: Vec<bool>,
    fans: Vec<(u32, u64)>,
    events: Vec<([u32; 2], [u32; 2])>,
    small: Box<Small>,
    skip: u32,
}

/// Fixed-size scratch for the common star (at most 64 tetrahedra over at most 32 other
/// vertices): byte tables indexed by masked values, so the loops run without bounds
/// checks and the whole working set stays in the L1 cache.
struct Small {
    /// Per cell `32a + b` (`a < b`, local ids): arrivals and the first two corners.
    count: [u8; 1024],
    arrivals: [[u8; 2]; 1024],
    cells: [[u16; 3]; 64],
    /// Per record: its three faces' mates (corner `4q + s`, 255 if unpaired), and their
    /// directions.
    mates: [[u8; 3]; 64],
    dirs: [u8; 64],
    /// Per local id: the smallest corner holding it, the smallest end corner.
    best: [u8; 32],
    best_end: [u8; 32],
    near: [u64; 64],
    /// Faces whose smallest vertex is `x`: corner, mate candidate, arrivals, flags.
    faces: [[u8; 4]; 256],
}

const SMALL_NONE: u8 = u8::MAX;

#[inline]
fn hf_of(r: &Record, s: usize) -> u32 {
    (r[0] & !3) + OTHERS[(r[0] & 3) as usize][s]
}

/// Edge slot `6t + k` of corner `c`'s edge `(x, vertex of c)`.
#[inline]
fn slot_of_corner(star: &[Record], c: u32) -> u64 {
    let r = &star[(c / 3) as usize];
    let i = r[0] & 3;
    6 * (r[0] >> 2) as u64 + edge_index(i, OTHERS[i as usize][(c % 3) as usize]) as u64
}

/// Per local of `x` and the order of the three other vertices (bit 0: `y0 < y1`, bit 1:
/// `y0 < y2`, bit 2: `y1 < y2`), the direction bits of the three faces.
const DIRS: [[u8; 8]; 4] = {
    let mut table = [[0u8; 8]; 4];
    let mut i = 0;
    while i < 4 {
        let mut order = 0;
        while order < 8 {
            let mut mask = 0u8;
            let mut s = 0;
            while s < 3 {
                // Is the vertex at corner a below the one at corner b?
                let [a, b] = CYCLE[i][s];
                let (lo, hi, flip) = if a < b { (a, b, false) } else { (b, a, true) };
                let bit = if lo == 0 && hi == 1 {
                    0
                } else if lo == 0 {
                    1
                } else {
                    2
                };
                if ((order >> bit) & 1 == 1) != flip {
                    mask |= 1 << s;
                }
                s += 1;
            }
            table[i][order] = mask;
            order += 1;
        }
        i += 1;
    }
    table
};

/// The corners other than `s`.
const OTHER_CORNERS: [[usize; 2]; 3] = [[1, 2], [0, 2], [0, 1]];

/// Per set of corners above `x` (bit `s`), the faces (opposite corner `s`) whose other two
/// corners are both above: the faces whose smallest vertex is `x`.
const SMALLEST: [u8; 8] = {
    let mut table = [0u8; 8];
    let mut above = 0;
    while above < 8 {
        let mut s = 0;
        while s < 3 {
            let [a, b] = OTHER_CORNERS[s];
            if (above >> a) & 1 == 1 && (above >> b) & 1 == 1 {
                table[above] |= 1 << s;
            }
            s += 1;
        }
        above += 1;
    }
    table
};

impl Link {
    pub(crate) fn new(n_vertices: usize) -> Self {
        Link {
            n_vertices,
            stamp_compact: if n_vertices < 1 << 24 {
                vec![0; n_vertices]
            } else {
                Vec::new()
            },
            stamp: Vec::new(),
            ids: Vec::new(),
            cells: Vec::new(),
            mates: Vec::new(),
            dirs: Vec::new(),
            near: Vec::new(),
            verts: Vec::new(),
            count: Vec::new(),
            arrivals: Vec::new(),
            best: Vec::new(),
            best_end: Vec::new(),
            queue: Vec::new(),
            seen: Vec::new(),
            walked: Vec::new(),
            fans: Vec::new(),
            events: Vec::new(),
            small: Box::new(Small {
                count: [0; 1024],
                arrivals: [[0; 2]; 1024],
                cells: [[0; 3]; 64],
                mates: [[SMALL_NONE; 3]; 64],
                dirs: [0; 64],
                best: [0; 32],
                best_end: [0; 32],
                near: [0; 64],
                faces: [[0; 4]; 256],
            }),
            skip: std::env::var("LSKIP")
                .ok()
                .and_then(|s| s.parse().ok())
                .unwrap_or(0),
        }
    }

    pub(crate) fn star(&mut self, star: &[Record], sums: &mut Sums) {
        let k = star.len();
        let x = star[0][1];
        self.local_ids(star);
        if self.skip == 1 {
            return;
        }
        let m = self.verts.len();
        if k <= 64 && m <= 32 {
            self.small_star(star, sums);
            return;
        }
        let cells = self.cells(star);
        if self.skip == 2 {
            self.count.fill(0);
            return;
        }
        let (first_open, unpaired) = self.match_faces(star, x, sums);
        if self.skip == 3 {
            self.count.fill(0);
            return;
        }
        if cells <= 12 * k {
            self.count[..cells].fill(0);
        } else {
            for c in &self.cells[..k] {
                for &e in c {
                    self.count[e as usize] = 0;
                }
            }
        }
        if let Some((census, _)) = sums.faces.as_mut() {
            flush_events(&mut self.events, x, census);
        }
        if !self.one_piece(k) {
            sums.split_needed = true;
            return;
        }
        if self.skip == 4 {
            return;
        }
        // `VH`: the first unpaired half-face, else the first half-face.
        let c = if first_open == NONE { 0 } else { first_open };
        sums.vh[x as usize] = hf_of(&star[(c / 3) as usize], (c % 3) as usize);

        let edges = (3 * k - unpaired) / 2 + unpaired;
        let euler = m as i64 - edges as i64 + k as i64;
        if euler == if unpaired == 0 { 2 } else { 1 } {
            for l in 0..m {
                let c = if self.best_end[l] != NONE {
                    self.best_end[l]
                } else {
                    self.best[l]
                };
                if self.verts[l] > x {
                    sums.edge_slots.push(slot_of_corner(star, c));
                    sums.input_edges += 1;
                }
            }
        } else {
            self.edges_by_walking(star, x, sums);
        }
    }

    /// [`Link::star`] for a star of at most 64 tetrahedra over at most 32 other vertices.
    /// Corners are numbered `4p + s` here (a shift, not a division, to find the record).
    fn small_star(&mut self, star: &[Record], sums: &mut Sums) {
        let k = star.len();
        let x = star[0][1];
        let m = self.verts.len();
        let small = &mut *self.small;
        for p in 0..k {
            let [a, b, c] = self.ids[p];
            let cell = |a: u32, b: u32| (a.min(b) * 32 + a.max(b)) as u16 & 1023;
            let cells = [cell(b, c), cell(a, c), cell(a, b)];
            small.cells[p & 63] = cells;
            small.dirs[p & 63] = self.dirs[p];
            for (s, &e) in cells.iter().enumerate() {
                let e = e as usize & 1023;
                let seen = small.count[e];
                small.count[e] = seen + 1;
                small.arrivals[e][seen.min(1) as usize] = (4 * p + s) as u8;
            }
        }
        small.best = [SMALL_NONE; 32];
        small.best_end = [SMALL_NONE; 32];
        let check_flags = !sums.flagged.is_empty();
        let census = sums.faces.is_some();
        let (mut first_open, mut unpaired) = (SMALL_NONE, 0usize);
        // Faces whose smallest vertex is `x`, counted after the loop (no branch in it).
        let mut n_faces = 0;
        for (p, r) in star.iter().enumerate().take(k) {
            let above =
                (r[2] > x) as usize | ((r[3] > x) as usize) << 1 | ((r[4] > x) as usize) << 2;
            let smallest = if census { SMALLEST[above] } else { 0 };
            let cells = small.cells[p & 63];
            let dirs = small.dirs[p & 63];
            let mut mates = [SMALL_NONE; 3];
            let mut near = 0u64;
            for s in 0..3 {
                let c = (4 * p + s) as u8;
                let e = cells[s] as usize & 1023;
                let count = small.count[e];
                let [first, second] = small.arrivals[e];
                // (The second slot is stale for a corner alone on its face.)
                let other = if first == c { second } else { first };
                let other = if count >= 2 { other } else { c };
                let (q, t) = ((other >> 2) as usize & 63, other & 3);
                let dir = (dirs >> s) & 1;
                let other_dir = (small.dirs[q] >> t) & 1;
                let mut mated = (count == 2) & (dir != other_dir);
                if check_flags && mated {
                    mated = sums.flagged.binary_search(&hf_of(r, s)).is_err();
                }
                mates[s] = if mated { other } else { SMALL_NONE };
                near |= (mated as u64) << q;
                unpaired += !mated as usize;
                first_open = first_open.min(if mated { SMALL_NONE } else { c });
                small.faces[n_faces & 255] = [
                    c,
                    other,
                    count,
                    mated as u8 | ((dir == other_dir) as u8) << 1,
                ];
                n_faces += (((smallest >> s) & 1 == 1) & (first == c)) as usize;
            }
            small.mates[p & 63] = mates;
            small.near[p & 63] = near;
            // The edges (x, y) of this tetrahedron: an end of its fan when one of the two
            // faces holding it is unpaired. Corners grow: keep the first one met.
            let ids = self.ids[p];
            for (s, [s1, s2]) in OTHER_CORNERS.iter().enumerate() {
                let c = (4 * p + s) as u8;
                let l = ids[s] as usize & 31;
                small.best[l] = small.best[l].min(c);
                let open = (mates[*s1] == SMALL_NONE) | (mates[*s2] == SMALL_NONE);
                small.best_end[l] = small.best_end[l].min(if open { c } else { SMALL_NONE });
            }
        }
        for cells in &small.cells[..k] {
            for &e in cells {
                small.count[e as usize & 1023] = 0;
            }
        }
        let three = |c: u8| 3 * (c as u32 >> 2) + (c as u32 & 3);
        let partners = sums.partners;
        if let Some((census, opposites)) = sums.faces.as_mut() {
            census.input_faces += n_faces;
            for &[c, other, count, flags] in &small.faces[..n_faces] {
                let (p, s) = ((c >> 2) as usize, (c & 3) as usize);
                match count {
                    1 => census.boundary_faces += 1,
                    2 => {
                        let (q, t) = ((other >> 2) as usize, (other & 3) as usize);
                        let (r, r2) = (&star[p], &star[q]);
                        let (h, g) = (hf_of(r, s), hf_of(r2, t));
                        if flags & 1 == 1 || partners {
                            opposites.pair(h, g);
                        }
                        census.same_direction |= flags & 2 == 2;
                        // Duplicate tetrahedra: the same fourth vertex, above the face.
                        let [s1, s2] = OTHER_CORNERS[s];
                        let (y, z) = (r[2 + s1], r[2 + s2]);
                        if r[2 + s] == r2[2 + t] && r[2 + s] > y.max(z) {
                            census.duplicates += 1;
                            let pair = [h.min(g) >> 2, h.max(g) >> 2];
                            self.events.push(([y.min(z), y.max(z)], pair));
                        }
                    }
                    _ => Self::non_manifold_face(&mut self.events, star, three(c) as usize, census),
                }
            }
            flush_events(&mut self.events, x, census);
        }
        // One piece: the tetrahedra reached from the first through matched faces.
        let all = if k == 64 { u64::MAX } else { (1u64 << k) - 1 };
        let (mut reached, mut todo) = (1u64, 1u64);
        while todo != 0 {
            let p = todo.trailing_zeros() as usize;
            todo &= todo - 1;
            let new = small.near[p & 63] & !reached;
            reached |= new;
            todo |= new;
        }
        if reached != all {
            sums.split_needed = true;
            return;
        }
        // `VH`: the first unpaired half-face, else the first half-face.
        let c = if first_open == SMALL_NONE {
            0
        } else {
            first_open as usize
        };
        sums.vh[x as usize] = hf_of(&star[c >> 2], c & 3);

        let edges = (3 * k - unpaired) / 2 + unpaired;
        let euler = m as i64 - edges as i64 + k as i64;
        if euler == if unpaired == 0 { 2 } else { 1 } {
            for l in 0..m {
                let end = small.best_end[l & 31];
                let c = if end != SMALL_NONE {
                    end
                } else {
                    small.best[l & 31]
                };
                if self.verts[l] > x {
                    sums.edge_slots.push(slot_of_corner(star, three(c)));
                    sums.input_edges += 1;
                }
            }
        } else {
            // A pinched link (rare): walk the fans.
            self.mates.clear();
            self.mates.extend(
                small.mates[..k]
                    .iter()
                    .map(|ms| ms.map(|c| if c == SMALL_NONE { NONE } else { three(c) })),
            );
            self.edges_by_walking(star, x, sums);
        }
    }

    /// Local ids of the star's other vertices, in order of first appearance.
    fn local_ids(&mut self, star: &[Record]) {
        let x = star[0][1];
        self.ids.clear();
        self.verts.clear();
        self.verts.resize(3 * star.len() + 1, 0);
        self.dirs.clear();
        let mut m = 0u32;
        // The compact table holds 24 bits of `x + 1` and an 8-bit id: exact while vertex
        // ids stay below 2^24 and a star has at most 255 other vertices.
        let compact = !self.stamp_compact.is_empty() && 3 * star.len() <= 255;
        let (tag32, tag64) = (((x + 1) & 0xFF_FFFF) << 8, ((x + 1) as u64) << 32);
        if !compact && self.stamp.is_empty() {
            self.stamp = vec![0; self.n_vertices];
        }
        for r in star {
            let mut ids = [0u32; 3];
            for s in 0..3 {
                let y = r[2 + s] as usize;
                let id = if compact {
                    let e = self.stamp_compact[y];
                    let fresh = e & !0xFF != tag32;
                    let id = if fresh { m } else { e & 0xFF };
                    self.stamp_compact[y] = tag32 | id;
                    m += fresh as u32;
                    id
                } else {
                    let e = self.stamp[y];
                    let fresh = e & !0xFFFF_FFFF != tag64;
                    let id = if fresh { m } else { e as u32 };
                    self.stamp[y] = tag64 | id as u64;
                    m += fresh as u32;
                    id
                };
                self.verts[id as usize] = y as u32;
                ids[s] = id;
            }
            self.ids.push(ids);
            let order = (r[2] < r[3]) as usize
                | ((r[2] < r[4]) as usize) << 1
                | ((r[3] < r[4]) as usize) << 2;
            self.dirs.push(DIRS[(r[0] & 3) as usize][order]);
        }
        self.verts.truncate(m as usize);
    }

    /// The link edge (face) opposite every corner as a cell: a pair of local ids in a
    /// square table, or on a very large link the rank of the pair among the link's pairs.
    /// Counts the arrivals in each cell and keeps the first two corners, branch-free.
    fn cells(&mut self, star: &[Record]) -> usize {
        let k = star.len();
        let m = self.verts.len();
        // As small as it can be, so that the table stays in the L1 cache.
        let side = m.next_power_of_two() as u32;
        self.cells.clear();
        let n_cells = if side <= 256 && 3 * k < u16::MAX as usize {
            let cell = |a: u32, b: u32| a.min(b) * side + a.max(b);
            self.cells.extend(
                self.ids
                    .iter()
                    .map(|&[a, b, c]| [cell(b, c), cell(a, c), cell(a, b)]),
            );
            (side * side) as usize
        } else {
            // Rare: too many vertices for a table; sort the pairs.
            let mut keyed: Vec<(u32, u32, u32)> = Vec::with_capacity(3 * k);
            for (p, ids) in self.ids.iter().enumerate() {
                for (s, [s1, s2]) in OTHER_CORNERS.iter().enumerate() {
                    let (a, b) = (ids[*s1], ids[*s2]);
                    keyed.push((a.min(b), a.max(b), (3 * p + s) as u32));
                }
            }
            keyed.sort_unstable();
            self.cells.resize(k, [0; 3]);
            let mut rank = 0u32;
            for (j, &(a, b, c)) in keyed.iter().enumerate() {
                if j > 0 && (keyed[j - 1].0, keyed[j - 1].1) != (a, b) {
                    rank += 1;
                }
                self.cells[(c / 3) as usize][(c % 3) as usize] = rank;
            }
            3 * k
        };
        if self.count.len() < n_cells.max(12 * k) {
            self.count = vec![0; n_cells.max(12 * k)];
            self.arrivals = vec![0; 2 * n_cells.max(12 * k)];
        }
        for (p, cells) in self.cells.iter().enumerate() {
            for (s, &e) in cells.iter().enumerate() {
                let e = e as usize;
                let seen = self.count[e];
                self.count[e] = seen.saturating_add(1);
                self.arrivals[2 * e + seen.min(1) as usize] = (3 * p + s) as u32;
            }
        }
        n_cells
    }

    /// Mates across matched link edges; records the faces whose smallest vertex is `x`;
    /// aggregates the smallest corner and end corner of every local id. Returns the first
    /// unpaired corner (`NONE` if none) and the number of unpaired corners.
    fn match_faces(&mut self, star: &[Record], x: u32, sums: &mut Sums) -> (u32, usize) {
        let k = star.len();
        let m = self.verts.len();
        self.mates.clear();
        self.mates.resize(k, [NONE; 3]);
        self.near.clear();
        self.near.resize(k, 0);
        self.best.clear();
        self.best.resize(m, NONE);
        self.best_end.clear();
        self.best_end.resize(m, NONE);
        let check_flags = !sums.flagged.is_empty();
        let census = sums.faces.is_some();
        let (mut first_open, mut unpaired) = (NONE, 0usize);
        for (p, r) in star.iter().enumerate().take(k) {
            let above =
                (r[2] > x) as usize | ((r[3] > x) as usize) << 1 | ((r[4] > x) as usize) << 2;
            let smallest = if census { SMALLEST[above] } else { 0 };
            let mut near = 0u64;
            for s in 0..3 {
                let c = (3 * p + s) as u32;
                let e = self.cells[p][s] as usize;
                let first = self.arrivals[2 * e];
                let count = self.count[e];
                // (The second slot is stale for a corner alone on its face.)
                let second = if count >= 2 {
                    self.arrivals[2 * e + 1]
                } else {
                    c
                };
                let other = if first == c { second } else { first };
                let (q, t) = ((other / 3) as usize, other % 3);
                let dir = (self.dirs[p] >> s) & 1;
                let mut mated = count == 2 && dir != (self.dirs[q] >> t) & 1;
                if check_flags && mated {
                    mated = sums.flagged.binary_search(&hf_of(r, s)).is_err();
                }
                self.mates[p][s] = if mated { other } else { NONE };
                near |= (mated as u64) << (q & 63);
                unpaired += !mated as usize;
                first_open = first_open.min(if mated { NONE } else { c });
                // The face `(x, y, z)` once, from its smallest vertex and first corner.
                if (smallest >> s) & 1 == 1 && first == c {
                    let same = dir == (self.dirs[q] >> t) & 1;
                    Self::face(
                        &mut self.events,
                        star,
                        c,
                        count as u32,
                        other,
                        mated,
                        same,
                        sums,
                    );
                }
            }
            self.near[p] = near;
            // The edges (x, y) of this tetrahedron: an end of its fan when one of the two
            // faces holding it is unpaired. Corners grow: keep the first one met.
            let mates = self.mates[p];
            for (s, [s1, s2]) in OTHER_CORNERS.iter().enumerate() {
                let c = (3 * p + s) as u32;
                let l = self.ids[p][s] as usize;
                self.best[l] = self.best[l].min(c);
                let open = mates[*s1] == NONE || mates[*s2] == NONE;
                self.best_end[l] = self.best_end[l].min(if open { c } else { NONE });
            }
        }
        (first_open, unpaired)
    }

    /// Counts the face of corner `c` (its smallest vertex is `x`) and pairs it.
    #[allow(clippy::too_many_arguments)]
    fn face(
        events: &mut Vec<([u32; 2], [u32; 2])>,
        star: &[Record],
        c: u32,
        count: u32,
        other: u32,
        mated: bool,
        same_direction: bool,
        sums: &mut Sums,
    ) {
        let (p, s) = ((c / 3) as usize, (c % 3) as usize);
        let r = &star[p];
        let [s1, s2] = OTHER_CORNERS[s];
        let (y, z) = (r[2 + s1], r[2 + s2]);
        let partners = sums.partners;
        let (census, opposites) = sums.faces.as_mut().expect("checked");
        census.input_faces += 1;
        match count {
            1 => census.boundary_faces += 1,
            2 => {
                let h = hf_of(r, s);
                let (q, t) = ((other / 3) as usize, (other % 3) as usize);
                let g = hf_of(&star[q], t);
                static NOPAIR: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
                if (mated || partners)
                    && !*NOPAIR.get_or_init(|| std::env::var_os("NOPAIR").is_some())
                {
                    opposites.pair(h, g);
                }
                census.same_direction |= same_direction;
                // Duplicate tetrahedra: the same fourth vertex, above the face.
                let (d, d2) = (r[2 + s], star[q][2 + t]);
                if d == d2 && d > y.max(z) {
                    census.duplicates += 1;
                    events.push(([y.min(z), y.max(z)], [h.min(g) >> 2, h.max(g) >> 2]));
                }
            }
            _ => Self::non_manifold_face(events, star, c as usize, census),
        }
    }

    /// A face of three or more tetrahedra: all its half-faces, and the duplicate pairs among
    /// them (the same fourth vertex, above the face), as the build counts them.
    fn non_manifold_face(
        events: &mut Vec<([u32; 2], [u32; 2])>,
        star: &[Record],
        c: usize,
        census: &mut FaceCensus,
    ) {
        let (y, z) = face_others(&star[c / 3], c % 3);
        let key = |d: usize| {
            let (a, b) = face_others(&star[d / 3], d % 3);
            (a.min(b), a.max(b))
        };
        let this = key(c);
        // (fourth vertex, half-face) of every half-face on the triple.
        let mut group: Vec<(u32, u32)> = (0..3 * star.len())
            .filter(|&d| key(d) == this)
            .map(|d| (star[d / 3][2 + d % 3], hf_of(&star[d / 3], d % 3)))
            .collect();
        group.sort_unstable_by_key(|&(_, h)| h);
        census.non_manifold_faces += 1;
        census.non_manifold.extend(group.iter().map(|&(_, h)| h));
        // Examples in triple order: queued with the duplicates, sorted per vertex.
        events.push(([this.0, this.1], [NONE, NONE]));
        let max = y.max(z);
        group.retain(|&(d, _)| d > max);
        group.sort_unstable();
        for run in group.chunk_by(|a, b| a.0 == b.0) {
            for (i, &(_, a)) in run.iter().enumerate() {
                for &(_, b) in &run[i + 1..] {
                    census.duplicates += 1;
                    events.push(([this.0, this.1], [a >> 2, b >> 2]));
                }
            }
        }
    }

    /// Is the star connected through its matched faces?
    fn one_piece(&mut self, k: usize) -> bool {
        if k <= 64 {
            let all = if k == 64 { u64::MAX } else { (1u64 << k) - 1 };
            let (mut reached, mut todo) = (1u64, 1u64);
            while todo != 0 {
                let p = todo.trailing_zeros() as usize;
                todo &= todo - 1;
                let new = self.near[p] & !reached;
                reached |= new;
                todo |= new;
            }
            return reached == all;
        }
        self.seen.clear();
        self.seen.resize(k, false);
        self.queue.clear();
        self.queue.push(0);
        self.seen[0] = true;
        let mut head = 0;
        while head < self.queue.len() {
            let p = self.queue[head] as usize;
            head += 1;
            for &c in &self.mates[p] {
                if c != NONE && !self.seen[(c / 3) as usize] {
                    self.seen[(c / 3) as usize] = true;
                    self.queue.push(c / 3);
                }
            }
        }
        self.queue.len() == k
    }

    /// A pinched link: walks every fan `(x, y)` with `y > x`, each once.
    fn edges_by_walking(&mut self, star: &[Record], x: u32, sums: &mut Sums) {
        let n = 3 * star.len();
        self.walked.clear();
        self.walked.resize(n, false);
        self.fans.clear();
        for c0 in 0..n {
            let y = star[c0 / 3][2 + c0 % 3];
            if y < x || self.walked[c0] {
                continue;
            }
            let c = self.fan(c0);
            self.fans.push((y, slot_of_corner(star, c)));
        }
        self.fans.sort_unstable();
        for run in self.fans.chunk_by(|a, b| a.0 == b.0) {
            sums.edge_slots.extend(run.iter().map(|&(_, s)| s));
            sums.input_edges += 1;
            if run.len() > 1 {
                let y = run[0].0;
                sums.non_manifold_edges += 1;
                push_example(&mut sums.non_manifold_edge_examples, [x, y]);
                sums.multi_fan.push(MultiFan {
                    a: x,
                    b: y,
                    first_slot: run[0].1,
                });
            }
        }
    }

    /// Walks the fan of corner `c0`'s edge both ways; returns its canonical corner: the
    /// smallest on a closed fan, the smaller end on an open one.
    fn fan(&mut self, c0: usize) -> u32 {
        let (p0, s0) = (c0 / 3, c0 % 3);
        let l = self.ids[p0][s0];
        self.walked[c0] = true;
        let mut smallest = c0;
        let mut ends = [c0; 2];
        for (side, &exit0) in OTHER_CORNERS[s0].iter().enumerate() {
            // At corner `(p, s)` of `l`, leave through the face opposite corner `exit`.
            let (mut p, mut c, mut exit) = (p0, c0, exit0);
            loop {
                let across = self.mates[p][exit];
                if across == NONE {
                    ends[side] = c;
                    break;
                }
                let (q, entered) = ((across / 3) as usize, (across % 3) as usize);
                if q == p0 {
                    return smallest as u32;
                }
                let sq = (0..3)
                    .find(|&s| self.ids[q][s] == l)
                    .expect("a fan's vertex");
                let cq = 3 * q + sq;
                self.walked[cq] = true;
                smallest = smallest.min(cq);
                // Out through the other face holding the edge.
                exit = 3 - sq - entered;
                (p, c) = (q, cq);
            }
        }
        ends[0].min(ends[1]) as u32
    }
}

/// The two vertices other than `x` of the face opposite corner `s`.
#[inline]
fn face_others(r: &Record, s: usize) -> (u32, u32) {
    match s {
        0 => (r[3], r[4]),
        1 => (r[2], r[4]),
        _ => (r[2], r[3]),
    }
}

/// Non-manifold faces and duplicate pairs of one vertex, in triple order (`[NONE, NONE]`
/// marks a non-manifold face, before its duplicates).
fn flush_events(events: &mut Vec<([u32; 2], [u32; 2])>, x: u32, census: &mut FaceCensus) {
    if events.is_empty() {
        return;
    }
    // Stable: a face's marker stays before its pairs, which stay in their order.
    events.sort_by_key(|&(yz, pair)| (yz, pair != [NONE, NONE]));
    for &([y, z], pair) in events.iter() {
        if pair == [NONE, NONE] {
            push_example(&mut census.non_manifold_face_examples, [x, y, z]);
        } else {
            push_example(&mut census.duplicate_examples, pair);
        }
    }
    events.clear();
}
