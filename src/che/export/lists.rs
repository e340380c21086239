//! Edge and face lists: the ends of every edge and the edges of every triangle.

use crate::che::Che;
use crate::che::ids::next;
use crate::error::Result;
use crate::util::sparse::reserve;

impl Che {
    /// The ends of every edge, `2E` entries: edge `e` runs from `[2e]` to `[2e + 1]` in
    /// the direction of its canonical half-edge (as [`Che::edge_vertices`]).
    pub fn edge_list(&self) -> Result<Vec<u32>> {
        self.check_collected("the edge list")?;
        let t = self.export_tables()?;
        let mut out = Vec::new();
        reserve(&mut out, 2 * t.eh.len(), "edge list")?;
        for &h in t.eh.iter() {
            out.extend([self.v[h as usize], self.v[next(h) as usize]]);
        }
        Ok(out)
    }
}
