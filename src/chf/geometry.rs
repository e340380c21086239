//! The orientation test of the build (soup pass) and the edits: a tetrahedron is positive when
//! `det(p1 - p0, p2 - p0, p3 - p0) > 0` (its faces then run outward, see `ids.rs`).
//!
//! The sign is exact (Shewchuk's adaptive `orient3d`, from the `robust` crate): a rounded
//! determinant can call a nearly flat tetrahedron positive when it is inverted, and an edit
//! accepted on that sign would leave an inverted tetrahedron behind (CGAL's predicates are
//! exact too, and the differential tests compare with them).

use glam::DVec3;
use robust::{Coord3D, orient3d};

/// Six times the signed volume of `(a, b, c, d)` (approximately), with the exact sign. Where the rounded
/// determinant is not finite (a non-finite corner, or finite corners whose product
/// overflows) it is returned as it is: the exact predicate has no answer there either, and
/// the callers give such a value its own meaning.
#[inline]
pub(crate) fn orient(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> f64 {
    let det = (b - a).dot((c - a).cross(d - a));
    if !det.is_finite() {
        return det;
    }
    let p = |v: DVec3| Coord3D {
        x: v.x,
        y: v.y,
        z: v.z,
    };
    // Shewchuk's `orient3d(a, b, c, d)` is `det(a - d, b - d, c - d)`, the opposite sign.
    -orient3d(p(a), p(b), p(c), p(d))
}

/// The signed volume test of tetrahedron `q` with positions from `at`.
pub(crate) fn orient_of(q: [u32; 4], at: impl Fn(u32) -> DVec3) -> f64 {
    orient(at(q[0]), at(q[1]), at(q[2]), at(q[3]))
}

#[cfg(test)]
mod tests {
    use super::orient;
    use glam::DVec3;

    #[test]
    fn the_unit_tetrahedron_is_positive_and_its_mirror_negative() {
        let (o, x, y, z) = (DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z);
        assert_eq!(orient(o, x, y, z), 1.0);
        assert_eq!(orient(o, y, x, z), -1.0);
        assert_eq!(orient(o, x, 2.0 * x, y), 0.0);
    }

    #[test]
    fn a_nearly_flat_tetrahedron_gets_its_exact_sign() {
        // d is a hair off the plane of a, b, c: the rounded determinant is +2.6e-26, the
        // exact one -2.5e-29 (found by comparing with rational arithmetic).
        let a = DVec3::splat(0.9818444667374244);
        let b = DVec3::new(0.982713991284183, 0.982633764602436, 0.9818444667374244);
        let c = DVec3::new(0.9823502009734625, 0.9818444667374244, 0.9820564251276062);
        let d = DVec3::new(0.9828001350092604, 0.9824288549021548, 0.9819751792885298);
        assert!(
            (b - a).dot((c - a).cross(d - a)) > 0.0,
            "the rounded sign is wrong"
        );
        assert!(orient(a, b, c, d) < 0.0);
        assert!(orient(a, c, b, d) > 0.0);
    }

    #[test]
    fn an_overflowing_determinant_keeps_its_rounded_value() {
        let big = 1e200;
        let o = orient(DVec3::ZERO, DVec3::X * big, DVec3::Y * big, DVec3::Z * big);
        assert_eq!(o, f64::INFINITY);
    }
}
