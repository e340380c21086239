//! Every write the edits make to the arrays a built CHF already has (`V`, `O`, `VH`, the
//! positions and the origin maps), in one place. A mapped level file's arrays are read-only:
//! [`promote`] copies them into memory, fallibly, when the edit state is made.

use crate::chf::Chf;
use crate::error::Result;
use crate::util::alloc::try_grow;
use glam::DVec3;

/// Appends tetrahedron `q` (`O` unpaired), coming from no input tetrahedron.
pub(crate) fn push_tetrahedron(chf: &mut Chf, q: [u32; 4]) -> Result<()> {
    try_grow(chf.v.to_mut("the tetrahedra V")?, 4, "the tetrahedra V")?;
    try_grow(chf.o.to_mut("the opposites O")?, 4, "the opposites O")?;
    chf.tet_origin
        .push(crate::NONE, "the tetrahedron origins")?;
    chf.v.owned_mut().extend_from_slice(&q);
    chf.o.owned_mut().extend_from_slice(&[crate::NONE; 4]);
    Ok(())
}

/// `O[hf] = g`.
#[inline]
pub(crate) fn set_opposite(chf: &mut Chf, hf: u32, g: u32) {
    chf.o.owned_mut()[hf as usize] = g;
}

/// `V[hf] = x`: vertex `local(hf)` of `tet(hf)` becomes `x`.
#[inline]
pub(crate) fn set_corner(chf: &mut Chf, hf: u32, x: u32) {
    chf.v.owned_mut()[hf as usize] = x;
}

/// `VH[x] = hf`.
#[inline]
pub(crate) fn set_vertex_half_face(chf: &mut Chf, x: u32, hf: u32) {
    chf.vh.owned_mut()[x as usize] = hf;
}

/// Appends a vertex (at `position` when the mesh has positions), from no input vertex.
pub(crate) fn push_vertex(chf: &mut Chf, position: Option<DVec3>) -> Result<()> {
    try_grow(
        chf.vh.to_mut("the vertex half-faces VH")?,
        1,
        "the vertex half-faces VH",
    )?;
    if position.is_some() {
        try_grow(chf.positions.to_mut("the positions")?, 1, "the positions")?;
    }
    chf.vertex_origin.push(crate::NONE, "the vertex origins")?;
    if let Some(p) = position {
        chf.positions.owned_mut().push(p);
    }
    chf.vh.owned_mut().push(crate::NONE);
    chf.n_vertices += 1;
    Ok(())
}

/// Copies every array an edit may write into owned memory (a no-op for owned arrays).
pub(crate) fn promote(chf: &mut Chf) -> Result<()> {
    chf.v.to_mut("the tetrahedra V")?;
    chf.o.to_mut("the opposites O")?;
    chf.vh.to_mut("the vertex half-faces VH")?;
    chf.positions.to_mut("the positions")?;
    Ok(())
}
