//! The queries: every relation, per element and in bulk, on a [`View`](view::View) of the
//! tables the level stores (or computes them for the one query below it).

mod boundary;
pub(crate) mod bulk;
pub(crate) mod fan;
pub(crate) mod memory;
pub(crate) mod relations;
pub(crate) mod star;
pub(crate) mod summary;
mod validate;
pub(crate) mod view;

pub use bulk::ChfCsr;
pub use fan::EdgeIds;
pub use memory::ChfMemory;
pub use star::{INLINE as STAR_INLINE, VertexIds};
pub use summary::ChfSummary;
