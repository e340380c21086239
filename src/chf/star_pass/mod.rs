//! One pass over the star of every vertex, from `V` alone: the faces and their pairs (`O`
//! and the face counts of the build report), whether every star is one piece (else the
//! vertex split must run), `VH`, the canonical slot of every fan (edge ids) and the edge
//! census. `link/` does the work on one star.
//!
//! Why one bucketed pass and no walks: on a large mesh the neighbours of a tetrahedron are
//! far away in memory, so every step of a walk through `O` misses the cache (and a random
//! write misses it too). One sequential scan of `V` writes a record per occurrence
//! (tetrahedron, vertex) to its vertex's bucket with a two-pass radix: the first pass
//! streams records to at most 256 coarse buckets (few enough write streams for the cache
//! and the TLB), the second sorts one coarse bucket at a time, in cache, by the low bits of
//! the vertex. The records of a vertex are then in tetrahedron order, hence half-face
//! order. Large meshes run in rounds over ranges of coarse buckets (each round rescans
//! `V`) so that the records never take more than 16 bytes per tetrahedron.
//! The pairs found and the canonical slots are written in place the same way, through
//! windows (`pairs.rs`, [`bits_from_slots`]).

pub(crate) mod link;
pub(crate) mod pairs;

use self::link::{FaceCensus, Link, Record, Sums};
use self::pairs::{Opposites, Writer};
use crate::NONE;
use crate::chf::edges::EdgeCensus;
use crate::chf::edges::MultiFan;
use crate::error::Result;
use crate::util::alloc::{
    try_collect, try_extend, try_push, try_resize, try_to_vec, try_vec, try_with_capacity,
};
use crate::util::extend_examples;
use crate::util::rank::RankBits;

/// 256 coarse buckets: the scatter's 256 write heads (a cache line each) stay in the L1
/// cache (512 heads do not; 128 gain nothing).
const COARSE_BITS: u32 = 8;

/// What the pass found.
#[derive(Debug)]
pub(crate) struct Stars {
    /// Some star is in several pieces: the vertex split must run (then the pass again),
    /// and `VH`, the edges and the census are incomplete.
    pub split_needed: bool,
    /// With `split_needed`, the first such vertex.
    pub first_split: u32,
    /// The number of edges (fans).
    pub num_edges: usize,
    /// With `tables`: `VH` and the canonical edge slots (else empty).
    pub vh: Vec<u32>,
    pub edge_bits: RankBits,
    /// The fans grouped by vertex pair (the ids of `V`).
    pub census: EdgeCensus,
    /// With pairs asked for: the face counts and the pairs, as a table like `O` (empty
    /// for the counts only).
    pub faces: Option<(FaceCensus, Vec<u32>)>,
}

/// Which pairs of half-faces to collect, with the face counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pairs {
    No,
    /// The face counts only.
    Census,
    /// Every triple of exactly two half-faces, whatever their direction (the build's
    /// partners, on the input's `V`).
    Partners,
    /// The twins by the rule of `O` (running opposite ways, not flagged).
    Opposites,
}

/// How many threads the pass over `n_tets` tetrahedra on `n_vertices` vertices takes when
/// `threads` are asked for. Each thread past the first brings a `Link` with a stamp per
/// vertex (4 bytes, 8 on the largest meshes): at most T / 2V threads keep those stamps to
/// about 2 bytes per tetrahedron in all, so that many cores do not lift the build's peak
/// (two threads are always allowed).
pub(crate) fn threads_for(n_tets: usize, n_vertices: usize, threads: usize) -> usize {
    threads.clamp(1, (n_tets / (2 * n_vertices.max(1))).max(2))
}

/// What the pass collects besides the stars themselves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct StarPass {
    /// Which pairs of half-faces to collect, with the face counts.
    pub pairs: Pairs,
    /// Also `VH` and the edge bits (level 2); without, the build keeps less memory at
    /// levels 0 and 1.
    pub tables: bool,
    /// Threads to share each round among (see [`threads_for`]).
    pub threads: usize,
}

