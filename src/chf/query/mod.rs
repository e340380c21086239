//! The queries: every relation, per element and in bulk, on a [`View`](view::View) of the
//! tables the level stores (or computes them for the one query below it).

mod boundary;
pub(crate) mod bulk;
pub(crate) mod fan;
pub(crate) mod memory;
mod non_manifold;
pub(crate) mod relations;
pub(crate) mod star;
pub(crate) mod summary;
mod validate;
pub(crate) mod view;

pub use bulk::Csr;
pub use fan::EdgeIds;
pub use memory::Memory;
pub use star::{STAR_INLINE, VertexIds};
pub use summary::Summary;
pub(crate) use validate::vertices_on;
