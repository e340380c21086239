//! `topomesh refine`: the largest tetrahedron split 1-4 at its centroid until every volume
//! is below a bound (a priority queue by volume, entries of removed tetrahedra skipped when
//! popped); then one pass of 2-3 flips over the faces around the new vertices, each taken
//! when the check accepts it and the smallest dihedral angle of the three new tetrahedra
//! beats that of the two old ones.

use crate::exit::Failure;
use crate::input::{build_volume_shown, load};
use crate::output::Out;
use crate::progress::Progress;
use glam::DVec3;
use std::collections::BinaryHeap;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use topomesh::{Chf, Error, chf};

#[derive(clap::Args)]
pub struct RefineOptions {
    /// The tetrahedral mesh to read.
    input: PathBuf,
    /// The file to write (format from the extension).
    output: PathBuf,
    /// Split until every tetrahedron's volume is below this.
    #[arg(long)]
    max_volume: f64,
}

pub fn run(options: &RefineOptions) -> Result<ExitCode, Failure> {
    let bound = options.max_volume;
    if !(bound.is_finite() && bound > 0.0) {
        return Err(Error::invalid("--max-volume: a positive volume").into());
    }
    let progress = Progress::new();
    let (name, data) = load(Some(&options.input), &progress)?;
    let mut chf = build_volume_shown(&data, chf::BuildOptions::default(), &progress)?;
    if chf.positions().is_empty() {
        return Err(Error::invalid(format!("{name}: refine needs positions")).into());
    }
    let before = chf.num_live_tetrahedra();
    let start = Instant::now();
    let n0 = chf.num_vertices() as u32;
    let estimate = (0..chf.num_tetrahedra() as u32)
        .map(|t| splits_needed(volume(&chf, t), bound))
        .sum();
    progress.start(format!("refining {name}"), estimate);
    let splits = split_largest(&mut chf, bound, &progress)?;
    progress.step(format!("flipping around {splits} new vertices"));
    let flips = improve(&mut chf, n0)?;
    chf.garbage_collect()?;
    let seconds = start.elapsed().as_secs_f64();
    chf.write(&options.output)?;
    drop(progress);
    let s = chf.summary();
    let mut out = Out::new();
    writeln!(
        out,
        "{name}: {before} -> {} tetrahedra ({splits} splits, {flips} flips) in {seconds:.3} s",
        chf.num_tetrahedra()
    )?;
    writeln!(
        out,
        "vertices {} edges {} faces {} tetrahedra {} boundary components {} euler {} manifold {}",
        s.vertices,
        s.edges,
        s.faces,
        s.tetrahedra,
        s.boundary_components,
        s.euler_characteristic,
        s.manifold
    )?;
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

fn volume_of(p: [DVec3; 4]) -> f64 {
    (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) / 6.0
}

fn corners(chf: &Chf, q: [u32; 4]) -> [DVec3; 4] {
    q.map(|x| chf.positions()[x as usize])
}

fn volume(chf: &Chf, t: u32) -> f64 {
    volume_of(corners(chf, chf.tetrahedron_vertices(t)))
}

/// The 1-4 splits a tetrahedron of volume `v` takes: each quarters the volume.
fn splits_needed(v: f64, bound: f64) -> u64 {
    let (mut v, mut n, mut width) = (v, 0u64, 1u64);
    while v >= bound && width < 1 << 40 {
        n += width;
        v /= 4.0;
        width *= 4;
    }
    n
}

/// Splits the largest tetrahedron until all are below `bound`; returns the splits.
fn split_largest(chf: &mut Chf, bound: f64, progress: &Progress) -> Result<usize, Error> {
    // Volumes are positive, so their bits order as the volumes do.
    let mut heap: BinaryHeap<(u64, u32)> = (0..chf.num_tetrahedra() as u32)
        .map(|t| (volume(chf, t).max(0.0).to_bits(), t))
        .collect();
    let mut splits = 0;
    while let Some((bits, t)) = heap.pop() {
        if f64::from_bits(bits) < bound {
            break;
        }
        if chf.is_tetrahedron_removed(t) {
            continue;
        }
        let x = chf.split_tetrahedron(t, None)?;
        splits += 1;
        progress.advance(1);
        for s in chf.vertex_tetrahedra(x).collect::<Vec<_>>() {
            heap.push((volume(chf, s).max(0.0).to_bits(), s));
        }
    }
    Ok(splits)
}

/// The smallest dihedral angle of a tetrahedron (radians): at each edge, the angle between
/// the two faces, measured across the edge's perpendicular plane.
fn min_dihedral(p: [DVec3; 4]) -> f64 {
    const EDGES: [[usize; 4]; 6] = [
        [0, 1, 2, 3],
        [0, 2, 1, 3],
        [0, 3, 1, 2],
        [1, 2, 0, 3],
        [1, 3, 0, 2],
        [2, 3, 0, 1],
    ];
    EDGES
        .iter()
        .map(|&[i, j, k, l]| {
            let e = p[j] - p[i];
            let (a, b) = (e.cross(p[k] - p[i]), e.cross(p[l] - p[i]));
            let c = a.dot(b) / (a.length() * b.length());
            if c.is_finite() {
                c.clamp(-1.0, 1.0).acos()
            } else {
                0.0
            }
        })
        .fold(f64::INFINITY, f64::min)
}

/// The smallest dihedral angle before and after the 2-3 flip of interior face `f`.
fn flip_gain(chf: &Chf, f: u32) -> Option<(f64, f64)> {
    let tri = chf.face_vertices(f);
    let tets: Vec<u32> = chf.face_tetrahedra(f).into_iter().collect();
    if tets.len() != 2 {
        return None;
    }
    let apex = |t: u32| {
        let q = chf.tetrahedron_vertices(t);
        q.into_iter().find(|x| !tri.contains(x))
    };
    let (a, b) = (apex(tets[0])?, apex(tets[1])?);
    let old = tets
        .iter()
        .map(|&t| min_dihedral(corners(chf, chf.tetrahedron_vertices(t))))
        .fold(f64::INFINITY, f64::min);
    let new = (0..3)
        .map(|i| min_dihedral(corners(chf, [tri[i], tri[(i + 1) % 3], a, b])))
        .fold(f64::INFINITY, f64::min);
    Some((old, new))
}

/// One pass of improving 2-3 flips over the faces of the tetrahedra around the vertices
/// from `first_new` on; returns the flips.
fn improve(chf: &mut Chf, first_new: u32) -> Result<usize, Error> {
    let mut faces: Vec<u32> = (first_new..chf.num_vertices() as u32)
        .flat_map(|x| chf.vertex_tetrahedra(x).collect::<Vec<_>>())
        .flat_map(|t| chf.tetrahedron_faces(t))
        .collect();
    faces.sort_unstable();
    faces.dedup();
    let mut flips = 0;
    for f in faces {
        if chf.is_face_removed(f) || chf.is_boundary_face(f) {
            continue;
        }
        let Some((old, new)) = flip_gain(chf, f) else {
            continue;
        };
        if new > old && chf.is_flip_23_ok(f)? {
            chf.flip_23(f)?;
            flips += 1;
        }
    }
    Ok(flips)
}