/// The pass over `V` (see [`StarPass`]). `flagged` (sorted) are half-faces never to pair:
/// the build's non-manifold faces and seams once `V` is split or oriented. The stars of
/// each round are shared among up to `options.threads` threads (contiguous ranges of
/// vertices), and what they find is added up in vertex order: the answer does not depend
/// on the number of threads.
pub(crate) fn stars(
    v: &[u32], n_vertices: usize, flagged: &[u32], options: StarPass,
) -> Result<Stars> {
    stars_within(v, n_vertices, flagged, options, usize::MAX)
}

/// [`stars`] with the records buffer held to about `max_records` records (five `u32`
/// each; more rounds over `V` when it is smaller than a build's share): the streaming
/// build's census, whose `V` lies in a file larger than memory.
pub(crate) fn stars_within(
    v: &[u32], n_vertices: usize, flagged: &[u32], options: StarPass, max_records: usize,
) -> Result<Stars> {
    let StarPass {
        pairs,
        tables,
        threads,
    } = options;
    let faces = pairs != Pairs::No;
    let collect = matches!(pairs, Pairs::Partners | Pairs::Opposites);
    let plan = Plan::new(v, n_vertices, threads, tables, max_records)?;
    let opposites = Opposites::new(if collect { v.len() } else { 0 })?;
    let mut vh = if tables {
        crate::util::pages::filled(n_vertices, NONE, "the vertex half-faces VH")?
    } else {
        Vec::new()
    };
    let mut workers = workers(v.len(), n_vertices, plan.threads, &opposites, tables)?;
    let mode = &Mode {
        flagged,
        faces,
        collect,
        partners: pairs == Pairs::Partners,
        tables,
        shift: plan.shift,
    };
    // With pairs, `O` takes the records' buffer over afterwards: at least its size.
    let mut records = plan.records(if collect { v.len() } else { 0 })?;
    let mut total = Tally::default();
    for &round in &plan.rounds {
        let vh = if tables { &mut vh[..] } else { &mut [] };
        plan.round(round, &mut records, &mut workers, vh, mode, &mut total)?;
    }
    let mut edge_slots = Vec::with_capacity(workers.len());
    for w in workers {
        w.pairs.flush();
        edge_slots.push(w.edge_slots);
    }
    // The pairs' memory then serves the edge bits.
    let (o, scratch) = if collect {
        opposites.finish(records)?
    } else {
        (Vec::new(), Vec::new())
    };
    let edge_bits = if tables {
        bits_from_slots(&edge_slots, 6 * (v.len() / 4), scratch)?
    } else {
        RankBits::default()
    };
    Ok(total.into_stars(vh, edge_bits, faces.then_some(o)))
}

/// A thread's scratch per part of the tetrahedra.
fn workers<'o>(
    len: usize, n_vertices: usize, threads: usize, opposites: &'o Opposites, tables: bool,
) -> Result<Vec<Worker<'o>>> {
    // About one edge per vertex and per tetrahedron, plus one per boundary face pair
    // (Euler): reserved at once, so that growing by doubling copies nothing at the peak
    // (with a margin per thread, whose share of the edges is not known in advance).
    let edge_estimate = n_vertices + len / 4 + len / 16;
    let share = if threads == 1 {
        edge_estimate
    } else {
        edge_estimate / threads + edge_estimate / 8
    };
    (0..threads)
        .map(|_| {
            Worker::new(
                n_vertices,
                opposites.writer()?,
                if tables { share } else { 0 },
            )
        })
        .collect()
}

/// How the pass cuts its work: the parts of `V` that threads scatter, the coarse buckets,
/// the rounds over ranges of them and each part's region of the records buffer.
struct Plan<'v> {
    /// Threads asked for, at most one per coarse bucket: one worker each.
    threads: usize,
    /// The coarse bucket of vertex `x` is `x >> shift`.
    shift: u32,
    n_vertices: usize,
    /// Contiguous parts of `V`, `part_len` ids each (the last one shorter).
    parts: Vec<&'v [u32]>,
    part_len: usize,
    /// Occurrences per part and coarse bucket, and per coarse bucket in all.
    part_counts: Vec<Vec<u32>>,
    count: Vec<u32>,
    /// Ranges of coarse buckets, one per round.
    rounds: Vec<(usize, usize)>,
    /// Each part's region of the records buffer: its length and where it starts.
    sizes: Vec<usize>,
    regions: Vec<usize>,
}

