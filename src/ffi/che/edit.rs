//! Editing a surface in place: the exports of `che/edit/`. Each call needs exclusive
//! access to the mesh; a refused or failed call leaves it unchanged and names the reason
//! in `topomesh_last_error`. Views and arrays obtained before an edit (V, O, VH, EH, CH,
//! the origin maps, the positions) are invalid after it, whatever its outcome; ids stay
//! valid until `che_mesh_garbage_collect`.

use super::CheMesh;
use crate::che::Che;
use crate::error::{Error, ErrorKind, Result};
use crate::ffi::boundary::{guard, handle_mut, out_arg, slice_arg};
use crate::ffi::shapes::{count, value};
use crate::ffi::status::Status;
use glam::DVec3;
use std::sync::OnceLock;

/// One edit through the handle: exclusive access, the origin views it lends dropped.
fn edit<T>(m: *mut CheMesh, f: impl FnOnce(&mut Che) -> Result<T>) -> Result<T> {
    // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared.
    let h = unsafe { handle_mut(m, "m")? };
    h.vertex_origins = OnceLock::new();
    h.triangle_origins = OnceLock::new();
    f(&mut h.che)
}

/// A check on the handle's mesh, which keeps every view (origins included) valid.
fn check<T>(m: *mut CheMesh, f: impl FnOnce(&mut Che) -> Result<T>) -> Result<T> {
    // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared.
    f(&mut unsafe { handle_mut(m, "m")? }.che)
}

/// An optional position: NULL, or 3 doubles.
fn position(p: *const f64) -> Result<Option<DVec3>> {
    if p.is_null() {
        return Ok(None);
    }
    // SAFETY: caller contract: NULL or 3 readable doubles.
    let xyz = unsafe { slice_arg(p, 3, "position")? };
    Ok(Some(DVec3::new(xyz[0], xyz[1], xyz[2])))
}

/// An edit returning an id into `out` (NULL: not wanted).
fn id_out(out: *mut u32, f: impl FnOnce() -> Result<u32>) -> Status {
    guard(|| {
        let id = f()?;
        if !out.is_null() {
            // SAFETY: caller contract: NULL (checked) or one writable u32.
            unsafe { out_arg(out, "out")? }.set(id);
        }
        Ok(())
    })
}

/// Adds an isolated vertex. `position` (3 doubles) is required when the mesh has
/// positions and must be NULL when it has none. Its id goes to `out` (NULL: not wanted).
///
/// Editing (this call and every `che_mesh_*` edit after it: add, remove, flip, split,
/// collapse, set_position, the checks, garbage_collect) needs exclusive access. Every
/// zero-copy view (`che_mesh_half_edge_vertices`, `_opposites`, `_vertex_half_edges`,
/// `_edge_half_edges`, `_curve_half_edges`, `_edge_ranks`, the origins and positions) and
/// every `che_star_iter` obtained before an edit is invalid after it, whatever its
/// outcome: fetch them again. Removed elements keep their ids (`V = NONE` for a removed
/// triangle's half-edges) until `che_mesh_garbage_collect`; until then `che_mesh_num_*`
/// are the id bounds, `che_mesh_num_live_*` the counts, the edge-rank view is NULL (edge
/// ids are not ranks), and exports and writers expect a collected mesh.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_add_vertex(
    m: *mut CheMesh, position_xyz: *const f64, out: *mut u32,
) -> Status {
    id_out(out, || {
        let p = position(position_xyz)?;
        edit(m, |c| c.add_vertex(p))
    })
}

/// Adds triangle (a, b, c) into `out`, paired with the boundary half-edges it meets.
/// Refused (INVALID_INPUT) for a degenerate triangle, OUT_OF_RANGE for a bad vertex id.
/// On a mesh built strict (`che_build_options.strict`, kept by level files) also refused
/// (INVALID_INPUT, the detail naming the edge or vertex) when an edge already has a
/// triangle on that side, would become non-manifold, or a corner would get a second fan,
/// and for a duplicate. On a mesh built non-strict (the default) those are repaired by
/// the build's rules and counted in `che_mesh_report` (status OK): an edge that would
/// carry a third triangle counts as non-manifold and the corners on it are split (the
/// new triangle's corners may then be new vertices: read them back with
/// `che_triangle_vertices`), a triangle against its neighbours' orientation is flipped
/// (`flipped_triangles`), a duplicate is kept; the mesh is then the one a fresh non-strict build of its live
/// triangles gives.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_add_triangle(
    m: *mut CheMesh, a: u32, b: u32, c: u32, out: *mut u32,
) -> Status {
    id_out(out, || edit(m, |che| che.add_triangle(a, b, c)))
}

/// Removes triangle `t` (marked: its id and the others stay until garbage collection).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_remove_triangle(m: *mut CheMesh, t: u32) -> Status {
    guard(|| edit(m, |c| c.remove_triangle(t)))
}

/// Removes vertex `v` and its star.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_remove_vertex(m: *mut CheMesh, v: u32) -> Status {
    guard(|| edit(m, |c| c.remove_vertex(v)))
}

/// Flips interior edge `e` (it keeps its id). Refused on a boundary edge or when the
/// flipped edge exists.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_flip_edge(m: *mut CheMesh, e: u32) -> Status {
    guard(|| edit(m, |c| c.flip_edge(e)))
}

/// Splits edge `e` at a new vertex (into `out`; position: `position_xyz`, or NULL for the
/// midpoint when the mesh has positions).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_split_edge(
    m: *mut CheMesh, e: u32, position_xyz: *const f64, out: *mut u32,
) -> Status {
    id_out(out, || {
        let p = position(position_xyz)?;
        edit(m, |c| c.split_edge(e, p))
    })
}

