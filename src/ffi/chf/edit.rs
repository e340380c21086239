//! Editing a mesh in place: inserting and removing tetrahedra and vertices, splits, flips
//! and edge collapse, their checks, the removed marks and the compaction. Every call needs
//! exclusive access; views obtained before an edit are invalid afterwards. A refused
//! operation returns `TOPOMESH_STATUS_INVALID_INPUT` (or `NON_MANIFOLD` for a face that
//! would have three tetrahedra, a broken link condition or a pinch) with a detail naming
//! the element and the reason, and changes nothing; a removed, out-of-range or
//! `TOPOMESH_NONE` id gives `TOPOMESH_STATUS_OUT_OF_RANGE`.
//!
//! Vertex and tetrahedron ids never move until `chf_mesh_garbage_collect`; neither do
//! face and edge ids. Positions: a `const double[3]` or NULL (the operation's default:
//! the centroid of what is split); a mesh without positions takes NULL only.

use super::ChfMesh;
use crate::chf::Chf;
use crate::error::{Error, Result};
use crate::ffi::boundary::{core, guard, handle_mut, out_arg, slice_arg};
use crate::ffi::status::Status;
use glam::DVec3;
use std::sync::OnceLock;

/// Runs `edit` on the handle's mesh and writes its answer into `out` (when not NULL); the
/// origin views the handle materialised are dropped, as the maps may have grown.
unsafe fn edit<T>(
    m: *mut ChfMesh, out: *mut T, edit: impl FnOnce(&mut Chf) -> Result<T>,
) -> Status {
    guard(|| {
        // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared.
        let h = unsafe { handle_mut(m, "m")? };
        // SAFETY: caller contract: NULL or valid for one write.
        let out = (!out.is_null())
            .then(|| unsafe { out_arg(out, "out") })
            .transpose()?;
        let answer = edit(&mut h.chf);
        h.vertex_origins = OnceLock::new();
        h.tetrahedron_origins = OnceLock::new();
        if let Some(out) = out {
            out.set(answer?);
        } else {
            answer?;
        }
        Ok(())
    })
}

/// A check on a shared handle: the status alone.
unsafe fn check(m: *const ChfMesh, check: impl FnOnce(&Chf) -> Result<()>) -> Status {
    guard(|| {
        // SAFETY: caller contract (see `ffi`): NULL or a live handle.
        check(unsafe { core(m)? })
    })
}

/// A position argument: NULL for none, else three finite doubles.
unsafe fn position_of(p: *const f64) -> Result<Option<DVec3>> {
    if p.is_null() {
        return Ok(None);
    }
    // SAFETY: caller contract: NULL (handled) or three doubles.
    let xyz = unsafe { slice_arg(p, 3, "position")? };
    Ok(Some(DVec3::new(xyz[0], xyz[1], xyz[2])))
}

/// Four vertex ids.
unsafe fn quad(q: *const u32) -> Result<[u32; 4]> {
    // SAFETY: caller contract: four ids.
    let q = unsafe { slice_arg(q, 4, "vertices")? };
    Ok([q[0], q[1], q[2], q[3]])
}

/// Adds an isolated vertex at `position` (required when the mesh has positions, NULL when
/// it has none); its id into `*out_v` (may be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_add_vertex(
    m: *mut ChfMesh, position: *const f64, out_v: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_v, |c| c.add_vertex(position_of(position)?)) }
}

/// Adds the tetrahedron of the four vertices `vertices[4]` (any order: oriented by the
/// determinant with positions, else by the faces it pairs with); its id into `*out_t`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_add_tetrahedron(
    m: *mut ChfMesh, vertices: *const u32, out_t: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_t, |c| c.add_tetrahedron(quad(vertices)?)) }
}

/// Would `chf_mesh_add_tetrahedron` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_add_tetrahedron(
    m: *const ChfMesh, vertices: *const u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_add_tetrahedron(quad(vertices)?)) }
}

/// Removes tetrahedron `t` (refused when that pinches a vertex or an edge).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_remove_tetrahedron(m: *mut ChfMesh, t: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, std::ptr::null_mut::<()>(), |c| c.remove_tetrahedron(t)) }
}

/// Would `chf_mesh_remove_tetrahedron` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_remove_tetrahedron(m: *const ChfMesh, t: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_remove_tetrahedron(t)) }
}

