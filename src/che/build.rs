//! From a triangle list to a CHE: validate, drop degenerate triangles, match half-edges,
//! orient, split non-manifold vertices, then build the requested level.

use super::matching::{for_each_group_par, half_edge};
use super::report::{BuildReport, push_example};
use super::{Che, level2, level3, orient, split};
use crate::NONE;
use crate::error::{Error, Result};
use crate::util::extend_examples;
use crate::util::rank::RankBits;
use crate::util::rank_directory::RankDirectory;
use glam::DVec3;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// How to build: the level (0..=3) and whether non-manifold input is an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuildOptions {
    pub level: u8,
    /// Reject non-manifold edges, non-manifold vertices and duplicate triangles instead of
    /// repairing them.
    pub strict: bool,
    /// Threads for the build: 0 (the default) for as many as the machine runs at once, 1
    /// for the calling thread alone. The structure is the same whatever the number.
    pub threads: usize,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            level: 2,
            strict: false,
            threads: 0,
        }
    }
}

impl BuildOptions {
    pub fn level(level: u8) -> Self {
        BuildOptions {
            level,
            ..Self::default()
        }
    }
}

/// Largest triangle count whose half-edge ids fit below `NONE`.
pub const MAX_TRIANGLES: usize = (u32::MAX as usize) / 3;

pub(crate) fn build(
    triangles: &[[u32; 3]],
    n_vertices: usize,
    positions: &[DVec3],
    options: BuildOptions,
) -> Result<Che> {
    if options.level > 3 {
        return Err(Error::out_of_range(format!(
            "level {} is not in 0..=3",
            options.level
        )));
    }
    if n_vertices >= NONE as usize {
        return Err(Error::too_large(format!(
            "{n_vertices} vertices: ids must fit below 2^32 - 1"
        )));
    }
    if triangles.len() > MAX_TRIANGLES {
        return Err(Error::too_large(format!(
            "{} triangles: half-edge ids must fit below 2^32 - 1 (at most {MAX_TRIANGLES} triangles)",
            triangles.len()
        )));
    }
    if !positions.is_empty() && positions.len() != n_vertices {
        return Err(Error::invalid(format!(
            "{} positions given for {n_vertices} vertices",
            positions.len()
        )));
    }
    let mut report = BuildReport {
        input_triangles: triangles.len(),
        input_vertices: n_vertices,
        ..BuildReport::default()
    };

    // Soup: range check, degenerate triangles dropped.
    let threads = crate::util::par::build_threads(options.threads, triangles.len());
    let (mut v, triangle_origin) = super::soup::soup(triangles, n_vertices, &mut report, threads)?;
    let dropped_any = !triangle_origin.is_empty();
    let origin_of = |t: u32| {
        if dropped_any {
            triangle_origin[t as usize]
        } else {
            t
        }
    };

    // Match on unordered vertex pairs; pairs of exactly two are partners. Threads take
    // ranges of pairs and write the partners at random (relaxed atomic stores, plain ones
    // on x86-64; the conversions in and out are in place and free); the rest is added up
    // in pair order.
    let partner: Vec<u32> = crate::util::pages::filled(v.len(), NONE);
    let partner: Vec<AtomicU32> = partner.into_iter().map(AtomicU32::new).collect();
    // Direction bits (`V[h] < V[next(h)]`): 1 bit per half-edge stays in cache, where
    // reading `V` at both half-edges of every pair would miss it.
    let forward = direction_bits(&v);
    let is_forward = |h: u32| (forward[(h >> 6) as usize] >> (h & 63)) & 1 == 1;
    let found = for_each_group_par(
        &v,
        n_vertices,
        threads,
        Matched::default,
        |m, a, b, group| {
            m.input_edges += 1;
            match group.len() {
                1 => m.boundary_edges += 1,
                2 => {
                    let (h, g) = (half_edge(group[0]), half_edge(group[1]));
                    partner[h as usize].store(g, Relaxed);
                    partner[g as usize].store(h, Relaxed);
                    m.same_direction |= is_forward(h) == is_forward(g);
                }
                _ => {
                    m.non_manifold_edges += 1;
                    push_example(&mut m.examples, [a, b]);
                    m.non_manifold.extend(group.iter().map(|&k| half_edge(k)));
                    // Duplicates on a non-manifold edge; paired ones are found on `O` below.
                    duplicates_on_edge(&v, group, &mut m.duplicates);
                }
            }
        },
    );
    let partner: Vec<u32> = partner.into_iter().map(AtomicU32::into_inner).collect();
    let mut non_manifold: Vec<u32> = Vec::new();
    let mut same_direction = false;
    let mut duplicates: Vec<[u32; 2]> = Vec::new();
    for m in found {
        report.input_edges += m.input_edges;
        report.boundary_edges += m.boundary_edges;
        report.non_manifold_edges += m.non_manifold_edges;
        extend_examples(&mut report.non_manifold_edge_examples, m.examples);
        non_manifold.extend(m.non_manifold);
        duplicates.extend(m.duplicates);
        same_direction |= m.same_direction;
    }
    if options.strict {
        strict_checks(&report, &v, &non_manifold, &origin_of)?;
    }

    // Orient only when some pair runs the same way: otherwise the partners are opposites.
    let (o, seams) = if same_direction {
        let oriented = orient::orient(&mut v, &partner);
        drop(partner);
        report.flipped_triangles = oriented.flipped_count;
        report.non_orientable_components = oriented.non_orientable_components;
        report.non_orientable_examples = oriented
            .non_orientable_examples
            .iter()
            .map(|&t| origin_of(t))
            .collect();
        report.seam_edges = oriented.seams.len() / 2;
        for h in non_manifold.iter_mut() {
            if oriented.flipped[(*h / 3) as usize] {
                *h = orient::flipped_id(*h);
            }
        }
        (oriented.o, oriented.seams)
    } else {
        (partner, Vec::new())
    };
    non_manifold.sort_unstable();
    count_pillows(&o, &mut duplicates);
    duplicates.sort_unstable();
    duplicates.dedup();
    report.duplicate_triangles = duplicates.len();
    for &[s, t] in &duplicates {
        push_example(&mut report.duplicate_examples, [origin_of(s), origin_of(t)]);
    }
    drop(duplicates);
    if let (true, Some(&[s, t])) = (options.strict, report.duplicate_examples.first()) {
        return Err(Error::non_manifold(format!(
            "triangles {s} and {t} have the same vertices; {} duplicate pairs",
            report.duplicate_triangles
        )));
    }

    let mut split = split::split(&mut v, &o, n_vertices, &seams, threads);
    report.split_vertices = split.split_vertices;
    report.split_vertex_examples = split.split_examples;
    report.seam_split_vertices = split.seam_split_vertices;
    report.added_vertices = split.copies.len();
    if options.strict && report.split_vertices > 0 {
        return Err(Error::non_manifold(format!(
            "non-manifold vertex {} (its star is several fans); {} such vertices",
            report.split_vertex_examples[0], report.split_vertices
        )));
    }
    let n_total = n_vertices + split.copies.len();
    let vertex_origin: Vec<u32> = if split.copies.is_empty() {
        Vec::new()
    } else {
        (0..n_vertices as u32)
            .chain(split.copies.iter().copied())
            .collect()
    };
    let mut positions = positions.to_vec();
    if !positions.is_empty() {
        for &c in &split.copies {
            positions.push(positions[c as usize]);
        }
    }
    let num_edges = o
        .iter()
        .enumerate()
        .filter(|&(h, &g)| g == NONE || (h as u32) < g)
        .count();

    let mut che = Che {
        level: 1,
        n_input_vertices: n_vertices,
        n_vertices: n_total,
        v,
        o,
        vh: Vec::new(),
        edge_bits: RankDirectory::default(),
        eh: Vec::new(),
        ch: Vec::new(),
        boundary_bits: RankBits::default(),
        curve_of: Vec::new(),
        num_edges,
        positions,
        vertex_origin,
        triangle_origin,
        non_manifold,
        seams,
        report,
    };
    if options.level == 0 {
        che.o = Vec::new();
        che.level = 0;
    }
    if options.level >= 2 {
        che.vh = std::mem::take(&mut split.vh);
        level2::build_edges(&mut che);
        che.level = 2;
    }
    if options.level >= 3 {
        level3::build(&mut che);
        che.level = 3;
    }
    Ok(che)
}

