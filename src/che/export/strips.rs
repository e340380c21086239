//! Triangle strips from the dual graph, greedy in the manner of SGI's `tomesh`: start at
//! an unvisited triangle with the fewest unvisited neighbours, extend across the strip's
//! last edge while the triangle there is unvisited, then extend backwards from the start.
//!
//! A strip `s` stands for the triangles `(s[i], s[i + 1], s[i + 2])` for even `i` and
//! `(s[i + 1], s[i], s[i + 2])` for odd `i` (the convention of OpenGL and Direct3D), each
//! in the orientation of its structure triangle: a neighbour across a paired edge runs
//! the edge the other way, which is what the alternation expects. A backward extension
//! shifts the parity of every triangle by its length, so it is kept to an even length.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{first, next, prev, tri};
use crate::error::Result;
use crate::util::alloc::{try_extend, try_push, try_reserve, try_with_capacity};
use crate::util::sparse::filled;

/// The strips of a mesh: every triangle in exactly one.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Strips {
    /// Every strip's vertices, one after another.
    pub vertices: Vec<u32>,
    /// Strip `k` is `vertices[offsets[k]..offsets[k + 1]]`.
    pub offsets: Vec<usize>,
}

/// The marker between strips in [`Strips::with_restarts`] (OpenGL's primitive restart).
pub const RESTART: u32 = u32::MAX;

impl Strips {
    /// The number of strips.
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Strip `k`.
    pub fn strip(&self, k: usize) -> &[u32] {
        &self.vertices[self.offsets[k]..self.offsets[k + 1]]
    }

    /// One index list, the strips separated by `RESTART` (`u32::MAX`).
    pub fn with_restarts(&self) -> Result<Vec<u32>> {
        let n = self.vertices.len() + self.len();
        let mut out = try_with_capacity(n, "the strips with restarts")?;
        for k in 0..self.len() {
            if k > 0 {
                out.push(RESTART);
            }
            out.extend_from_slice(self.strip(k));
        }
        Ok(out)
    }

    /// One strip, the strips joined by degenerate triangles: the last vertex of one and the
    /// first of the next repeated, and the first once more when the next strip would start
    /// at an odd position (which would reverse its triangles).
    pub fn joined(&self) -> Result<Vec<u32>> {
        let n = self.vertices.len() + 3 * self.len();
        let mut out: Vec<u32> = try_with_capacity(n, "the joined strip")?;
        for k in 0..self.len() {
            let s = self.strip(k);
            if let Some(&last) = out.last() {
                out.extend([last, s[0]]);
                if out.len() % 2 == 1 {
                    out.push(s[0]);
                }
            }
            out.extend_from_slice(s);
        }
        Ok(out)
    }
}

impl Che {
    /// Triangle strips covering every triangle once, orientation kept; see [`Strips`].
    pub fn triangle_strips(&self) -> Result<Strips> {
        self.check_collected("the triangle strips")?;
        let o = self.try_opposites_or_computed()?;
        let nt = self.num_triangles();
        let mut free = filled(nt, 0u8, "strip degrees")?;
        for (h, &g) in o.iter().enumerate() {
            free[h / 3] += u8::from(g != NONE);
        }
        let mut walk = Walk {
            o: &o,
            v: &self.v,
            free,
            strip: Vec::new(),
        };
        let mut out = Strips {
            vertices: try_with_capacity(nt + 2, "the strip vertices")?,
            offsets: try_with_capacity(2, "the strip offsets")?,
        };
        out.offsets.push(0);
        // Buckets of triangles by unvisited neighbours: an entry is stale when the count
        // dropped since; the lowest bucket with a live unvisited triangle starts a strip.
        let mut buckets: [Vec<u32>; 4] = Default::default();
        for t in (0..nt as u32).rev() {
            try_push(&mut buckets[walk.free[t as usize] as usize], t, BUCKETS)?;
        }
        while let Some(t) = pop_lowest(&mut buckets, &walk.free) {
            walk.strip_from(t, &mut buckets)?;
            try_extend(
                &mut out.vertices,
                walk.strip.iter().copied(),
                "the strip vertices",
            )?;
            try_push(&mut out.offsets, out.vertices.len(), "the strip offsets")?;
        }
        Ok(out)
    }
}

const VISITED: u8 = u8::MAX;

/// What the triangle buckets' growth is called when it fails.
const BUCKETS: &str = "the strip buckets";
/// What a strip's growth is called when it fails.
const STRIP: &str = "a strip";

