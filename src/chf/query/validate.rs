//! The invariant checker: every rule the structure's arrays obey at its level, checked in
//! O(T) (one star pass recomputes the pairs and the edge slots to compare), the first
//! violation returned with the element and what is wrong.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{face_cycle, same_direction, sorted_triple};
use crate::chf::star_pass::{self, Pairs, StarPass};
use crate::error::{Error, Result};
use crate::util::alloc::{try_collect, try_vec};
use crate::util::origin::increasing_below_violation;

/// Which vertices of `chf` lie on one of the half-faces `hfs` (the unpaired ones: the
/// boundary vertices).
pub(crate) fn vertices_on(chf: &Chf, hfs: impl Iterator<Item = u32>) -> Result<Vec<bool>> {
    let mut on = try_vec(chf.n_vertices, false, "the boundary vertices")?;
    for hf in hfs {
        for x in face_cycle(&chf.v, hf) {
            on[x as usize] = true;
        }
    }
    Ok(on)
}

/// The first violation, as an error naming the structure.
fn broken(what: String) -> Result<()> {
    Err(Error::invalid(format!("invalid CHF: {what}")))
}

/// `Err` unless the array `name` has one entry for each of the `n` elements (`of`).
fn ensure_len(name: &str, len: usize, n: usize, of: &str) -> Result<()> {
    ensure(len == n, || {
        format!("{name} has {len} entries for {n} {of}")
    })
}

/// `Err` unless the stored list `got` is the recomputed `want`; `what` gives the detail
/// from both lengths.
fn ensure_same(got: &[u32], want: &[u32], what: impl FnOnce(usize, usize) -> String) -> Result<()> {
    ensure(got == want, || what(got.len(), want.len()))
}

/// `Err` unless a directory of `kind` sets one bit (`ones` in all) for each of `n` elements.
fn ensure_ones(kind: &str, ones: usize, n: usize) -> Result<()> {
    ensure(ones == n, || format!("{ones} {kind} bits for {n} {kind}s"))
}

/// `Err` with `what` unless `ok`.
fn ensure(ok: bool, what: impl FnOnce() -> String) -> Result<()> {
    if ok { Ok(()) } else { broken(what()) }
}

/// `Err` unless `xs` increases strictly and stays below `n`.
fn increasing_below(xs: &[u32], n: usize, name: &str) -> Result<()> {
    increasing_below_violation(xs, n, name).map_or(Ok(()), broken)
}

impl Chf {
    /// Checks every invariant of the structure at its level and returns the first
    /// violation (an [`ErrorKind::InvalidInput`](crate::ErrorKind::InvalidInput) error whose
    /// message names the element and what is wrong):
    /// - `V`: ids in range, no tetrahedron with a repeated vertex;
    /// - the maps: vertex and tetrahedron origins, positions, the flagged half-faces;
    /// - `O` (level 1): an involution pairing half-faces on the same vertex triple running
    ///   opposite ways, never a flagged one, and the pairs the rule gives;
    /// - faces and edges: the counts, and at level 2 the rank bits, `FH`, the edge slots
    ///   and `VH` (a half-face holding its vertex, a boundary one exactly on boundary
    ///   vertices, `NONE` on isolated vertices);
    /// - level 3: the boundary surface is the unpaired half-faces, with its vertex maps
    ///   and components.
    ///
    /// O(T) time and memory.
    pub fn validate(&self) -> Result<()> {
        if self.edit.is_some() {
            return self.validate_edited();
        }
        self.validate_tetrahedra()?;
        self.validate_maps()?;
        // The pairs and the edge slots by the rule, from `V` alone.
        let flagged = star_pass::merged(&self.non_manifold, &self.seams)?;
        // The build's own pass, on the threads a build of this size takes (its result
        // does not depend on them): a full open runs it.
        let pass = StarPass {
            pairs: Pairs::Opposites,
            tables: true,
            threads: crate::util::par::planned_threads(0, self.num_tetrahedra()),
        };
        let rule = star_pass::stars(&self.v, self.n_vertices, &flagged, pass)?;
        let rule_o = rule.faces.as_ref().map_or(&[][..], |(_, o)| &o[..]);
        if self.level >= 1 {
            self.validate_opposites(&flagged, rule_o)?;
        }
        let o = if self.level >= 1 { &self.o[..] } else { rule_o };
        let canonical = |hf: usize| o[hf] == NONE || (hf as u32) < o[hf];
        let faces = (0..o.len()).filter(|&hf| canonical(hf)).count();
        ensure(faces == self.num_faces, || {
            format!(
                "{} faces counted, {faces} canonical half-faces",
                self.num_faces
            )
        })?;
        ensure(rule.num_edges == self.num_edges, || {
            format!("{} edges counted, {} fans", self.num_edges, rule.num_edges)
        })?;
        if self.level >= 2 {
            self.validate_faces(&canonical)?;
            self.validate_edges(&rule.edge_bits)?;
            self.validate_vertex_half_faces(o)?;
        }
        ensure((self.level >= 3) == self.boundary.is_some(), || {
            format!(
                "level {} with the boundary surface: {}",
                self.level,
                self.boundary.is_some()
            )
        })?;
        if self.level >= 3 {
            self.validate_boundary(o)?;
        }
        Ok(())
    }