impl<'v> Plan<'v> {
    fn new(
        v: &'v [u32], n_vertices: usize, threads: usize, tables: bool, max_records: usize,
    ) -> Result<Self> {
        const WHAT: &str = "the star pass's plan";
        let bits = usize::BITS - n_vertices.saturating_sub(1).leading_zeros();
        // At most 2^16 vertices per coarse bucket, so that the second pass's counts stay
        // small (past 2^24 vertices there are more than 256 coarse buckets).
        let shift = bits.saturating_sub(COARSE_BITS).min(16);
        let n_coarse = (n_vertices.saturating_sub(1) >> shift) + 1;
        let threads = threads.clamp(1, n_coarse);
        // Each thread scatters the occurrences of a part of the tetrahedra (contiguous, so
        // that the parts one after the other keep the tetrahedron order) to records of its
        // own.
        let part_len = (v.len() / 4).div_ceil(threads) * 4;
        let mut parts: Vec<&[u32]> = v.chunks(part_len.max(4)).collect();
        if parts.is_empty() {
            parts.push(v);
        }
        let part_counts = crate::util::par::run_all(parts.clone(), |part| {
            let mut count = try_vec(n_coarse, 0u32, WHAT)?;
            for &x in part {
                count[(x >> shift) as usize] += 1;
            }
            Ok(count)
        });
        let part_counts: Vec<Vec<u32>> = part_counts.into_iter().collect::<Result<_>>()?;
        let count = (0..n_coarse).map(|c| part_counts.iter().map(|p| p[c]).sum());
        let count: Vec<u32> = try_collect(count, WHAT)?;
        // Rounds of coarse buckets, so that the records stay under 16 bytes per tetrahedron
        // (all of them would take 80): as many `u32` as `O` has entries, so that `O` can
        // then take over the buffer (fresh memory costs a page fault per 4 KB).
        // With the level-2 tables the final structure is larger, so the records may take
        // 20 bytes per tetrahedron at the same peak ratio: four rounds instead of five, each
        // a pass over `V` (three rounds would take 27 bytes and lift the level-2 peak to
        // about twice the final size).
        let budget = (v.len() / if tables { 4 } else { 5 })
            .min(max_records)
            .max(1 << 16);
        // Each part's records of a round fit in its share of the budget, so that the
        // regions of all parts (each as large as its part's largest round) add up to the
        // budget.
        let rounds = rounds(&part_counts, budget.div_ceil(parts.len()))?;
        let sizes = region_sizes(&part_counts, &rounds);
        // Never cleared: every record a round reads, it wrote. Where each region starts:
        let regions: Vec<usize> = sizes
            .iter()
            .scan(0, |at, &n| {
                *at += n;
                Some(*at - n)
            })
            .collect();
        Ok(Plan {
            threads,
            shift,
            n_vertices,
            parts,
            part_len,
            part_counts,
            count,
            rounds,
            sizes,
            regions,
        })
    }

    /// One buffer for every region, at least as large as `O` (`len` ids), so that `O` can
    /// then take it over.
    fn records(&self, len: usize) -> Result<Vec<u32>> {
        let total = self.sizes.iter().sum::<usize>();
        let mut records: Vec<u32> =
            crate::util::pages::with_capacity(len.max(total), "the star pass's records")?;
        records.resize(total, 0);
        Ok(records)
    }

