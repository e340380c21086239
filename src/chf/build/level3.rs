//! Level 3: the boundary surface as a CHE (level 3, so with its curves).
//!
//! - Triangles: triangle `k` is the `k`-th unpaired half-face in half-face order (the
//!   boundary faces, and also the half-faces of non-manifold faces and orientation seams,
//!   which the structure keeps unpaired), its corners in the half-face's outward order.
//! - Vertices: only the vertices of those half-faces, with compact ids: boundary vertex `b`
//!   is the `b`-th such volume vertex in increasing id order (so interior vertices are not
//!   in the surface, and its Euler characteristic is the boundary's). Vertices the CHE
//!   itself splits (a boundary pinched at a vertex) are appended after them, with the CHE's
//!   own origin map back to a boundary vertex.
//!
//! Maps: boundary half-face -> triangle (a rank over the unpaired half-faces) and back (an
//! array); volume vertex -> boundary vertex (a rank over the boundary vertices) and back
//! (an array); a boundary-component id per boundary vertex: components of the boundary
//! triangles joined through shared vertices, numbered in order of their first triangle.
//! Below level 3 every map is computed for the call (O(T)). An edited CHF at level 3 keeps
//! no bit directories over all half-faces and vertices: its boundary is rebuilt from the
//! boundary half-faces alone (see `chf/edit/boundary.rs`), and its lookups binary-search the
//! sorted lists (O(log B)) instead of taking a rank.

use crate::NONE;
use crate::che::{BuildOptions, Che};
use crate::chf::Chf;
use crate::chf::ids::face_cycle;
use crate::chf::query::view::Need;
use crate::error::Result;
use crate::util::alloc::{or_panic, try_collect, try_vec};
use crate::util::dsu::Dsu;
use crate::util::rank::RankBits;
use std::borrow::Cow;

#[derive(Clone, Debug)]
pub(crate) struct Boundary {
    pub che: Che,
    /// Bit `hf` set on unpaired half-faces; the triangle is the rank. `None` on a boundary
    /// rebuilt after edits (`half_faces` is searched instead).
    pub bits: Option<RankBits>,
    /// Triangle -> half-face.
    pub half_faces: Vec<u32>,
    /// Bit `v` set on boundary vertices; the boundary vertex id is the rank. `None` on a
    /// boundary rebuilt after edits (`vertices` is searched instead).
    pub vertex_bits: Option<RankBits>,
    /// Boundary vertex -> volume vertex.
    pub vertices: Vec<u32>,
    /// Boundary vertex -> boundary component.
    pub component: Vec<u32>,
    pub components: usize,
    /// Unpaired half-faces that are neither non-manifold nor seams: faces with one
    /// tetrahedron.
    pub true_faces: usize,
}

impl Boundary {
    pub fn memory_bytes(&self) -> usize {
        let bits = |b: &Option<RankBits>| b.as_ref().map_or(0, |b| b.memory_bytes());
        self.che.memory_bytes().topology
            + bits(&self.bits)
            + bits(&self.vertex_bits)
            + 4 * (self.half_faces.len() + self.vertices.len() + self.component.len())
    }

    /// The triangle of half-face `hf`, `NONE` when it is paired.
    fn triangle_of(&self, hf: u32) -> u32 {
        position(self.bits.as_ref(), &self.half_faces, hf)
    }
}

/// The rank of `x` among the set members `sorted` (their bits `bits` when kept), `NONE`
/// when `x` is not one.
fn position(bits: Option<&RankBits>, sorted: &[u32], x: u32) -> u32 {
    match bits {
        Some(b) if b.get(x as usize) => b.rank(x as usize) as u32,
        Some(_) => NONE,
        None => sorted.binary_search(&x).map_or(NONE, |k| k as u32),
    }
}

/// What every boundary map below level 3 derives from: the unpaired half-faces and the
/// boundary vertices.
struct Parts {
    half_faces: Vec<u32>,
    /// `None` when built from the boundary half-faces alone (`vertices` is searched).
    vertex_bits: Option<RankBits>,
    vertices: Vec<u32>,
}

