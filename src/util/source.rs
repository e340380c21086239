//! What a streaming build reads: a mesh of `N`-vertex elements (triangles for 3,
//! tetrahedra for 4) in order, block by block, as many times as the build needs.

use crate::error::Result;
use glam::DVec3;

/// A mesh read in order, block by block: a generator, or arrays on disk.
pub trait Source<const N: usize>: Sync {
    fn num_elements(&self) -> usize;
    fn num_vertices(&self) -> usize;
    /// Does [`Source::positions`] give points?
    fn has_positions(&self) -> bool;
    /// Elements `first..first + out.len()` into `out`.
    fn elements(&self, first: usize, out: &mut [[u32; N]]) -> Result<()>;
    /// Positions of vertices `first..first + out.len()` into `out`.
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()>;
}

/// The arrays of a mesh held in memory, as a source (tests compare the builds).
pub struct SliceSource<'a, const N: usize> {
    pub elements: &'a [[u32; N]],
    pub n_vertices: usize,
    pub positions: &'a [DVec3],
}

impl<const N: usize> Source<N> for SliceSource<'_, N> {
    fn num_elements(&self) -> usize {
        self.elements.len()
    }
    fn num_vertices(&self) -> usize {
        self.n_vertices
    }
    fn has_positions(&self) -> bool {
        !self.positions.is_empty()
    }
    fn elements(&self, first: usize, out: &mut [[u32; N]]) -> Result<()> {
        out.copy_from_slice(&self.elements[first..first + out.len()]);
        Ok(())
    }
    fn positions(&self, first: usize, out: &mut [DVec3]) -> Result<()> {
        out.copy_from_slice(&self.positions[first..first + out.len()]);
        Ok(())
    }
}
