//! Generated surfaces and volumes for tests, benchmarks, the CLI's default mesh and
//! `topomesh generate`: plain parametric grids with known topology. The `*_of` forms take
//! a size in elements, refuse one whose ids would not fit in 32 bits, and allocate
//! fallibly, so that a size too large for memory is an error, not an abort.

use crate::error::{Error, Result};
use crate::util::alloc::try_with_capacity;
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
    let mut v = Volume::default();
    cube_grid_into(&mut v, n);
    v
}

/// [`cube_grid`] appended to `v`.
fn cube_grid_into(v: &mut Volume, n: u32) {
    let grid = CubeGrid { n };
    let (n_points, n_tets) = (grid.num_points(), grid.num_tets());
    v.positions.extend((0..n_points).map(|k| grid.position(k)));
    v.tetrahedra
        .extend((0..n_tets).map(|t| grid.tetrahedron(t)));
}

/// The box of `n`^3 cubes element by element, so that a tetrahedron or a point is had
/// without the others: what [`cube_grid`] lists, and what a streaming build reads. Cubes
/// row by row, then layer by layer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CubeGrid {
    pub n: u32,
}

impl CubeGrid {
    /// The box [`cube_grid_of`] makes for at least `tetrahedra` tetrahedra.
    pub fn of(tetrahedra: u64) -> Result<CubeGrid> {
        check_size(tetrahedra, 4, "tetrahedra")?;
        let mut n = (tetrahedra as f64 / 6.0).cbrt().floor().max(1.0) as u64;
        while 6 * n * n * n < tetrahedra {
            n += 1;
        }
        check_size(6 * n * n * n, 4, "tetrahedra")?;
        Ok(CubeGrid { n: n as u32 })
    }

    fn num_points(&self) -> u32 {
        (self.n + 1).pow(3)
    }

    fn num_tets(&self) -> u32 {
        6 * self.n.pow(3)
    }

    /// Vertex `k`, the corner `(k % (n + 1), k / (n + 1) % (n + 1), k / (n + 1)^2)`.
    pub fn position(&self, k: u32) -> DVec3 {
        let m = self.n + 1;
        DVec3::new((k % m) as f64, (k / m % m) as f64, (k / (m * m)) as f64)
    }

    /// Tetrahedron `t`: the `t % 6`-th of cube `t / 6`, around the cube's main diagonal
    /// from corner `(i, j, k)` to `(i + 1, j + 1, k + 1)`.
    pub fn tetrahedron(&self, t: u32) -> [u32; 4] {
        const PATHS: [[u32; 2]; 6] = [[1, 2], [2, 1], [1, 4], [4, 1], [2, 4], [4, 2]];
        let (n, m) = (self.n, self.n + 1);
        let c = t / 6;
        let (i, j, k) = (c % n, c / n % n, c / (n * n));
        let corner = |b: u32| ((k + (b >> 2)) * m + j + (b >> 1 & 1)) * m + i + (b & 1);
        let [p, q] = PATHS[(t % 6) as usize];
        [corner(0), corner(p), corner(p | q), corner(7)]
    }
}

impl crate::Source<4> for CubeGrid {
    fn num_elements(&self) -> usize {
        self.num_tets() as usize
    }
    fn num_vertices(&self) -> usize {
        self.num_points() as usize
    }
    fn has_positions(&self) -> bool {
        true
    }
    fn elements(&self, first: usize, out: &mut [[u32; 4]]) -> Result<()> {
        for (t, x) in (first as u32..).zip(out) {
            *x = self.tetrahedron(t);
        }
        Ok(())
    }
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()> {
        for (k, x) in (first as u32..).zip(out) {
            *x = self.position(k);
        }
        Ok(())
    }
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
    let mut s = Surface::default();
    torus_into(&mut s, nu, nv);
    s
}

/// [`torus`] appended to the empty `s`.
fn torus_into(s: &mut Surface, nu: u32, nv: u32) {
    let grid = TorusGrid { nu, nv };
    s.positions.extend((0..nu * nv).map(|k| grid.position(k)));
    s.triangles
        .extend((0..2 * nu * nv).map(|t| grid.triangle(t)));
}

/// The torus of `nu` by `nv` quads element by element, so that a triangle or a point is
/// had without the others: what [`torus`] lists, and what a streaming build reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TorusGrid {
    pub nu: u32,
    pub nv: u32,
}

