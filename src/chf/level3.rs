//! Level 3: the boundary surface as a CHE (level 3, so with its curves), whose triangle `k`
//! is the `k`-th boundary half-face in half-face order, with its vertices in the half-face's
//! outward order and the CHF's vertex ids (interior vertices are isolated vertices of the
//! CHE; vertices the CHE itself splits are appended after them, with its own origin map).
//! Maps both ways (a rank over boundary half-faces one way, an array the other), and a
//! boundary-component id per vertex (`NONE` off the boundary): components of the boundary
//! triangles joined through shared vertices, numbered in order of their first triangle.

use super::Chf;
use super::ids::face_cycle;
use super::view::Need;
use crate::NONE;
use crate::che::{BuildOptions, Che};
use crate::error::Result;
use crate::rank::RankBits;

#[derive(Clone, Debug)]
pub(crate) struct Boundary {
    pub che: Che,
    /// Bit `hf` set on boundary half-faces; the triangle is the rank.
    pub bits: RankBits,
    /// Triangle -> half-face.
    pub half_faces: Vec<u32>,
    /// Vertex -> boundary component, `NONE` off the boundary.
    pub component: Vec<u32>,
    pub components: usize,
}

impl Boundary {
    pub fn memory_bytes(&self) -> usize {
        self.che.memory_bytes().topology
            + self.bits.memory_bytes()
            + 4 * (self.half_faces.len() + self.component.len())
    }
}

pub(crate) fn build(chf: &Chf) -> Result<Boundary> {
    let view = chf.view(Need::NOTHING);
    let o = &view.o;
    let half_faces: Vec<u32> = (0..o.len() as u32)
        .filter(|&hf| o[hf as usize] == NONE)
        .collect();
    let che = surface(chf, &half_faces, 3)?;
    let bits = RankBits::from_fn(o.len(), |hf| o[hf] == NONE);
    let (component, components) = components(chf, &half_faces);
    Ok(Boundary {
        che,
        bits,
        half_faces,
        component,
        components,
    })
}

fn surface(chf: &Chf, half_faces: &[u32], level: u8) -> Result<Che> {
    let tris: Vec<[u32; 3]> = half_faces
        .iter()
        .map(|&hf| face_cycle(&chf.v, hf))
        .collect();
    Che::from_triangles(
        &tris,
        chf.n_vertices,
        &chf.positions,
        BuildOptions {
            level,
            strict: false,
        },
    )
}

/// Boundary component of every vertex, by union-find over the boundary triangles.
fn components(chf: &Chf, half_faces: &[u32]) -> (Vec<u32>, usize) {
    let mut parent: Vec<u32> = (0..chf.n_vertices as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    for &hf in half_faces {
        let [a, b, c] = face_cycle(&chf.v, hf);
        for y in [b, c] {
            let (ra, ry) = (find(&mut parent, a), find(&mut parent, y));
            if ra != ry {
                parent[ra.max(ry) as usize] = ra.min(ry);
            }
        }
    }
    let mut id_of_root = vec![NONE; chf.n_vertices];
    let mut component = vec![NONE; chf.n_vertices];
    let mut n = 0u32;
    for &hf in half_faces {
        for x in face_cycle(&chf.v, hf) {
            let r = find(&mut parent, x) as usize;
            if id_of_root[r] == NONE {
                id_of_root[r] = n;
                n += 1;
            }
            component[x as usize] = id_of_root[r];
        }
    }
    (component, n as usize)
}

impl Chf {
    /// The boundary surface, at level 3.
    pub fn boundary(&self) -> Option<&Che> {
        self.boundary.as_ref().map(|b| &b.che)
    }

    /// The boundary surface as a new level-3 CHE, at any level (a copy of the stored one at
    /// level 3). O(T).
    pub fn boundary_surface(&self) -> Result<Che> {
        if let Some(b) = &self.boundary {
            return Ok(b.che.clone());
        }
        surface(self, &self.boundary_half_face_list(), 3)
    }

    /// Boundary half-faces in increasing order: triangle `k` of the boundary surface is the
    /// `k`-th. Borrowed at level 3.
    pub fn boundary_half_faces(&self) -> std::borrow::Cow<'_, [u32]> {
        match &self.boundary {
            Some(b) => std::borrow::Cow::Borrowed(&b.half_faces),
            None => std::borrow::Cow::Owned(self.boundary_half_face_list()),
        }
    }

    fn boundary_half_face_list(&self) -> Vec<u32> {
        let view = self.view(Need::NOTHING);
        (0..self.v.len() as u32)
            .filter(|&hf| view.o[hf as usize] == NONE)
            .collect()
    }

    /// The boundary triangle of half-face `hf`, `NONE` when `hf` is interior. O(1) at
    /// level 3, O(T) below.
    pub fn boundary_triangle(&self, hf: u32) -> u32 {
        match &self.boundary {
            Some(b) if b.bits.get(hf as usize) => b.bits.rank(hf as usize) as u32,
            Some(_) => NONE,
            None => {
                let list = self.boundary_half_face_list();
                list.binary_search(&hf).map_or(NONE, |k| k as u32)
            }
        }
    }

    /// The half-face of boundary triangle `k`. O(1) at level 3, O(T) below.
    pub fn boundary_triangle_half_face(&self, k: u32) -> u32 {
        self.boundary_half_faces()
            .get(k as usize)
            .copied()
            .unwrap_or(NONE)
    }

    /// The boundary component of vertex `v` (`NONE` off the boundary). O(1) at level 3,
    /// O(T) below.
    pub fn boundary_component(&self, v: u32) -> u32 {
        match &self.boundary {
            Some(b) => b.component[v as usize],
            None => components(self, &self.boundary_half_face_list()).0[v as usize],
        }
    }

    /// The boundary component of every vertex (`NONE` off the boundary), at level 3.
    pub fn boundary_components(&self) -> Option<&[u32]> {
        self.boundary.as_ref().map(|b| &b.component[..])
    }

    /// Number of boundary components (of the structure: after the vertex split). O(1) at
    /// level 3, O(T) below.
    pub fn num_boundary_components(&self) -> usize {
        match &self.boundary {
            Some(b) => b.components,
            None => components(self, &self.boundary_half_face_list()).1,
        }
    }
}