/// What one thread's range of vertex pairs found.
#[derive(Default)]
struct Matched {
    input_edges: usize,
    boundary_edges: usize,
    non_manifold_edges: usize,
    examples: Vec<[u32; 2]>,
    non_manifold: Vec<u32>,
    duplicates: Vec<[u32; 2]>,
    same_direction: bool,
}

fn direction_bits(v: &[u32]) -> Vec<u64> {
    let mut bits = vec![0u64; v.len().div_ceil(64)];
    for (t, tri) in v.chunks_exact(3).enumerate() {
        let h = 3 * t;
        for (i, (a, b)) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])]
            .into_iter()
            .enumerate()
        {
            bits[(h + i) >> 6] |= ((a < b) as u64) << ((h + i) & 63);
        }
    }
    bits
}

/// Two triangles with the same three vertices whose edges are all paired to each other
/// (a closed "pillow"): found with one sequential pass over `O`.
fn count_pillows(o: &[u32], out: &mut Vec<[u32; 2]>) {
    for (t, opp) in o.chunks_exact(3).enumerate() {
        let other = opp[0] / 3;
        if opp[0] != NONE
            && opp[1] != NONE
            && opp[2] != NONE
            && opp[1] / 3 == other
            && opp[2] / 3 == other
            && other > t as u32
        {
            out.push([t as u32, other]);
        }
    }
}

/// Pairs of triangles with the same three vertices among the half-edges of one
/// non-manifold vertex pair (such a pair is seen on each of its non-manifold pairs:
/// deduplicated by the caller).
fn duplicates_on_edge(v: &[u32], group: &[u64], out: &mut Vec<[u32; 2]>) {
    let third = |k: u64| v[super::ids::prev(half_edge(k)) as usize];
    let mut by_third: Vec<(u32, u32)> = group
        .iter()
        .map(|&k| (third(k), half_edge(k) / 3))
        .collect();
    by_third.sort_unstable();
    for run in by_third.chunk_by(|x, y| x.0 == y.0) {
        for (i, &(_, s)) in run.iter().enumerate() {
            for &(_, t) in &run[i + 1..] {
                out.push([s.min(t), s.max(t)]);
            }
        }
    }
}

fn strict_checks(
    report: &BuildReport,
    v: &[u32],
    non_manifold: &[u32],
    origin_of: &impl Fn(u32) -> u32,
) -> Result<()> {
    if let Some(&[a, b]) = report.non_manifold_edge_examples.first() {
        let tris: Vec<String> = non_manifold
            .iter()
            .filter(|&&h| {
                let (x, y) = (v[h as usize], v[super::ids::next(h) as usize]);
                (x.min(y), x.max(y)) == (a, b)
            })
            .map(|&h| origin_of(h / 3).to_string())
            .collect();
        return Err(Error::non_manifold(format!(
            "non-manifold edge ({a}, {b}) is shared by triangles {}; {} such edges",
            tris.join(", "),
            report.non_manifold_edges
        )));
    }
    Ok(())
}