impl Parts {
    /// The boundary vertex of volume vertex `x`, `NONE` off the boundary.
    fn vertex_of(&self, x: u32) -> u32 {
        position(self.vertex_bits.as_ref(), &self.vertices, x)
    }
}

fn parts(chf: &Chf) -> Parts {
    or_panic(try_parts(chf))
}

fn try_parts(chf: &Chf) -> Result<Parts> {
    let view = chf.try_view(Need::NOTHING)?;
    let o = &view.o;
    let unpaired = (0..o.len() as u32).filter(|&hf| o[hf as usize] == NONE);
    let half_faces = try_collect(unpaired, "the boundary half-faces")?;
    let mut on = try_vec(
        chf.n_vertices.div_ceil(64),
        0u64,
        "the boundary vertex marks",
    )?;
    for &hf in &half_faces {
        for x in face_cycle(&chf.v, hf) {
            on[x as usize >> 6] |= 1 << (x & 63);
        }
    }
    let vertex_bits = RankBits::from_words(on, chf.n_vertices)?;
    let mut vertices = Vec::new();
    vertex_bits.ones_map(&mut vertices, |v| v as u32, "the boundary vertices")?;
    Ok(Parts {
        half_faces,
        vertex_bits: Some(vertex_bits),
        vertices,
    })
}

/// The parts from the boundary half-faces alone (increasing): O(B log B) for B of them,
/// whatever the size of the mesh.
fn parts_of(chf: &Chf, half_faces: Vec<u32>) -> Result<Parts> {
    let mut vertices = try_vec(3 * half_faces.len(), NONE, "the boundary vertices")?;
    for (k, &hf) in half_faces.iter().enumerate() {
        vertices[3 * k..3 * k + 3].copy_from_slice(&face_cycle(&chf.v, hf));
    }
    vertices.sort_unstable();
    vertices.dedup();
    Ok(Parts {
        half_faces,
        vertex_bits: None,
        vertices,
    })
}

/// The boundary, its CHE built on up to `threads` threads.
pub(crate) fn build(chf: &Chf, threads: usize, memory_limit_bytes: u64) -> Result<Boundary> {
    let p = try_parts(chf)?;
    let n_hf = chf.v.len();
    let mut words = try_vec(n_hf.div_ceil(64), 0u64, "the boundary half-face bits")?;
    for &hf in &p.half_faces {
        words[hf as usize >> 6] |= 1 << (hf & 63);
    }
    let bits = RankBits::from_words(words, n_hf)?;
    assemble(chf, p, Some(bits), threads, memory_limit_bytes)
}

/// The boundary of an edited CHF from its unpaired half-faces `half_faces` (increasing),
/// without bit directories: O(B log B) for B of them, never a scan of the mesh.
pub(crate) fn build_from_half_faces(chf: &Chf, half_faces: Vec<u32>) -> Result<Boundary> {
    let p = parts_of(chf, half_faces)?;
    assemble(chf, p, None, 1, 0)
}

/// The surface, the components and the counts of the parts `p`.
fn assemble(
    chf: &Chf, p: Parts, bits: Option<RankBits>, threads: usize, memory_limit_bytes: u64,
) -> Result<Boundary> {
    let options = BuildOptions {
        level: 3,
        strict: false,
        threads,
        memory_limit_bytes,
        weld_tolerance: 0.0,
    };
    let che = surface(chf, &p, options)?;
    let (component, components) = components(chf, &p)?;
    let true_faces = p.half_faces.len() - flagged_count(chf)?;
    Ok(Boundary {
        che,
        bits,
        half_faces: p.half_faces,
        vertex_bits: p.vertex_bits,
        vertices: p.vertices,
        component,
        components,
        true_faces,
    })
}

/// Flagged half-faces (non-manifold or seam), all unpaired.
fn flagged_count(chf: &Chf) -> Result<usize> {
    Ok(crate::chf::star_pass::merged(&chf.non_manifold, &chf.seams)?.len())
}

