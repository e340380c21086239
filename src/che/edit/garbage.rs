//! Garbage collection: the live elements compacted (`h = 3t + i` without holes), every
//! level's tables rebuilt from `V` and `O` in O(T), and old -> new id maps returned.

use super::arrays::{
    ch_mut, curve_of_mut, eh_mut, non_manifold_mut, o_mut, positions_mut, seams_mut,
    triangle_origin_mut, v_mut, vertex_origin_mut, vh_mut,
};
use crate::NONE;
use crate::che::build::level2::{self, Spare};
use crate::che::tables::is_canonical;
use crate::che::{Che, Checked};
use crate::error::Result;
use crate::util::alloc::{try_vec, try_with_capacity};
use crate::util::origin::OriginMap;
use std::borrow::Cow;

/// Old id -> new id after [`Che::garbage_collect`] (`NONE` for a removed element).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GarbageMaps {
    pub vertices: Vec<u32>,
    pub triangles: Vec<u32>,
    pub edges: Vec<u32>,
}

/// `map[i]`: the rank of `i` among the kept, `NONE` if not kept, from the flag of each
/// `i` in turn; the number kept.
fn ranks(map: &mut [u32], kept: impl Iterator<Item = bool>) -> usize {
    let mut next = 0u32;
    for (m, k) in map.iter_mut().zip(kept) {
        next += u32::from(k);
        *m = if k { next - 1 } else { NONE };
    }
    next as usize
}

/// Where a map is written: the caller's buffer, or memory of its own for a map the caller
/// does not want (the collection needs the vertex and triangle maps itself).
enum MapMemory<'a> {
    Lent(&'a mut [u32]),
    Own(Vec<u32>),
}

impl MapMemory<'_> {
    fn of<'a>(lent: Option<&'a mut [u32]>, n: usize, what: &str) -> Result<MapMemory<'a>> {
        match lent {
            Some(b) if b.len() == n => Ok(MapMemory::Lent(b)),
            Some(b) => Err(crate::error::Error::invalid(format!(
                "{what}: {n} entries needed, {} given",
                b.len()
            ))),
            None => Ok(MapMemory::Own(try_vec(n, NONE, what)?)),
        }
    }
}

impl std::ops::Deref for MapMemory<'_> {
    type Target = [u32];
    fn deref(&self) -> &[u32] {
        match self {
            MapMemory::Lent(b) => b,
            MapMemory::Own(v) => v,
        }
    }
}

impl std::ops::DerefMut for MapMemory<'_> {
    fn deref_mut(&mut self) -> &mut [u32] {
        match self {
            MapMemory::Lent(b) => b,
            MapMemory::Own(v) => v,
        }
    }
}

/// The old -> new maps of [`Che::garbage_collect_into`] written into the caller's buffers,
/// each exactly as long as its count before the call (`None`: not wanted).
#[derive(Default)]
pub struct GarbageMapsOut<'a> {
    pub vertices: Option<&'a mut [u32]>,
    pub triangles: Option<&'a mut [u32]>,
    pub edges: Option<&'a mut [u32]>,
}

/// The ids `i` that `map` keeps, in order: an identity origin map over the kept.
fn kept_ids(map: &[u32], what: &str) -> Result<Vec<u32>> {
    let kept = (0..map.len() as u32).filter(|&i| map[i as usize] != NONE);
    crate::util::alloc::try_collect(kept, what)
}

/// `map[i]`, `NONE` past the end (for `i = NONE` among others), by selects, not branches:
/// half the ids may be `NONE` (unpaired half-edges, removed triangles' corners) in no
/// pattern. An index past the end reads a clamped slot, masked after.
#[inline]
fn map_id(map: &[u32], i: usize) -> u32 {
    let x = map
        .get(i.min(map.len().saturating_sub(1)))
        .copied()
        .unwrap_or(NONE);
    if i < map.len() { x } else { NONE }
}

/// Half-edge `h` in the new ids (`NONE` when its triangle is removed, or `h` is `NONE`).
#[inline]
fn half_edge_map(tmap: &[u32], h: u32) -> u32 {
    let t = map_id(tmap, h as usize / 3);
    let mapped = t.wrapping_mul(3).wrapping_add(h % 3);
    if t != NONE { mapped } else { NONE }
}

/// Keeps, in order and in place, the entries `i` of `list` that are `kept(i)`, each as
/// `map` gives it: an entry moves only down, onto one already read.
fn compact_in_place<T: Copy>(
    list: &mut Vec<T>, kept: impl Fn(usize) -> bool, map: impl Fn(T) -> T,
) {
    let mut w = 0;
    for i in 0..list.len() {
        if kept(i) {
            list[w] = map(list[i]);
            w += 1;
        }
    }
    list.truncate(w);
}

