//! The common star: at most 64 tetrahedra over at most 32 other vertices, nothing flagged,
//! every face on one or two tetrahedra running opposite ways. Byte tables indexed by
//! masked values, so the loops run without bounds checks and the working set stays in the
//! L1 cache.

use super::{
    CYCLE, Link, OTHER_CORNERS, Record, SMALLEST, Sums, flush_events, hf_of, slot_of_corner,
};
use crate::NONE;
use crate::error::Result;
use crate::util::alloc::try_push;

/// Fixed-size scratch for the common star (at most 64 tetrahedra over at most 32 other
/// vertices): byte tables indexed by masked values, so the loops run without bounds
/// checks and the whole working set stays in the L1 cache.
pub(super) struct Small {
    /// Per directed link edge `32a + b` (local ids): the last corner on it, and how many.
    corner: [u8; 1024],
    count: [u8; 1024],
    cells: [[u16; 3]; 64],
    /// Per record: its three faces' mates (corner `4q + s`, 255 if unpaired).
    mates: [[u8; 3]; 64],
    /// Per local id: the smallest end corner.
    best_end: [u8; 32],
    near: [u64; 64],
    /// Faces whose smallest vertex is `x`: corner, mate, arrivals on the reversed edge.
    faces: [[u8; 3]; 256],
}

const SMALL_NONE: u8 = u8::MAX;

impl Small {
    pub(super) fn new() -> Self {
        Small {
            corner: [0; 1024],
            count: [0; 1024],
            cells: [[0; 3]; 64],
            mates: [[SMALL_NONE; 3]; 64],
            best_end: [0; 32],
            near: [0; 64],
            faces: [[0; 3]; 256],
        }
    }
}

/// What matching the faces of a small star found.
struct Matched {
    /// The first unpaired corner (`4p + s`), `SMALL_NONE` when every face is paired.
    first_open: u8,
    unpaired: usize,
    /// Some directed link edge arrived twice: not a small star.
    irregular: bool,
    /// Faces whose smallest vertex is `x`, in `Small::faces`.
    n_faces: usize,
}

/// Corner `4p + s` of the small tables as corner `3p + s` of `Link`.
#[inline(always)]
fn three(c: u8) -> u32 {
    3 * (c as u32 >> 2) + (c as u32 & 3)
}

impl Small {
    /// Each face of the star as a directed link edge: its cell, its corner, and arrivals.
    #[inline(always)]
    fn directed_edges(&mut self, star: &[Record], ids: &[[u32; 3]]) {
        for p in 0..star.len() {
            let ids = ids[p];
            let cycles = &CYCLE[(star[p][0] & 3) as usize];
            let mut cells = [0u16; 3];
            for s in 0..3 {
                let [a, b] = cycles[s];
                let cell = (ids[a as usize] * 32 + ids[b as usize]) as usize & 1023;
                cells[s] = cell as u16;
                self.corner[cell] = (4 * p + s) as u8;
                self.count[cell] += 1;
            }
            self.cells[p & 63] = cells;
        }
    }

    /// The mate of every corner (the one on the reversed edge), the neighbours of every
    /// tetrahedron, and with `census` the faces whose smallest vertex is `x`. Leaves the
    /// arrival counts at zero for the next star.
    #[inline(always)]
    fn match_faces(&mut self, star: &[Record], x: u32, census: bool) -> Matched {
        let (mut first_open, mut unpaired, mut irregular) = (SMALL_NONE, 0usize, false);
        // Faces whose smallest vertex is `x`, counted once the star is known regular.
        let mut n_faces = 0;
        for (p, r) in star.iter().enumerate() {
            let above =
                (r[2] > x) as usize | ((r[3] > x) as usize) << 1 | ((r[4] > x) as usize) << 2;
            let smallest = if census { SMALLEST[above] } else { 0 };
            let cells = self.cells[p & 63];
            let mut mates = [SMALL_NONE; 3];
            let mut near = 0u64;
            for s in 0..3 {
                let c = (4 * p + s) as u8;
                let cell = cells[s] as usize & 1023;
                let reverse = ((cell & 31) << 5) | (cell >> 5);
                let (count, back) = (self.count[cell], self.count[reverse]);
                let other = self.corner[reverse];
                let mated = (count == 1) & (back == 1);
                irregular |= count > 1;
                mates[s] = if mated { other } else { SMALL_NONE };
                near |= (mated as u64) << ((other >> 2) & 63);
                unpaired += !mated as usize;
                first_open = first_open.min(if mated { SMALL_NONE } else { c });
                // Each face once: a pair from its smaller corner; an unpaired one alone.
                self.faces[n_faces & 255] = [c, other, back];
                let once = if mated { c < other } else { back == 0 };
                n_faces += (((smallest >> s) & 1 == 1) & once) as usize;
            }
            self.mates[p & 63] = mates;
            self.near[p & 63] = near;
        }
        for cells in &self.cells[..star.len()] {
            for &cell in cells {
                self.count[cell as usize & 1023] = 0;
            }
        }
        Matched {
            first_open,
            unpaired,
            irregular,
            n_faces,
        }
    }

    /// Whether the tetrahedra reached from the first through matched faces are all `k`.
    #[inline(always)]
    fn one_piece(&self, k: usize) -> bool {
        let all = if k == 64 { u64::MAX } else { (1u64 << k) - 1 };
        let (mut reached, mut todo) = (1u64, 1u64);
        while todo != 0 {
            let p = todo.trailing_zeros() as usize;
            todo &= todo - 1;
            let new = self.near[p & 63] & !reached;
            reached |= new;
            todo |= new;
        }
        reached == all
    }

