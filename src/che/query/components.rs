//! The connected component of each triangle, joined through shared input vertices as the
//! summary counts them, for callers that colour or split a mesh by component.

use crate::NONE;
use crate::che::Che;
use crate::error::Result;
use crate::util::alloc::try_vec;
use crate::util::dsu::Dsu;

impl Che {
    /// The component of each triangle, numbered from 0 in the order of each component's
    /// first triangle, and the number of components (the summary's `components`). O(T).
    pub fn triangle_components(&self) -> Result<(Vec<u32>, usize)> {
        let n = self.n_input_vertices;
        let mut dsu = Dsu::new(n)?;
        for t in self.v.chunks_exact(3) {
            let a = self.vertex_origin(t[0]);
            dsu.union(a, self.vertex_origin(t[1]));
            dsu.union(a, self.vertex_origin(t[2]));
        }
        let mut label = try_vec(n, NONE, "the component of each root")?;
        let mut component = try_vec(self.v.len() / 3, 0u32, "the component of each triangle")?;
        let mut count = 0u32;
        for (t, c) in component.iter_mut().enumerate() {
            let root = dsu.find(self.vertex_origin(self.v[3 * t])) as usize;
            if label[root] == NONE {
                label[root] = count;
                count += 1;
            }
            *c = label[root];
        }
        Ok((component, count as usize))
    }
}

#[cfg(test)]
mod tests {
    use crate::{BuildOptions, Che};

    /// Two bowties apart: two components, each triangle labelled with its own, and the
    /// count the summary gives.
    #[test]
    fn labels_agree_with_the_summary() {
        let tris = [[0, 1, 2], [0, 3, 4], [5, 6, 7], [5, 8, 9], [1, 2, 10]];
        let che = Che::from_triangles(&tris, 11, &[], BuildOptions::level(0)).unwrap();
        let (labels, n) = che.triangle_components().unwrap();
        assert_eq!(n as u64, che.summary().components);
        let origin = |t: u32| che.triangle_origin(t) as usize;
        let expect = [0, 0, 1, 1, 0];
        for t in 0..che.num_triangles() as u32 {
            assert_eq!(labels[t as usize], expect[origin(t)], "triangle {t}");
        }
    }
}
