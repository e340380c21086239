//! What CHE and CHF have alike as structures: the accessors every one of them has (over
//! the fields both name the same way) and the id range check of the `check_*` calls.

use crate::error::{Error, Result};

/// The accessors both structures have, for an `impl` block of a type with the fields
/// `level`, `n_vertices`, `n_input_vertices`, `num_edges`, `o`, `positions`,
/// `vertex_origin` (an `OriginMap`) and `report` (of the type named).
macro_rules! structure_accessors {
    ($report:ty) => {
        pub fn level(&self) -> u8 {
            self.level
        }
        /// Vertices of the structure: the input vertices, then copies made by splitting.
        pub fn num_vertices(&self) -> usize {
            self.n_vertices
        }
        pub fn num_input_vertices(&self) -> usize {
            self.n_input_vertices
        }
        pub fn num_edges(&self) -> usize {
            self.num_edges
        }
        /// `O`, from level 1.
        pub fn opposites(&self) -> Option<&[u32]> {
            (self.level >= 1).then_some(&self.o[..])
        }
        /// Positions of the structure's vertices (copies repeat their origin); may be empty.
        pub fn positions(&self) -> &[::glam::DVec3] {
            &self.positions
        }
        /// The input vertex a structure vertex comes from.
        pub fn vertex_origin(&self, v: u32) -> u32 {
            self.vertex_origin.get(v)
        }
        /// The vertex origin map, or `None` when it is the identity.
        pub fn vertex_origins(&self) -> Option<&[u32]> {
            self.vertex_origin.explicit()
        }
        pub fn report(&self) -> &$report {
            &self.report
        }
        #[inline]
        pub fn check_vertex(&self, v: u32) -> $crate::error::Result<()> {
            $crate::util::structure::check_id(v, self.n_vertices, "vertex", "vertices")
        }
        #[inline]
        pub fn check_edge(&self, e: u32) -> $crate::error::Result<()> {
            $crate::util::structure::check_id(e, self.num_edges, "edge", "edges")
        }
    };
}
pub(crate) use structure_accessors;

/// The constructors both structures have, for an `impl` block of `$ty` whose module has
/// `build::build(Input, options, progress)`, `BuildOptions`, `BuildProgress`, `Input` and
/// `as_elements` in scope: from borrowed arrays (`$from`, and `$from_progress` with a
/// progress callback), from `Vec`s handed over (`from_vecs`, `from_vecs_with_progress`) and
/// from a flat id array (`from_flat`); `$k` corners per element, `$what` the elements.
macro_rules! build_constructors {
    ($ty:ident, $k:literal, $from:ident, $from_progress:ident, $what:literal, $one:literal) => {
        #[doc = concat!("Builds from ", $what, " over vertices `0..n_vertices`; `positions` ")]
        #[doc = "is empty or holds `n_vertices` points."]
        pub fn $from(
            elements: &[[u32; $k]], n_vertices: usize, positions: &[DVec3], options: BuildOptions,
        ) -> Result<$ty> {
            let progress = BuildProgress::default();
            Self::$from_progress(elements, n_vertices, positions, options, progress)
        }

        #[doc = concat!("[`", stringify!($ty), "::", stringify!($from), "`], telling ")]
        #[doc = "`progress` how far the build is after each step."]
        pub fn $from_progress(
            elements: &[[u32; $k]], n_vertices: usize, positions: &[DVec3], options: BuildOptions,
            progress: BuildProgress,
        ) -> Result<$ty> {
            let input = Input::borrowed(elements, n_vertices, positions);
            build::build(input, options, progress)
        }

        #[doc = concat!("[`", stringify!($ty), "::", stringify!($from), "`] from arrays ")]
        #[doc = concat!("handed over: the ", $what, " become `V` in place and the positions")]
        #[doc = "move into the structure, so the input is not held twice (a build near the"]
        #[doc = "machine's memory needs that). On an error the arrays are dropped."]
        pub fn from_vecs(
            elements: Vec<[u32; $k]>, n_vertices: usize, positions: Vec<DVec3>,
            options: BuildOptions,
        ) -> Result<$ty> {
            let progress = BuildProgress::default();
            Self::from_vecs_with_progress(elements, n_vertices, positions, options, progress)
        }

        #[doc = concat!("[`", stringify!($ty), "::from_vecs`], telling `progress` how far")]
        #[doc = "the build is after each step."]
        pub fn from_vecs_with_progress(
            elements: Vec<[u32; $k]>, n_vertices: usize, positions: Vec<DVec3>,
            options: BuildOptions, progress: BuildProgress,
        ) -> Result<$ty> {
            let input = Input::owned(elements, n_vertices, positions);
            build::build(input, options, progress)
        }

        #[doc = concat!("Builds from a flat array of `", $k, " * n` vertex ids.")]
        pub fn from_flat(
            ids: &[u32], n_vertices: usize, positions: &[DVec3], options: BuildOptions,
        ) -> Result<$ty> {
            let elements = as_elements::<$k>(ids, $one)?;
            Self::$from(elements, n_vertices, positions, options)
        }
    };
}
pub(crate) use build_constructors;

/// `id` below `count`, or an out-of-range error naming the element (`one` of `many`).
#[inline]
pub(crate) fn check_id(id: u32, count: usize, one: &str, many: &str) -> Result<()> {
    if (id as usize) < count {
        Ok(())
    } else {
        Err(out_of_range(id, count, one, many))
    }
}

#[cold]
fn out_of_range(id: u32, count: usize, one: &str, many: &str) -> Error {
    Error::out_of_range(format!(
        "{one} {id} out of range (the mesh has {count} {many})"
    ))
}

/// `Ok` unless the mesh has `holes` (removed elements waiting for `garbage_collect`), else
/// the error that refuses `what` until then.
pub(crate) fn refuse_holes(holes: bool, what: &str) -> Result<()> {
    if holes {
        let detail = format!("{what}: the mesh has removed elements; call garbage_collect first");
        return Err(Error::invalid(detail));
    }
    Ok(())
}

/// `Ok` unless the mesh was `edited` since its last garbage collection, else the error
/// that refuses `what` until then.
pub(crate) fn refuse_edited(edited: bool, what: &str) -> Result<()> {
    if edited {
        let detail = format!("{what}: the mesh was edited; call garbage_collect first");
        return Err(Error::invalid(detail));
    }
    Ok(())
}

/// A flat id array as elements of `K` ids, without copying (the build's peak is what it
/// allocates); an error naming the `element` kind when the length is not a multiple of
/// `K`.
pub(crate) fn as_elements<'a, const K: usize>(
    flat: &'a [u32], element: &str,
) -> Result<&'a [[u32; K]]> {
    let (elements, rest) = flat.as_chunks::<K>();
    if !rest.is_empty() {
        return Err(Error::invalid(format!(
            "{element} array has {} ids, not a multiple of {K}",
            flat.len()
        )));
    }
    Ok(elements)
}
