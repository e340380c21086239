//! The streaming build's passes for a volume: tetrahedra from a [`Source`](crate::Source)
//! in their order, checked and oriented block by block as the soup does, `O` found by the
//! sweep of `util::sweep` (half-faces keyed by their vertex triple, only the open ones in
//! memory), and the edges counted by the star pass run in rounds over `V` that hold its
//! records to a bound, so that a volume larger than memory is built into a mapped file.
//!
//! It pairs and orients by the determinant; it does not repair. A degenerate or flat
//! tetrahedron, a vertex out of range, a face of three tetrahedra, two tetrahedra on the
//! same four vertices, a pair of faces that still runs the same way, an edge or a vertex
//! whose tetrahedra fall apart into pieces: each is an error naming the place, since the
//! in-memory build (which repairs them) is the one for such input.

use super::soup;
use crate::chf::ids::tet;
use crate::chf::star_pass::{self, Pairs, StarPass};
use crate::error::{Error, Result};
use crate::util::sweep;
use glam::DVec3;

/// How the streaming build of a volume runs.
#[derive(Clone, Copy, Debug)]
pub struct SweepLimits {
    /// Tetrahedra sorted at a time.
    pub block_tetrahedra: usize,
    /// The most half-faces left open at once; past it the order does not suit the
    /// streaming build and it stops.
    pub max_open: usize,
    /// The edge census's records, in bytes (20 per occurrence of a vertex in a
    /// tetrahedron): a smaller bound makes more rounds over `V`.
    pub census_bytes: usize,
}

impl Default for SweepLimits {
    fn default() -> Self {
        SweepLimits {
            block_tetrahedra: 1 << 20,
            max_open: 1 << 27,
            census_bytes: 1 << 30,
        }
    }
}

/// An input the streaming build does not take.
fn refused(what: String) -> Error {
    Error::non_manifold(format!(
        "{what}: the streaming build pairs clean input only (the in-memory build repairs it)"
    ))
}

/// Checks tetrahedra `t0..` of `v` as the soup does (ids below `n_vertices`, four distinct
/// corners, a determinant that is not zero) and flips those whose determinant is negative;
/// returns how many it flipped.
pub(crate) fn check_tetrahedra(
    v: &mut [u32], t0: usize, n_vertices: usize, positions: &[DVec3],
) -> Result<usize> {
    let n_signs = if positions.is_empty() { 0 } else { v.len() / 4 };
    let mut sign = crate::util::alloc::try_vec(n_signs, 0i8, "the determinant signs")?;
    let run = soup::run(t0, None, v, &mut sign, n_vertices, positions);
    if let Some(e) = run.error {
        return Err(e);
    }
    if let Some(&t) = run.dropped.first() {
        return Err(refused(format!("tetrahedron {t} is degenerate")));
    }
    if let Some(&t) = run.zero_volume_examples.first() {
        return Err(refused(format!("tetrahedron {t} has no volume")));
    }
    Ok(run.flipped)
}

/// The pairing rules of half-faces: keyed by their sorted vertex triple, twins run the
/// other way, belong to tetrahedra of different fourth vertices, and no face has three.
struct HalfFaces<'a> {
    v: &'a [u32],
}

impl sweep::Rules for HalfFaces<'_> {
    type Key = [u32; 3];

    fn key(&self, h: u32) -> [u32; 3] {
        crate::chf::ids::sorted_triple(self.v, h)
    }

    fn check_pair(&self, g: u32, h: u32) -> Result<()> {
        let v = self.v;
        // Half-face `i` lies opposite corner `i`.
        if v[g as usize] == v[h as usize] {
            return Err(refused(format!(
                "tetrahedra {} and {} have the same four vertices",
                tet(g),
                tet(h)
            )));
        }
        if crate::chf::ids::same_direction(v, g, h) {
            let face = crate::chf::ids::face_cycle(v, g);
            return Err(refused(format!(
                "tetrahedra {} and {} run their face {face:?} the same way round",
                tet(g),
                tet(h)
            )));
        }
        Ok(())
    }

    fn crowded(&self, key: [u32; 3], group: [u32; 3], n: usize) -> Error {
        let [a, b, c] = group.map(tet);
        refused(format!(
            "the face of vertices {key:?} has {n} tetrahedra ({a}, {b}, {c}, ...)"
        ))
    }

    fn too_open(&self, open: usize, last: u32, max_open: usize) -> Error {
        Error::too_large(format!(
            "{open} half-faces open after tetrahedron {}: the tetrahedra's order does not \
             sweep the volume (at most {max_open} open); build it in memory",
            tet(last)
        ))
    }
}

/// Fills `o` (all `NONE` on entry) for `v`, block by block: the faces are its keys, the
/// boundary faces the half-faces left open.
pub(crate) fn sweep(v: &[u32], o: &mut [u32], limits: SweepLimits) -> Result<sweep::Swept> {
    let block = 4 * limits.block_tetrahedra.max(1);
    let max_open = limits.max_open;
    sweep::sweep(&HalfFaces { v }, o, sweep::Limits { block, max_open })
}

/// What the census found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Census {
    /// Faces as the sweep counts them: pairs, and boundary faces left open.
    pub faces: sweep::Swept,
    pub edges: usize,
}

/// Counts the faces and edges of `v` by the star pass, its records held to
/// `census_bytes`. What the sweep cannot see is an error there (what the in-memory build
/// repairs and reports): a third tetrahedron on a face whose pair the sweep had closed, a
/// vertex whose star is in several pieces, an edge whose tetrahedra form several fans.
pub(crate) fn census(v: &[u32], n_vertices: usize, census_bytes: usize) -> Result<Census> {
    let n_tets = v.len() / 4;
    let threads = crate::util::par::build_threads(0, n_tets);
    let pass = StarPass {
        pairs: Pairs::Census,
        tables: false,
        threads: star_pass::threads_for(n_tets, n_vertices, threads),
    };
    let stars = star_pass::stars_within(v, n_vertices, &[], pass, census_bytes / 20)?;
    let (faces, _) = stars.faces.as_ref().expect("faces were asked for");
    if let Some(f) = faces.non_manifold_face_examples.first() {
        return Err(refused(format!(
            "the face of vertices {f:?} has three tetrahedra or more"
        )));
    }
    if stars.split_needed {
        return Err(refused(format!(
            "the tetrahedra around vertex {} fall apart into pieces (the in-memory build \
             splits it)",
            stars.first_split
        )));
    }
    let edges = &stars.census;
    if let Some(&[a, b]) = edges.non_manifold_examples.first() {
        return Err(refused(format!(
            "the tetrahedra around the edge of vertices {a} and {b} form several fans"
        )));
    }
    // The sweep refused a duplicate pair and a pair run the same way before.
    debug_assert!(faces.duplicates == 0 && !faces.same_direction);
    debug_assert!(edges.non_manifold == 0 && edges.multi_fan.is_empty());
    Ok(Census {
        faces: sweep::Swept {
            pairs: faces.input_faces - faces.boundary_faces,
            open: faces.boundary_faces,
        },
        edges: stars.num_edges,
    })
}