fn surface(chf: &Chf, p: &Parts, options: BuildOptions) -> Result<Che> {
    let local = |x: u32| p.vertex_of(x);
    let tris = p
        .half_faces
        .iter()
        .map(|&hf| face_cycle(&chf.v, hf).map(local));
    let tris: Vec<[u32; 3]> = try_collect(tris, "the boundary triangles")?;
    let positions: Vec<_> = if chf.positions.is_empty() {
        Vec::new()
    } else {
        let positions = p.vertices.iter().map(|&x| chf.positions[x as usize]);
        try_collect(positions, "the boundary positions")?
    };
    Che::from_triangles(&tris, p.vertices.len(), &positions, options)
}

/// Boundary component of every boundary vertex, by union-find over the boundary
/// triangles.
fn components(chf: &Chf, p: &Parts) -> Result<(Vec<u32>, usize)> {
    let n = p.vertices.len();
    let mut dsu = Dsu::new(n)?;
    let local = |x: u32| p.vertex_of(x);
    for &hf in &p.half_faces {
        let [a, b, c] = face_cycle(&chf.v, hf).map(local);
        dsu.union(a, b);
        dsu.union(a, c);
    }
    let mut id_of_root = try_vec(n, NONE, "the boundary components")?;
    let mut component = try_vec(n, NONE, "the boundary components")?;
    let mut count = 0u32;
    for &hf in &p.half_faces {
        for x in face_cycle(&chf.v, hf).map(local) {
            let r = dsu.find(x) as usize;
            if id_of_root[r] == NONE {
                id_of_root[r] = count;
                count += 1;
            }
            component[x as usize] = id_of_root[r];
        }
    }
    Ok((component, count as usize))
}

impl Chf {
    /// The level-3 boundary: the built one, or on an edited CHF the one rebuilt from the
    /// boundary half-faces at the first query after an edit (O(B log B)); `None` below
    /// level 3.
    pub(crate) fn try_stored(&self) -> Result<Option<&Boundary>> {
        if self.level < 3 {
            return Ok(None);
        }
        match &self.edit {
            Some(s) => s.surface(self).map(Some),
            None => Ok(self.boundary.as_ref()),
        }
    }

    /// [`Chf::try_stored`] for the queries that have no error to return.
    fn stored(&self) -> Option<&Boundary> {
        or_panic(self.try_stored())
    }

    /// The boundary surface, at level 3.
    pub fn boundary(&self) -> Option<&Che> {
        self.stored().map(|b| &b.che)
    }

    /// The boundary surface as a new level-3 CHE, at any level (a copy of the stored one at
    /// level 3). O(T).
    pub fn boundary_surface(&self) -> Result<Che> {
        if let Some(b) = self.try_stored()? {
            return Ok(b.che.clone());
        }
        let options = BuildOptions {
            threads: 1,
            ..BuildOptions::level(3)
        };
        surface(self, &try_parts(self)?, options)
    }