/// Removes vertex `v` with every tetrahedron around it.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_remove_vertex(m: *mut ChfMesh, v: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, std::ptr::null_mut::<()>(), |c| c.remove_vertex(v)) }
}

/// Would `chf_mesh_remove_vertex` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_remove_vertex(m: *const ChfMesh, v: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_remove_vertex(v)) }
}

/// Splits tetrahedron `t` in four (1-4) at a new vertex (id into `*out_v`), at `position`
/// or the centroid; refused unless the position is strictly inside.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_split_tetrahedron(
    m: *mut ChfMesh, t: u32, position: *const f64, out_v: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_v, |c| c.split_tetrahedron(t, position_of(position)?)) }
}

/// Would `chf_mesh_split_tetrahedron` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_split_tetrahedron(
    m: *const ChfMesh, t: u32, position: *const f64,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_split_tetrahedron(t, position_of(position)?)) }
}

/// Splits face `f` (2-6, or 1-3 on the boundary) at a new vertex (id into `*out_v`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_split_face(
    m: *mut ChfMesh, f: u32, position: *const f64, out_v: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_v, |c| c.split_face(f, position_of(position)?)) }
}

/// Would `chf_mesh_split_face` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_split_face(
    m: *const ChfMesh, f: u32, position: *const f64,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_split_face(f, position_of(position)?)) }
}

/// Splits edge `e` at a new vertex (id into `*out_v`): each tetrahedron around it in two.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_split_edge(
    m: *mut ChfMesh, e: u32, position: *const f64, out_v: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_v, |c| c.split_edge(e, position_of(position)?)) }
}

/// Would `chf_mesh_split_edge` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_split_edge(
    m: *const ChfMesh, e: u32, position: *const f64,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_split_edge(e, position_of(position)?)) }
}

/// Flips interior face `f` (2-3); the three new tetrahedra into `out_tets[3]` (may be
/// NULL). Refused on the boundary, when the apexes share an edge already, or (with
/// positions) when the union is not strictly convex.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_flip_23(m: *mut ChfMesh, f: u32, out_tets: *mut u32) -> Status {
    // SAFETY: forwarded contract: NULL or three writable ids.
    unsafe { edit(m, out_tets.cast::<[u32; 3]>(), |c| c.flip_23(f)) }
}

/// Would `chf_mesh_flip_23` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_flip_23(m: *const ChfMesh, f: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_flip_23(f)) }
}

/// Flips interior edge `e` with three tetrahedra around it (3-2); the two new tetrahedra
/// into `out_tets[2]` (may be NULL).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_flip_32(m: *mut ChfMesh, e: u32, out_tets: *mut u32) -> Status {
    // SAFETY: forwarded contract: NULL or two writable ids.
    unsafe { edit(m, out_tets.cast::<[u32; 2]>(), |c| c.flip_32(e)) }
}

/// Would `chf_mesh_flip_32` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_flip_32(m: *const ChfMesh, e: u32) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_flip_32(e)) }
}

/// Collapses half-edge `he` (`3 * hf + j`): its origin merges into its target (id into
/// `*out_v`). Refused when the link condition fails or a tetrahedron would invert.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_collapse_edge(
    m: *mut ChfMesh, he: u64, out_v: *mut u32,
) -> Status {
    // SAFETY: forwarded contract.
    unsafe { edit(m, out_v, |c| c.collapse_edge(he)) }
}

/// Would `chf_mesh_collapse_edge` succeed? Changes nothing.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_check_collapse_edge(m: *const ChfMesh, he: u64) -> Status {
    // SAFETY: forwarded contract.
    unsafe { check(m, |c| c.check_collapse_edge(he)) }
}

/// A removed mark into `*out` after a range check on the id bound.
fn removed_mark(
    c: &Chf, id: u32, bound: usize, names: (&str, &str), is: fn(&Chf, u32) -> bool,
) -> Result<bool> {
    crate::util::structure::check_id(id, bound, names.0, names.1).map(|_| is(c, id))
}

/// Is tetrahedron `t` removed (by an edit, until `chf_mesh_garbage_collect`)?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_tetrahedron_is_removed(
    m: *const ChfMesh, t: u32, out: *mut bool,
) -> Status {
    crate::ffi::shapes::value!(m, out, |c| {
        let names = ("tetrahedron", "tetrahedra");
        removed_mark(c, t, c.num_tetrahedra(), names, Chf::is_tetrahedron_removed)
    })
}

