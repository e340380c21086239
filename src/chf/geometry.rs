//! The orientation test of the build (soup pass) and the edits: a tetrahedron is positive when
//! `det(p1 - p0, p2 - p0, p3 - p0) > 0` (its faces then run outward, see `ids.rs`).

use glam::DVec3;

/// Six times the signed volume of `(a, b, c, d)`.
#[inline]
pub(crate) fn orient(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> f64 {
    (b - a).dot((c - a).cross(d - a))
}

/// The signed volume test of tetrahedron `q` with positions from `at`.
pub(crate) fn orient_of(q: [u32; 4], at: impl Fn(u32) -> DVec3) -> f64 {
    orient(at(q[0]), at(q[1]), at(q[2]), at(q[3]))
}
