//! Any star (the common one goes through `small.rs` first): large stars, non-manifold
//! faces, faces running the same way, flagged half-faces, pinched links (walked).

use super::{
    CYCLE, FaceCensus, Link, OTHER_CORNERS, Record, SMALLEST, Sums, face_others, flush_events,
    hf_of, slot_of_corner,
};
use crate::NONE;
use crate::chf::build::report::push_example;
use crate::chf::edges::MultiFan;
use crate::error::Result;
use crate::util::alloc::{
    try_collect, try_extend, try_push, try_reserve, try_resize, try_vec, try_with_capacity,
};

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

impl Link {
    /// [`Link::star`] after [`Link::local_ids`], for any star.
    pub(super) fn general_star(&mut self, star: &[Record], sums: &mut Sums) -> Result<()> {
        let k = star.len();
        let x = star[0][1];
        let m = self.verts.len();
        self.dirs.clear();
        let dirs = star.iter().map(|r| {
            let order = (r[2] < r[3]) as usize
                | ((r[2] < r[4]) as usize) << 1
                | ((r[3] < r[4]) as usize) << 2;
            DIRS[(r[0] & 3) as usize][order]
        });
        try_extend(&mut self.dirs, dirs, "a star's face directions")?;
        let cells = self.cells(star)?;
        let (first_open, unpaired) = self.match_faces(star, x, sums)?;
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
        if !self.one_piece(k)? {
            sums.split_at(x);
            return Ok(());
        }
        // `VH`: the first unpaired half-face, else the first half-face.
        let c = if first_open == NONE { 0 } else { first_open };
        if sums.tables {
            sums.vh[x as usize - sums.vh_base] = hf_of(&star[(c / 3) as usize], (c % 3) as usize);
        }

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
                    if sums.tables {
                        try_push(sums.edge_slots, slot_of_corner(star, c), "the edge slots")?;
                    }
                    sums.num_edges += 1;
                    sums.input_edges += 1;
                }
            }
            Ok(())
        } else {
            self.edges_by_walking(star, x, sums)
        }
    }

    /// The link edge (face) opposite every corner as a cell: a pair of local ids in a
    /// square table, or on a very large link the rank of the pair among the link's pairs.
    /// Counts the arrivals in each cell and keeps the first two corners, branch-free.
    fn cells(&mut self, star: &[Record]) -> Result<usize> {
        const WHAT: &str = "a star's link edges";
        let k = star.len();
        let m = self.verts.len();
        // As small as it can be, so that the table stays in the L1 cache.
        let side = m.next_power_of_two() as u32;
        self.cells.clear();
        let n_cells = if side <= 256 && 3 * k < u16::MAX as usize {
            let cell = |a: u32, b: u32| a.min(b) * side + a.max(b);
            let cells = self
                .ids
                .iter()
                .map(|&[a, b, c]| [cell(b, c), cell(a, c), cell(a, b)]);
            try_extend(&mut self.cells, cells, WHAT)?;
            (side * side) as usize
        } else {
            // Rare: too many vertices for a table; sort the pairs.
            let mut keyed: Vec<(u32, u32, u32)> = try_with_capacity(3 * k, WHAT)?;
            for (p, ids) in self.ids.iter().enumerate() {
                for (s, [s1, s2]) in OTHER_CORNERS.iter().enumerate() {
                    let (a, b) = (ids[*s1], ids[*s2]);
                    keyed.push((a.min(b), a.max(b), (3 * p + s) as u32));
                }
            }
            keyed.sort_unstable();
            try_resize(&mut self.cells, k, [0; 3], WHAT)?;
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
            // The old tables go first, so that the peak holds one pair.
            (self.count, self.arrivals) = (Vec::new(), Vec::new());
            self.count = try_vec(n_cells.max(12 * k), 0, WHAT)?;
            self.arrivals = try_vec(2 * n_cells.max(12 * k), 0, WHAT)?;
        }
        for (p, cells) in self.cells.iter().enumerate() {
            for (s, &e) in cells.iter().enumerate() {
                let e = e as usize;
                let seen = self.count[e];
                self.count[e] = seen.saturating_add(1);
                self.arrivals[2 * e + seen.min(1) as usize] = (3 * p + s) as u32;
            }
        }
        Ok(n_cells)
    }

    /// Mates across matched link edges; records the faces whose smallest vertex is `x`;
    /// aggregates the smallest corner and end corner of every local id. Returns the first
    /// unpaired corner (`NONE` if none) and the number of unpaired corners.
    fn match_faces(&mut self, star: &[Record], x: u32, sums: &mut Sums) -> Result<(u32, usize)> {
        const WHAT: &str = "a star's face mates";
        let k = star.len();
        let m = self.verts.len();
        self.mates.clear();
        try_resize(&mut self.mates, k, [NONE; 3], WHAT)?;
        self.near.clear();
        try_resize(&mut self.near, k, 0, WHAT)?;
        self.best.clear();
        try_resize(&mut self.best, m, NONE, WHAT)?;
        self.best_end.clear();
        try_resize(&mut self.best_end, m, NONE, WHAT)?;
        let check_flags = !sums.flagged.is_empty();
        let census = sums.faces.is_some();
        let (mut first_open, mut unpaired) = (NONE, 0usize);
        for p in 0..k {
            let r = &star[p];
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
                    )?;
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
        Ok((first_open, unpaired))
    }

    /// Counts the face of corner `c` (its smallest vertex is `x`) and pairs it.
    #[allow(clippy::too_many_arguments)]
    fn face(
        events: &mut Vec<([u32; 2], [u32; 2])>, star: &[Record], c: u32, count: u32, other: u32,
        mated: bool, same_direction: bool, sums: &mut Sums,
    ) -> Result<()> {
        let (p, s) = ((c / 3) as usize, (c % 3) as usize);
        let r = &star[p];
        let [s1, s2] = OTHER_CORNERS[s];
        let (y, z) = (r[2 + s1], r[2 + s2]);
        let (collect, partners) = (sums.collect, sums.partners);
        let (census, opposites) = sums.faces.as_mut().expect("checked");
        census.input_faces += 1;
        match count {
            1 => {
                census.boundary_faces += 1;
                Ok(())
            }
            2 => {
                let h = hf_of(r, s);
                let (q, t) = ((other / 3) as usize, (other % 3) as usize);
                let g = hf_of(&star[q], t);
                if collect && (mated || partners) {
                    opposites.pair(h, g);
                }
                census.same_direction |= same_direction;
                // Duplicate tetrahedra: the same fourth vertex, above the face.
                let (d, d2) = (r[2 + s], star[q][2 + t]);
                if d == d2 && d > y.max(z) {
                    census.duplicates += 1;
                    let event = ([y.min(z), y.max(z)], [h.min(g) >> 2, h.max(g) >> 2]);
                    try_push(events, event, "a star's duplicate faces")?;
                }
                Ok(())
            }
            _ => Self::non_manifold_face(events, star, c as usize, census),
        }
    }

    /// A face of three or more tetrahedra: all its half-faces, and the duplicate pairs among
    /// them (the same fourth vertex, above the face), as the build counts them.
    fn non_manifold_face(
        events: &mut Vec<([u32; 2], [u32; 2])>, star: &[Record], c: usize, census: &mut FaceCensus,
    ) -> Result<()> {
        const WHAT: &str = "the non-manifold half-faces";
        let (y, z) = face_others(&star[c / 3], c % 3);
        let key = |d: usize| {
            let (a, b) = face_others(&star[d / 3], d % 3);
            (a.min(b), a.max(b))
        };
        let this = key(c);
        // (fourth vertex, half-face) of every half-face on the triple.
        let group = (0..3 * star.len())
            .filter(|&d| key(d) == this)
            .map(|d| (star[d / 3][2 + d % 3], hf_of(&star[d / 3], d % 3)));
        let mut group: Vec<(u32, u32)> = try_collect(group, WHAT)?;
        group.sort_unstable_by_key(|&(_, h)| h);
        census.non_manifold_faces += 1;
        try_extend(
            &mut census.non_manifold,
            group.iter().map(|&(_, h)| h),
            WHAT,
        )?;
        // Examples in triple order: queued with the duplicates, sorted per vertex.
        try_push(events, ([this.0, this.1], [NONE, NONE]), WHAT)?;
        let max = y.max(z);
        group.retain(|&(d, _)| d > max);
        group.sort_unstable();
        for run in group.chunk_by(|a, b| a.0 == b.0) {
            for (i, &(_, a)) in run.iter().enumerate() {
                for &(_, b) in &run[i + 1..] {
                    census.duplicates += 1;
                    try_push(events, ([this.0, this.1], [a >> 2, b >> 2]), WHAT)?;
                }
            }
        }
        Ok(())
    }

    /// Is the star connected through its matched faces?
    fn one_piece(&mut self, k: usize) -> Result<bool> {
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
            return Ok(reached == all);
        }
        self.seen.clear();
        try_resize(&mut self.seen, k, false, "a star's walk")?;
        self.queue.clear();
        // Each tetrahedron enters the queue once: no growth past this.
        try_reserve(&mut self.queue, k, "a star's walk")?;
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
        Ok(self.queue.len() == k)
    }

    /// A pinched link: walks every fan `(x, y)` with `y > x`, each once.
    pub(super) fn edges_by_walking(
        &mut self, star: &[Record], x: u32, sums: &mut Sums,
    ) -> Result<()> {
        const WHAT: &str = "a star's fans";
        let n = 3 * star.len();
        self.walked.clear();
        try_resize(&mut self.walked, n, false, WHAT)?;
        self.fans.clear();
        for c0 in 0..n {
            let y = star[c0 / 3][2 + c0 % 3];
            if y < x || self.walked[c0] {
                continue;
            }
            let c = self.fan(c0);
            try_push(&mut self.fans, (y, slot_of_corner(star, c)), WHAT)?;
        }
        self.fans.sort_unstable();
        for run in self.fans.chunk_by(|a, b| a.0 == b.0) {
            if sums.tables {
                try_extend(
                    sums.edge_slots,
                    run.iter().map(|&(_, s)| s),
                    "the edge slots",
                )?;
            }
            sums.num_edges += run.len();
            sums.input_edges += 1;
            if run.len() > 1 {
                let y = run[0].0;
                sums.non_manifold_edges += 1;
                push_example(&mut sums.non_manifold_edge_examples, [x, y]);
                let fan = MultiFan {
                    a: x,
                    b: y,
                    first_slot: run[0].1,
                };
                try_push(&mut sums.multi_fan, fan, "the multi-fan edges")?;
            }
        }
        Ok(())
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