fn pop_lowest(buckets: &mut [Vec<u32>; 4], free: &[u8]) -> Option<u32> {
    for (d, bucket) in buckets.iter_mut().enumerate() {
        while let Some(t) = bucket.pop() {
            if free[t as usize] as usize == d {
                return Some(t);
            }
        }
    }
    None
}

struct Walk<'a> {
    o: &'a [u32],
    v: &'a [u32],
    /// Unvisited neighbours of each triangle, `VISITED` once in a strip.
    free: Vec<u8>,
    strip: Vec<u32>,
}

impl Walk<'_> {
    fn visit(&mut self, t: u32, buckets: &mut [Vec<u32>; 4]) -> Result<()> {
        self.free[t as usize] = VISITED;
        self.release_neighbours(t, buckets)
    }

    /// One unvisited neighbour fewer for each unvisited neighbour of `t`.
    fn release_neighbours(&mut self, t: u32, buckets: &mut [Vec<u32>; 4]) -> Result<()> {
        for h in first(t)..first(t) + 3 {
            let g = self.o[h as usize];
            if g != NONE && self.free[tri(g) as usize] != VISITED {
                let d = &mut self.free[tri(g) as usize];
                *d -= 1;
                try_push(&mut buckets[*d as usize], tri(g), BUCKETS)?;
            }
        }
        Ok(())
    }

    /// The unvisited triangle across `h`, if any.
    fn across(&self, h: u32) -> Option<u32> {
        let g = self.o[h as usize];
        (g != NONE && self.free[tri(g) as usize] != VISITED).then_some(g)
    }

    /// The half-edge of triangle `t` between `a` and `b` (either way).
    fn between(&self, t: u32, a: u32, b: u32) -> u32 {
        (first(t)..first(t) + 3)
            .find(|&h| {
                let (x, y) = (self.v[h as usize], self.v[next(h) as usize]);
                (x == a && y == b) || (x == b && y == a)
            })
            .expect("consecutive strip vertices are an edge of the strip's triangle")
    }

    fn strip_from(&mut self, t: u32, buckets: &mut [Vec<u32>; 4]) -> Result<()> {
        // Leave through the edge whose neighbour has the fewest unvisited neighbours.
        let exit = (first(t)..first(t) + 3)
            .min_by_key(|&h| {
                self.across(h)
                    .map_or(u8::MAX, |g| self.free[tri(g) as usize])
            })
            .expect("three half-edges");
        let h = prev(exit);
        self.strip.clear();
        self.strip
            .extend([h, next(h), prev(h)].map(|x| self.v[x as usize]));
        self.visit(t, buckets)?;
        let mut last = t;
        while let Some(g) = self.across(self.between(last, self.end(2), self.end(1))) {
            try_push(&mut self.strip, self.v[prev(g) as usize], STRIP)?;
            last = tri(g);
            self.visit(last, buckets)?;
        }
        self.extend_back(t, buckets)
    }

    fn end(&self, k: usize) -> u32 {
        self.strip[self.strip.len() - k]
    }

    /// Prepends triangles across the strip's first edge, an even number of them: they
    /// are only marked while the walk goes on, and the last one is given back when odd.
    fn extend_back(&mut self, t: u32, buckets: &mut [Vec<u32>; 4]) -> Result<()> {
        let (mut front, mut f0, mut f1) = (t, self.strip[0], self.strip[1]);
        let mut back: Vec<(u32, u32)> = Vec::new();
        while let Some(g) = self.across(self.between(front, f0, f1)) {
            let r = self.v[prev(g) as usize];
            front = tri(g);
            self.free[front as usize] = VISITED;
            try_push(&mut back, (front, r), STRIP)?;
            (f0, f1) = (r, f0);
        }
        let dropped = (back.len() % 2 == 1).then(|| back.pop().expect("odd, so not empty").0);
        for &(f, _) in &back {
            self.release_neighbours(f, buckets)?;
        }
        // Counted after the kept ones are released, which skipped it while it was marked.
        if let Some(d) = dropped {
            let free = (first(d)..first(d) + 3)
                .filter(|&h| self.across(h).is_some())
                .count() as u8;
            self.free[d as usize] = free;
            try_push(&mut buckets[free as usize], d, BUCKETS)?;
        }
        let tail = std::mem::take(&mut self.strip);
        try_reserve(&mut self.strip, back.len() + tail.len(), STRIP)?;
        self.strip.extend(back.iter().rev().map(|&(_, r)| r));
        self.strip.extend(tail);
        Ok(())
    }
}