    /// `V`: ids below the vertex count, four distinct per tetrahedron.
    fn validate_tetrahedra(&self) -> Result<()> {
        ensure(self.v.len().is_multiple_of(4), || {
            format!("V has {} ids, not a multiple of 4", self.v.len())
        })?;
        ensure(self.level <= 3, || {
            format!("level {} is not in 0..=3", self.level)
        })?;
        for (t, q) in self.v.chunks_exact(4).enumerate() {
            for (i, &x) in q.iter().enumerate() {
                ensure((x as usize) < self.n_vertices, || {
                    format!(
                        "V[{}] = {x}: vertex out of range (the mesh has {} vertices)",
                        4 * t + i,
                        self.n_vertices
                    )
                })?;
                ensure(!q[..i].contains(&x), || {
                    format!("tetrahedron {t} {q:?} is degenerate (vertex {x} twice)")
                })?;
            }
        }
        Ok(())
    }

    /// The origin maps, the positions and the flagged half-faces.
    fn validate_maps(&self) -> Result<()> {
        let (n, n_input) = (self.n_vertices, self.n_input_vertices);
        if let Some(what) = self.vertex_origin.vertex_violation(n, n_input) {
            return broken(what);
        }
        let n_tets = self.num_tetrahedra();
        ensure(
            self.tet_origin.is_empty() || self.tet_origin.len() == n_tets,
            || {
                format!(
                    "{} tetrahedron origins for {n_tets} tetrahedra",
                    self.tet_origin.len()
                )
            },
        )?;
        let n_input_tets = self.report.input_tetrahedra.max(n_tets);
        increasing_below(&self.tet_origin, n_input_tets, "tetrahedron origin")?;
        let p = &self.positions;
        ensure(p.is_empty() || p.len() == n, || {
            format!("{} positions for {n} vertices", p.len())
        })?;
        // A copy holds its origin's coordinates bit for bit: a NaN one (the input may
        // have them; the build warns) equals itself here, as `==` would not have it.
        let bits = |q: glam::DVec3| q.to_array().map(f64::to_bits);
        for v in n_input..p.len() {
            let x = self.vertex_origin(v as u32) as usize;
            ensure(bits(p[v]) == bits(p[x]), || {
                format!("copy {v} is not at its origin {x}'s position")
            })?;
        }
        increasing_below(&self.non_manifold, self.v.len(), "non-manifold half-face")?;
        increasing_below(&self.seams, self.v.len(), "seam half-face")
    }