/// Collapses half-edge `h`: its target merges into its origin (the kept vertex goes to
/// `out`). Refused, with the reason, when the link condition fails.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_collapse_edge(m: *mut CheMesh, h: u32, out: *mut u32) -> Status {
    id_out(out, || edit(m, |c| c.collapse_edge(h)))
}

/// Splits triangle `t` into 3 at a new vertex (into `out`; NULL position: the centroid).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_split_triangle(
    m: *mut CheMesh, t: u32, position_xyz: *const f64, out: *mut u32,
) -> Status {
    id_out(out, || {
        let p = position(position_xyz)?;
        edit(m, |c| c.split_triangle(t, p))
    })
}

/// Would `che_mesh_flip_edge(m, e)` succeed? Never modifies the mesh: every view stays
/// valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_is_flip_ok(m: *mut CheMesh, e: u32, out: *mut bool) -> Status {
    guard(|| {
        // SAFETY: caller contract: one writable bool.
        let out = unsafe { out_arg(out, "out")? };
        out.set(check(m, |c| c.is_flip_ok(e))?);
        Ok(())
    })
}

/// Would `che_mesh_collapse_edge(m, h)` succeed? Never modifies the mesh: every view
/// stays valid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_is_collapse_ok(
    m: *mut CheMesh, h: u32, out: *mut bool,
) -> Status {
    guard(|| {
        // SAFETY: caller contract: one writable bool.
        let out = unsafe { out_arg(out, "out")? };
        out.set(check(m, |c| c.is_collapse_ok(h))?);
        Ok(())
    })
}

/// One old -> new map into a caller buffer of `cap` entries (NULL: not wanted).
fn map_out(map: &[u32], buf: *mut u32, cap: usize, name: &str) -> Result<()> {
    if buf.is_null() {
        return Ok(());
    }
    if cap < map.len() {
        return Err(Error::new(
            ErrorKind::BufferTooSmall,
            format!("{name}: {} entries needed, {cap} given", map.len()),
        ));
    }
    // SAFETY: caller contract: `cap` writable u32 at `buf` (non-NULL, checked).
    let out = unsafe { std::slice::from_raw_parts_mut(buf, map.len()) };
    out.copy_from_slice(map);
    Ok(())
}

/// Compacts the removed elements away (ids become `h = 3t + i` without holes, edge ids
/// ranks again) and writes the old -> new maps (`UINT32_MAX` for a removed element) into
/// the buffers given (NULL: not wanted), sized by the counts before the call
/// (`che_mesh_num_vertices`, `_num_triangles`, `_num_edges`). A buffer too small is
/// BUFFER_TOO_SMALL before anything changes. Every id and view from before is invalid.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_garbage_collect(
    m: *mut CheMesh, vertex_map: *mut u32, vertex_cap: usize, triangle_map: *mut u32,
    triangle_cap: usize, edge_map: *mut u32, edge_cap: usize,
) -> Status {
    guard(|| {
        edit(m, |c| {
            let needs = [
                (vertex_map, vertex_cap, c.num_vertices(), "vertex_map"),
                (
                    triangle_map,
                    triangle_cap,
                    c.num_triangles(),
                    "triangle_map",
                ),
                (edge_map, edge_cap, c.num_edges(), "edge_map"),
            ];
            for (buf, cap, n, name) in needs {
                if !buf.is_null() && cap < n {
                    return Err(Error::new(
                        ErrorKind::BufferTooSmall,
                        format!("{name}: {n} entries needed, {cap} given"),
                    ));
                }
            }
            let maps = c.garbage_collect()?;
            map_out(&maps.vertices, vertex_map, vertex_cap, "vertex_map")?;
            map_out(&maps.triangles, triangle_map, triangle_cap, "triangle_map")?;
            map_out(&maps.edges, edge_map, edge_cap, "edge_map")
        })
    })
}

/// Is vertex `v` removed (until garbage collection)?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_vertex_is_removed(
    m: *const CheMesh, v: u32, out: *mut bool,
) -> Status {
    value!(m, out, check_vertex(v) => |c| c.is_vertex_removed(v))
}

/// Is triangle `t` removed?
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_triangle_is_removed(
    m: *const CheMesh, t: u32, out: *mut bool,
) -> Status {
    value!(m, out, check_triangle(t) => |c| c.is_triangle_removed(t))
}

/// Is edge `e` removed? (Below level 2 edge ids are the ranks of the live edges: never.)
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_edge_is_removed(m: *const CheMesh, e: u32, out: *mut bool) -> Status {
    value!(m, out, check_edge(e) => |c| c.is_edge_removed(e))
}

/// Live vertices (`che_mesh_num_vertices` stays the id bound until garbage collection).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_num_live_vertices(m: *const CheMesh) -> usize {
    count!(m, |c| c.num_live_vertices())
}

/// Live triangles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_num_live_triangles(m: *const CheMesh) -> usize {
    count!(m, |c| c.num_live_triangles())
}

/// Live edges.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_num_live_edges(m: *const CheMesh) -> usize {
    count!(m, |c| c.num_live_edges())
}

/// Moves vertex `v` to `position_xyz` (3 doubles); refused on a mesh without positions.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn che_mesh_set_position(
    m: *mut CheMesh, v: u32, position_xyz: *const f64,
) -> Status {
    guard(|| {
        let p = position(position_xyz)?.ok_or_else(|| {
            Error::new(ErrorKind::NullArgument, "argument 'position_xyz' is NULL")
        })?;
        edit(m, |c| c.set_position(v, p))
    })
}
