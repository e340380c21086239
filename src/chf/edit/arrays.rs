//! Every write the edits make to the arrays a built CHF already has (`V`, `O`, `VH`, the
//! positions and the origin maps), in one place: how those arrays are stored may change,
//! and then only this file follows.

use crate::chf::Chf;
use crate::error::Result;
use crate::util::alloc::try_reserve;
use glam::DVec3;

/// Appends tetrahedron `q` (`O` unpaired), coming from no input tetrahedron.
pub(crate) fn push_tetrahedron(chf: &mut Chf, q: [u32; 4]) -> Result<()> {
    try_reserve(&mut chf.v, 4, "the tetrahedra V")?;
    try_reserve(&mut chf.o, 4, "the opposites O")?;
    chf.tet_origin
        .push(crate::NONE, "the tetrahedron origins")?;
    chf.v.extend_from_slice(&q);
    chf.o.extend_from_slice(&[crate::NONE; 4]);
    Ok(())
}

/// `O[hf] = g`.
#[inline]
pub(crate) fn set_opposite(chf: &mut Chf, hf: u32, g: u32) {
    chf.o[hf as usize] = g;
}

/// `VH[x] = hf`.
#[inline]
pub(crate) fn set_vertex_half_face(chf: &mut Chf, x: u32, hf: u32) {
    chf.vh[x as usize] = hf;
}

/// Appends a vertex (at `position` when the mesh has positions), from no input vertex.
pub(crate) fn push_vertex(chf: &mut Chf, position: Option<DVec3>) -> Result<()> {
    try_reserve(&mut chf.vh, 1, "the vertex half-faces VH")?;
    if position.is_some() {
        try_reserve(&mut chf.positions, 1, "the positions")?;
    }
    chf.vertex_origin.push(crate::NONE, "the vertex origins")?;
    if let Some(p) = position {
        chf.positions.push(p);
    }
    chf.vh.push(crate::NONE);
    chf.n_vertices += 1;
    Ok(())
}