    /// `O`: an involution on the same vertex triple, opposite ways, the flagged half-faces
    /// unpaired, and what the rule pairs (`rule`).
    fn validate_opposites(&self, flagged: &[u32], rule: &[u32]) -> Result<()> {
        let o = &self.o;
        ensure_len("O", o.len(), self.v.len(), "half-faces")?;
        // The rule's pairs are twins on one vertex triple, run opposite ways, never on a
        // flagged half-face (a build stores them): `O` equal to them holds every check
        // below, and one sequential comparison settles it. Otherwise the checks run in
        // order, so that the error names the first broken pair as it did.
        if o.len() == rule.len() && o[..] == *rule {
            return Ok(());
        }
        for (h, &g) in o.iter().enumerate() {
            let h = h as u32;
            if g == NONE {
                continue;
            }
            ensure((g as usize) < o.len() && g != h, || format!("O[{h}] = {g}"))?;
            ensure(o[g as usize] == h, || {
                format!("O[{h}] = {g} but O[{g}] = {}", o[g as usize])
            })?;
            ensure(
                sorted_triple(&self.v, h) == sorted_triple(&self.v, g),
                || format!("half-faces {h} and {g} are twins on different vertex triples"),
            )?;
            ensure(!same_direction(&self.v, h, g), || {
                format!("twin half-faces {h} and {g} run the same way")
            })?;
            ensure(flagged.binary_search(&h).is_err(), || {
                format!("half-face {h} is non-manifold or a seam but has a twin")
            })?;
        }
        for (h, (&g, &r)) in o.iter().zip(rule).enumerate() {
            ensure(g == r, || {
                format!("O[{h}] = {g}, the pairing rule gives {r}")
            })?;
        }
        Ok(())
    }

    /// Level 2's faces: a bit on each canonical half-face, `FH` the canonical half-faces
    /// in order.
    fn validate_faces(&self, canonical: &impl Fn(usize) -> bool) -> Result<()> {
        ensure_ones("face", self.face_bits.ones(), self.num_faces)?;
        ensure_len("FH", self.fh.len(), self.num_faces, "faces")?;
        let mut f = 0;
        for hf in 0..self.v.len() {
            ensure(self.face_bits.get(hf) == canonical(hf), || {
                format!("face bit of half-face {hf} is {}", self.face_bits.get(hf))
            })?;
            if canonical(hf) {
                ensure(self.fh[f] as usize == hf, || {
                    format!("FH[{f}] = {}, the canonical half-face is {hf}", self.fh[f])
                })?;
                f += 1;
            }
        }
        Ok(())
    }

    /// Level 2's edges: the canonical slots the rule gives (`rule`), `EH` the tetrahedron
    /// of each.
    fn validate_edges(&self, rule: &crate::util::rank::RankBits) -> Result<()> {
        let n_slots = 6 * self.num_tetrahedra();
        ensure_ones("edge", self.edge_bits.ones(), self.num_edges)?;
        ensure_len("EH", self.eh.len(), self.num_edges, "edges")?;
        let mut e = 0;
        for s in 0..n_slots {
            let bit = self.edge_bits.get(s);
            ensure(bit == rule.get(s), || {
                format!(
                    "edge bit of slot {s} is {bit}, the rule gives {}",
                    rule.get(s)
                )
            })?;
            if bit {
                ensure(self.eh[e] as usize == s / 6, || {
                    format!(
                        "EH[{e}] = {}, the canonical slot is in tetrahedron {}",
                        self.eh[e],
                        s / 6
                    )
                })?;
                e += 1;
            }
        }
        Ok(())
    }

    /// `VH`: a half-face holding its vertex, unpaired exactly on boundary vertices, `NONE`
    /// exactly on isolated ones.
    fn validate_vertex_half_faces(&self, o: &[u32]) -> Result<()> {
        let vh = &self.vh;
        ensure_len("VH", vh.len(), self.n_vertices, "vertices")?;
        let mut used = try_vec(self.n_vertices, false, "the used vertices")?;
        let mut boundary = try_vec(self.n_vertices, false, "the boundary vertices")?;
        for &x in self.v.iter() {
            used[x as usize] = true;
        }
        for hf in (0..o.len() as u32).filter(|&hf| o[hf as usize] == NONE) {
            for x in face_cycle(&self.v, hf) {
                boundary[x as usize] = true;
            }
        }
        for (v, &hf) in vh.iter().enumerate() {
            if hf == NONE {
                ensure(!used[v], || {
                    format!("VH[{v}] = NONE on a vertex with tetrahedra")
                })?;
                continue;
            }
            ensure(
                (hf as usize) < o.len() && face_cycle(&self.v, hf).contains(&(v as u32)),
                || format!("VH[{v}] = {hf}, a half-face without vertex {v}"),
            )?;
            ensure((o[hf as usize] == NONE) == boundary[v], || {
                format!(
                    "VH[{v}] = {hf}: unpaired {}, boundary vertex {}",
                    o[hf as usize] == NONE,
                    boundary[v]
                )
            })?;
        }
        Ok(())
    }