    /// One round over coarse buckets `first..last`: every part scatters its occurrences to
    /// its region, then each worker takes the stars of a run of the buckets.
    fn round(
        &self, (first, last): (usize, usize), records: &mut [u32], workers: &mut [Worker],
        vh: &mut [u32], mode: &Mode, total: &mut Tally,
    ) -> Result<()> {
        const BUCKETS: &str = "the star pass's buckets";
        let shift = self.shift;
        let mut rest = &mut records[..];
        let mut jobs = Vec::with_capacity(self.parts.len());
        for (j, (&part, pc)) in self.parts.iter().zip(&self.part_counts).enumerate() {
            let (mine, r) = std::mem::take(&mut rest).split_at_mut(self.sizes[j]);
            rest = r;
            jobs.push((j * self.part_len / 4, part, &pc[first..last], mine));
        }
        // `scatter`'s starts are one per coarse bucket of the round: bounded.
        let starts = crate::util::par::run_all(jobs, |(t0, part, pc, rec)| {
            scatter(part, t0 as u32, pc, first as u32, shift, rec)
        });
        let starts: Vec<Vec<u32>> = starts.into_iter().collect::<Result<_>>()?;
        let records = &records[..];
        let cuts = self.cuts(first, last, workers.len())?;
        let n_vertices = self.n_vertices;
        let mut jobs = Vec::with_capacity(workers.len());
        let mut vh_rest = if mode.tables {
            &mut vh[(first << shift).min(n_vertices)..]
        } else {
            &mut []
        };
        for (k, worker) in workers.iter_mut().enumerate() {
            let (a, b) = (cuts[k] - first, cuts[k + 1] - first);
            let vh_base = ((first + a) << shift).min(n_vertices);
            let vh_len = if mode.tables {
                ((first + b) << shift).min(n_vertices) - vh_base
            } else {
                0
            };
            let (mine, rest) = std::mem::take(&mut vh_rest).split_at_mut(vh_len);
            vh_rest = rest;
            // Bucket `c` of this run, from every part in turn.
            let mut buckets: Vec<Vec<&[u32]>> = try_with_capacity(b - a, BUCKETS)?;
            for c in a..b {
                let parts = self.regions.iter().zip(&starts).map(|(&lo, st)| {
                    &records[lo + 5 * st[c] as usize..lo + 5 * st[c + 1] as usize]
                });
                buckets.push(try_collect(parts, BUCKETS)?);
            }
            jobs.push((worker, buckets, mine, vh_base));
        }
        let tallies = crate::util::par::run_all(jobs, |(w, buckets, vh, base)| {
            w.round(&buckets, vh, base, mode)
        });
        for t in tallies {
            total.add(t?)?;
        }
        Ok(())
    }

    /// Where each of `n_workers` runs of coarse buckets starts (and, last, `last`): runs
    /// of about an equal share of the round's records.
    fn cuts(&self, first: usize, last: usize, n_workers: usize) -> Result<Vec<usize>> {
        let count = &self.count;
        let in_round: usize = count[first..last].iter().map(|&c| c as usize).sum();
        // One cut per worker and the end: no growth past this.
        let mut cuts = try_with_capacity(n_workers + 1, "the star pass's cuts")?;
        cuts.push(first);
        let mut acc = 0;
        for (c, &n) in count.iter().enumerate().take(last).skip(first) {
            acc += n as usize;
            if cuts.len() < n_workers && acc * n_workers >= in_round * cuts.len() {
                cuts.push(c + 1);
            }
        }
        while cuts.len() <= n_workers {
            cuts.push(last);
        }
        Ok(cuts)
    }
}

/// Ranges of coarse buckets such that each part's occurrences in a range fit in `share`
/// records (a range holds at least one bucket).
fn rounds(part_counts: &[Vec<u32>], share: usize) -> Result<Vec<(usize, usize)>> {
    let n_coarse = part_counts.first().map_or(0, Vec::len);
    let mut rounds = Vec::new();
    let mut first = 0;
    while first < n_coarse {
        // One count per part (at most one per thread).
        let mut in_round: Vec<usize> = part_counts.iter().map(|p| p[first] as usize).collect();
        let mut last = first + 1;
        while last < n_coarse
            && part_counts
                .iter()
                .zip(&in_round)
                .all(|(p, &n)| n + p[last] as usize <= share)
        {
            for (n, p) in in_round.iter_mut().zip(part_counts) {
                *n += p[last] as usize;
            }
            last += 1;
        }
        try_push(&mut rounds, (first, last), "the star pass's rounds")?;
        first = last;
    }
    Ok(rounds)
}

