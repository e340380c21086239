//! The `chf_mesh` handle: a boxed [`Chf`] plus the identity origin maps, materialised on
//! the first request for a zero-copy view (the core stores none when they are the identity).

use super::boundary::{Sink, guard, guard_or, handle, value_answer};
use super::che::level_arg;
use super::status::Status;
use crate::chf::{Chf, ChfBuildOptions as CoreOptions};
use crate::error::Result;
use std::sync::OnceLock;

/// Opaque handle to a CHF tetrahedral mesh. Create with `chf_mesh_from_tetrahedra` or
/// `chf_mesh_load`, free with `chf_mesh_free`.
pub struct ChfMesh {
    pub(crate) chf: Chf,
    vertex_origins: OnceLock<Box<[u32]>>,
    tetrahedron_origins: OnceLock<Box<[u32]>>,
}

impl ChfMesh {
    pub(crate) fn new(chf: Chf) -> Self {
        ChfMesh {
            chf,
            vertex_origins: OnceLock::new(),
            tetrahedron_origins: OnceLock::new(),
        }
    }

    /// Structure vertex -> input vertex, identity included (origins do not depend on the level).
    pub(crate) fn vertex_origins(&self) -> &[u32] {
        match self.chf.vertex_origins() {
            Some(map) => map,
            None => self
                .vertex_origins
                .get_or_init(|| (0..self.chf.num_vertices() as u32).collect()),
        }
    }

    /// Structure tetrahedron -> input tetrahedron, identity included.
    pub(crate) fn tetrahedron_origins(&self) -> &[u32] {
        match self.chf.tetrahedron_origins() {
            Some(map) => map,
            None => self
                .tetrahedron_origins
                .get_or_init(|| (0..self.chf.num_tetrahedra() as u32).collect()),
        }
    }
}

/// How to build a CHF.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChfBuildOptions {
    /// The level, 0..3 (default 2).
    pub level: u32,
    /// Reject non-manifold faces (three or more tetrahedra on a face), non-manifold edges
    /// and vertices, and duplicate tetrahedra with `TOPOMESH_STATUS_NON_MANIFOLD` (detail:
    /// the offending ids) instead of keeping them (default false).
    pub strict: bool,
    /// Threads for the build: 0 (default) for as many as the machine runs at once, 1 for
    /// the calling thread alone. The mesh is the same whatever the number.
    pub threads: u32,
}

impl Default for ChfBuildOptions {
    fn default() -> Self {
        let d = CoreOptions::default();
        ChfBuildOptions {
            level: d.level as u32,
            strict: d.strict,
            threads: d.threads as u32,
        }
    }
}

impl ChfBuildOptions {
    pub(crate) fn to_core(self) -> Result<CoreOptions> {
        Ok(CoreOptions {
            level: level_arg(self.level)?,
            strict: self.strict,
            threads: self.threads as usize,
        })
    }
}

/// The default CHF build options: level 2, not strict, every thread of the machine.
#[unsafe(no_mangle)]
pub extern "C" fn chf_build_options_default() -> ChfBuildOptions {
    ChfBuildOptions::default()
}

/// The shapes of the per-element exports: the guard, the range check of the element, one
/// call into the core.
///
/// A count or other plain value of the mesh; the default (0, false) for NULL.
///
/// # Safety
/// `m` is NULL or a live handle.
pub(super) unsafe fn count<T: Default>(m: *const ChfMesh, f: impl FnOnce(&Chf) -> T) -> T {
    // SAFETY: forwarded contract.
    guard_or(T::default(), || Ok(f(&unsafe { handle(m, "m")? }.chf)))
}

/// The range check of an element id.
pub(super) type Check = fn(&Chf, u32) -> Result<()>;

/// One value about element `id` into `*out`, after `check`.
///
/// # Safety
/// `m` is NULL or a live handle; `out` NULL or valid for one write.
#[inline(always)]
pub(super) unsafe fn value<T>(
    m: *const ChfMesh,
    out: *mut T,
    check: Check,
    id: u32,
    f: impl FnOnce(&Chf) -> T,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe {
        value_answer(m, out, |m: &ChfMesh| {
            check(&m.chf, id)?;
            Ok(f(&m.chf))
        })
    }
}

/// The answer about element `id` into the caller buffer `out = (buf, cap, out_len)`,
/// after `check`.
///
/// # Safety
/// `m` is NULL or a live handle; `buf` NULL or valid for `cap` writes; `out_len` NULL or
/// valid for one write.
#[inline(always)]
pub(super) unsafe fn ids<'a, I: IntoIterator<Item = u32>>(
    m: *const ChfMesh,
    (buf, cap, out_len): (*mut u32, usize, *mut usize),
    check: Check,
    id: u32,
    f: impl FnOnce(&'a Chf) -> I,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (m, mut sink) = unsafe { (handle(m, "m")?, Sink::new(buf, cap, out_len, "buf")?) };
        check(&m.chf, id)?;
        sink.extend(f(&m.chf));
        sink.finish()
    })
}
