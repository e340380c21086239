//! Generated surfaces and volumes for tests, benchmarks and the CLI's default mesh: plain
//! parametric grids with known topology.

use glam::DVec3;
use std::f64::consts::TAU;

/// A triangle list with positions.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Surface {
    pub positions: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
}

/// A tetrahedron list with positions.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Volume {
    pub positions: Vec<DVec3>,
    pub tetrahedra: Vec<[u32; 4]>,
}

/// A box of `n`^3 unit cubes, six tetrahedra each around the cube's main diagonal (Kuhn's
/// subdivision, so neighbouring cubes meet face to face): a ball.
pub fn cube_grid(n: u32) -> Volume {
    let id = |i: u32, j: u32, k: u32| (k * (n + 1) + j) * (n + 1) + i;
    let mut v = Volume::default();
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                v.positions.push(DVec3::new(i as f64, j as f64, k as f64));
            }
        }
    }
    for (i, j, k) in (0..n).flat_map(|k| (0..n).flat_map(move |j| (0..n).map(move |i| (i, j, k)))) {
        let c = |b: u32| id(i + (b & 1), j + (b >> 1 & 1), k + (b >> 2));
        for [p, q] in [[1, 2], [2, 1], [1, 4], [4, 1], [2, 4], [4, 2]] {
            v.tetrahedra.push([c(0), c(p), c(p | q), c(7)]);
        }
    }
    v
}

/// An open `nx` by `ny` grid of quads, two triangles each: a disk with one boundary curve.
pub fn grid(nx: u32, ny: u32) -> Surface {
    let id = |i: u32, j: u32| j * (nx + 1) + i;
    let mut s = Surface::default();
    for j in 0..=ny {
        for i in 0..=nx {
            s.positions.push(DVec3::new(i as f64, j as f64, 0.0));
        }
    }
    push_quads(&mut s, nx, ny, id);
    s
}

/// Two triangles for each of the `nx` by `ny` quads, whose corner `(i, j)` is vertex
/// `id(i, j)`.
fn push_quads(s: &mut Surface, nx: u32, ny: u32, id: impl Fn(u32, u32) -> u32) {
    for j in 0..ny {
        for i in 0..nx {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s.triangles.push([a, b, c]);
            s.triangles.push([a, c, d]);
        }
    }
}

/// A torus of `nu` by `nv` quads (both at least 3): closed, genus 1.
pub fn torus(nu: u32, nv: u32) -> Surface {
    let id = |i: u32, j: u32| (j % nv) * nu + (i % nu);
    let mut s = Surface::default();
    for j in 0..nv {
        for i in 0..nu {
            let (u, v) = (TAU * i as f64 / nu as f64, TAU * j as f64 / nv as f64);
            let r = 2.0 + v.cos();
            s.positions
                .push(DVec3::new(r * u.cos(), r * u.sin(), v.sin()));
        }
    }
    push_quads(&mut s, nu, nv, id);
    s
}

/// A sphere of `nu` meridians and `nv` bands (nu >= 3, nv >= 2) with two poles: closed,
/// genus 0.
pub fn sphere(nu: u32, nv: u32) -> Surface {
    let mut s = Surface::default();
    s.positions.push(DVec3::new(0.0, 0.0, 1.0));
    for j in 1..nv {
        let theta = std::f64::consts::PI * j as f64 / nv as f64;
        for i in 0..nu {
            let phi = TAU * i as f64 / nu as f64;
            s.positions.push(DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            ));
        }
    }
    s.positions.push(DVec3::new(0.0, 0.0, -1.0));
    let south = s.positions.len() as u32 - 1;
    let ring = |j: u32, i: u32| 1 + (j - 1) * nu + (i % nu);
    for i in 0..nu {
        s.triangles.push([0, ring(1, i), ring(1, i + 1)]);
    }
    for j in 1..nv - 1 {
        for i in 0..nu {
            let (a, b, c, d) = (
                ring(j, i),
                ring(j + 1, i),
                ring(j + 1, i + 1),
                ring(j, i + 1),
            );
            s.triangles.push([a, b, c]);
            s.triangles.push([a, c, d]);
        }
    }
    for i in 0..nu {
        s.triangles
            .push([south, ring(nv - 1, i + 1), ring(nv - 1, i)]);
    }
    s
}

/// A surface as OFF text.
pub fn to_off(s: &Surface) -> String {
    use std::fmt::Write;
    let mut out = format!("OFF\n{} {} 0\n", s.positions.len(), s.triangles.len());
    for p in &s.positions {
        let _ = writeln!(out, "{} {} {}", p.x, p.y, p.z);
    }
    for t in &s.triangles {
        let _ = writeln!(out, "3 {} {} {}", t[0], t[1], t[2]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BuildOptions, Che};

    fn chi(s: &Surface) -> (i64, i64, u64) {
        let che = Che::from_triangles(
            &s.triangles,
            s.positions.len(),
            &s.positions,
            BuildOptions::level(3),
        )
        .unwrap();
        let sum = che.summary();
        (sum.euler_characteristic, sum.genus, sum.boundary_curves)
    }

    #[test]
    fn generated_surfaces_have_their_topology() {
        assert_eq!(chi(&grid(4, 3)), (1, 0, 1));
        assert_eq!(chi(&torus(5, 4)), (0, 1, 0));
        assert_eq!(chi(&sphere(6, 4)), (2, 0, 0));
    }
}
