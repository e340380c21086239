//! Level 2: `VH` (a boundary vertex stores a boundary half-face, so that
//! `is_boundary(v) == (O[VH[v]] == NONE)`; the first such in half-face order, else the first
//! half-face holding the vertex, the same rule the scans below level 2 use), face ids (rank
//! over canonical half-faces plus `FH`) and edge ids (rank over canonical edge slots plus
//! the tetrahedron of each).

use super::Chf;
use super::view::face_bits;
use crate::rank::RankBits;

/// `edge_bits` (the canonical slots) and `vh` come from the star pass (`stars.rs`), run
/// once by the build or the level change.
pub(crate) fn build(chf: &mut Chf, edge_bits: RankBits, vh: Vec<u32>) {
    let (v, o) = (&chf.v, &chf.o);
    debug_assert_eq!(vh.len(), chf.n_vertices);
    let faces = face_bits(o);
    let mut fh = Vec::with_capacity(faces.ones());
    fh.extend((0..v.len() as u32).filter(|&hf| faces.get(hf as usize)));
    debug_assert_eq!(fh.len(), chf.num_faces);
    let mut eh = Vec::with_capacity(edge_bits.ones());
    for t in 0..(v.len() / 4) as u32 {
        for k in 0..6 {
            if edge_bits.get(6 * t as usize + k) {
                eh.push(t);
            }
        }
    }
    debug_assert_eq!(eh.len(), chf.num_edges);
    chf.vh = vh;
    chf.face_bits = faces;
    chf.fh = fh;
    chf.edge_bits = edge_bits;
    chf.eh = eh;
}