    /// The smallest end corner of each local id (only on the boundary: an end is a corner
    /// one of whose two faces holding the edge is unpaired).
    #[inline(always)]
    fn ends(&mut self, ids: &[[u32; 3]], k: usize, unpaired: usize) {
        self.best_end = [SMALL_NONE; 32];
        if unpaired > 0 {
            for (p, ids) in ids.iter().enumerate().take(k) {
                let mates = self.mates[p & 63];
                for (s, [s1, s2]) in OTHER_CORNERS.iter().enumerate() {
                    let l = ids[s] as usize & 31;
                    let open = (mates[*s1] == SMALL_NONE) | (mates[*s2] == SMALL_NONE);
                    let c = if open { (4 * p + s) as u8 } else { SMALL_NONE };
                    self.best_end[l] = self.best_end[l].min(c);
                }
            }
        }
    }
}

impl Link {
    /// [`Link::star`] for the common star: at most 64 tetrahedra over at most 32 other
    /// vertices, nothing flagged, every face of it on one or two tetrahedra running
    /// opposite ways. Returns false, having recorded nothing, on any other star.
    ///
    /// Faces are matched as directed link edges: the face opposite corner `s` runs
    /// `x -> a -> b`, the link edge `a -> b`; its twin runs the other way, so it is the
    /// link edge `b -> a`. One table of directed edges (local ids `32a + b`) holds the
    /// corner of each and how many arrived; the mate of a corner is the one on the
    /// reversed edge. Corners are numbered `4p + s` here (a shift, not a division).
    pub(super) fn small_star(&mut self, star: &[Record], sums: &mut Sums) -> Result<bool> {
        let k = star.len();
        let x = star[0][1];
        let m = self.verts.len();
        self.small.directed_edges(star, &self.ids);
        let matched = self.small.match_faces(star, x, sums.faces.is_some());
        if matched.irregular {
            return Ok(false);
        }
        self.count_small_faces(star, x, matched.n_faces, sums);
        if !self.small.one_piece(k) {
            sums.split_at(x);
            return Ok(true);
        }
        // `VH`: the first unpaired half-face, else the first half-face.
        let c = if matched.first_open == SMALL_NONE {
            0
        } else {
            matched.first_open as usize
        };
        if sums.tables {
            sums.vh[x as usize - sums.vh_base] = hf_of(&star[c >> 2], c & 3);
        }
        let unpaired = matched.unpaired;
        let edges = (3 * k - unpaired) / 2 + unpaired;
        let euler = m as i64 - edges as i64 + k as i64;
        if euler != if unpaired == 0 { 2 } else { 1 } {
            // A pinched link (rare): walk the fans. (At most 64 mates: no need to ask.)
            self.mates.clear();
            self.mates.extend(
                self.small.mates[..k]
                    .iter()
                    .map(|ms| ms.map(|c| if c == SMALL_NONE { NONE } else { three(c) })),
            );
            self.edges_by_walking(star, x, sums)?;
            return Ok(true);
        }
        self.small.ends(&self.ids, k, unpaired);
        self.small_edges(star, x, sums)?;
        Ok(true)
    }

    /// The face census of a small star (the `n_faces` faces whose smallest vertex is `x`),
    /// with the pairs when collected.
    #[inline(always)]
    fn count_small_faces(&mut self, star: &[Record], x: u32, n_faces: usize, sums: &mut Sums) {
        let collect = sums.collect;
        let Some((census, opposites)) = sums.faces.as_mut() else {
            return;
        };
        census.input_faces += n_faces;
        for &[c, other, back] in &self.small.faces[..n_faces] {
            let (p, s) = ((c >> 2) as usize, (c & 3) as usize);
            if back == 0 {
                census.boundary_faces += 1;
                continue;
            }
            let (q, t) = ((other >> 2) as usize, (other & 3) as usize);
            let (r, r2) = (&star[p], &star[q]);
            let (h, g) = (hf_of(r, s), hf_of(r2, t));
            if collect {
                opposites.pair(h, g);
            }
            // Duplicate tetrahedra: the same fourth vertex, above the face.
            let [s1, s2] = OTHER_CORNERS[s];
            let (y, z) = (r[2 + s1], r[2 + s2]);
            if r[2 + s] == r2[2 + t] && r[2 + s] > y.max(z) {
                census.duplicates += 1;
                let pair = [h.min(g) >> 2, h.max(g) >> 2];
                self.events.push(([y.min(z), y.max(z)], pair));
            }
        }
        flush_events(&mut self.events, x, census);
    }

    /// One edge per link vertex above `x`, named by its smallest end corner, else its
    /// first corner.
    #[inline(always)]
    fn small_edges(&mut self, star: &[Record], x: u32, sums: &mut Sums) -> Result<()> {
        for l in 0..self.verts.len() {
            if self.verts[l] > x {
                let end = self.small.best_end[l & 31];
                let c = if end != SMALL_NONE {
                    three(end)
                } else {
                    self.first_corner[l]
                };
                if sums.tables {
                    try_push(sums.edge_slots, slot_of_corner(star, c), "the edge slots")?;
                }
                sums.num_edges += 1;
                sums.input_edges += 1;
            }
        }
        Ok(())
    }
}