/// Keeps, in order and in place, the three entries per triangle of `list` of the triangles
/// `tmap` keeps, each as `map` gives it: `compact_in_place` a triangle at a time.
fn compact_corners(list: &mut Vec<u32>, tmap: &[u32], map: impl Fn(u32) -> u32) {
    let mut w = 0;
    for (t, &kept) in tmap.iter().enumerate() {
        // Every triangle written, a removed one overwritten by the next: no branch on
        // which were removed. `w <= 3 * t`, so nothing unread is overwritten.
        for i in 0..3 {
            list[w + i] = map(list[3 * t + i]);
        }
        w += 3 * usize::from(kept != NONE);
    }
    list.truncate(w);
}

/// The kept entries of `list`, in order.
fn compact<T: Copy>(list: &[T], map: &[u32], what: &str) -> Result<Vec<T>> {
    let mut out = try_with_capacity(list.len(), what)?;
    out.extend(
        list.iter()
            .zip(map)
            .filter(|&(_, &m)| m != NONE)
            .map(|(&x, _)| x),
    );
    Ok(out)
}

impl Che {
    /// Compacts the removed elements away and returns the old -> new maps. The new ids are
    /// those a fresh build of the live triangles gives (edge ids: ranks again). O(T); the
    /// identity maps, and nothing touched, on a CHE never edited. Every id, borrowed slice
    /// and C view from before is invalid after it.
    pub fn garbage_collect(&mut self) -> Result<GarbageMaps> {
        let mut maps = GarbageMaps {
            vertices: try_vec(self.n_vertices, NONE, "the vertex map")?,
            triangles: try_vec(self.num_triangles(), NONE, "the triangle map")?,
            edges: try_vec(self.num_edges, NONE, "the edge map")?,
        };
        self.garbage_collect_into(GarbageMapsOut {
            vertices: Some(&mut maps.vertices),
            triangles: Some(&mut maps.triangles),
            edges: Some(&mut maps.edges),
        })?;
        Ok(maps)
    }

    /// [`Che::garbage_collect`], the maps written into the caller's buffers (the C API's):
    /// no map of its own to allocate and copy out. A buffer of another length than its
    /// count is an invalid-input error before anything changes.
    pub fn garbage_collect_into(&mut self, out: GarbageMapsOut<'_>) -> Result<()> {
        self.checked = Checked::Nothing;
        let level = self.level;
        let nv = self.n_vertices;
        let mut vmap = MapMemory::of(out.vertices, nv, "the vertex map")?;
        let mut tmap = MapMemory::of(out.triangles, self.num_triangles(), "the triangle map")?;
        let mut emap = MapMemory::of(out.edges, self.num_edges, "the edge map")?;
        if self.edit.is_none() {
            for map in [&mut vmap, &mut tmap, &mut emap] {
                map.iter_mut().zip(0..).for_each(|(m, i)| *m = i);
            }
            return Ok(());
        }
        let vkept = (0..nv as u32).map(|x| !self.is_vertex_removed(x));
        let new_nv = ranks(&mut vmap, vkept);
        ranks(&mut tmap, self.v.chunks_exact(3).map(|c| c[0] != NONE));
        // Level 0 stores no `O`: the edge map takes the one the edits kept, or computes it.
        let level0_o = match level {
            0 => Some(match self.kept_opposites() {
                Some(o) => Cow::Borrowed(o),
                None => Cow::Owned(self.live_opposites()?),
            }),
            _ => None,
        };
        let num_edges = self.edge_map(level0_o.as_deref().unwrap_or(&self.o), &tmap, &mut emap)?;
        let (vorigin, torigin) = self.compacted_origins(&vmap, &tmap, new_nv)?;
        let flags = |list: &[u32]| -> Result<Vec<u32>> {
            let kept = list.iter().map(|&h| half_edge_map(&tmap, h));
            crate::util::alloc::try_collect(kept.filter(|&h| h != NONE), "the flagged half-edges")
        };
        let (nm, seams) = (flags(&self.non_manifold)?, flags(&self.seams)?);
        // From here on nothing is allocated but the rebuilt levels: the arrays are
        // compacted in place, as the peers' collections do (they keep their capacity).
        drop(level0_o);
        self.compact_half_edges(&vmap, &tmap, level != 0);
        if !self.positions.is_empty() {
            compact_in_place(positions_mut(self), |x| vmap[x] != NONE, |p| p);
        }
        *vertex_origin_mut(self) = vorigin;
        *triangle_origin_mut(self) = torigin;
        *non_manifold_mut(self) = nm;
        *seams_mut(self) = seams;
        self.n_vertices = new_nv;
        self.num_edges = num_edges;
        self.rebuild_levels(level)
    }