    /// Unpaired half-faces in increasing order: triangle `k` of the boundary surface is the
    /// `k`-th. Borrowed at level 3.
    pub fn boundary_half_faces(&self) -> Cow<'_, [u32]> {
        match self.stored() {
            Some(b) => Cow::Borrowed(&b.half_faces),
            None => Cow::Owned(parts(self).half_faces),
        }
    }

    /// The triangles of the boundary surface: every unpaired half-face (boundary faces,
    /// and the half-faces of non-manifold faces and seams). O(1) at level 3, O(T) below.
    pub fn num_boundary_triangles(&self) -> usize {
        match self.stored() {
            Some(b) => b.half_faces.len(),
            None => {
                let view = self.view(Need::NOTHING);
                view.o.iter().filter(|&&g| g == NONE).count()
            }
        }
    }

    /// Faces with exactly one tetrahedron: the unpaired half-faces that are neither
    /// non-manifold ([`Chf::num_non_manifold_half_faces`]) nor seams
    /// ([`Chf::num_seam_half_faces`]). O(1) at level 3, O(T) below.
    pub fn num_boundary_faces(&self) -> usize {
        match self.stored() {
            Some(b) => b.true_faces,
            None => self.num_boundary_triangles() - or_panic(flagged_count(self)),
        }
    }

    /// Half-faces of faces shared by 3+ tetrahedra (unpaired, one per tetrahedron). O(1).
    pub fn num_non_manifold_half_faces(&self) -> usize {
        self.non_manifold.len()
    }

    /// Half-faces on orientation seams (two tetrahedra whose orientations disagree across
    /// the face; unpaired). O(1).
    pub fn num_seam_half_faces(&self) -> usize {
        self.seams.len()
    }

    /// The boundary triangle of half-face `hf`, `NONE` when `hf` is interior. O(1) at
    /// level 3, O(T) below.
    pub fn boundary_triangle(&self, hf: u32) -> u32 {
        match self.stored() {
            Some(b) => b.triangle_of(hf),
            None => {
                let list = parts(self).half_faces;
                list.binary_search(&hf).map_or(NONE, |k| k as u32)
            }
        }
    }

    /// The half-face of boundary triangle `k` (`NONE` out of range). O(1) at level 3, O(T)
    /// below.
    pub fn boundary_triangle_half_face(&self, k: u32) -> u32 {
        self.boundary_half_faces()
            .get(k as usize)
            .copied()
            .unwrap_or(NONE)
    }

    /// Boundary vertices (the vertices of the boundary surface before its own split).
    /// O(1) at level 3, O(T) below.
    pub fn num_boundary_vertices(&self) -> usize {
        match self.stored() {
            Some(b) => b.vertices.len(),
            None => parts(self).vertices.len(),
        }
    }

    /// Boundary vertex -> volume vertex, in increasing order. Borrowed at level 3.
    pub fn boundary_vertices(&self) -> Cow<'_, [u32]> {
        match self.stored() {
            Some(b) => Cow::Borrowed(&b.vertices),
            None => Cow::Owned(parts(self).vertices),
        }
    }

    /// The boundary-surface vertex of volume vertex `v`, `NONE` off the boundary. O(1) at
    /// level 3, O(T) below.
    pub fn boundary_vertex(&self, v: u32) -> u32 {
        match self.stored() {
            Some(b) => position(b.vertex_bits.as_ref(), &b.vertices, v),
            None => parts(self).vertex_of(v),
        }
    }

    /// The volume vertex of boundary-surface vertex `b` (a vertex of
    /// [`Chf::boundary_surface`], copies the CHE split included), `NONE` out of range.
    /// O(1) at level 3, O(T) below.
    pub fn boundary_vertex_volume_vertex(&self, b: u32) -> u32 {
        let map = |che: &Che, vertices: &[u32]| {
            if (b as usize) < che.num_vertices() {
                vertices[che.vertex_origin(b) as usize]
            } else {
                NONE
            }
        };
        match self.stored() {
            Some(s) => map(&s.che, &s.vertices),
            None => match self.boundary_surface() {
                Ok(che) => map(&che, &parts(self).vertices),
                Err(_) => NONE,
            },
        }
    }

    /// The boundary component of volume vertex `v` (`NONE` off the boundary). O(1) at
    /// level 3, O(T) below.
    pub fn boundary_component(&self, v: u32) -> u32 {
        or_panic(self.try_boundary_component(v))
    }

    /// [`Chf::boundary_component`], or an error when the tables it computes below level
    /// 3 do not fit in memory.
    pub fn try_boundary_component(&self, v: u32) -> Result<u32> {
        let b = self.boundary_vertex(v);
        if b == NONE {
            return Ok(NONE);
        }
        Ok(match self.try_stored()? {
            Some(s) => s.component[b as usize],
            None => components(self, &try_parts(self)?)?.0[b as usize],
        })
    }

    /// The boundary component of every boundary vertex (indexed like
    /// [`Chf::boundary_vertices`]), at level 3.
    pub fn boundary_vertex_components(&self) -> Option<&[u32]> {
        self.stored().map(|b| &b.component[..])
    }

    /// Number of boundary components (of the structure: after the vertex split). O(1) at
    /// level 3, O(T) below.
    pub fn num_boundary_components(&self) -> usize {
        or_panic(self.try_num_boundary_components())
    }

    /// [`Chf::num_boundary_components`], or an error when the tables it computes below
    /// level 3 do not fit in memory.
    pub fn try_num_boundary_components(&self) -> Result<usize> {
        Ok(match self.try_stored()? {
            Some(b) => b.components,
            None => components(self, &try_parts(self)?)?.1,
        })
    }
}
