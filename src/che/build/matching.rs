//! Step 2 of the build, matching: the half-edges on each unordered vertex pair (grouped by
//! `crate::che::pairs`); a pair of exactly two is a partner pair, three or more a
//! non-manifold edge whose half-edges stay unpaired and are flagged.

use super::report::{BuildReport, push_example};
use crate::NONE;
use crate::che::ids::{next, prev};
use crate::che::pairs::{for_each_group_par, half_edge};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_extend, try_push, try_vec};
use crate::util::extend_examples;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// What the matching found, over the whole soup.
pub(crate) struct Matching {
    /// The other half-edge on `h`'s vertex pair when there are exactly two, else `NONE`.
    pub partner: Vec<u32>,
    /// Half-edges of non-manifold edges (unsorted).
    pub non_manifold: Vec<u32>,
    /// Triangle pairs with the same three vertices seen on non-manifold edges.
    pub duplicates: Vec<[u32; 2]>,
    /// Does some partner pair run the same way (so the soup needs orienting)?
    pub same_direction: bool,
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
    /// The first allocation that failed; the thread then skips the rest of its pairs.
    failed: Option<Error>,
}

/// Matches on unordered vertex pairs; the counts go into `report`. Threads take ranges of
/// pairs and write the partners at random (relaxed atomic stores, plain ones on x86-64; the
/// conversions in and out are in place and free); the rest is added up in pair order.
pub(crate) fn match_pairs(
    v: &[u32], n_vertices: usize, threads: usize, report: &mut BuildReport,
) -> Result<Matching> {
    let partner = crate::util::pages::from_fn(v.len(), || AtomicU32::new(NONE), "the partners")?;
    // Direction bits (`V[h] < V[next(h)]`): 1 bit per half-edge stays in cache, where
    // reading `V` at both half-edges of every pair would miss it.
    let forward = direction_bits(v)?;
    let is_forward = |h: u32| (forward[(h >> 6) as usize] >> (h & 63)) & 1 == 1;
    let found = for_each_group_par(
        v,
        n_vertices,
        threads,
        Matched::default,
        |m, a, b, group| {
            if m.failed.is_some() {
                return;
            }
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
                    m.failed = non_manifold_edge(v, group, m).err();
                }
            }
        },
    )?;
    let mut out = Matching {
        // In place (the same size and alignment): no allocation.
        partner: partner.into_iter().map(AtomicU32::into_inner).collect(),
        non_manifold: Vec::new(),
        duplicates: Vec::new(),
        same_direction: false,
    };
    for mut m in found {
        if let Some(e) = m.failed.take() {
            return Err(e);
        }
        report.input_edges += m.input_edges;
        report.boundary_edges += m.boundary_edges;
        report.non_manifold_edges += m.non_manifold_edges;
        extend_examples(&mut report.non_manifold_edge_examples, m.examples);
        try_extend(
            &mut out.non_manifold,
            m.non_manifold,
            "the non-manifold half-edges",
        )?;
        try_extend(&mut out.duplicates, m.duplicates, "the duplicate triangles")?;
        out.same_direction |= m.same_direction;
    }
    Ok(out)
}

/// The half-edges of a non-manifold edge, and the duplicates on it (paired duplicates are
/// found on `O` later), into the thread's lists.
fn non_manifold_edge(v: &[u32], group: &[u64], m: &mut Matched) -> Result<()> {
    let half_edges = group.iter().map(|&k| half_edge(k));
    try_extend(
        &mut m.non_manifold,
        half_edges,
        "the non-manifold half-edges",
    )?;
    duplicates_on_edge(v, group, &mut m.duplicates)
}

fn direction_bits(v: &[u32]) -> Result<Vec<u64>> {
    let mut bits = try_vec(v.len().div_ceil(64), 0u64, "the half-edge directions")?;
    for (t, tri) in v.chunks_exact(3).enumerate() {
        let h = 3 * t;
        for (i, (a, b)) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])]
            .into_iter()
            .enumerate()
        {
            bits[(h + i) >> 6] |= ((a < b) as u64) << ((h + i) & 63);
        }
    }
    Ok(bits)
}

/// Pairs of triangles with the same three vertices among the half-edges of one
/// non-manifold vertex pair (such a pair is seen on each of its non-manifold pairs:
/// deduplicated by the caller).
fn duplicates_on_edge(v: &[u32], group: &[u64], out: &mut Vec<[u32; 2]>) -> Result<()> {
    let third = |k: u64| v[prev(half_edge(k)) as usize];
    let by_third = group.iter().map(|&k| (third(k), half_edge(k) / 3));
    let mut by_third: Vec<(u32, u32)> = try_collect(by_third, "a non-manifold edge")?;
    by_third.sort_unstable();
    for run in by_third.chunk_by(|x, y| x.0 == y.0) {
        for (i, &(_, s)) in run.iter().enumerate() {
            for &(_, t) in &run[i + 1..] {
                try_push(out, [s.min(t), s.max(t)], "the duplicate triangles")?;
            }
        }
    }
    Ok(())
}

/// Two triangles with the same three vertices whose edges are all paired to each other
/// (a closed "pillow"): found with one sequential pass over `O`.
pub(crate) fn count_pillows(o: &[u32], out: &mut Vec<[u32; 2]>) -> Result<()> {
    for (t, opp) in o.chunks_exact(3).enumerate() {
        let other = opp[0] / 3;
        if opp[0] != NONE
            && opp[1] != NONE
            && opp[2] != NONE
            && opp[1] / 3 == other
            && opp[2] / 3 == other
            && other > t as u32
        {
            try_push(out, [t as u32, other], "the duplicate triangles")?;
        }
    }
    Ok(())
}

/// Strict mode: the first non-manifold edge, with the input triangles on it, as an error.
pub(crate) fn reject_non_manifold_edges(
    report: &BuildReport, v: &[u32], non_manifold: &[u32], origin_of: impl Fn(u32) -> u32,
) -> Result<()> {
    if let Some(&[a, b]) = report.non_manifold_edge_examples.first() {
        let tris: Vec<String> = non_manifold
            .iter()
            .filter(|&&h| {
                let (x, y) = (v[h as usize], v[next(h) as usize]);
                (x.min(y), x.max(y)) == (a, b)
            })
            .map(|&h| origin_of(h / 3).to_string())
            .collect();
        return Err(Error::non_manifold(format!(
            "non-manifold edge ({a}, {b}) is shared by triangles {}; such edges in all: {}",
            tris.join(", "),
            report.non_manifold_edges
        )));
    }
    Ok(())
}
