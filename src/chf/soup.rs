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

use super::report::{ChfBuildReport, push_example};
use crate::error::{Error, Result};
use glam::DVec3;

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

pub(crate) fn soup(
    tets: &[[u32; 4]],
    n_vertices: usize,
    positions: &[DVec3],
    report: &mut ChfBuildReport,
) -> Result<Soup> {
    let mut v: Vec<u32> = crate::pages::with_capacity(4 * tets.len());
    // Stays empty (the identity) until the first dropped tetrahedron.
    let mut tet_origin: Vec<u32> = Vec::new();
    let mut remapped = false;
    let mut sign: Vec<i8> = Vec::with_capacity(if positions.is_empty() { 0 } else { tets.len() });
    let mut flipped = 0;
    for (t, tet) in tets.iter().enumerate() {
        if tet.iter().any(|&x| x as usize >= n_vertices) {
            let i = tet
                .iter()
                .position(|&x| x as usize >= n_vertices)
                .unwrap_or(0);
            return Err(Error::out_of_range(format!(
                "tetrahedron {t}, corner {i}: vertex {} out of range (there are {n_vertices} vertices)",
                tet[i]
            )));
        }
        let [a, b, c, d] = *tet;
        if a == b || a == c || a == d || b == c || b == d || c == d {
            if !remapped {
                remapped = true;
                tet_origin.extend(0..t as u32);
            }
            report.dropped_degenerate += 1;
            push_example(&mut report.degenerate_examples, t as u32);
            continue;
        }
        if remapped {
            tet_origin.push(t as u32);
        }
        if positions.is_empty() {
            v.extend_from_slice(tet);
            continue;
        }
        let [p0, p1, p2, p3] = tet.map(|x| positions[x as usize]);
        let det = (p1 - p0).dot((p2 - p0).cross(p3 - p0));
        let s = if det > 0.0 {
            1
        } else if det < 0.0 {
            -1
        } else {
            report.zero_volume += 1;
            push_example(&mut report.zero_volume_examples, t as u32);
            0
        };
        sign.push(s);
        if s < 0 {
            flipped += 1;
            v.extend_from_slice(&[a, c, b, d]);
        } else {
            v.extend_from_slice(tet);
        }
    }
    Ok(Soup {
        v,
        tet_origin,
        sign,
        flipped,
    })
}

impl Soup {
    /// Is structure tetrahedron `t` flipped here?
    #[inline]
    pub(crate) fn is_flipped(&self, t: u32) -> bool {
        !self.sign.is_empty() && self.sign[t as usize] < 0
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
