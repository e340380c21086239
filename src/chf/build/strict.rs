//! Strict mode: the first offending ids of each kind of non-manifold input, as an error
//! (faces and duplicates before orienting, edges and vertices once the split is known).

use crate::chf::build::report::BuildReport;
use crate::chf::ids::{first, sorted_triple, tet};
use crate::error::{Error, Result};
use crate::util::origin::origin;

/// What the strict checks read: the report so far, `V`, and the input tetrahedron of each
/// structure tetrahedron.
pub(crate) struct Strict<'a, F> {
    pub report: &'a BuildReport,
    pub v: &'a [u32],
    pub origin_of: &'a F,
}

impl<F: Fn(u32) -> u32> Strict<'_, F> {
    /// Non-manifold faces and duplicate tetrahedra, before orienting.
    pub(crate) fn faces(&self, non_manifold: &[u32]) -> Result<()> {
        let (report, v, origin_of) = (self.report, self.v, self.origin_of);
        if let Some(&triple) = report.non_manifold_face_examples.first() {
            let tets: Vec<String> = non_manifold
                .iter()
                .filter(|&&hf| sorted_triple(v, hf) == triple)
                .map(|&hf| origin_of(tet(hf)).to_string())
                .collect();
            return Err(Error::non_manifold(format!(
                "non-manifold face ({}, {}, {}) is shared by tetrahedra {}; such faces in all: {}",
                triple[0],
                triple[1],
                triple[2],
                tets.join(", "),
                report.non_manifold_faces
            )));
        }
        if let Some(&[s, t]) = report.duplicate_examples.first() {
            return Err(Error::non_manifold(format!(
                "tetrahedra {s} and {t} have the same vertices; duplicate pairs in all: {}",
                report.duplicate_tetrahedra
            )));
        }
        Ok(())
    }

    /// Non-manifold edges and vertices, once the split is known.
    pub(crate) fn after_split(&self, vertex_origin: &[u32]) -> Result<()> {
        let (report, v, origin_of) = (self.report, self.v, self.origin_of);
        let input = |x: u32| origin(vertex_origin, x);
        if let Some(&[a, b]) = report.non_manifold_edge_examples.first() {
            let tets: Vec<String> = (0..(v.len() / 4) as u32)
                .filter(|&t| {
                    let quad = &v[first(t) as usize..first(t) as usize + 4];
                    quad.iter().any(|&x| input(x) == a) && quad.iter().any(|&x| input(x) == b)
                })
                .map(|t| origin_of(t).to_string())
                .collect();
            return Err(Error::non_manifold(format!(
                "non-manifold edge ({a}, {b}): tetrahedra {} form several fans around it; such edges in all: {}",
                tets.join(", "),
                report.non_manifold_edges
            )));
        }
        if let Some(&x) = report.split_vertex_examples.first() {
            return Err(Error::non_manifold(format!(
                "non-manifold vertex {x} (its star is several face-connected pieces); such vertices in all: {}",
                report.split_vertices
            )));
        }
        Ok(())
    }
}
