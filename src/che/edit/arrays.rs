//! Every write to the arrays of a [`Che`] that an edit makes goes through these accessors,
//! so that a change of the arrays' storage type changes this file only. Reads index the
//! fields directly.

use crate::che::Che;
use crate::util::origin::OriginMap;
use glam::DVec3;

pub(super) fn v_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.v
}
pub(super) fn o_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.o
}
pub(super) fn vh_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.vh
}
pub(super) fn eh_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.eh
}
pub(super) fn positions_mut(che: &mut Che) -> &mut Vec<DVec3> {
    &mut che.positions
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
    &mut che.ch
}
pub(super) fn curve_of_mut(che: &mut Che) -> &mut Vec<u32> {
    &mut che.curve_of
}
