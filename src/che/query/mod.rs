//! Queries at every level: the rotation around a vertex (the one walk every star query,
//! the bulk sweeps and the C API step), the relations one element at a time, boundary
//! curves, whole relations as CSR, the summary and the memory used.

mod bulk;
mod components;
mod curves;
pub(crate) mod memory;
mod relations;
mod star;
mod star_lent;
pub(crate) mod summary;
mod validate;

pub use bulk::Csr;
pub(crate) use bulk::{Push, Rows};
pub use curves::BoundaryWalk;
pub use memory::Memory;
pub(crate) use star::for_each_step;
pub use star::{Rotation, StarCursor, StarStep};
pub use star_lent::{LentStar, LentStep};
pub use summary::Summary;