    /// Level 3: triangle `k` is the `k`-th unpaired half-face, over the boundary vertices
    /// in increasing order, one component per connected piece.
    fn validate_boundary(&self, o: &[u32]) -> Result<()> {
        let Some(b) = &self.boundary else {
            return Ok(());
        };
        let unpaired = (0..o.len() as u32).filter(|&h| o[h as usize] == NONE);
        let unpaired = try_collect(unpaired, "the unpaired half-faces")?;
        ensure_same(&b.half_faces, &unpaired, |t, u| {
            format!("{t} boundary triangles for {u} unpaired half-faces")
        })?;
        let flagged = self.non_manifold.len() + self.seams.len();
        ensure(b.true_faces + flagged == unpaired.len(), || {
            format!(
                "{} boundary faces with {flagged} flagged half-faces, {} unpaired",
                b.true_faces,
                unpaired.len()
            )
        })?;
        for (h, &g) in o.iter().enumerate() {
            ensure(
                b.bits.as_ref().is_some_and(|b| b.get(h)) == (g == NONE),
                || format!("boundary bit of half-face {h}"),
            )?;
        }
        let vertices = self.validate_boundary_vertices(&unpaired)?;
        self.validate_boundary_surface(&unpaired, &vertices)
    }

    /// Level 3's boundary vertices: the vertices of the unpaired half-faces (returned), in
    /// increasing order, with their bits and a component each.
    fn validate_boundary_vertices(&self, unpaired: &[u32]) -> Result<Vec<u32>> {
        let Some(b) = &self.boundary else {
            return Ok(Vec::new());
        };
        let on = vertices_on(self, unpaired.iter().copied())?;
        let vertices = (0..self.n_vertices as u32).filter(|&v| on[v as usize]);
        let vertices = try_collect(vertices, "the boundary vertices")?;
        ensure_same(&b.vertices, &vertices, |b, v| {
            format!("{b} boundary vertices, {v} vertices on unpaired half-faces")
        })?;
        for (v, &on) in on.iter().enumerate() {
            ensure(
                b.vertex_bits.as_ref().is_some_and(|b| b.get(v)) == on,
                || format!("boundary bit of vertex {v}"),
            )?;
        }
        ensure(b.component.len() == vertices.len(), || {
            format!(
                "{} component ids for {} boundary vertices",
                b.component.len(),
                vertices.len()
            )
        })?;
        Ok(vertices)
    }

