//! The topology of the input complex as given (input vertices, unique input edges, kept
//! triangles), whatever the build split or left unpaired, plus what the build did.

use crate::che::Che;
use crate::che::ids::next;
use crate::error::Result;
use crate::util::alloc::or_panic;
use crate::util::dsu::{InputComplex, input_boundary};

/// The fields of [`Summary`], once for it and for its C mirror in `ffi` (see
/// `util::fields`).
macro_rules! summary_fields {
    ($($head:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            vertices: u64,
            edges: u64,
            triangles: u64,
            /// Edges with exactly one triangle.
            boundary_edges: u64,
            /// Connected components of the boundary edges (for a manifold, the boundary loops).
            boundary_curves: u64,
            /// Connected components of the triangles (joined through shared vertices).
            components: u64,
            isolated_vertices: u64,
            /// V - E + F of the input complex (isolated vertices count).
            euler_characteristic: i64,
            /// Sum of the component genera; -1 where undefined (non-manifold or non-orientable).
            genus: i64,
            orientable: bool,
            manifold: bool,
            dropped_degenerate: u64,
            non_manifold_edges: u64,
            split_vertices: u64,
            flipped_triangles: u64,
            non_orientable_components: u64,
        }}
    };
}
pub(crate) use summary_fields;

summary_fields! {
    /// Field names match `che_summary` in the C API and the CLI's JSON.
    #[derive(Clone, Debug, Default, PartialEq, Eq)]
    pub struct Summary
}

impl Che {
    /// The summary; O(T) at every level. Panics when memory runs out: see
    /// [`Che::try_summary`].
    pub fn summary(&self) -> Summary {
        or_panic(self.try_summary())
    }

    /// The summary, or an [`ErrorKind::OutOfMemory`](crate::ErrorKind) error when the
    /// arrays it needs (the opposites below level 1, the marks) do not fit.
    pub fn try_summary(&self) -> Result<Summary> {
        if self.edits().is_some() {
            return self.edited_summary();
        }
        let r = &self.report;
        let n = self.n_input_vertices;
        let mut input =
            InputComplex::new::<3>(&self.v, n, r.welded_vertices, |x| self.vertex_origin(x))?;
        let o = self.try_opposites_or_computed()?;
        for h in input_boundary(&o, &self.non_manifold, &self.seams) {
            let a = self.vertex_origin(self.v[h as usize]);
            let b = self.vertex_origin(self.v[next(h) as usize]);
            input.boundary.edge(a, b);
        }
        let summary = Summary {
            vertices: input.kept as u64,
            edges: r.input_edges as u64,
            triangles: self.num_triangles() as u64,
            boundary_edges: r.boundary_edges as u64,
            boundary_curves: input.boundary.components(),
            components: input.components,
            isolated_vertices: input.isolated,
            orientable: r.non_orientable_components == 0,
            manifold: r.non_manifold_edges == 0 && r.split_vertices == 0,
            dropped_degenerate: r.dropped_degenerate as u64,
            non_manifold_edges: r.non_manifold_edges as u64,
            split_vertices: r.split_vertices as u64,
            flipped_triangles: r.flipped_triangles as u64,
            non_orientable_components: r.non_orientable_components as u64,
            ..Summary::default()
        };
        Ok(summary.with_genus())
    }
}

impl Summary {
    /// The summary with its Euler characteristic, V - E + F, and its genus, the sum of the
    /// component genera (each has chi = 2 - 2g - b, an isolated vertex adding 1 to chi), -1
    /// where undefined (non-manifold, non-orientable, or counts no surface has).
    pub(crate) fn with_genus(mut self) -> Summary {
        let euler = self.vertices as i64 - self.edges as i64 + self.triangles as i64;
        let twice = 2 * self.components as i64
            - (euler - self.isolated_vertices as i64)
            - self.boundary_curves as i64;
        self.euler_characteristic = euler;
        self.genus = if self.orientable && self.manifold && twice >= 0 && twice % 2 == 0 {
            twice / 2
        } else {
            -1
        };
        self
    }
}
