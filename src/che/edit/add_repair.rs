//! [`Che::add_triangle`] on a CHE built non-strict: what the strict form refuses is
//! repaired by the build's rules, so that the CHE stays the one a fresh non-strict build of
//! its live triangles gives, and the build report counts the repair:
//! - matching: a vertex pair with exactly two half-edges pairs them; with three or more,
//!   all stay unpaired and are flagged non-manifold;
//! - orientation: a triangle whose paired edges run the same way as their neighbours' is
//!   flipped, keeping the orientation most of them agree with; a pair that still disagrees
//!   is a seam (unpaired, flagged);
//! - vertex split: a vertex whose triangles form several fans keeps the fan of its smallest
//!   half-edge, each other fan moves to a new copy of it;
//! - duplicate triangles are kept (and listed).
//!
//! Everything is local: the stars of the three corners. On a valid CHE the edges of the
//! new triangle never disagree about its orientation: two of its edges meet at a corner
//! whose one fan holds both neighbours, consistently oriented, as that fan's two ends. So
//! the build's flip of the smaller of two components oriented against each other, and
//! its seams, which depend on the order its traversal meets the triangles, are never
//! needed; the seam rule below only keeps a CHE whose invariants were broken valid.

use super::arrays::{non_manifold_mut, seams_mut, set_o, set_v};
use crate::NONE;
use crate::che::Che;
use crate::che::build::walk_fan;
use crate::che::ids::{first, next, prev};
use crate::error::Result;
use crate::util::alloc::try_reserve;
use crate::util::push_example;

/// What one edge of the new triangle meets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Meets {
    /// No triangle: a boundary edge.
    Nothing,
    /// One triangle, through its half-edge `g` on the edge: paired with it, or a seam when
    /// they run the same way after the orientation is chosen.
    One(u32),
    /// Two half-edges (paired, a seam, or left unpaired): with the new one, three.
    Two(u32, u32),
    /// Three or more, already non-manifold.
    Many,
}

/// The orientation chosen for the new triangle: flipped or not, and per edge whether it
/// is left a seam.
struct Orientation {
    flip: bool,
    seam: [bool; 3],
}

impl Che {
    /// [`Che::add_triangle`] on a non-strict CHE, after the checks every CHE makes.
    pub(super) fn add_repaired(&mut self, corners: [u32; 3]) -> Result<u32> {
        let [a, b, c] = corners;
        let duplicate = self.triangle_on(a, b, c);
        let meets = [0, 1, 2].map(|i| self.meets(corners[i], corners[(i + 1) % 3]));
        let orientation = self.orientation(corners, &meets);
        let outs = [self.outgoing(a)?, self.outgoing(b)?, self.outgoing(c)?];
        // Each corner's fan may break at its two edges, and the new triangle may be a
        // fan of its own: at most three copies a corner. A non-manifold edge adds an id.
        self.make_room(1, 9, 6)?;
        try_reserve(non_manifold_mut(self), 9, "the non-manifold half-edges")?;
        try_reserve(seams_mut(self), 6, "the seam half-edges")?;
        for (i, m) in meets.iter().enumerate() {
            if let Meets::Two(h, g) = *m {
                self.make_non_manifold(h, g, corners[i], corners[(i + 1) % 3]);
            }
        }
        let t = self.push_triangle(if orientation.flip { [a, c, b] } else { corners }, NONE);
        let mut third = [NONE; 3];
        for (i, &m) in meets.iter().enumerate() {
            // Flipping swaps corners 1 and 2: edge `i` is then half-edge `2 - i`, reversed.
            let h = first(t) + if orientation.flip { 2 - i } else { i } as u32;
            self.attach(h, m, orientation.seam[i]);
            third[i] = h;
        }
        for (x, outs) in corners.into_iter().zip(outs) {
            let own = (first(t)..first(t) + 3).find(|&h| self.v[h as usize] == x);
            let copies = self.split_fans(x, &outs, own.expect("a corner of the triangle"));
            if copies > 0 {
                let r = &mut self.report;
                r.split_vertices += 1;
                r.added_vertices += copies;
                push_example(&mut r.split_vertex_examples, self.vertex_origin.get(x));
            }
        }
        for (i, &m) in meets.iter().enumerate() {
            if let Meets::Two(h, g) = m {
                self.rematch([h, g, third[i]]);
            }
        }
        self.report_repairs(&orientation, &meets, duplicate);
        Ok(t)
    }

