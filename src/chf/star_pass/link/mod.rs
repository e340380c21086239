//! The work on one vertex star, from its records alone (see the star pass, `star_pass/mod.rs`): the star of `x`
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

mod general;
mod small;

use crate::NONE;
use crate::chf::build::report::push_example;
use crate::chf::edges::MultiFan;
use crate::chf::ids::{FACE, edge_index};
use crate::error::Result;
use crate::util::alloc::{try_reserve, try_resize, try_vec};
use small::Small;

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
#[derive(Debug, Default)]
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

/// What the stars of a range of vertices add up to (one thread's share of a round).
pub(crate) struct Sums<'a, 'o> {
    /// Half-faces never paired (sorted): non-manifold faces and seams of the build, when
    /// `V` has been split or oriented since.
    pub flagged: &'a [u32],
    /// Record the faces and their pairs (only right on the build's first pass, before any
    /// split).
    pub faces: Option<(
        &'a mut FaceCensus,
        &'a mut crate::chf::star_pass::pairs::Writer<'o>,
    )>,
    /// Collect the pairs (else count the faces only), and all pairs of two half-faces
    /// (else only the mates).
    pub collect: bool,
    pub partners: bool,
    /// Fill `vh` and `edge_slots` (else count the edges only).
    pub tables: bool,
    pub split_needed: bool,
    /// The first vertex of this share whose star is in several pieces.
    pub first_split: u32,
    /// `VH` of the vertices from `vh_base` on (this thread's range).
    pub vh: &'a mut [u32],
    pub vh_base: usize,
    /// Canonical edge slots, in no order, and how many.
    pub edge_slots: &'a mut Vec<u64>,
    pub num_edges: usize,
    pub input_edges: usize,
    pub non_manifold_edges: usize,
    pub non_manifold_edge_examples: Vec<[u32; 2]>,
    pub multi_fan: Vec<MultiFan>,
}

impl Sums<'_, '_> {
    /// The star of `x` is in several pieces: the vertex split must run.
    pub(crate) fn split_at(&mut self, x: u32) {
        if !self.split_needed {
            self.first_split = x;
        }
        self.split_needed = true;
    }
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
    /// Local id -> vertex id, and the first corner (`3p + s`) holding it (one spare entry
    /// each: written before it is known to be new).
    verts: Vec<u32>,
    first_corner: Vec<u32>,
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
}

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
    pub(crate) fn new(n_vertices: usize) -> crate::error::Result<Self> {
        Ok(Link {
            n_vertices,
            stamp_compact: if n_vertices < 1 << 24 {
                try_vec(n_vertices, 0, "a star pass's vertex stamps")?
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
            first_corner: Vec::new(),
            count: Vec::new(),
            arrivals: Vec::new(),
            best: Vec::new(),
            best_end: Vec::new(),
            queue: Vec::new(),
            seen: Vec::new(),
            walked: Vec::new(),
            fans: Vec::new(),
            events: Vec::new(),
            small: Box::new(Small::new()),
        })
    }

    /// The star of one vertex: its records, in tetrahedron order.
    pub(crate) fn star(&mut self, star: &[Record], sums: &mut Sums) -> Result<()> {
        self.local_ids(star)?;
        let small = star.len() <= 64 && self.verts.len() <= 32 && sums.flagged.is_empty();
        if !(small && self.small_star(star, sums)?) {
            self.general_star(star, sums)?;
        }
        Ok(())
    }

    /// Local ids of the star's other vertices, in order of first appearance.
    fn local_ids(&mut self, star: &[Record]) -> Result<()> {
        const WHAT: &str = "a star's local ids";
        self.ids.clear();
        // Room for every record: `name_vertices` pushes without asking again.
        try_reserve(&mut self.ids, star.len(), WHAT)?;
        self.verts.clear();
        try_resize(&mut self.verts, 3 * star.len() + 1, 0, WHAT)?;
        self.first_corner.clear();
        try_resize(&mut self.first_corner, 3 * star.len() + 1, 0, WHAT)?;
        // The compact table holds 24 bits of `x + 1` and an 8-bit id: exact while vertex
        // ids stay below 2^24 and a star has at most 255 other vertices.
        let compact = !self.stamp_compact.is_empty() && 3 * star.len() <= 255;
        if !compact && self.stamp.is_empty() {
            self.stamp = try_vec(self.n_vertices, 0, "a star pass's vertex stamps")?;
        }
        // Separate borrows, so that the stores do not make the compiler reload the vectors
        // after each one.
        let (verts, first_corner, ids) = (
            &mut self.verts[..],
            &mut self.first_corner[..],
            &mut self.ids,
        );
        let m = if compact {
            name_vertices(star, &mut self.stamp_compact, verts, first_corner, ids)
        } else {
            name_vertices(star, &mut self.stamp, verts, first_corner, ids)
        };
        self.verts.truncate(m as usize);
        self.first_corner.truncate(m as usize);
        Ok(())
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

/// A vertex's entry in [`Link`]'s stamp tables: a tag naming the star that saw it last and
/// the local id it had there.
trait Stamp: Copy + Into<u64> {
    /// The tag of the star of `x`.
    fn tag(x: u32) -> Self;
    /// Whether the entry carries `tag`, and its id.
    fn split(self, tag: Self) -> (bool, u32);
    fn join(tag: Self, id: u32) -> Self;
}

impl Stamp for u32 {
    fn tag(x: u32) -> Self {
        ((x + 1) & 0xFF_FFFF) << 8
    }
    fn split(self, tag: Self) -> (bool, u32) {
        (self & !0xFF == tag, self & 0xFF)
    }
    fn join(tag: Self, id: u32) -> Self {
        tag | id
    }
}

impl Stamp for u64 {
    fn tag(x: u32) -> Self {
        ((x + 1) as u64) << 32
    }
    fn split(self, tag: Self) -> (bool, u32) {
        (self & !0xFFFF_FFFF == tag, self as u32)
    }
    fn join(tag: Self, id: u32) -> Self {
        tag | id as u64
    }
}

/// Names the other vertices of a star 0, 1, ... in order of first appearance: `ids` gets
/// the three names of each record, `verts` the vertex of each name and `first_corner` the
/// first corner (`3p + s`) holding it. Returns how many names. Branch-free per corner:
/// one stamp lookup each.
fn name_vertices<S: Stamp>(
    star: &[Record], stamps: &mut [S], verts: &mut [u32], first_corner: &mut [u32],
    ids: &mut Vec<[u32; 3]>,
) -> u32 {
    let tag = S::tag(star[0][1]);
    // The stamps are read at random (one per corner): read them all first, so that their
    // cache misses overlap, then name the vertices from the L1 cache.
    let mut touched = 0u64;
    for r in star {
        for &y in &r[2..5] {
            touched ^= stamps[y as usize].into();
        }
    }
    std::hint::black_box(touched);
    let mut m = 0u32;
    for (p, r) in star.iter().enumerate() {
        let mut names = [0u32; 3];
        for s in 0..3 {
            let y = r[2 + s] as usize;
            first_corner[m as usize] = (3 * p + s) as u32;
            let (seen, old) = stamps[y].split(tag);
            let id = if seen { old } else { m };
            stamps[y] = S::join(tag, id);
            m += !seen as u32;
            verts[id as usize] = y as u32;
            names[s] = id;
        }
        ids.push(names);
    }
    m
}
