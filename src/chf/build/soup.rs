//! The soup: range check, degenerate tetrahedra dropped, determinant signs, and every
//! tetrahedron with a negative determinant flipped (local vertices 1 and 2 swapped).
//!
//! Why flip before matching: on a valid mesh the orientation pass then has nothing to do
//! (every matched pair already runs opposite), which the build checks from the matching
//! alone and skips it. That is exactly what the propagation in `orient.rs` would decide:
//! it flips a tetrahedron when its determinant disagrees with its component's majority,
//! and with every pair opposite after this flip the majority is positive everywhere. When
//! some pair still runs the same way the build undoes the flip ([`Soup::unflip`]) and
//! orients by propagation from the input as given.

use crate::chf::build::report::{BuildReport, push_example};
use crate::error::{Error, Result};
use crate::util::alloc::{try_extend, try_push, try_vec};
use glam::DVec3;
use std::borrow::Cow;

pub(crate) struct Soup {
    /// `V`, flipped where the determinant is negative.
    pub v: Vec<u32>,
    /// Structure tetrahedron -> input tetrahedron; empty when the identity.
    pub tet_origin: Vec<u32>,
    /// Sign of each tetrahedron's determinant as given; empty without positions.
    pub sign: Vec<i8>,
    /// Tetrahedra flipped here.
    pub flipped: usize,
}

/// What one run of tetrahedra found.
#[derive(Default)]
pub(crate) struct Run {
    /// The first out-of-range id: the run stops there.
    pub error: Option<Error>,
    /// Degenerate tetrahedra (input ids, increasing): their slots in `V` hold nothing.
    pub dropped: Vec<u32>,
    pub zero_volume: usize,
    pub zero_volume_examples: Vec<u32>,
    pub flipped: usize,
}

/// Runs of tetrahedra on up to `threads` threads, each checking (and flipping) its own part
/// of `V` and writing its part of the signs; degenerate ones leave a hole, closed afterwards
/// by one pass when there is any. Tetrahedra handed over as a `Vec` become `V` in place;
/// borrowed ones are copied into it run by run.
pub(crate) fn soup(
    tets: Cow<'_, [[u32; 4]]>, n_vertices: usize, positions: &[DVec3], report: &mut BuildReport,
    threads: usize,
) -> Result<Soup> {
    let n = tets.len();
    let chunk = n.div_ceil(threads.max(1)).max(1);
    let (mut v, source) = match tets {
        Cow::Owned(t) => (t.into_flattened(), None),
        Cow::Borrowed(t) => (
            crate::util::pages::zeroed(4 * n, "the tetrahedron vertices V")?,
            Some(t),
        ),
    };
    let n_signs = if positions.is_empty() { 0 } else { n };
    let mut sign: Vec<i8> = try_vec(n_signs, 0, "the determinant signs")?;
    let mut sign_parts: Vec<&mut [i8]> = if positions.is_empty() {
        v.chunks(4 * chunk).map(|_| &mut [][..]).collect()
    } else {
        sign.chunks_mut(chunk).collect()
    };
    let jobs: Vec<_> = v
        .chunks_mut(4 * chunk)
        .zip(sign_parts.drain(..))
        .enumerate()
        .map(|(j, (v, sign))| {
            let t0 = j * chunk;
            (t0, source.map(|s| &s[t0..][..v.len() / 4]), v, sign)
        })
        .collect();
    let runs = crate::util::par::run_all(jobs, |(t0, tets, v, sign)| {
        run(t0, tets, v, sign, n_vertices, positions)
    });
    let mut dropped: Vec<u32> = Vec::new();
    let mut flipped = 0;
    for r in runs {
        if let Some(e) = r.error {
            return Err(e);
        }
        report.dropped_degenerate += r.dropped.len();
        crate::util::extend_examples(&mut report.degenerate_examples, r.dropped.iter().copied());
        try_extend(&mut dropped, r.dropped, "the dropped tetrahedra")?;
        report.zero_volume += r.zero_volume;
        crate::util::extend_examples(&mut report.zero_volume_examples, r.zero_volume_examples);
        flipped += r.flipped;
    }
    // Stays empty (the identity) unless a tetrahedron was dropped.
    let tet_origin = if dropped.is_empty() {
        Vec::new()
    } else {
        crate::util::holes::close_holes(&mut v, 4, &mut sign, &dropped)?
    };
    Ok(Soup {
        v,
        tet_origin,
        sign,
        flipped,
    })
}

/// One run: the tetrahedra from input id `t0` on, in `v` (four per tetrahedron; copied from
/// `tets` first when borrowed), and their `sign` (empty without positions).
pub(crate) fn run(
    t0: usize, tets: Option<&[[u32; 4]]>, v: &mut [u32], sign: &mut [i8], n_vertices: usize,
    positions: &[DVec3],
) -> Run {
    let mut out = Run::default();
    for (k, q) in v.chunks_exact_mut(4).enumerate() {
        let t = t0 + k;
        if let Some(tets) = tets {
            q.copy_from_slice(&tets[k]);
        }
        let tet = &[q[0], q[1], q[2], q[3]];
        if let Some(i) = tet.iter().position(|&x| x as usize >= n_vertices) {
            out.error = Some(Error::out_of_range(format!(
                "tetrahedron {t}, corner {i}: vertex {} out of range (there are {n_vertices} vertices)",
                tet[i]
            )));
            return out;
        }
        let [a, b, c, d] = *tet;
        if a == b || a == c || a == d || b == c || b == d || c == d {
            if let Err(e) = try_push(&mut out.dropped, t as u32, "the dropped tetrahedra") {
                out.error = Some(e);
                return out;
            }
            continue;
        }
        if positions.is_empty() {
            continue;
        }
        let [p0, p1, p2, p3] = tet.map(|x| positions[x as usize]);
        let det = crate::chf::geometry::orient(p0, p1, p2, p3);
        // A non-finite corner makes the determinant NaN or infinite; it has no sign then
        // (the report counts those vertices), while finite corners whose determinant
        // overflows keep the sign of the overflow.
        let s = if !det.is_finite() && [p0, p1, p2, p3].iter().any(|p| !p.is_finite()) {
            0
        } else if det > 0.0 {
            1
        } else if det < 0.0 {
            -1
        } else {
            out.zero_volume += 1;
            push_example(&mut out.zero_volume_examples, t as u32);
            0
        };
        sign[k] = s;
        if s < 0 {
            out.flipped += 1;
            q.copy_from_slice(&[a, c, b, d]);
        }
    }
    out
}

impl Soup {
    /// Is structure tetrahedron `t` flipped here?
    #[inline]
    pub(crate) fn is_flipped(&self, t: u32) -> bool {
        self.flipped != 0 && self.sign[t as usize] < 0
    }

    /// The tetrahedra of negative determinant as they stand (none once the soup's flips
    /// are applied): their count and first examples, named by `origin_of`.
    pub(crate) fn negative(&self, origin_of: impl Fn(u32) -> u32) -> (usize, Vec<u32>) {
        let (mut count, mut examples) = (0, Vec::new());
        for (t, &s) in self.sign.iter().enumerate() {
            if s < 0 && !self.is_flipped(t as u32) {
                count += 1;
                push_example(&mut examples, origin_of(t as u32));
            }
        }
        (count, examples)
    }

    /// Back to the input's orientation.
    pub(crate) fn unflip(&mut self) {
        if self.flipped == 0 {
            return;
        }
        for (q, &s) in self.v.chunks_exact_mut(4).zip(&self.sign) {
            if s < 0 {
                q.swap(1, 2);
            }
        }
        self.flipped = 0;
    }
}