    /// The live half-edges on the vertex pair `{x, y}`, either way, classified.
    fn meets(&self, x: u32, y: u32) -> Meets {
        // Every live vertex has one fan, so its rotation reaches all its triangles, each
        // with one outgoing half-edge of `x`.
        let (mut found, mut n) = ([NONE; 3], 0);
        self.any_outgoing(x, |h| {
            let g = match (self.v[next(h) as usize] == y, self.v[prev(h) as usize] == y) {
                (true, _) => h,
                (false, true) => prev(h),
                (false, false) => return false,
            };
            found[n] = g;
            n += 1;
            n == 3
        });
        match n {
            0 => Meets::Nothing,
            1 => Meets::One(found[0]),
            2 => Meets::Two(found[0], found[1]),
            _ => Meets::Many,
        }
    }

    /// The build's orientation rule for the new triangle: each edge that meets one
    /// triangle wants the new one flipped when its half-edge there runs the same way
    /// (`x -> y`). They all agree on a valid CHE (see the module comment); otherwise the
    /// orientation most of them want is kept (a tie goes to the neighbour of the smallest
    /// id, where the build's traversal starts) and the others are left seams.
    fn orientation(&self, corners: [u32; 3], meets: &[Meets; 3]) -> Orientation {
        let mut wants = [None; 3];
        for (i, m) in meets.iter().enumerate() {
            if let Meets::One(g) = *m {
                wants[i] = Some((self.v[g as usize] == corners[i], g));
            }
        }
        let flips = wants.iter().flatten().filter(|w| w.0).count();
        let keeps = wants.iter().flatten().filter(|w| !w.0).count();
        let flip = match flips.cmp(&keeps) {
            std::cmp::Ordering::Greater => true,
            std::cmp::Ordering::Less => false,
            std::cmp::Ordering::Equal => wants
                .iter()
                .flatten()
                .min_by_key(|w| w.1)
                .is_some_and(|w| w.0),
        };
        Orientation {
            flip,
            seam: wants.map(|w| w.is_some_and(|(f, _)| f != flip)),
        }
    }

    /// Edge `x`-`y`, whose half-edges are `h` and `g`, gets a third triangle: both are
    /// unpaired (the edge splits into two ids, the canonical half-edge keeping the old
    /// one) and flagged non-manifold.
    fn make_non_manifold(&mut self, h: u32, g: u32, x: u32, y: u32) {
        let was_non_manifold = self.non_manifold.binary_search(&h).is_ok();
        if self.o[h as usize] == g {
            let e = self.edge_id(h);
            for k in [h, g] {
                set_o(self, k, NONE);
                self.note_unpaired(k);
            }
            self.name_edge(h.min(g), e);
            self.name_edge(h.max(g), NONE);
        }
        for k in [h, g] {
            self.unflag(k);
            insert_sorted(non_manifold_mut(self), k);
        }
        if !was_non_manifold {
            let pair = [self.vertex_origin.get(x), self.vertex_origin.get(y)];
            self.report.non_manifold_edges += 1;
            push_example(&mut self.report.non_manifold_edge_examples, pair);
        }
    }

    /// Pairs or flags the new half-edge `h` by what its edge meets.
    fn attach(&mut self, h: u32, meets: Meets, seam: bool) {
        match meets {
            Meets::One(g) if !seam => {
                // A flag left on a lone half-edge is stale: the build pairs the two.
                self.unflag(g);
                self.link(h, g);
                self.name_edge(h, self.edge_id(g));
            }
            Meets::One(g) => {
                self.unflag(g);
                insert_sorted(seams_mut(self), g);
                insert_sorted(seams_mut(self), h);
                self.name_edge(h, NONE);
            }
            Meets::Nothing => self.name_edge(h, NONE),
            Meets::Two(..) | Meets::Many => {
                insert_sorted(non_manifold_mut(self), h);
                self.name_edge(h, NONE);
            }
        }
    }