    /// Level 3's surface: triangle `k` runs as the `k`-th unpaired half-face, over boundary
    /// vertices of one component.
    fn validate_boundary_surface(&self, unpaired: &[u32], vertices: &[u32]) -> Result<()> {
        let Some(b) = &self.boundary else {
            return Ok(());
        };
        let che = &b.che;
        ensure(che.num_triangles() == unpaired.len(), || {
            format!(
                "the surface has {} triangles for {} unpaired half-faces",
                che.num_triangles(),
                unpaired.len()
            )
        })?;
        for c in 0..che.num_vertices() as u32 {
            let x = che.vertex_origin(c);
            ensure((x as usize) < vertices.len(), || {
                format!("surface vertex {c} has origin {x}, not a boundary vertex")
            })?;
        }
        for (k, &hf) in unpaired.iter().enumerate() {
            let tri = che
                .triangle_vertices(k as u32)
                .map(|c| che.vertex_origin(c));
            let cycle = face_cycle(&self.v, hf);
            ensure(tri.map(|x| vertices[x as usize]) == cycle, || {
                format!("boundary triangle {k} is not half-face {hf} {cycle:?}")
            })?;
            let comp = b.component[tri[0] as usize];
            ensure(
                (comp as usize) < b.components
                    && tri.iter().all(|&x| b.component[x as usize] == comp),
                || format!("boundary triangle {k} has vertices in different components"),
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chf::BuildOptions;

    /// Two boxes of six tetrahedra sharing a vertex (so a split), level 3.
    fn mesh() -> Chf {
        let kuhn = [
            [0, 1, 3, 7],
            [0, 1, 5, 7],
            [0, 2, 3, 7],
            [0, 2, 6, 7],
            [0, 4, 5, 7],
            [0, 4, 6, 7],
        ];
        let mut tets: Vec<[u32; 4]> = kuhn.to_vec();
        tets.extend(
            kuhn.iter()
                .map(|t| t.map(|x| if x == 7 { 7 } else { x + 8 })),
        );
        for t in &mut tets {
            t.swap(2, 3);
        }
        Chf::from_tetrahedra(&tets, 15, &[], BuildOptions::level(3)).unwrap()
    }

    fn fails(chf: &Chf, needle: &str) {
        let e = chf.validate().expect_err(needle);
        assert_eq!(e.kind, crate::ErrorKind::InvalidInput);
        assert!(
            e.message.contains(needle),
            "{needle:?} not in {:?}",
            e.message
        );
    }

    #[test]
    fn a_build_passes_at_every_level() {
        let chf = mesh();
        assert!(chf.num_vertices() > 15, "the shared vertex is split");
        for level in [3, 2, 1, 0, 3] {
            let mut c = chf.clone();
            c.build_level(level).unwrap();
            c.validate().unwrap();
        }
    }

    #[test]
    fn each_array_corrupted_fails() {
        let chf = mesh();
        let mut c = chf.clone();
        c.v.to_mut("test").unwrap()[5] = 99;
        fails(&c, "V[5] = 99");
        let mut c = chf.clone();
        c.v.to_mut("test").unwrap()[5] = c.v[4];
        fails(&c, "degenerate");
        let mut c = chf.clone();
        let mut map = c.vertex_origin.to_vec();
        map[0] = 3;
        c.vertex_origin = map.into();
        fails(&c, "vertex 0 has origin 3");
        let mut c = chf.clone();
        c.tet_origin = vec![1, 0].into();
        fails(&c, "tetrahedron origins");
        let mut c = chf.clone();
        c.seams = vec![4, 2];
        fails(&c, "does not increase");
        let paired = chf.o.iter().position(|&g| g != NONE).unwrap();
        let mut c = chf.clone();
        c.o.to_mut("test").unwrap()[paired] = NONE;
        fails(&c, &format!("O[{}]", chf.o[paired]));
        let mut c = chf.clone();
        let g = c.o[paired] as usize;
        c.o.to_mut("test").unwrap().swap(paired, g);
        fails(&c, "O[");
        let mut c = chf.clone();
        c.num_faces += 1;
        fails(&c, "faces counted");
        let mut c = chf.clone();
        c.num_edges += 1;
        fails(&c, "edges counted");
        let mut c = chf.clone();
        c.fh.to_mut("test").unwrap().swap(0, 1);
        fails(&c, "FH[0]");
        let mut c = chf.clone();
        c.eh.to_mut("test").unwrap()[0] ^= 1;
        fails(&c, "EH[0]");
        let mut c = chf.clone();
        c.vh.to_mut("test").unwrap()[0] = NONE;
        fails(&c, "VH[0] = NONE");
        let mut c = chf.clone();
        let foreign = (0..c.v.len() as u32)
            .find(|&h| !face_cycle(&c.v, h).contains(&0))
            .unwrap();
        c.vh.to_mut("test").unwrap()[0] = foreign;
        fails(&c, &format!("VH[0] = {foreign}"));
        let mut c = chf.clone();
        c.boundary.as_mut().unwrap().vertices.pop();
        fails(&c, "boundary vertices");
        let mut c = chf.clone();
        c.boundary.as_mut().unwrap().component[0] = 7;
        fails(&c, "components");
        let mut c = chf.clone();
        c.boundary = None;
        fails(&c, "level 3");
    }

    /// A copy's position is its origin's, bit for bit: NaN coordinates (which an input may
    /// have) included, as the fuzz target of edits found; any other coordinate is caught.
    #[test]
    fn a_copy_holds_its_origins_coordinates_bit_for_bit() {
        let mut c = mesh();
        let n = c.num_vertices();
        let at = |v: usize| {
            let x = c.vertex_origin(v as u32);
            glam::DVec3::new(f64::NAN, f64::from(x), 0.5)
        };
        let mut p: Vec<glam::DVec3> = (0..n).map(at).collect();
        c.positions = p.clone().into();
        c.validate().unwrap();
        p[n - 1].y += 1.0;
        c.positions = p.into();
        fails(&c, &format!("copy {} is not at its origin", n - 1));
    }
}
