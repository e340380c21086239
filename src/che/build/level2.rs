//! Level 2: `VH` (boundary vertices store their outgoing boundary half-edge, so one
//! counter-clockwise rotation sweeps the whole fan) and edge ids (rank over the canonical
//! half-edges, `O[h] == NONE || h < O[h]`, in a directory of 2 bits per half-edge that the C API
//! lends as it is, plus `EH`).

use crate::che::Che;
use crate::che::tables::{edge_directory, vertex_half_edges};
use crate::error::Result;

pub(crate) fn build(che: &mut Che) -> Result<()> {
    // Nothing is stored until every table is had: a failure leaves the structure at the
    // level it had.
    let vh = vertex_half_edges(che.n_vertices, &che.v, &che.o)?;
    build_edges(che)?;
    che.vh = vh.into();
    Ok(())
}

/// Edge ids, with `VH` already in place (the build finds it while splitting vertices).
pub(crate) fn build_edges(che: &mut Che) -> Result<()> {
    let (v, o) = (&che.v, &che.o);
    let edge_bits = edge_directory(o)?;
    let mut eh = crate::util::pages::with_capacity(edge_bits.ones(), "the edge half-edges EH")?;
    // Exactly `ones` half-edges pass the filter: the room asked for above is enough.
    eh.extend((0..v.len() as u32).filter(|&h| edge_bits.get(h as usize)));
    debug_assert_eq!(eh.len(), che.num_edges);
    che.edge_bits = edge_bits;
    che.eh = eh.into();
    Ok(())
}