impl TorusGrid {
    /// The grid [`torus_of`] makes for at least `triangles` triangles.
    pub fn of(triangles: u64) -> Result<TorusGrid> {
        check_size(triangles, 3, "triangles")?;
        let quads = triangles.div_ceil(2).max(9);
        let nv = ((quads as f64 / 3.0).sqrt().ceil() as u64).max(3);
        let nu = quads.div_ceil(nv).max(3);
        check_size(2 * nu * nv, 3, "triangles")?;
        Ok(TorusGrid {
            nu: nu as u32,
            nv: nv as u32,
        })
    }

    /// Vertex `k`, the corner `(k % nu, k / nu)` of the grid.
    pub fn position(&self, k: u32) -> DVec3 {
        let (i, j) = (k % self.nu, k / self.nu);
        let (u, v) = (
            TAU * i as f64 / self.nu as f64,
            TAU * j as f64 / self.nv as f64,
        );
        let r = 2.0 + v.cos();
        DVec3::new(r * u.cos(), r * u.sin(), v.sin())
    }

    /// Triangle `t`: the first or second half of quad `t / 2` (row by row).
    pub fn triangle(&self, t: u32) -> [u32; 3] {
        let (nu, nv) = (self.nu, self.nv);
        let id = |i: u32, j: u32| (j % nv) * nu + (i % nu);
        let (i, j) = ((t / 2) % nu, (t / 2) / nu);
        let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
        if t.is_multiple_of(2) {
            [a, b, c]
        } else {
            [a, c, d]
        }
    }
}

impl crate::Source<3> for TorusGrid {
    fn num_elements(&self) -> usize {
        2 * self.nu as usize * self.nv as usize
    }
    fn num_vertices(&self) -> usize {
        self.nu as usize * self.nv as usize
    }
    fn has_positions(&self) -> bool {
        true
    }
    fn elements(&self, first: usize, out: &mut [[u32; 3]]) -> Result<()> {
        for (t, x) in (first as u32..).zip(out) {
            *x = self.triangle(t);
        }
        Ok(())
    }
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()> {
        for (k, x) in (first as u32..).zip(out) {
            *x = self.position(k);
        }
        Ok(())
    }
}

/// A sphere of `nu` meridians and `nv` bands (nu >= 3, nv >= 2) with two poles: closed,
/// genus 0.
pub fn sphere(nu: u32, nv: u32) -> Surface {
    let mut s = Surface::default();
    sphere_into(&mut s, nu, nv);
    s
}

/// [`sphere`] appended to the empty `s`.
fn sphere_into(s: &mut Surface, nu: u32, nv: u32) {
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
}

/// The largest number of elements of `k` vertices each whose ids (`k` per element: half-
/// edges, half-faces) fit in 32 bits.
fn most(k: u64) -> u64 {
    u64::from(u32::MAX - 1) / k
}

/// Refuses a size of zero or past the id range; `what` names the elements.
fn check_size(n: u64, k: u64, what: &str) -> Result<()> {
    if n == 0 || n > most(k) {
        return Err(Error::invalid(format!(
            "{n} {what}: give 1 to {} (ids are 32 bits)",
            most(k)
        )));
    }
    Ok(())
}

/// An empty surface with room for `n` positions and `m` triangles, or an out-of-memory
/// error.
fn surface_with_room(n: u64, m: u64) -> Result<Surface> {
    Ok(Surface {
        positions: try_with_capacity(n as usize, "the generated positions")?,
        triangles: try_with_capacity(m as usize, "the generated triangles")?,
    })
}

/// A torus of at least `triangles` triangles (and at least 18), its tube a third of its
/// ring in quads, as close to the count as the grid allows.
pub fn torus_of(triangles: u64) -> Result<Surface> {
    let TorusGrid { nu, nv } = TorusGrid::of(triangles)?;
    let (nu64, nv64) = (u64::from(nu), u64::from(nv));
    let mut s = surface_with_room(nu64 * nv64, 2 * nu64 * nv64)?;
    torus_into(&mut s, nu, nv);
    Ok(s)
}

/// A sphere of at least `triangles` triangles (and at least 12), twice as many meridians
/// as bands.
pub fn sphere_of(triangles: u64) -> Result<Surface> {
    check_size(triangles, 3, "triangles")?;
    // 2 nu (nv - 1) triangles with nu = 2 nv.
    let nv = ((((triangles as f64) / 4.0).sqrt()).ceil() as u64 + 1).max(2);
    let mut nu = (2 * nv).max(3);
    nu = nu.max(triangles.div_ceil(2 * (nv - 1)));
    check_size(2 * nu * (nv - 1), 3, "triangles")?;
    let mut s = surface_with_room(nu * (nv - 1) + 2, 2 * nu * (nv - 1))?;
    sphere_into(&mut s, nu as u32, nv as u32);
    Ok(s)
}

