//! Level 2: `VH` (a boundary vertex stores a boundary half-face, so that
//! `is_boundary(v) == (O[VH[v]] == NONE)`; the first such in half-face order, else the first
//! half-face holding the vertex, the same rule the scans below level 2 use), face ids (rank
//! over canonical half-faces plus `FH`) and edge ids (rank over canonical edge slots plus
//! the tetrahedron of each).

use crate::chf::Chf;
use crate::chf::query::view::face_bits;
use crate::error::Result;
use crate::util::rank::RankBits;

/// `edge_bits` (the canonical slots) and `vh` come from the star pass (`stars.rs`), run
/// once by the build or the level change.
pub(crate) fn build(chf: &mut Chf, edge_bits: RankBits, vh: Vec<u32>) -> Result<()> {
    let (v, o) = (&chf.v, &chf.o);
    debug_assert_eq!(vh.len(), chf.n_vertices);
    let faces = face_bits(o)?;
    let mut fh = Vec::new();
    faces.ones_map(&mut fh, |hf| hf as u32, "the face half-faces FH")?;
    debug_assert_eq!(fh.len(), chf.num_faces);
    let mut eh = Vec::new();
    edge_bits.ones_map(&mut eh, |s| (s / 6) as u32, "the edge tetrahedra EH")?;
    debug_assert_eq!(eh.len(), chf.num_edges);
    debug_assert_eq!(v.len() % 4, 0);
    chf.vh = vh.into();
    chf.face_bits = faces;
    chf.fh = fh.into();
    chf.edge_bits = edge_bits;
    chf.eh = eh.into();
    Ok(())
}
