//! Shared by the CHF integration tests (`mod chf_common;`): mesh generators, a brute-force
//! reference computed from the raw tetrahedron list, and the checks built on it.
#![allow(dead_code, unused_imports)]

mod answers;
mod checks;
mod mesh;
mod reference;

pub use answers::*;
pub use checks::*;
pub use mesh::*;
pub use reference::*;