/// Flat records, five `u32` each, in one buffer cut in a region per part: each as large as
/// the part's largest round needs, plus a spare record at its end that takes the writes of
/// the occurrences outside the round, so that the scatter has no branch.
fn region_sizes(part_counts: &[Vec<u32>], rounds: &[(usize, usize)]) -> Vec<usize> {
    part_counts
        .iter()
        .map(|pc| {
            let most = rounds
                .iter()
                .map(|&(a, b)| pc[a..b].iter().map(|&c| c as usize).sum::<usize>())
                .max()
                .unwrap_or(0);
            5 * (most + 1)
        })
        .collect()
}

/// Scatters the occurrences in `part` (tetrahedra from `t0` on) of the vertices of the
/// coarse buckets from `first` on (`count`: how many each has in `part`) to their bucket, in
/// tetrahedron order (records of five `u32`: see [`Record`]). Returns where each bucket
/// starts in `records`, in records.
fn scatter(
    part: &[u32], t0: u32, count: &[u32], first: u32, shift: u32, records: &mut [u32],
) -> Result<Vec<u32>> {
    let span = count.len() as u32;
    let mut start = try_vec(count.len() + 2, 0u32, "the star pass's bucket starts")?;
    for (c, &n) in count.iter().enumerate() {
        start[c + 1] = start[c] + n;
    }
    let in_round = start[count.len()];
    let mut fill = try_to_vec(&start, "the star pass's bucket starts")?;
    // The spare record, never advanced.
    fill[span as usize] = in_round;
    debug_assert!(records.len() >= 5 * (in_round as usize + 1));
    for (t, q) in part.chunks_exact(4).enumerate() {
        let t = t0 + t as u32;
        for i in 0..4u32 {
            let x = q[i as usize];
            let c = (x >> shift).wrapping_sub(first);
            let inside = c < span;
            let bucket = if inside { c } else { span } as usize;
            let [a, b, c] = crate::chf::star_pass::link::OTHERS[i as usize].map(|j| q[j as usize]);
            let at = 5 * fill[bucket] as usize;
            records[at..at + 5].copy_from_slice(&[4 * t + i, x, a, b, c]);
            fill[bucket] += inside as u32;
        }
    }
    start.truncate(count.len() + 1);
    Ok(start)
}

/// What every thread of the pass needs to know.
struct Mode<'a> {
    flagged: &'a [u32],
    faces: bool,
    collect: bool,
    partners: bool,
    tables: bool,
    shift: u32,
}

/// What a thread's share of a round found, added up in vertex order.
#[derive(Default)]
struct Tally {
    split_needed: bool,
    first_split: u32,
    num_edges: usize,
    input_edges: usize,
    non_manifold_edges: usize,
    non_manifold_edge_examples: Vec<[u32; 2]>,
    multi_fan: Vec<MultiFan>,
    census: FaceCensus,
}

impl Tally {
    /// What the pass found, with the tables it wrote and, with pairs asked for, the pairs.
    fn into_stars(self, vh: Vec<u32>, edge_bits: RankBits, o: Option<Vec<u32>>) -> Stars {
        let Tally {
            split_needed,
            first_split,
            num_edges,
            input_edges,
            non_manifold_edges,
            non_manifold_edge_examples,
            mut multi_fan,
            census,
        } = self;
        multi_fan.sort_unstable();
        let edge_census = EdgeCensus {
            input_edges,
            non_manifold: non_manifold_edges,
            non_manifold_examples: non_manifold_edge_examples.clone(),
            // Without a split the structure pairs are the input pairs.
            kept: non_manifold_edges,
            kept_examples: non_manifold_edge_examples,
            multi_fan,
        };
        Stars {
            split_needed,
            first_split,
            num_edges,
            vh,
            edge_bits,
            census: edge_census,
            faces: o.map(|o| (census, o)),
        }
    }