/// Is vertex `v` removed?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_vertex_is_removed(
    m: *const ChfMesh, v: u32, out: *mut bool,
) -> Status {
    crate::ffi::shapes::value!(m, out, |c| {
        let names = ("vertex", "vertices");
        removed_mark(c, v, c.num_vertices(), names, Chf::is_vertex_removed)
    })
}

/// Is face `f` removed?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_face_is_removed(m: *const ChfMesh, f: u32, out: *mut bool) -> Status {
    crate::ffi::shapes::value!(m, out, |c| {
        removed_mark(c, f, c.num_faces(), ("face", "faces"), Chf::is_face_removed)
    })
}

/// Is edge `e` removed?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_edge_is_removed(m: *const ChfMesh, e: u32, out: *mut bool) -> Status {
    crate::ffi::shapes::value!(m, out, |c| {
        removed_mark(c, e, c.num_edges(), ("edge", "edges"), Chf::is_edge_removed)
    })
}

/// Live tetrahedra (the `chf_mesh_num_*` counts are id bounds, removed ids included).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_live_tetrahedra(m: *const ChfMesh) -> usize {
    crate::ffi::shapes::count!(m, |c| c.num_live_tetrahedra())
}
/// Live vertices.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_live_vertices(m: *const ChfMesh) -> usize {
    crate::ffi::shapes::count!(m, |c| c.num_live_vertices())
}
/// Live faces.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_live_faces(m: *const ChfMesh) -> usize {
    crate::ffi::shapes::count!(m, |c| c.num_live_faces())
}
/// Live edges.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn chf_mesh_num_live_edges(m: *const ChfMesh) -> usize {
    crate::ffi::shapes::count!(m, |c| c.num_live_edges())
}

/// One map of `chf_mesh_garbage_collect`: NULL (not wanted) or room for the old count.
unsafe fn map_out<'a>(
    p: *mut u32, cap: usize, need: usize, name: &str,
) -> Result<Option<&'a mut [u32]>> {
    if p.is_null() {
        return Ok(None);
    }
    if cap < need {
        return Err(Error::new(
            crate::ErrorKind::BufferTooSmall,
            format!("{name} has room for {cap} ids, the map needs {need}"),
        ));
    }
    // SAFETY: caller contract: `cap` writable ids.
    Ok(Some(unsafe { std::slice::from_raw_parts_mut(p, need) }))
}

/// Compacts the mesh: removed elements go, the others take the ids a fresh build of the
/// live tetrahedra gives. Each map (NULL: not wanted) receives old id -> new id
/// (`TOPOMESH_NONE` for removed ones) and needs room for the count before the call
/// (`chf_mesh_num_vertices`, `_tetrahedra`, `_faces`, `_edges`); too little room gives
/// `TOPOMESH_STATUS_BUFFER_TOO_SMALL` before anything changes. O(T log T).
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn chf_mesh_garbage_collect(
    m: *mut ChfMesh, vertex_map: *mut u32, vertex_cap: usize, tetrahedron_map: *mut u32,
    tetrahedron_cap: usize, face_map: *mut u32, face_cap: usize, edge_map: *mut u32,
    edge_cap: usize,
) -> Status {
    guard(|| {
        // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared.
        let h = unsafe { handle_mut(m, "m")? };
        let c = &h.chf;
        // SAFETY: caller contract: NULL or buffers of the stated capacities.
        let outs = unsafe {
            [
                map_out(vertex_map, vertex_cap, c.num_vertices(), "vertex_map")?,
                map_out(
                    tetrahedron_map,
                    tetrahedron_cap,
                    c.num_tetrahedra(),
                    "tetrahedron_map",
                )?,
                map_out(face_map, face_cap, c.num_faces(), "face_map")?,
                map_out(edge_map, edge_cap, c.num_edges(), "edge_map")?,
            ]
        };
        let maps = h.chf.garbage_collect()?;
        h.vertex_origins = OnceLock::new();
        h.tetrahedron_origins = OnceLock::new();
        let [a, b, f, e] = outs;
        for (out, map) in [
            (a, &maps.vertices),
            (b, &maps.tetrahedra),
            (f, &maps.faces),
            (e, &maps.edges),
        ] {
            if let Some(out) = out {
                out.copy_from_slice(map);
            }
        }
        Ok(())
    })
}
