//! Level 2: `VH` (boundary vertices store their outgoing boundary half-edge, so one
//! counter-clockwise rotation sweeps the whole fan) and edge ids (rank over the canonical
//! half-edges, `O[h] == NONE || h < O[h]`, in a directory of 2 bits per half-edge that the C API
//! lends as it is, plus `EH`).

use super::Che;
use crate::NONE;
use crate::util::rank_directory::RankDirectory;

pub(crate) fn build(che: &mut Che) {
    let (v, o) = (&che.v, &che.o);
    let mut vh = crate::util::pages::filled(che.n_vertices, NONE);
    for (h, (&x, &opp)) in v.iter().zip(o).enumerate() {
        let slot = &mut vh[x as usize];
        if *slot == NONE || opp == NONE {
            *slot = h as u32;
        }
    }
    che.vh = vh;
    build_edges(che);
}

/// The edge-id directory of the opposites `o`: the rank over the canonical half-edges,
/// `O[h] == NONE || h < O[h]` (the C API computes it with this at level 1 too).
pub(crate) fn edge_directory(o: &[u32]) -> RankDirectory {
    RankDirectory::from_fn(o.len(), |h| {
        let g = o[h];
        g == NONE || (h as u32) < g
    })
    .expect("half-edge ids fit 32 bits, so edge counts do")
}

/// Edge ids, with `VH` already in place (the build finds it while splitting vertices).
pub(crate) fn build_edges(che: &mut Che) {
    let (v, o) = (&che.v, &che.o);
    let edge_bits = edge_directory(o);
    let mut eh = crate::util::pages::with_capacity(edge_bits.ones());
    eh.extend((0..v.len() as u32).filter(|&h| edge_bits.get(h as usize)));
    debug_assert_eq!(eh.len(), che.num_edges);
    che.edge_bits = edge_bits;
    che.eh = eh;
}