    /// Splits `x` as the build splits a vertex: its outgoing half-edges (`outs`, from
    /// before the edit, and `own`, the new triangle's) fall into fans; the fan of the
    /// smallest half-edge keeps `x`, each other moves to a new copy of `x`. Returns the
    /// number of copies (room made first).
    fn split_fans(&mut self, x: u32, outs: &[u32], own: u32) -> usize {
        let mut hs: Vec<u32> = outs.to_vec();
        hs.push(own);
        hs.sort_unstable();
        let mut seen: Vec<u32> = Vec::new();
        let mut fans: Vec<Vec<u32>> = Vec::new();
        for &h in &hs {
            if seen.binary_search(&h).is_ok() {
                continue;
            }
            let mut fan = Vec::new();
            walk_fan(&self.o, h, &mut |g| fan.push(g));
            seen.extend_from_slice(&fan);
            seen.sort_unstable();
            fans.push(fan);
        }
        for fan in &fans[1..] {
            let copy = self.push_vertex(self.position_of(x), self.vertex_origin.get(x));
            for &h in fan {
                set_v(self, h, copy);
            }
            self.fix_vh(copy, fan[0]);
        }
        self.fix_vh(x, fans[0][0]);
        fans.len() - 1
    }

    /// After the split, the three half-edges of a non-manifold edge lie on other vertex
    /// pairs (a vertex on three unpaired half-edges of one pair has three fan ends, so
    /// at least two fans): matched again as a rebuild of the result matches them, so that
    /// the CHE is the one a fresh build of its triangles gives. Two that share a pair,
    /// running opposite ways, with the third elsewhere, are paired again (the ends of one
    /// fan at each vertex: the fan closes); a flag on a half-edge left alone on its pair
    /// goes. Anything else keeps the flags.
    fn rematch(&mut self, hs: [u32; 3]) {
        let pair = |h: u32| {
            let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
            (a.min(b), a.max(b))
        };
        let p = hs.map(pair);
        let apart = |i: usize| (0..3).all(|j| j == i || p[j] != p[i]);
        if (0..3).all(apart) {
            hs.iter().for_each(|&h| self.unflag(h));
            return;
        }
        let Some(i) = (0..3).find(|&i| apart(i)) else {
            return;
        };
        let (lo, hi) = {
            let (h, g) = (hs[(i + 1) % 3], hs[(i + 2) % 3]);
            (h.min(g), h.max(g))
        };
        if self.v[lo as usize] == self.v[hi as usize] {
            return;
        }
        hs.iter().for_each(|&h| self.unflag(h));
        let (e_lo, e_hi) = (self.edge_id(lo), self.edge_id(hi));
        self.link(lo, hi);
        self.drop_edge(e_hi);
        self.name_edge(lo, e_lo);
        self.fix_vh(self.v[lo as usize], lo);
        self.fix_vh(self.v[hi as usize], hi);
    }

    /// The report's counts of a flipped triangle, new seams and a kept duplicate (the
    /// new triangle has no input id: `NONE` in the examples).
    fn report_repairs(
        &mut self, orientation: &Orientation, meets: &[Meets; 3], duplicate: Option<u32>,
    ) {
        let t = (self.num_triangles() - 1) as u32;
        let across = meets
            .iter()
            .zip(orientation.seam)
            .find_map(|(m, seam)| match m {
                Meets::One(g) if seam => Some(crate::che::ids::tri(*g)),
                _ => None,
            });
        let r = &mut self.report;
        if orientation.flip {
            r.flipped_triangles += 1;
        }
        if let Some(s) = across {
            r.seam_edges += orientation.seam.iter().filter(|&&s| s).count();
            r.non_orientable_components += 1;
            push_example(&mut r.non_orientable_examples, self.triangle_origin.get(s));
        }
        if let Some(s) = duplicate {
            r.duplicate_triangles += 1;
            let pair = [self.triangle_origin.get(s), self.triangle_origin.get(t)];
            push_example(&mut r.duplicate_examples, pair);
        }
    }
}

/// Inserts `h` into the sorted `list` (room reserved first), once.
fn insert_sorted(list: &mut Vec<u32>, h: u32) {
    if let Err(i) = list.binary_search(&h) {
        list.insert(i, h);
    }
}
