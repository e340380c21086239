//! The checks element by element, which name the first violation: what `validate` runs
//! when a pass of `sweep` has found that there is one.

use crate::NONE;
use crate::che::Che;
use crate::che::for_each_step;
use crate::che::ids::next;
use crate::che::tables::is_canonical;
use crate::error::Result;
use crate::util::alloc::try_vec;

/// What is wrong with `O[h]`, if anything: it must pair `h` with a live half-edge on
/// the same vertex pair run the other way, whose `O` is `h` (`NONE` on the boundary).
#[inline]
fn o_violation(v: &[u32], o: &[u32], h: usize) -> Option<String> {
    let g = o[h];
    // A removed half-edge (V = NONE, on an edited CHE) pairs with nothing.
    if v[h] == NONE && g != NONE {
        return Some(format!("removed half-edge {h} has O = {g}"));
    }
    if v[h] == NONE || g == NONE {
        return None;
    }
    let h32 = h as u32;
    if g as usize >= o.len() || g == h32 || o[g as usize] != h32 || v[g as usize] == NONE {
        return Some(format!("O[{h}] = {g}: not an involution"));
    }
    if v[g as usize] != v[next(h32) as usize] || v[next(g) as usize] != v[h] {
        return Some(format!(
            "O[{h}] = {g}: not the same vertex pair run the other way"
        ));
    }
    None
}

/// What is wrong with `VH[x]`, if anything, for a vertex with `degree` outgoing
/// half-edges, one of them on the boundary when `on_boundary`.
#[inline]
fn vh_violation(
    (v, o, vh): (&[u32], &[u32], &[u32]), x: usize, degree: u32, on_boundary: bool,
) -> Option<String> {
    let h = vh[x];
    if h == NONE {
        return (degree != 0).then(|| format!("VH[{x}] is NONE but vertex {x} has half-edges"));
    }
    if h as usize >= v.len() || v[h as usize] as usize != x {
        return Some(format!("VH[{x}] = {h} does not start at vertex {x}"));
    }
    if on_boundary && o[h as usize] != NONE {
        return Some(format!(
            "VH[{x}] = {h} is not the boundary half-edge of a boundary vertex"
        ));
    }
    let mut steps = 0u32;
    for_each_step(o, h, |s| {
        steps += matches!(s, crate::che::StarStep::Out(_)) as u32
    });
    (steps != degree)
        .then(|| format!("the rotation of vertex {x} meets {steps} of its {degree} half-edges"))
}

impl Che {
    /// The first entry of `V` that is no vertex, or the first degenerate triangle, named.
    pub(super) fn first_v_violation(&self) -> Option<String> {
        if let Some((h, &x)) = self
            .v
            .iter()
            .enumerate()
            .find(|&(_, &x)| x as usize >= self.n_vertices)
        {
            return Some(format!(
                "V[{h}] = {x} is not a vertex (the mesh has {})",
                self.n_vertices
            ));
        }
        for (t, c) in self.v.chunks_exact(3).enumerate() {
            if c[0] == c[1] || c[1] == c[2] || c[0] == c[2] {
                return Some(format!("triangle {t} is degenerate ({c:?})"));
            }
        }
        None
    }

    /// The first `O[h]` that breaks the pairing, named.
    pub(super) fn first_o_violation(&self) -> Option<String> {
        let (v, o) = (&self.v, &self.o);
        let threads = crate::util::par::planned_threads(0, self.num_triangles());
        crate::util::par::first_found(o.len(), threads, |hs| {
            hs.into_iter().find_map(|h| o_violation(v, o, h))
        })
    }

    /// The first vertex whose `VH` entry or rotation is wrong, named.
    pub(super) fn first_vh_violation(&self) -> Result<Option<String>> {
        let (v, o, vh) = (&self.v, &self.o, &self.vh);
        // Outgoing half-edges per vertex, and whether one is on the boundary.
        let mut degree = try_vec(self.n_vertices, 0u32, "the vertex degrees")?;
        let mut on_boundary = try_vec(self.n_vertices, false, "the boundary vertices")?;
        // Removed half-edges (V = NONE, on an edited CHE) belong to no vertex.
        for (h, &x) in v.iter().enumerate().filter(|&(_, &x)| x != NONE) {
            degree[x as usize] += 1;
            on_boundary[x as usize] |= o[h] == NONE;
        }
        let threads = crate::util::par::planned_threads(0, self.num_triangles());
        Ok(crate::util::par::first_found(vh.len(), threads, |xs| {
            xs.into_iter()
                .find_map(|x| vh_violation((v, o, vh), x, degree[x], on_boundary[x]))
        }))
    }

    /// The first flag of the edge directory or entry of `EH` that is wrong, named.
    pub(super) fn first_edge_violation(&self) -> Option<String> {
        let o = &self.o;
        if let Some(h) = (0..o.len()).find(|&h| self.edge_bits.get(h) != is_canonical(o, h)) {
            return Some(format!("the edge directory flags half-edge {h} wrongly"));
        }
        for (e, &h) in self.eh.iter().enumerate() {
            if h as usize >= o.len()
                || !is_canonical(o, h as usize)
                || self.edge_bits.rank(h as usize) != e
            {
                return Some(format!(
                    "EH[{e}] = {h} is not the canonical half-edge of edge {e}"
                ));
            }
        }
        None
    }
}
