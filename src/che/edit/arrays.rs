//! Every write to the arrays of a [`Che`] that an edit makes goes through these accessors,
//! so that a change of the arrays' storage type changes this file only. Reads index the
//! fields directly. [`promote`] copies mapped arrays into memory before an edit writes.

use crate::che::Che;
use crate::error::Result;
use crate::util::origin::OriginMap;
use glam::DVec3;

pub(super) fn v_mut(che: &mut Che) -> &mut Vec<u32> {
    che.v.owned_mut()
}
pub(super) fn o_mut(che: &mut Che) -> &mut Vec<u32> {
    che.o.owned_mut()
}
/// `O[h] = g`.
pub(super) fn set_o(che: &mut Che, h: u32, g: u32) {
    che.o.owned_mut()[h as usize] = g;
    touch_edge_ranks(che, h);
}
/// `V[h] = x` (`NONE`: its triangle is removed).
pub(super) fn set_v(che: &mut Che, h: u32, x: u32) {
    che.v.owned_mut()[h as usize] = x;
    touch_edge_ranks(che, h);
}
/// Below level 2, whether `h` is a live canonical half-edge may have changed: its block of
/// the live edges' counts is recounted at the end of the operation.
pub(super) fn touch_edge_ranks(che: &mut Che, h: u32) {
    if che.level < 2
        && let Some(ranks) = che
            .edit
            .as_deref_mut()
            .and_then(|st| st.edge_ranks.as_mut())
    {
        ranks.touch(h as usize);
    }
}
pub(super) fn vh_mut(che: &mut Che) -> &mut Vec<u32> {
    che.vh.owned_mut()
}
/// `VH[x] = now` where `VH[x]` was `was`: the half-edge a local edit (flip, split) moved
/// away from `x` or replaced, by the one of the same kind that took its place, so that no
/// star is walked (the edit leaves every vertex's boundary as it was).
pub(super) fn replace_vh(che: &mut Che, x: u32, was: u32, now: u32) {
    if che.vh[x as usize] == was {
        vh_mut(che)[x as usize] = now;
    }
}
pub(super) fn eh_mut(che: &mut Che) -> &mut Vec<u32> {
    che.eh.owned_mut()
}
pub(super) fn positions_mut(che: &mut Che) -> &mut Vec<DVec3> {
    che.positions.owned_mut()
}
pub(super) fn non_manifold_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.non_manifold
}
pub(super) fn seams_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.seams
}
pub(super) fn vertex_origin_mut(che: &mut Che) -> &mut OriginMap {
    &mut che.vertex_origin
}
pub(super) fn triangle_origin_mut(che: &mut Che) -> &mut OriginMap {
    &mut che.triangle_origin
}
pub(super) fn ch_mut(che: &mut Che) -> &mut Vec<u32> {
    che.ch.owned_mut()
}
pub(super) fn curve_of_mut(che: &mut Che) -> &mut Vec<u32> {
    che.curve_of.owned_mut()
}

/// Copies every array an edit may write into owned memory (a mapped level file's arrays
/// are read-only), fallibly, before the edit's first write.
pub(super) fn promote(che: &mut Che) -> Result<()> {
    che.v.to_mut("the half-edge vertices V")?;
    che.o.to_mut("the opposites O")?;
    che.vh.to_mut("the vertex half-edges VH")?;
    che.eh.to_mut("the edge half-edges EH")?;
    che.positions.to_mut("the positions")?;
    che.ch.to_mut("the curve half-edges CH")?;
    che.curve_of
        .to_mut("the curve of each boundary half-edge")?;
    Ok(())
}