    /// `V` (and `O` when the level stores it) of the live triangles in the new ids.
    fn compact_half_edges(&mut self, vmap: &[u32], tmap: &[u32], with_o: bool) {
        // A removed triangle's corners (`NONE`) are mapped too, and then overwritten.
        compact_corners(v_mut(self), tmap, |x| map_id(vmap, x as usize));
        if with_o {
            compact_corners(o_mut(self), tmap, |g| half_edge_map(tmap, g));
        }
    }

    /// Old edge id -> new edge id (`NONE` for a removed edge), and the number of edges
    /// left. A fresh build numbers the edges by their canonical half-edges in order, and
    /// compaction keeps that order: the live half-edges canonical after it (unpaired, or
    /// before their kept twin) take the new ids in turn.
    fn edge_map(&self, old_o: &[u32], tmap: &[u32], emap: &mut [u32]) -> Result<usize> {
        let old_ids = self.old_edge_ids(old_o)?;
        emap.fill(NONE);
        let mut next = 0u32;
        // Only the kept triangles' half-edges, a triangle at a time: half the work when
        // half the triangles are removed. A live half-edge's twin is live (removing a
        // triangle unpairs its twins), so the canonical ones stay canonical, and a twin's
        // edge id is the canonical one's. Which twin comes first is a coin toss, so the
        // map is written without a branch on it (the second twin writes back its entry).
        for (t, _) in tmap.iter().enumerate().filter(|&(_, &m)| m != NONE) {
            for h in 3 * t..3 * t + 3 {
                let canonical = is_canonical(old_o, h);
                let slot = &mut emap[old_ids[h] as usize];
                *slot = if canonical { next } else { *slot };
                next += u32::from(canonical);
            }
        }
        Ok(next as usize)
    }

    /// The vertex and triangle origin maps over the new ids. An identity map over the old
    /// ids is not the identity over the new ones once something was removed: it is written
    /// out then.
    fn compacted_origins(
        &self, vmap: &[u32], tmap: &[u32], new_nv: usize,
    ) -> Result<(OriginMap, OriginMap)> {
        let nv = vmap.len();
        let vorigin = match self.vertex_origin.explicit() {
            Some(map) => OriginMap::from(compact(map, vmap, "the vertex origins")?),
            None if new_nv == nv => OriginMap::default(),
            None => OriginMap::from(kept_ids(vmap, "the vertex origins")?),
        };
        let torigin = match self.triangle_origin.explicit() {
            Some(map) => OriginMap::from(compact(map, tmap, "the triangle origins")?),
            None if !tmap.contains(&NONE) => OriginMap::default(),
            None => OriginMap::from(kept_ids(tmap, "the triangle origins")?),
        };
        Ok((vorigin, torigin))
    }

    /// The edge id of every half-edge before the collection (`NONE` when removed): from
    /// level 2 the edit state's own ids when it holds them, else computed.
    fn old_edge_ids(&self, old_o: &[u32]) -> Result<Cow<'_, [u32]>> {
        if self.level >= 2 {
            if let Some(ids) = self.edited_edge_ids() {
                return Ok(Cow::Borrowed(ids));
            }
            let ids = (0..self.v.len() as u32).map(|h| {
                if self.v[h as usize] == NONE {
                    NONE
                } else {
                    self.edge_of(h)
                }
            });
            return Ok(Cow::Owned(crate::util::alloc::try_collect(
                ids,
                "the edge ids",
            )?));
        }
        Ok(Cow::Owned(self.live_edge_ids(old_o)?))
    }

    /// Every table of `level` again from `V` and `O` (or `V` alone at level 0), and the
    /// edit state reset to "nothing removed".
    fn rebuild_levels(&mut self, level: u8) -> Result<()> {
        let st = self.edit.get_or_insert_with(Default::default);
        st.edge_of = Vec::new();
        st.drop_kept_tables();
        st.changed = false;
        st.curves = Default::default();
        st.boundary = Default::default();
        st.removed_vertex
            .reset(self.n_vertices, "the removed-vertex flags")?;
        st.live_vertices = self.n_vertices;
        st.live_triangles = self.v.len() / 3;
        st.live_edges = self.num_edges;
        self.lazy_edge_bits = Default::default();
        if level == 0 {
            *o_mut(self) = Vec::new();
            return Ok(());
        }
        self.level = 1;
        // The rebuilt tables are at most as large as the old ones: they take the old ones'
        // memory, already mapped, instead of faulting in fresh pages.
        let spare = Spare {
            vh: std::mem::take(vh_mut(self)),
            eh: std::mem::take(eh_mut(self)),
        };
        *ch_mut(self) = Vec::new();
        *curve_of_mut(self) = Vec::new();
        self.edge_bits = Default::default();
        self.boundary_bits = Default::default();
        if level >= 2 {
            level2::build_in(self, spare)?;
            self.level = 2;
        }
        crate::che::build::change_level(self, level)?;
        self.seed_boundary_log()
    }
}
