//! Whole relations at once, as CSR arrays (offsets + indices), in O(T) at every level:
//! below level 2 the missing `O`, `VH` or edge ranks are computed once for the sweep
//! instead of once per element.

use super::Che;
use super::ids::{next, prev, tri};
use super::star::StarStep;
use crate::NONE;
use std::borrow::Cow;

/// A relation for every element: element `i` has `indices[offsets[i]..offsets[i + 1]]`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Csr {
    pub offsets: Vec<usize>,
    pub indices: Vec<u32>,
}

impl Csr {
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    pub fn get(&self, i: usize) -> &[u32] {
        &self.indices[self.offsets[i]..self.offsets[i + 1]]
    }
}

/// The tables a sweep needs, borrowed or computed once.
struct Tables<'a> {
    o: Cow<'a, [u32]>,
    vh: Cow<'a, [u32]>,
}

impl Che {
    fn sweep_tables(&self) -> Tables<'_> {
        let o = self.opposites_or_computed();
        let vh = if self.level >= 2 {
            Cow::Borrowed(&self.vh[..])
        } else {
            let mut vh = vec![NONE; self.n_vertices];
            for (h, &x) in self.v.iter().enumerate() {
                let slot = &mut vh[x as usize];
                if *slot == NONE || o[h] == NONE {
                    *slot = h as u32;
                }
            }
            Cow::Owned(vh)
        };
        Tables { o, vh }
    }

    /// Edge id of every half-edge, as a table (for levels 0 and 1).
    fn edge_ids(&self, o: &[u32]) -> Vec<u32> {
        let mut ids = vec![NONE; self.v.len()];
        let mut next_id = 0u32;
        for h in 0..self.v.len() {
            let g = o[h];
            if g == NONE || (h as u32) < g {
                ids[h] = next_id;
                if g != NONE {
                    ids[g as usize] = next_id;
                }
                next_id += 1;
            }
        }
        ids
    }

    fn star_csr(&self, t: &Tables, mut item: impl FnMut(StarStep) -> Option<u32>) -> Csr {
        let mut csr = Csr {
            offsets: Vec::with_capacity(self.n_vertices + 1),
            indices: Vec::with_capacity(self.v.len() + self.v.len() / 8),
        };
        csr.offsets.push(0);
        for v in 0..self.n_vertices {
            let start = t.vh[v];
            if start != NONE {
                let mut h = start;
                loop {
                    csr.indices.extend(item(StarStep::Out(h)));
                    let around = t.o[prev(h) as usize];
                    if around == NONE {
                        csr.indices.extend(item(StarStep::LastIn(prev(h))));
                        break;
                    }
                    if around == start {
                        break;
                    }
                    h = around;
                }
            }
            csr.offsets.push(csr.indices.len());
        }
        csr
    }

    /// VV for every vertex, in the order of [`Che::vertex_vertices`].
    pub fn all_vertex_vertices(&self) -> Csr {
        let t = self.sweep_tables();
        self.star_csr(&t, |s| {
            Some(match s {
                StarStep::Out(h) => self.v[next(h) as usize],
                StarStep::LastIn(h) => self.v[h as usize],
            })
        })
    }

    /// VE for every vertex, in the order of [`Che::vertex_edges`].
    pub fn all_vertex_edges(&self) -> Csr {
        let t = self.sweep_tables();
        if self.level >= 2 {
            return self.star_csr(&t, |s| match s {
                StarStep::Out(h) | StarStep::LastIn(h) => Some(self.edge_of(h)),
            });
        }
        let ids = self.edge_ids(&t.o);
        self.star_csr(&t, |s| match s {
            StarStep::Out(h) | StarStep::LastIn(h) => Some(ids[h as usize]),
        })
    }

    /// VF for every vertex, in the order of [`Che::vertex_triangles`].
    pub fn all_vertex_triangles(&self) -> Csr {
        let t = self.sweep_tables();
        self.star_csr(&t, |s| match s {
            StarStep::Out(h) => Some(tri(h)),
            StarStep::LastIn(_) => None,
        })
    }

    /// FF for every triangle: 3 entries each, `NONE` across boundary edges.
    pub fn all_triangle_triangles(&self) -> Vec<u32> {
        let o = self.opposites_or_computed();
        o.iter()
            .map(|&g| if g == NONE { NONE } else { tri(g) })
            .collect()
    }

    /// FE for every triangle: 3 edge ids each.
    pub fn all_triangle_edges(&self) -> Vec<u32> {
        if self.level >= 2 {
            return (0..self.v.len() as u32).map(|h| self.edge_of(h)).collect();
        }
        let o = self.opposites_or_computed();
        self.edge_ids(&o)
    }
}