    /// Adds `t`, which covers vertices after all those of `self`.
    fn add(&mut self, t: Tally) -> Result<()> {
        if !self.split_needed {
            self.first_split = t.first_split;
        }
        self.split_needed |= t.split_needed;
        self.num_edges += t.num_edges;
        self.input_edges += t.input_edges;
        self.non_manifold_edges += t.non_manifold_edges;
        extend_examples(
            &mut self.non_manifold_edge_examples,
            t.non_manifold_edge_examples,
        );
        try_extend(&mut self.multi_fan, t.multi_fan, "the multi-fan edges")?;
        let (a, b) = (&mut self.census, t.census);
        a.input_faces += b.input_faces;
        a.boundary_faces += b.boundary_faces;
        a.non_manifold_faces += b.non_manifold_faces;
        extend_examples(
            &mut a.non_manifold_face_examples,
            b.non_manifold_face_examples,
        );
        try_extend(
            &mut a.non_manifold,
            b.non_manifold,
            "the non-manifold half-faces",
        )?;
        a.duplicates += b.duplicates;
        extend_examples(&mut a.duplicate_examples, b.duplicate_examples);
        a.same_direction |= b.same_direction;
        Ok(())
    }
}

/// One thread's scratch, kept from round to round.
struct Worker<'o> {
    link: Link,
    pairs: Writer<'o>,
    edge_slots: Vec<u64>,
    sorter: Sorter,
}

/// A coarse bucket's records sorted by vertex: `local[fine_start[i]..fine_start[i + 1]]`
/// holds the records of the bucket's `i`-th vertex.
#[derive(Default)]
struct Sorter {
    local: Vec<Record>,
    fine_start: Vec<u32>,
    cursor: Vec<u32>,
}

impl<'o> Worker<'o> {
    fn new(n_vertices: usize, pairs: Writer<'o>, edge_slots: usize) -> Result<Self> {
        Ok(Worker {
            link: Link::new(n_vertices)?,
            pairs,
            edge_slots: if edge_slots == 0 {
                Vec::new()
            } else {
                crate::util::pages::with_capacity(edge_slots, "the edge slots")?
            },
            sorter: Sorter::default(),
        })
    }

    /// The stars of a run of coarse buckets, each in records from every part in turn.
    /// Sorts one coarse bucket at a time, in cache, by the low bits of the vertex, then
    /// hands each star to the link.
    fn round(
        &mut self, buckets: &[Vec<&[u32]>], vh: &mut [u32], vh_base: usize, mode: &Mode,
    ) -> Result<Tally> {
        let mut census = FaceCensus::default();
        let mut sums = Sums {
            flagged: mode.flagged,
            faces: mode.faces.then_some((&mut census, &mut self.pairs)),
            collect: mode.collect,
            partners: mode.partners,
            tables: mode.tables,
            split_needed: false,
            first_split: NONE,
            vh,
            vh_base,
            edge_slots: &mut self.edge_slots,
            num_edges: 0,
            input_edges: 0,
            non_manifold_edges: 0,
            non_manifold_edge_examples: Vec::new(),
            multi_fan: Vec::new(),
        };
        let n_fine = 1usize << mode.shift;
        let sorter = &mut self.sorter;
        try_resize(
            &mut sorter.fine_start,
            n_fine + 1,
            0,
            "the star pass's fine buckets",
        )?;
        try_resize(
            &mut sorter.cursor,
            n_fine,
            0,
            "the star pass's fine buckets",
        )?;
        for parts in buckets {
            if sorter.sort_bucket(parts, n_fine)? == 0 {
                continue;
            }
            let fine_start = &sorter.fine_start;
            for i in 0..n_fine {
                let star = &sorter.local[fine_start[i] as usize..fine_start[i + 1] as usize];
                if !star.is_empty() {
                    self.link.star(star, &mut sums)?;
                }
            }
        }
        let mut tally = Tally::from_sums(sums);
        tally.census = census;
        Ok(tally)
    }
}

