//! The walks behind the per-element and bulk calls when the arrays they need are stored:
//! the same arithmetic as the zero-copy path (`V`, `O`, `VH`, `EH` and `che_next` /
//! `che_prev`), read through bounds-checked slices, with no level test per step. The
//! rotation is the core's (`crate::che::star`): from `VH[v]`, then `O[prev(h)]` until the
//! boundary or back at the start; on the boundary one last step for the incoming boundary
//! half-edge `prev(h)`.

use crate::NONE;
use crate::che::{Che, next, prev, tri};

/// `V`, `O` and the starting half-edge of every vertex.
#[derive(Clone, Copy)]
pub(crate) struct Walk<'a> {
    pub(crate) v: &'a [u32],
    pub(crate) o: &'a [u32],
    pub(crate) vh: &'a [u32],
}

impl<'a> Walk<'a> {
    /// From level 2 (`VH` stored); `None` below.
    #[inline]
    pub(crate) fn of(che: &'a Che) -> Option<Self> {
        Some(Walk {
            v: che.half_edge_vertices(),
            o: che.opposites()?,
            vh: che.vertex_half_edges()?,
        })
    }

    /// The rotation around `v` (checked by the caller): `out(h)` for each outgoing
    /// half-edge, then `last_in(p)` for the incoming boundary half-edge of a boundary vertex.
    #[inline]
    pub(crate) fn star(&self, v: u32, mut out: impl FnMut(u32), last_in: impl FnOnce(u32)) {
        let start = self.vh[v as usize];
        if start == NONE {
            return;
        }
        let mut h = start;
        loop {
            out(h);
            let p = prev(h);
            let around = self.o[p as usize];
            if around == NONE {
                last_in(p);
                return;
            }
            if around == start {
                return;
            }
            h = around;
        }
    }

    /// VV of `v` into `push`.
    #[inline]
    pub(crate) fn vertex_vertices(&self, v: u32, push: &mut impl FnMut(u32)) {
        let vs = self.v;
        let mut out = |h: u32| push(vs[next(h) as usize]);
        let mut tail = NONE;
        self.star(v, &mut out, |p| tail = vs[p as usize]);
        if tail != NONE {
            push(tail);
        }
    }

    /// VF of `v` into `push`.
    #[inline]
    pub(crate) fn vertex_triangles(&self, v: u32, push: &mut impl FnMut(u32)) {
        self.star(v, |h| push(tri(h)), |_| {});
    }
}

/// The triangle across `h`, or `NONE`.
#[inline]
pub(crate) fn across(o: &[u32], h: usize) -> u32 {
    let g = o[h];
    if g == NONE { NONE } else { tri(g) }
}

/// The starting half-edge of every vertex below level 2 (the boundary one on a boundary
/// vertex, as `VH`), from `V` and `O` in one pass.
pub(crate) fn vertex_half_edges(n_vertices: usize, v: &[u32], o: &[u32]) -> Vec<u32> {
    let mut vh = vec![NONE; n_vertices];
    for (h, (&x, &g)) in v.iter().zip(o).enumerate() {
        let slot = &mut vh[x as usize];
        if *slot == NONE || g == NONE {
            *slot = h as u32;
        }
    }
    vh
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::che::BuildOptions;

    #[test]
    fn walks_match_the_core() {
        // A fan of 5 triangles around vertex 0 (open), plus a closed tetrahedron.
        let tris = [
            0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 7, 9, 8, 7, 8, 10, 7, 10, 9, 8, 9, 10,
        ];
        for level in 1..=3u8 {
            let che = Che::from_flat(&tris, 11, &[], BuildOptions::level(level)).unwrap();
            let o = che.opposites().unwrap();
            let vh = vertex_half_edges(che.num_vertices(), che.half_edge_vertices(), o);
            let walk = Walk::of(&che).unwrap_or(Walk {
                v: che.half_edge_vertices(),
                o,
                vh: &vh,
            });
            for v in 0..che.num_vertices() as u32 {
                let (mut vv, mut vf) = (Vec::new(), Vec::new());
                walk.vertex_vertices(v, &mut |x| vv.push(x));
                walk.vertex_triangles(v, &mut |x| vf.push(x));
                assert_eq!(vv, che.vertex_vertices(v).collect::<Vec<_>>(), "VV {v}");
                assert_eq!(vf, che.vertex_triangles(v).collect::<Vec<_>>(), "VF {v}");
            }
            for t in 0..che.num_triangles() {
                let ff: Vec<u32> = (0..3).map(|i| across(o, 3 * t + i)).collect();
                assert_eq!(ff, che.triangle_triangles(t as u32));
            }
        }
    }
}
