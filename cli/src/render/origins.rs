//! The vertex numbering both structures share (the input vertices, then the copies the
//! split added), and the input vertices that have copies.

use topomesh::{Che, Chf};

/// The input vertices the build split into copies, in increasing order, once each.
pub fn split_origins(structure: &impl Origins) -> Vec<u32> {
    let mut v: Vec<u32> = (structure.inputs()..structure.all())
        .map(|c| structure.origin(c as u32))
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// The vertex numbering both structures share: input vertices, then copies.
pub trait Origins {
    fn inputs(&self) -> usize;
    fn all(&self) -> usize;
    fn origin(&self, v: u32) -> u32;
}

impl Origins for Che {
    fn inputs(&self) -> usize {
        self.num_input_vertices()
    }
    fn all(&self) -> usize {
        self.num_vertices()
    }
    fn origin(&self, v: u32) -> u32 {
        self.vertex_origin(v)
    }
}

impl Origins for Chf {
    fn inputs(&self) -> usize {
        self.num_input_vertices()
    }
    fn all(&self) -> usize {
        self.num_vertices()
    }
    fn origin(&self, v: u32) -> u32 {
        self.vertex_origin(v)
    }
}