impl Sorter {
    /// Sorts the records of one coarse bucket (from every part in turn) into `local` by the
    /// low bits of the vertex, `fine_start` marking where each vertex's records start;
    /// returns how many records.
    #[inline(always)]
    fn sort_bucket(&mut self, parts: &[&[u32]], n_fine: usize) -> Result<usize> {
        let mask = (n_fine - 1) as u32;
        let bucket = || {
            parts
                .iter()
                .flat_map(|p| p.chunks_exact(5))
                .map(|r| [r[0], r[1], r[2], r[3], r[4]])
        };
        let fine_start = &mut self.fine_start;
        fine_start.fill(0);
        for r in bucket() {
            fine_start[(r[1] & mask) as usize + 1] += 1;
        }
        for i in 0..n_fine {
            fine_start[i + 1] += fine_start[i];
        }
        let size = fine_start[n_fine] as usize;
        if size == 0 {
            return Ok(0);
        }
        if self.local.len() < size {
            try_resize(&mut self.local, size, [0; 5], "the star pass's bucket")?;
        }
        self.cursor.copy_from_slice(&fine_start[..n_fine]);
        for r in bucket() {
            let slot = &mut self.cursor[(r[1] & mask) as usize];
            self.local[*slot as usize] = r;
            *slot += 1;
        }
        Ok(size)
    }
}

impl Tally {
    /// What a worker's sums of one round add up to (the face census aside).
    fn from_sums(sums: Sums) -> Tally {
        Tally {
            split_needed: sums.split_needed,
            first_split: sums.first_split,
            num_edges: sums.num_edges,
            input_edges: sums.input_edges,
            non_manifold_edges: sums.non_manifold_edges,
            non_manifold_edge_examples: sums.non_manifold_edge_examples,
            multi_fan: sums.multi_fan,
            census: FaceCensus::default(),
        }
    }
}

/// The rank bits of `n` slots with `slots` set: the slots are bucketed by window of bits
/// first (at most 256 windows), then each window's bits are set in cache. `scratch` is
/// memory to reuse.
pub(crate) fn bits_from_slots(slots: &[Vec<u64>], n: usize, scratch: Vec<u64>) -> Result<RankBits> {
    let n_slots: usize = slots.iter().map(Vec::len).sum();
    let slots = || slots.iter().flatten();
    let bits = u64::BITS - (n as u64).saturating_sub(1).leading_zeros();
    // Windows of at least one word, so that each word is written by one window.
    let shift = bits.saturating_sub(COARSE_BITS).max(6);
    let n_windows = (n.saturating_sub(1) >> shift) + 1;
    let mut start = try_vec(n_windows + 1, 0u32, "the edge slot windows")?;
    for &s in slots() {
        start[(s >> shift) as usize + 1] += 1;
    }
    for w in 0..n_windows {
        start[w + 1] += start[w];
    }
    let mut fill = try_to_vec(&start, "the edge slot windows")?;
    let mut low = scratch;
    low.clear();
    try_resize(&mut low, n_slots, 0, "the edge slots")?;
    for &s in slots() {
        let f = &mut fill[(s >> shift) as usize];
        low[*f as usize] = s & ((1 << shift) - 1);
        *f += 1;
    }
    let mut words = try_vec(n.div_ceil(64), 0u64, "the edge bits")?;
    for w in 0..n_windows {
        let base = w << (shift - 6);
        for &l in &low[start[w] as usize..start[w + 1] as usize] {
            words[base + (l >> 6) as usize] |= 1 << (l & 63);
        }
    }
    RankBits::from_words(words, n)
}

