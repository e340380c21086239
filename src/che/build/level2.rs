//! Level 2: `VH` (boundary vertices store their outgoing boundary half-edge, so one
//! counter-clockwise rotation sweeps the whole fan) and edge ids (rank over the canonical
//! half-edges, `O[h] == NONE || h < O[h]`, in a directory of 2 bits per half-edge that the C API
//! lends as it is, plus `EH`).

use crate::che::Che;
use crate::che::tables::{edge_directory, vertex_half_edges_in};
use crate::error::Result;

/// Arrays of a structure's earlier level 2 whose memory the new tables may take.
#[derive(Default)]
pub(crate) struct Spare {
    pub vh: Vec<u32>,
    pub eh: Vec<u32>,
}

pub(crate) fn build(che: &mut Che) -> Result<()> {
    build_in(che, Spare::default())
}

/// [`build`] in the memory of `spare` where it has the room.
pub(crate) fn build_in(che: &mut Che, spare: Spare) -> Result<()> {
    // Nothing is stored until every table is had: a failure leaves the structure at the
    // level it had.
    let vh = vertex_half_edges_in(spare.vh, che.n_vertices, &che.v, &che.o)?;
    build_edges_in(che, spare.eh)?;
    che.vh = vh.into();
    Ok(())
}

/// Edge ids, with `VH` already in place (the build finds it while splitting vertices).
pub(crate) fn build_edges(che: &mut Che) -> Result<()> {
    build_edges_in(che, Vec::new())
}

/// [`build_edges`], `EH` in `spare`'s memory when it has the room.
fn build_edges_in(che: &mut Che, spare: Vec<u32>) -> Result<()> {
    let edge_bits = edge_directory(&che.o)?;
    let what = "the edge half-edges EH";
    let mut eh = crate::util::pages::reusing(spare, edge_bits.ones(), what)?;
    edge_bits.ones_map(&mut eh, |h| h as u32, what)?;
    debug_assert_eq!(eh.len(), che.num_edges);
    che.edge_bits = edge_bits;
    che.eh = eh.into();
    Ok(())
}
