//! The non-manifold edges the structure keeps, for callers that show or list them.

use crate::chf::Chf;

impl Chf {
    /// The structure vertex pairs that carry several edges (several fans of tetrahedra
    /// around them, still sharing both ends after the vertex split): the non-manifold
    /// edges the structure keeps, sorted, each pair once.
    pub fn multi_fan_vertex_pairs(&self) -> impl Iterator<Item = [u32; 2]> + '_ {
        let mut last = None;
        self.multi_fan.iter().filter_map(move |m| {
            let pair = [m.a, m.b];
            (last.replace(pair) != Some(pair)).then_some(pair)
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::chf::{BuildOptions, Chf};

    /// Three tetrahedra around one edge, two of them glued by a face and the third
    /// touching only along the edge: the edge {0, 1} keeps two fans and is listed once.
    #[test]
    fn lists_the_edge_with_several_fans_once() {
        let tets = [[0, 1, 2, 3], [0, 1, 3, 4], [0, 1, 5, 6], [0, 1, 6, 7]];
        let chf = Chf::from_tetrahedra(&tets, 8, &[], BuildOptions::default()).unwrap();
        let pairs: Vec<_> = chf.multi_fan_vertex_pairs().collect();
        let mut dedup = pairs.clone();
        dedup.dedup();
        assert_eq!(pairs, dedup);
        assert_eq!(
            pairs.len(),
            chf.report().kept_non_manifold_edges,
            "{pairs:?}"
        );
        for [a, b] in pairs {
            let mut ends = [chf.vertex_origin(a), chf.vertex_origin(b)];
            ends.sort();
            assert_eq!(ends, [0, 1]);
        }
    }
}