/// The sorted union of two sorted lists: the half-faces the pass never pairs (non-manifold
/// faces and seams) are both lists of the structure.
pub(crate) fn merged(a: &[u32], b: &[u32]) -> Result<Vec<u32>> {
    let mut out: Vec<u32> = try_collect(a.iter().chain(b).copied(), "the flagged half-faces")?;
    out.sort_unstable();
    out.dedup();
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bits_land_in_place() {
        for n in [0usize, 1, 64, 65, 1000, 100_000] {
            let slots: Vec<u64> = (0..n as u64)
                .filter(|s| s % 7 == 3 || s % 11 == 0)
                .rev()
                .collect();
            let bits = bits_from_slots(std::slice::from_ref(&slots), n, Vec::new()).unwrap();
            for s in 0..n {
                assert_eq!(bits.get(s), s % 7 == 3 || s % 11 == 0, "n = {n}, slot {s}");
            }
            assert_eq!(bits.ones(), slots.len());
        }
    }
}

#[cfg(test)]
mod against_walks {
    use super::*;
    use crate::chf::ids::{FACE, first, local, tet};
    use crate::chf::{BuildOptions, Chf, edges};

    /// The first boundary half-face holding each vertex, else the first half-face.
    fn vh_by_scan(v: &[u32], o: &[u32], n: usize) -> Vec<u32> {
        let mut vh = vec![NONE; n];
        for hf in 0..v.len() as u32 {
            let base = first(tet(hf)) as usize;
            for l in FACE[local(hf) as usize] {
                let slot = &mut vh[v[base + l as usize] as usize];
                if *slot == NONE || (o[hf as usize] == NONE && o[*slot as usize] != NONE) {
                    *slot = hf;
                }
            }
        }
        vh
    }

    #[test]
    fn stars_match_walking_the_fans() {
        // Random soups: duplicates, non-manifold faces and edges, pinched links, seams.
        let seed = 0x1234_5678_9ABC_DEF0u64;
        for (round, (n, tets)) in
            crate::util::test_soups::<4>(seed, 200, (6, 20), (10, 60)).enumerate()
        {
            let chf = Chf::from_tetrahedra(&tets, n, &[], BuildOptions::level(1)).unwrap();
            let flagged = merged(&chf.non_manifold, &chf.seams).unwrap();
            let stars = stars(
                &chf.v,
                chf.n_vertices,
                &flagged,
                StarPass {
                    pairs: Pairs::Opposites,
                    tables: true,
                    threads: 1,
                },
            )
            .unwrap();
            assert!(!stars.split_needed);
            let walked = edges::canonical_slots(&chf.v, &chf.o);
            let n_slots = 6 * chf.num_tetrahedra();
            for s in 0..n_slots {
                assert_eq!(
                    stars.edge_bits.get(s),
                    walked.get(s),
                    "round {round}, slot {s}"
                );
            }
            assert_eq!(
                stars.vh,
                vh_by_scan(&chf.v, &chf.o, chf.n_vertices),
                "round {round}"
            );
            assert_eq!(stars.faces.unwrap().1, chf.o, "round {round}");
        }
    }

    #[test]
    fn any_number_of_threads_finds_the_same() {
        // Soups dense enough that every pair mode meets duplicates, non-manifold faces and
        // edges and pinched stars; the pass itself on 2, 3 and 7 threads (the build caps
        // them by memory and size, see `threads_for`).
        let mut rnd = crate::util::test_rng(0x00DD_BA11_u64);
        for (n, t) in [(40usize, 600usize), (300, 3000), (2000, 5000)] {
            let v: Vec<u32> = (0..4 * t)
                .map(|_| rnd(n))
                .collect::<Vec<_>>()
                .chunks(4)
                .filter(|q| (0..4).all(|i| (0..i).all(|j| q[i] != q[j])))
                .flatten()
                .copied()
                .collect();
            let run = |pairs, tables, threads| {
                let pass = StarPass {
                    pairs,
                    tables,
                    threads,
                };
                format!("{:?}", stars(&v, n, &[], pass).unwrap())
            };
            for pairs in [Pairs::No, Pairs::Census, Pairs::Partners, Pairs::Opposites] {
                for tables in [false, true] {
                    let one = run(pairs, tables, 1);
                    for threads in [2, 3, 7] {
                        let many = run(pairs, tables, threads);
                        assert!(
                            one == many,
                            "n {n}, {pairs:?}, tables {tables}, {threads} threads"
                        );
                    }
                }
            }
        }
    }
}