/// A box of `n`^3 cubes ([`cube_grid`]) with the smallest `n` giving at least
/// `tetrahedra` tetrahedra.
pub fn cube_grid_of(tetrahedra: u64) -> Result<Volume> {
    let CubeGrid { n } = CubeGrid::of(tetrahedra)?;
    let n = u64::from(n);
    let mut v = Volume {
        positions: try_with_capacity(
            ((n + 1) * (n + 1) * (n + 1)) as usize,
            "the generated positions",
        )?,
        tetrahedra: try_with_capacity((6 * n * n * n) as usize, "the generated tetrahedra")?,
    };
    cube_grid_into(&mut v, n as u32);
    Ok(v)
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

    /// The grid as a source reads, block by block, what `torus_of` lists.
    #[test]
    fn the_torus_grid_reads_what_torus_of_lists() {
        use crate::Source;
        let grid = TorusGrid::of(1000).unwrap();
        let listed = torus_of(1000).unwrap();
        let (mut tris, mut points) = (vec![[0; 3]; 7], vec![DVec3::ZERO; 5]);
        assert_eq!(grid.num_elements(), listed.triangles.len());
        assert_eq!(grid.num_vertices(), listed.positions.len());
        for first in [0, 13, listed.positions.len() - 5] {
            grid.elements(first, &mut tris).unwrap();
            grid.positions(first, &mut points).unwrap();
            assert_eq!(&tris[..], &listed.triangles[first..first + 7]);
            assert_eq!(&points[..], &listed.positions[first..first + 5]);
        }
    }

    /// The box as a source reads, block by block, what `cube_grid` lists: Kuhn's six
    /// tetrahedra per cube around its main diagonal, cubes row by row.
    #[test]
    fn the_cube_grid_reads_what_cube_grid_lists() {
        use crate::Source;
        let one = cube_grid(1);
        // Each a path along the cube's edges: corner 0, corners p and q, corner 7.
        let kuhn = [[1, 3], [2, 3], [1, 5], [4, 5], [2, 6], [4, 6]].map(|[p, q]| [0, p, q, 7]);
        assert_eq!(one.tetrahedra, kuhn);
        assert_eq!(one.positions[6], DVec3::new(0.0, 1.0, 1.0));
        let grid = CubeGrid::of(1000).unwrap();
        let listed = cube_grid_of(1000).unwrap();
        assert_eq!(grid.num_elements(), listed.tetrahedra.len());
        assert_eq!(grid.num_vertices(), listed.positions.len());
        // The second cube of the second row: cube (1, 1, 0) of a box of n = 6.
        assert_eq!(grid.n, 6);
        assert_eq!(listed.tetrahedra[6 * 7], [8, 9, 16, 65]);
        let (mut tets, mut points) = (vec![[0; 4]; 7], vec![DVec3::ZERO; 5]);
        for first in [0, 13, listed.positions.len() - 5] {
            grid.elements(first, &mut tets).unwrap();
            grid.positions(first, &mut points).unwrap();
            assert_eq!(&tets[..], &listed.tetrahedra[first..first + 7]);
            assert_eq!(&points[..], &listed.positions[first..first + 5]);
        }
    }

    /// The sized forms give at least the count asked (within a few percent above it on
    /// large counts), the shape's topology, and refuse zero and counts past the id range.
    #[test]
    fn sized_forms_reach_their_count() {
        for n in [1, 17, 100, 1000, 12345, 200_000] {
            let t = torus_of(n).unwrap();
            let s = sphere_of(n).unwrap();
            for (m, what) in [(t.triangles.len(), "torus"), (s.triangles.len(), "sphere")] {
                let m = m as u64;
                assert!(m >= n && m <= n + n / 20 + 64, "{what} of {n}: {m}");
            }
            if n <= 12345 {
                assert_eq!(chi(&t), (0, 1, 0), "torus of {n}");
                assert_eq!(chi(&s), (2, 0, 0), "sphere of {n}");
            }
            let b = cube_grid_of(n).unwrap();
            let k = b.tetrahedra.len() as u64;
            assert!(k >= n && (k == 6 || k < 2 * n + 6 * 64), "box of {n}: {k}");
        }
        assert_eq!(cube_grid_of(6000).unwrap().tetrahedra.len(), 6000);
        for bad in [0, most(3) + 1, u64::MAX] {
            let e = torus_of(bad).unwrap_err();
            assert!(e.message.contains("ids are 32 bits"), "{e}");
            assert!(sphere_of(bad).is_err() && cube_grid_of(bad).is_err());
        }
    }
}
