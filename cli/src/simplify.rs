//! `topomesh simplify`: shortest-edge-first collapse until a number of triangles remain.
//! A priority queue of edges by length (entries checked when popped: an edge changed since
//! it was queued is queued again with its new length); a collapse is refused when it fails
//! the link condition or would turn a triangle's normal over, and the merged vertex goes
//! to the midpoint.

use crate::exit::Failure;
use crate::input::{build_surface_shown, load};
use crate::output::Out;
use crate::progress::Progress;
use glam::DVec3;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use topomesh::{BuildOptions, Che, Error};

#[derive(clap::Args)]
pub struct SimplifyOptions {
    /// The surface to read.
    input: PathBuf,
    /// The file to write (format from the extension).
    output: PathBuf,
    /// Stop when at most this many triangles remain.
    #[arg(long, conflicts_with = "ratio", required_unless_present = "ratio")]
    triangles: Option<usize>,
    /// Stop when at most this fraction of the triangles remains (0 to 1).
    #[arg(long)]
    ratio: Option<f64>,
}

/// A queued edge: its length's bits (non-negative floats order as their bits), the
/// half-edge and its ends when queued.
type Entry = Reverse<(u64, u32, u32, u32)>;

pub fn run(options: &SimplifyOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let (name, data) = load(Some(&options.input), &progress)?;
    let mut che = build_surface_shown(&data, BuildOptions::level(2), &progress)?;
    if che.positions().is_empty() {
        return Err(Error::invalid(format!("{name}: simplify needs positions")).into());
    }
    let before = che.num_live_triangles();
    let target = match (options.triangles, options.ratio) {
        (Some(n), _) => n,
        (None, Some(r)) if (0.0..=1.0).contains(&r) => (before as f64 * r) as usize,
        _ => return Err(Error::invalid("--ratio: a fraction from 0 to 1").into()),
    };
    let start = Instant::now();
    progress.start(
        format!("simplifying {name}"),
        (before.saturating_sub(target)) as u64,
    );
    let collapses = simplify(&mut che, target, &progress)?;
    che.garbage_collect()?;
    let seconds = start.elapsed().as_secs_f64();
    che.write(&options.output)?;
    drop(progress);
    let s = che.summary();
    let mut out = Out::new();
    writeln!(
        out,
        "{name}: {before} -> {} triangles ({collapses} collapses) in {seconds:.3} s",
        che.num_triangles()
    )?;
    writeln!(
        out,
        "vertices {} edges {} triangles {} boundary curves {} components {} genus {} manifold {}",
        s.vertices, s.edges, s.triangles, s.boundary_curves, s.components, s.genus, s.manifold
    )?;
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

fn length_bits(che: &Che, h: u32) -> u64 {
    let p = che.positions();
    let (a, b) = (che.origin(h) as usize, che.target(h) as usize);
    p[a].distance(p[b]).to_bits()
}

fn queue_star(che: &Che, x: u32, heap: &mut BinaryHeap<Entry>) {
    for step in che.vertex_star(x) {
        let h = step.half_edge();
        heap.push(Reverse((
            length_bits(che, h),
            h,
            che.origin(h),
            che.target(h),
        )));
    }
}

/// Collapses until `target` triangles remain or no edge can go; returns the collapses.
fn simplify(che: &mut Che, target: usize, progress: &Progress) -> Result<usize, Error> {
    let mut heap = BinaryHeap::new();
    for e in 0..che.num_edges() as u32 {
        let h = che.edge_half_edge(e);
        heap.push(Reverse((
            length_bits(che, h),
            h,
            che.origin(h),
            che.target(h),
        )));
    }
    let mut collapses = 0;
    while che.num_live_triangles() > target {
        let Some(Reverse((len, h, a, b))) = heap.pop() else {
            break;
        };
        if che.is_half_edge_removed(h) || che.origin(h) != a || che.target(h) != b {
            continue;
        }
        if length_bits(che, h) != len {
            heap.push(Reverse((length_bits(che, h), h, a, b)));
            continue;
        }
        let p = che.positions();
        let mid = (p[a as usize] + p[b as usize]) / 2.0;
        if !che.is_collapse_ok(h)? || flips_a_normal(che, h, mid) {
            continue;
        }
        let removed = che.num_live_triangles();
        che.collapse_edge(h)?;
        che.set_position(a, mid)?;
        progress.advance((removed - che.num_live_triangles()) as u64);
        collapses += 1;
        queue_star(che, a, &mut heap);
    }
    Ok(collapses)
}

/// Would moving both ends of `h` to `mid` turn the normal of a triangle around them over?
fn flips_a_normal(che: &Che, h: u32, mid: DVec3) -> bool {
    let (a, b) = (che.origin(h), che.target(h));
    let p = che.positions();
    for x in [a, b] {
        for t in che.vertex_triangles(x) {
            let c = che.triangle_vertices(t);
            if c.contains(&a) && c.contains(&b) {
                continue;
            }
            let at = |y: u32| p[y as usize];
            let moved = |y: u32| if y == a || y == b { mid } else { p[y as usize] };
            let n0 = (at(c[1]) - at(c[0])).cross(at(c[2]) - at(c[0]));
            let n1 = (moved(c[1]) - moved(c[0])).cross(moved(c[2]) - moved(c[0]));
            if n0.dot(n1) <= 0.0 {
                return true;
            }
        }
    }
    false
}
