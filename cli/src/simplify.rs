//! `topomesh simplify`: shortest-edge-first collapse until a number of triangles remain.
//! A priority queue of edges by length, one entry per edge id (an edge whose length
//! changes has its entry moved, so the queue never holds more than the edges and each step
//! costs O(log E) besides the collapse's stars); a collapse is refused when it fails the
//! link condition or would turn a triangle's normal over, and the merged vertex goes to the
//! midpoint.

use crate::exit::Failure;
use crate::input::{build_surface_shown, load};
use crate::output::Out;
use crate::progress::Progress;
use glam::DVec3;
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

fn queue_star(che: &Che, x: u32, queue: &mut EdgeQueue) {
    for step in che.vertex_star(x) {
        let h = step.half_edge();
        queue.set(che.edge_of(h), (length_bits(che, h), h));
    }
}

/// Collapses until `target` triangles remain or no edge can go; returns the collapses.
fn simplify(che: &mut Che, target: usize, progress: &Progress) -> Result<usize, Error> {
    let mut queue = EdgeQueue::new(che.num_edges())?;
    for e in 0..che.num_edges() as u32 {
        let h = che.edge_half_edge(e);
        queue.set(e, (length_bits(che, h), h));
    }
    let mut collapses = 0;
    while che.num_live_triangles() > target {
        let Some(((len, h), e)) = queue.pop() else {
            break;
        };
        if che.is_edge_removed(e) || che.is_half_edge_removed(h) || che.edge_of(h) != e {
            continue;
        }
        if length_bits(che, h) != len {
            queue.set(e, (length_bits(che, h), h));
            continue;
        }
        let (a, b) = (che.origin(h), che.target(h));
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
        queue_star(che, a, &mut queue);
    }
    Ok(collapses)
}

/// The key of a queued edge: its length's bits (non-negative floats order as their bits)
/// and the half-edge to collapse.
type Key = (u64, u32);

/// A binary min-heap of edge ids whose keys can change in place: `slot[e]` is where edge
/// `e` sits in `heap` (`u32::MAX` when it is not queued).
struct EdgeQueue {
    heap: Vec<(Key, u32)>,
    slot: Vec<u32>,
}

impl EdgeQueue {
    fn new(edges: usize) -> Result<Self, Error> {
        let mut slot = Vec::new();
        let mut heap = Vec::new();
        if slot.try_reserve_exact(edges).is_err() || heap.try_reserve_exact(edges).is_err() {
            let bytes = (edges * std::mem::size_of::<(Key, u32, u32)>()) as u64;
            return Err(Error::out_of_memory(bytes, "simplify: the edge queue"));
        }
        slot.resize(edges, u32::MAX);
        Ok(EdgeQueue { heap, slot })
    }

    /// Queues edge `e` with `key`, or moves it there if queued.
    fn set(&mut self, e: u32, key: Key) {
        let i = match self.slot[e as usize] {
            u32::MAX => {
                self.heap.push((key, e));
                self.heap.len() - 1
            }
            i => {
                self.heap[i as usize].0 = key;
                i as usize
            }
        };
        let i = self.up(i);
        self.down(i);
    }

    /// The edge with the smallest key, out of the queue.
    fn pop(&mut self) -> Option<(Key, u32)> {
        let last = self.heap.len().checked_sub(1)?;
        self.heap.swap(0, last);
        let top = self.heap.pop()?;
        self.slot[top.1 as usize] = u32::MAX;
        if !self.heap.is_empty() {
            self.down(0);
        }
        Some(top)
    }

    fn place(&mut self, i: usize, item: (Key, u32)) {
        self.slot[item.1 as usize] = i as u32;
        self.heap[i] = item;
    }

    fn up(&mut self, mut i: usize) -> usize {
        let item = self.heap[i];
        while i > 0 && item.0 < self.heap[(i - 1) / 2].0 {
            let parent = self.heap[(i - 1) / 2];
            self.place(i, parent);
            i = (i - 1) / 2;
        }
        self.place(i, item);
        i
    }

    fn down(&mut self, mut i: usize) {
        let item = self.heap[i];
        let n = self.heap.len();
        loop {
            let l = 2 * i + 1;
            if l >= n {
                break;
            }
            let c = if l + 1 < n && self.heap[l + 1].0 < self.heap[l].0 {
                l + 1
            } else {
                l
            };
            if self.heap[c].0 >= item.0 {
                break;
            }
            let child = self.heap[c];
            self.place(i, child);
            i = c;
        }
        self.place(i, item);
    }
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
