//! The topology of the input complex as given (input vertices, unique input edges and
//! faces, kept tetrahedra), whatever the build split or left unpaired, plus what the build
//! did.

use crate::chf::Chf;
use crate::chf::ids::face_cycle;
use crate::chf::query::view::Need;
use crate::error::Result;
use crate::util::alloc::{or_panic, try_push};
use crate::util::dsu::{InputComplex, input_boundary};

/// The fields of [`Summary`], once for it and for its C mirror in `ffi` (see
/// `util::fields`).
macro_rules! summary_fields {
    ($($head:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            vertices: u64,
            edges: u64,
            faces: u64,
            tetrahedra: u64,
            /// Faces with exactly one tetrahedron.
            boundary_faces: u64,
            /// Edges and vertices of the boundary faces.
            boundary_edges: u64,
            boundary_vertices: u64,
            /// Components of the boundary faces, joined through shared vertices.
            boundary_components: u64,
            /// Components of the tetrahedra, joined through shared vertices.
            components: u64,
            isolated_vertices: u64,
            /// V - E + F - T of the input complex (isolated vertices count).
            euler_characteristic: i64,
            /// No non-manifold face, edge or vertex.
            manifold: bool,
            orientable: bool,
            dropped_degenerate: u64,
            /// Tetrahedra of zero volume (kept), when built with positions.
            zero_volume: u64,
            /// Tetrahedra whose volume has the sign opposite to their component's orientation.
            inverted_tetrahedra: u64,
            non_manifold_faces: u64,
            non_manifold_edges: u64,
            split_vertices: u64,
            flipped_tetrahedra: u64,
            non_orientable_components: u64,
        }}
    };
}
pub(crate) use summary_fields;

summary_fields! {
    /// Field names match `chf_summary` in the C API and the CLI's JSON.
    #[derive(Clone, Debug, Default, PartialEq, Eq)]
    pub struct Summary
}

impl Chf {
    /// The summary; O(T log T) at every level (it sorts the boundary edges). Panics when
    /// memory runs out: see [`Chf::try_summary`].
    pub fn summary(&self) -> Summary {
        or_panic(self.try_summary())
    }

    /// The summary, or an [`ErrorKind::OutOfMemory`](crate::ErrorKind) error when the
    /// arrays it needs (the opposites below level 1, the marks, the boundary edges) do not
    /// fit.
    pub fn try_summary(&self) -> Result<Summary> {
        if self.edit.is_some() {
            // The live tetrahedra as a build sees them (O(T log T), like the rest).
            return self.compacted()?.chf.try_summary();
        }
        let r = &self.report;
        let n = self.n_input_vertices;
        let mut input =
            InputComplex::new::<4>(&self.v, n, r.welded_vertices, |x| self.vertex_origin(x))?;
        let view = self.try_view(Need::NOTHING)?;
        let mut pairs: Vec<u64> = Vec::new();
        for hf in input_boundary(&view.o, &self.non_manifold, &self.seams) {
            let [a, b, c] = face_cycle(&self.v, hf).map(|x| self.vertex_origin(x));
            for (x, y) in [(a, b), (b, c), (c, a)] {
                input.boundary.edge(x, y);
                let pair = ((x.min(y) as u64) << 32) | x.max(y) as u64;
                try_push(&mut pairs, pair, "the summary's boundary edges")?;
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let boundary_components = input.boundary.components();

        let t = self.num_tetrahedra() as i64;
        let euler = input.kept as i64 - r.input_edges as i64 + r.input_faces as i64 - t;
        Ok(Summary {
            vertices: input.kept as u64,
            edges: r.input_edges as u64,
            faces: r.input_faces as u64,
            tetrahedra: t as u64,
            boundary_faces: r.boundary_faces as u64,
            boundary_edges: pairs.len() as u64,
            boundary_vertices: input.boundary.on_boundary.iter().filter(|&&b| b).count() as u64,
            boundary_components,
            components: input.components,
            isolated_vertices: input.isolated,
            euler_characteristic: euler,
            manifold: r.non_manifold_faces == 0
                && r.non_manifold_edges == 0
                && r.split_vertices == 0,
            orientable: r.non_orientable_components == 0,
            dropped_degenerate: r.dropped_degenerate as u64,
            zero_volume: r.zero_volume as u64,
            inverted_tetrahedra: r.inverted_tetrahedra as u64,
            non_manifold_faces: r.non_manifold_faces as u64,
            non_manifold_edges: r.non_manifold_edges as u64,
            split_vertices: r.split_vertices as u64,
            flipped_tetrahedra: r.flipped_tetrahedra as u64,
            non_orientable_components: r.non_orientable_components as u64,
        })
    }
}
