//! Queries that compute arrays for the call (below the level that stores them) running out
//! of memory: through the C API they give `TOPOMESH_STATUS_OUT_OF_MEMORY` with the detail,
//! never `PANIC` nor an abort, and the same calls succeed once memory is back.
//!
//! A global allocator of this test binary refuses, on the armed thread only, every request
//! larger than a limit (the other test threads allocate as usual). An allocation that is
//! not fallible would abort the whole binary: the test fails loudly then too.

mod chf_common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ffi::c_char;
use topomesh::ffi::Status;
use topomesh::ffi::che::*;
use topomesh::ffi::chf::*;
use topomesh::ffi::status::topomesh_last_error;

struct Limited;

thread_local! {
    // `const` and without a destructor: reading it never allocates.
    static LIMIT: Cell<usize> = const { Cell::new(usize::MAX) };
    /// With `LIMIT` set: how many requests above it still succeed before one is refused
    /// (`usize::MAX`: none succeeds).
    static GRANTS: Cell<usize> = const { Cell::new(usize::MAX) };
    /// Whether a request was refused since the last `limited` call began.
    static REFUSED: Cell<bool> = const { Cell::new(false) };
}

fn refused(size: usize) -> bool {
    let over = LIMIT.try_with(|l| size > l.get()).unwrap_or(false);
    if !over {
        return false;
    }
    let grant = GRANTS
        .try_with(|g| match g.get() {
            0 | usize::MAX => false,
            n => {
                g.set(n - 1);
                true
            }
        })
        .unwrap_or(false);
    if !grant {
        let _ = REFUSED.try_with(|r| r.set(true));
    }
    !grant
}

// Sound: every call forwards to `System` with the caller's arguments, or returns NULL (a
// refusal, which `GlobalAlloc` allows).
unsafe impl GlobalAlloc for Limited {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if refused(layout.size()) {
            return std::ptr::null_mut();
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if refused(layout.size()) {
            return std::ptr::null_mut();
        }
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // A shrink gives memory back: never refused (`shrink_to_fit` cannot fail).
        if new_size > layout.size() && refused(new_size) {
            return std::ptr::null_mut();
        }
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Limited = Limited;

/// Runs `f` with every request above `bytes` refused on this thread.
fn limited<R>(bytes: usize, f: impl FnOnce() -> R) -> R {
    // A panic under the limit lifts it before the message and backtrace are written:
    // writing them allocates, and a refusal there would hang the report.
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let report = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            LIMIT.set(usize::MAX);
            report(info)
        }));
    });
    LIMIT.set(bytes);
    let r = f();
    LIMIT.set(usize::MAX);
    r
}

/// Runs `f` with the requests above `bytes` on this thread granted `grants` times, then
/// refused; also says whether one was refused.
fn refused_after<R>(bytes: usize, grants: usize, f: impl FnOnce() -> R) -> (R, bool) {
    GRANTS.set(grants);
    REFUSED.set(false);
    let r = limited(bytes, f);
    GRANTS.set(usize::MAX);
    (r, REFUSED.get())
}

/// Calls `f` with the first large request refused, then the second, and so on until `f`
/// runs without a refusal: each refusal must come back as an out-of-memory error (an
/// allocation that cannot fail would abort the binary). Returns how many were refused.
fn refuse_each<T>(what: &str, f: impl Fn() -> Result<T, topomesh::Error>) -> usize {
    refuse_each_above(4 << 10, what, f)
}

/// [`refuse_each`] for the requests above `large` bytes: the writers' buffers, of a fixed
/// size that no input changes, are below it.
fn refuse_each_above<T>(
    large: usize, what: &str, f: impl Fn() -> Result<T, topomesh::Error>,
) -> usize {
    for n in 0.. {
        let (r, refused) = refused_after(large, n, &f);
        if !refused {
            assert!(r.is_ok(), "{what}: {:?}", r.err());
            return n;
        }
        let e = r
            .err()
            .unwrap_or_else(|| panic!("{what}: request {n} refused, yet Ok"));
        assert_eq!(
            e.kind,
            topomesh::ErrorKind::OutOfMemory,
            "{what}, request {n}: {e:?}"
        );
    }
    unreachable!()
}

/// Far below the arrays of the meshes below, far above an error message.
const LIMIT_BYTES: usize = 32 << 10;

fn last_error() -> String {
    let mut buf = vec![0 as c_char; 4096];
    let mut len = 0;
    // SAFETY: the buffer holds `buf.len()` bytes.
    unsafe { topomesh_last_error(buf.as_mut_ptr(), buf.len(), &mut len) };
    let bytes: Vec<u8> = buf
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// `status` is OUT_OF_MEMORY and the detail says so.
fn assert_out_of_memory(status: Status, call: &str) {
    assert_eq!(status, Status::OutOfMemory, "{call}: {}", last_error());
    assert!(
        last_error().starts_with("out of memory: "),
        "{call}: {}",
        last_error()
    );
}

fn che_at(level: u32) -> *mut CheMesh {
    let s = topomesh::generate::grid(100, 100);
    let flat: Vec<u32> = s.triangles.iter().flatten().copied().collect();
    let mut m = std::ptr::null_mut();
    // SAFETY: the arrays hold what the counts say; `m` is an out-parameter.
    let status = unsafe {
        che_mesh_from_triangles(
            flat.as_ptr(),
            s.triangles.len(),
            s.positions.len(),
            std::ptr::null(),
            level,
            &mut m,
        )
    };
    assert_eq!(status, Status::Ok);
    m
}

fn chf_at(level: u32) -> *mut ChfMesh {
    let mesh = chf_common::cube(12, 12, 12, false);
    let flat: Vec<u32> = mesh.tets.iter().flatten().copied().collect();
    let mut m = std::ptr::null_mut();
    // SAFETY: as in `che_at`.
    let status = unsafe {
        chf_mesh_from_tetrahedra(
            flat.as_ptr(),
            mesh.tets.len(),
            mesh.n(),
            std::ptr::null(),
            level,
            &mut m,
        )
    };
    assert_eq!(status, Status::Ok);
    m
}

#[test]
fn che_queries_out_of_memory_give_the_status() {
    let (low, full) = (che_at(0), che_at(3));
    // SAFETY: live handles and local out-parameters throughout.
    unsafe {
        let mut summary = CheSummary::default();
        let status = limited(LIMIT_BYTES, || che_mesh_summary(low, &mut summary));
        assert_out_of_memory(status, "che_mesh_summary at level 0");
        let mut edge = 0u32;
        let status = limited(LIMIT_BYTES, || che_half_edge_edge(low, 7, &mut edge));
        assert_out_of_memory(status, "che_half_edge_edge at level 0");

        // Memory back: the same answers as the structure that stores everything.
        let mut expected = CheSummary::default();
        assert_eq!(che_mesh_summary(low, &mut summary), Status::Ok);
        assert_eq!(che_mesh_summary(full, &mut expected), Status::Ok);
        assert_eq!(summary, expected);
        let mut expected_edge = 0u32;
        assert_eq!(che_half_edge_edge(low, 7, &mut edge), Status::Ok);
        assert_eq!(che_half_edge_edge(full, 7, &mut expected_edge), Status::Ok);
        assert_eq!(edge, expected_edge);
        che_mesh_free(low);
        che_mesh_free(full);
    }
}

/// An edited CHE at level 3 computes its curves at the first curve query after an edit:
/// out of memory there, the status, and the curves once memory is back.
#[test]
fn edited_curves_out_of_memory_give_the_status() {
    let m = che_at(3);
    // SAFETY: a live handle and local buffers throughout.
    unsafe {
        // Every other triangle removed: a boundary of tens of thousands of half-edges.
        for t in (0..che_mesh_num_triangles(m) as u32).step_by(2) {
            assert_eq!(che_mesh_remove_triangle(m, t), Status::Ok);
        }
        let mut buf = vec![0u32; 1 << 16];
        let (ptr, cap, mut len) = (buf.as_mut_ptr(), buf.len(), 0);
        let status = limited(LIMIT_BYTES, || {
            che_boundary_curve_vertices(m, 0, ptr, cap, &mut len)
        });
        assert_out_of_memory(status, "che_boundary_curve_vertices after edits");
        assert_eq!(
            che_boundary_curve_vertices(m, 0, ptr, cap, &mut len),
            Status::Ok
        );
        assert!(len >= 3 && che_mesh_num_boundary_curves(m) > 100);
        assert_eq!(che_mesh_validate(m), Status::Ok);
        che_mesh_free(m);
    }
}

/// The identity origin maps a view materialises: out of memory, NULL with the status; once
/// memory is back, the identity.
#[test]
fn identity_origin_views_out_of_memory_give_the_status() {
    let (che, chf) = (che_at(2), chf_at(2));
    // SAFETY: live handles and local out-parameters throughout.
    unsafe {
        let mut len = 0;
        let p = limited(LIMIT_BYTES, || che_mesh_vertex_origins(che, &mut len));
        assert!(
            p.is_null() && last_error().starts_with("out of memory: "),
            "{}",
            last_error()
        );
        let p = limited(LIMIT_BYTES, || chf_mesh_tetrahedron_origins(chf, &mut len));
        assert!(
            p.is_null() && last_error().starts_with("out of memory: "),
            "{}",
            last_error()
        );
        let p = che_mesh_vertex_origins(che, &mut len);
        let map = std::slice::from_raw_parts(p, len);
        assert!(len == che_mesh_num_vertices(che) && map.iter().zip(0..).all(|(&a, b)| a == b));
        let p = chf_mesh_tetrahedron_origins(chf, &mut len);
        assert!(!p.is_null() && len == chf_mesh_num_tetrahedra(chf));
        che_mesh_free(che);
        chf_mesh_free(chf);
    }
}

#[test]
fn chf_queries_out_of_memory_give_the_status() {
    let (low, full) = (chf_at(0), chf_at(3));
    // SAFETY: live handles and local out-parameters throughout.
    unsafe {
        let mut summary = ChfSummary::default();
        let status = limited(LIMIT_BYTES, || chf_mesh_summary(low, &mut summary));
        assert_out_of_memory(status, "chf_mesh_summary at level 0");
        let mut component = 0u32;
        let status = limited(LIMIT_BYTES, || {
            chf_vertex_boundary_component(low, 0, &mut component)
        });
        assert_out_of_memory(status, "chf_vertex_boundary_component at level 0");
        // A count has no status: 0, with the detail recorded.
        let count = limited(LIMIT_BYTES, || chf_mesh_num_boundary_components(low));
        assert_eq!(count, 0);
        assert!(
            last_error().starts_with("out of memory: "),
            "{}",
            last_error()
        );
        // A one-element relation that computes the face ids for the call.
        let (mut buf, mut len) = ([0u32; 8], 0usize);
        let status = limited(LIMIT_BYTES, || {
            chf_face_vertices(low, 5, buf.as_mut_ptr(), buf.len(), &mut len)
        });
        assert_out_of_memory(status, "chf_face_vertices at level 0");

        let mut expected = ChfSummary::default();
        assert_eq!(chf_mesh_summary(low, &mut summary), Status::Ok);
        assert_eq!(chf_mesh_summary(full, &mut expected), Status::Ok);
        assert_eq!(summary, expected);
        let mut expected_component = 0u32;
        assert_eq!(
            chf_vertex_boundary_component(low, 0, &mut component),
            Status::Ok
        );
        assert_eq!(
            chf_vertex_boundary_component(full, 0, &mut expected_component),
            Status::Ok
        );
        assert_eq!(component, expected_component);
        assert_eq!(chf_mesh_num_boundary_components(low), 1);
        assert_eq!(chf_mesh_num_boundary_components(full), 1);
        let (mut expected_buf, mut expected_len) = ([0u32; 8], 0usize);
        assert_eq!(
            chf_face_vertices(low, 5, buf.as_mut_ptr(), 8, &mut len),
            Status::Ok
        );
        let status = chf_face_vertices(full, 5, expected_buf.as_mut_ptr(), 8, &mut expected_len);
        assert_eq!(status, Status::Ok);
        assert_eq!(buf[..len], expected_buf[..expected_len]);
        chf_mesh_free(low);
        chf_mesh_free(full);
    }
}

/// Every reader, on a file whose arrays are larger than the limit: an out-of-memory error
/// naming what it was reading, the same for each of its large requests refused in turn,
/// then the same bytes read whole once memory is back.
#[test]
fn readers_out_of_memory_give_the_error() {
    use topomesh::io::{Format, Mesh, MeshData, WriteOptions, parse, write_to};
    let s = topomesh::generate::grid(60, 60);
    let volume = chf_common::cube(8, 8, 8, false);
    let surface = MeshData {
        positions: s.positions.clone(),
        triangles: s.triangles.clone(),
        ..MeshData::default()
    };
    let solid = MeshData {
        positions: volume.positions.clone(),
        tetrahedra: volume.tets.clone(),
        ..MeshData::default()
    };
    let cases = [
        (Format::Off, &surface, false),
        (Format::Obj, &surface, false),
        (Format::Ply, &surface, false),
        (Format::Ply, &surface, true),
        (Format::Stl, &surface, true),
        (Format::Stl, &surface, false),
        (Format::Medit, &solid, false),
        (Format::Gmsh, &solid, false),
        (Format::Vtk, &solid, false),
    ];
    for (format, data, binary) in cases {
        let options = WriteOptions {
            binary,
            ..WriteOptions::default()
        };
        let mut bytes = Vec::new();
        if format == Format::Stl && !binary {
            // The writer writes binary STL only.
            bytes = ascii_stl(data).into_bytes();
        } else {
            write_to(&mut bytes, &Mesh::from_data(data), format, &options, "t").unwrap();
        }
        let e = limited(LIMIT_BYTES, || parse(&bytes, format, "t")).unwrap_err();
        let case = format!("{format:?} binary={binary}");
        assert_eq!(e.kind, topomesh::ErrorKind::OutOfMemory, "{case}: {e:?}");
        assert!(e.message.starts_with("out of memory: "), "{case}: {e:?}");
        // Every large request of the reader refused in turn.
        refuse_each(&case, || parse(&bytes, format, "t"));
        let read = parse(&bytes, format, "t").unwrap();
        assert_eq!(read.triangles.len(), data.triangles.len(), "{case}");
        assert_eq!(read.tetrahedra.len(), data.tetrahedra.len(), "{case}");
    }
}

fn ascii_stl(data: &topomesh::io::MeshData) -> String {
    let mut text = String::from("solid t\n");
    for t in &data.triangles {
        text += "facet normal 0 0 1\nouter loop\n";
        for &v in t {
            let p = data.positions[v as usize];
            text += &format!("vertex {} {} {}\n", p.x, p.y, p.z);
        }
        text += "endloop\nendfacet\n";
    }
    text + "endsolid t\n"
}

/// A cube of `n` cells a side, and `pinch` tetrahedra on one new vertex, each with its own
/// other three: a pinched star (a vertex whose star is in many pieces).
fn pinched_cube(n: u32, pinch: u32) -> chf_common::Mesh {
    let mut volume = chf_common::cube(n, n, n, false);
    let apex = volume.positions.len() as u32;
    volume.positions.push(glam::DVec3::new(-1.0, -1.0, -1.0));
    for i in 0..pinch {
        let base = volume.positions.len() as u32;
        for k in 0..3 {
            volume
                .positions
                .push(glam::DVec3::new(-2.0 - i as f64, k as f64, 1.0));
        }
        volume.tets.push([apex, base, base + 1, base + 2]);
    }
    volume
}

/// Every large allocation of both builds, at every level, refused in turn, on input that
/// takes the rare paths too: a vertex whose star is in many pieces (the vertex split, the
/// star pass's general link) and non-manifold edges.
#[test]
fn every_build_allocation_can_fail() {
    use topomesh::{che::Che, chf::Chf};
    let volume = pinched_cube(6, 80);
    let s = topomesh::generate::grid(30, 30);
    let mut triangles = s.triangles.clone();
    // A third triangle on an edge of the grid: a non-manifold edge.
    triangles.push([0, 1, s.positions.len() as u32]);
    let n = s.positions.len() + 1;
    let mut refused = 0;
    for level in 0..=3 {
        let options = topomesh::BuildOptions {
            level,
            threads: 1,
            ..topomesh::BuildOptions::default()
        };
        refused += refuse_each(&format!("CHE level {level}"), || {
            Che::from_triangles(&triangles, n, &[], options)
        });
        refused += refuse_each(&format!("CHF level {level}"), || {
            Chf::from_tetrahedra(&volume.tets, volume.n(), &volume.positions, options)
        });
    }
    assert!(refused > 40, "only {refused} large requests");
}

/// The queries of an edited CHE that compute arrays for the call (the summary, the
/// curves below level 3 and a curve's vertices), every large request refused in turn: each
/// refusal an out-of-memory error, never a panic nor an abort. (A small grid: the pairing's
/// coarse buckets, one per vertex up to 2048 whatever the input, stay below the limit.)
#[test]
fn edited_che_queries_can_fail() {
    use topomesh::{BuildOptions, che::Che};
    let s = topomesh::generate::grid(16, 16);
    for level in 0..=3 {
        let mut che = Che::from_triangles(
            &s.triangles,
            s.positions.len(),
            &[],
            BuildOptions::level(level),
        )
        .unwrap();
        for t in (0..che.num_triangles() as u32).step_by(2) {
            che.remove_triangle(t).unwrap();
        }
        let at = format!("level {level}");
        let refused = refuse_each(&format!("summary, {at}"), || che.try_summary());
        assert!(refused > 0, "{at}");
        refuse_each(&format!("curve starts, {at}"), || {
            che.try_boundary_curve_starts().map(|s| s.len())
        });
        refuse_each(&format!("curve vertices, {at}"), || {
            che.boundary_curve_vertices(0)
        });
        assert!(che.try_boundary_curve_starts().unwrap().len() > 10, "{at}");
    }
}

/// A surface that takes every path of the exports: a grid with a fan of three triangles on
/// one edge (a non-manifold edge, whose rows the Betti numbers reduce apart) and positions.
fn damaged_surface(level: u8) -> topomesh::Che {
    let s = topomesh::generate::grid(30, 30);
    let mut triangles = s.triangles.clone();
    let mut positions = s.positions.clone();
    let n = positions.len() as u32;
    triangles.extend([[0, 1, n], [1, 0, n + 1]]);
    positions.extend([
        glam::DVec3::new(0.5, -1.0, 1.0),
        glam::DVec3::new(0.5, -1.0, -1.0),
    ]);
    let options = topomesh::BuildOptions::level(level);
    topomesh::Che::from_triangles(&triangles, positions.len(), &positions, options).unwrap()
}

/// Every export and check of a built surface, at every level, every large request refused
/// in turn: each refusal an out-of-memory error, never an abort.
#[test]
fn every_surface_export_allocation_can_fail() {
    use topomesh::che::{HalfEdgeOptions, MatrixKind};
    for level in 0..=3 {
        let che = damaged_surface(level);
        let at = |what: &str| format!("{what}, level {level}");
        let mut refused = refuse_each(&at("betti_numbers"), || che.betti_numbers());
        for kind in MatrixKind::ALL {
            refused += refuse_each(&at(&format!("{kind:?}")), || che.matrix(kind));
        }
        for explicit_boundary in [false, true] {
            let options = HalfEdgeOptions { explicit_boundary };
            refused += refuse_each(&at("half_edge_arrays"), || che.half_edge_arrays(options));
        }
        refused += refuse_each(&at("corner_table"), || che.corner_table().map(|_| ()));
        refused += refuse_each(&at("winged_edges"), || che.winged_edges());
        refused += refuse_each(&at("edge_list"), || che.edge_list());
        refused += refuse_each(&at("triangle_strips"), || {
            let strips = che.triangle_strips()?;
            Ok((strips.with_restarts()?, strips.joined()?))
        });
        refused += refuse_each(&at("validate"), || che.validate());
        refused += surface_bulk_queries(&che, &at("bulk"));
        let exports = at("exports");
        assert!(refused > 20, "{exports}: only {refused} large requests");
        let mut edited = che;
        for t in (0..edited.num_triangles() as u32).step_by(5) {
            edited.remove_triangle(t).unwrap();
        }
        refused = surface_bulk_queries(&edited, &at("edited, bulk"));
        refused += refuse_each(&at("edited, validate"), || edited.validate());
        assert!(
            refused > 5,
            "{}: only {refused} large requests",
            at("edited")
        );
    }
}

/// The bulk relations of a surface, every large request refused in turn; the refusals.
fn surface_bulk_queries(che: &topomesh::Che, at: &str) -> usize {
    refuse_each(&format!("VV, {at}"), || che.all_vertex_vertices())
        + refuse_each(&format!("VE, {at}"), || che.all_vertex_edges())
        + refuse_each(&format!("VT, {at}"), || che.all_vertex_triangles())
        + refuse_each(&format!("TT, {at}"), || che.all_triangle_triangles())
        + refuse_each(&format!("TE, {at}"), || che.all_triangle_edges())
        + refuse_each(&format!("summary, {at}"), || che.try_summary())
}

/// The bulk relations of a volume, as [`surface_bulk_queries`].
fn volume_bulk_queries(chf: &topomesh::Chf, at: &str) -> usize {
    refuse_each(&format!("O, {at}"), || chf.all_opposites())
        + refuse_each(&format!("VT, {at}"), || chf.all_vertex_tetrahedra())
        + refuse_each(&format!("VF, {at}"), || chf.all_vertex_faces())
        + refuse_each(&format!("VE, {at}"), || chf.all_vertex_edges())
        + refuse_each(&format!("VV, {at}"), || chf.all_vertex_vertices())
        + refuse_each(&format!("summary, {at}"), || chf.try_summary())
}

/// The same for a volume: a cube with a pinched star (a vertex shared by many pieces).
#[test]
fn every_volume_export_allocation_can_fail() {
    use topomesh::chf::VolumeMatrixKind;
    // Large enough that the boundary's lists pass the limit too.
    let volume = pinched_cube(10, 20);
    for level in 0..=3 {
        let options = topomesh::BuildOptions::level(level);
        let chf =
            topomesh::Chf::from_tetrahedra(&volume.tets, volume.n(), &volume.positions, options)
                .unwrap();
        let at = |what: &str| format!("{what}, level {level}");
        let mut refused = refuse_each(&at("betti_numbers"), || chf.betti_numbers());
        for kind in VolumeMatrixKind::ALL {
            refused += refuse_each(&at(&format!("{kind:?}")), || chf.volume_matrix(kind));
        }
        refused += refuse_each(&at("half_face_arrays"), || chf.half_face_arrays());
        refused += refuse_each(&at("dual graph"), || chf.tetrahedron_dual_graph());
        refused += refuse_each(&at("validate"), || chf.validate());
        refused += volume_bulk_queries(&chf, &at("bulk"));
        let exports = at("exports");
        assert!(refused > 10, "{exports}: only {refused} large requests");
        let mut edited = chf;
        for t in (0..edited.num_tetrahedra() as u32).step_by(7) {
            // Some removals would pinch a vertex or an edge and are refused: kept.
            let _ = edited.remove_tetrahedron(t);
        }
        refused = volume_bulk_queries(&edited, &at("edited, bulk"));
        refused += refuse_each(&at("edited, validate"), || edited.validate());
        assert!(
            refused > 5,
            "{}: only {refused} large requests",
            at("edited")
        );
    }
}

/// Saving and opening level files, and writing mesh files, of a surface and a volume at
/// level 3, every request above the writers' fixed buffers refused in turn.
#[test]
fn every_file_write_and_open_allocation_can_fail() {
    use topomesh::levelfile::{OpenOptions, Verify};
    const LARGE: usize = 128 << 10;
    let dir = std::env::temp_dir().join(format!("topomesh-oom-files-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let s = topomesh::generate::grid(150, 150);
    let options = topomesh::BuildOptions::level(3);
    let che = topomesh::Che::from_triangles(&s.triangles, s.positions.len(), &s.positions, options)
        .unwrap();
    let volume = chf_common::cube(20, 20, 20, false);
    let chf = topomesh::Chf::from_tetrahedra(&volume.tets, volume.n(), &volume.positions, options)
        .unwrap();
    let (surface, solid) = (dir.join("s.che"), dir.join("v.chf"));
    let refuse =
        |what: &str, f: &dyn Fn() -> topomesh::error::Result<()>| refuse_each_above(LARGE, what, f);
    let mut refused = refuse("che save", &|| che.save(&surface));
    refused += refuse("chf save", &|| chf.save(&solid));
    for verify in [Verify::Full, Verify::Trusted] {
        let open = OpenOptions::loaded(verify);
        refused += refuse("che open", &|| {
            topomesh::Che::open(&surface, open).map(|_| ())
        });
        refused += refuse("chf open", &|| {
            topomesh::Chf::open(&solid, open).map(|_| ())
        });
    }
    for ext in ["off", "obj", "ply", "stl"] {
        let path = dir.join(format!("s.{ext}"));
        refused += refuse(&format!("che write {ext}"), &|| che.write(&path));
    }
    for ext in ["vtk", "msh", "mesh", "node"] {
        let path = dir.join(format!("v.{ext}"));
        refused += refuse(&format!("chf write {ext}"), &|| chf.write(&path));
    }
    let boundary = dir.join("b.off");
    refused += refuse("chf write_boundary", &|| chf.write_boundary(&boundary));
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(refused > 20, "only {refused} large requests");
}

/// An edit's answer with its refusals (a removed id, the link condition, ...) taken as
/// `None`: only running out of memory is an error here.
fn unless_refused<T>(r: Result<T, topomesh::Error>) -> Result<Option<T>, topomesh::Error> {
    match r {
        Ok(x) => Ok(Some(x)),
        Err(e) if e.kind == topomesh::ErrorKind::OutOfMemory => Err(e),
        Err(_) => Ok(None),
    }
}

/// Runs `edits` on a mesh fresh from `make`, with its first large request refused, then
/// its second, and so on until the edits run without a refusal: each refusal must come
/// back as an out-of-memory error that leaves the mesh valid (the edit it stopped wrote
/// nothing). Returns how many were refused.
fn refuse_each_edit<M>(
    what: &str, make: impl Fn() -> M, edits: impl Fn(&mut M) -> Result<(), topomesh::Error>,
    validate: impl Fn(&M) -> Result<(), topomesh::Error>,
) -> usize {
    for n in 0.. {
        let mut mesh = make();
        let (r, refused) = refused_after(4 << 10, n, || edits(&mut mesh));
        if let Err(e) = &r {
            assert!(refused, "{what}: {e:?}");
            assert_eq!(
                e.kind,
                topomesh::ErrorKind::OutOfMemory,
                "{what}, request {n}: {e:?}"
            );
        }
        if let Err(e) = validate(&mesh) {
            panic!("{what}, request {n} refused ({r:?}): the mesh left is not valid: {e}");
        }
        if !refused {
            return n;
        }
    }
    unreachable!()
}

/// Every kind of surface edit and the garbage collection, at every level, every large
/// request refused in turn (the first edit makes the edit state, later ones grow it).
#[test]
fn every_surface_edit_allocation_can_fail() {
    use topomesh::Che;
    let s = topomesh::generate::grid(30, 30);
    for level in 0..=3 {
        let make = || {
            let options = topomesh::BuildOptions::level(level);
            Che::from_triangles(&s.triangles, s.positions.len(), &s.positions, options).unwrap()
        };
        let edits = |che: &mut Che| -> Result<(), topomesh::Error> {
            let (ne, nt) = (che.num_edges() as u32, che.num_triangles() as u32);
            for e in (0..ne).step_by(7) {
                if che.is_flip_ok(e)? {
                    che.flip_edge(e)?;
                }
            }
            for t in (0..nt).step_by(11) {
                unless_refused(che.split_triangle(t, None))?;
            }
            for e in (3..ne).step_by(13) {
                unless_refused(che.split_edge(e, None))?;
            }
            for h in (5..3 * nt).step_by(97) {
                if che.is_collapse_ok(h)? {
                    che.collapse_edge(h)?;
                }
            }
            for t in (1..nt).step_by(17) {
                unless_refused(che.remove_triangle(t))?;
            }
            let x = che.add_vertex(Some(glam::DVec3::new(2.0, 2.0, 0.0)))?;
            unless_refused(che.add_triangle(0, 1, x))?;
            unless_refused(che.remove_vertex(200))?;
            che.garbage_collect()?;
            Ok(())
        };
        let refused = refuse_each_edit(&format!("level {level}"), make, edits, Che::validate);
        assert!(refused > 10, "level {level}: only {refused} large requests");
    }
}

/// The same for a volume.
#[test]
fn every_volume_edit_allocation_can_fail() {
    use topomesh::Chf;
    let volume = chf_common::cube(6, 6, 6, false);
    for level in 0..=3 {
        let make = || {
            let options = topomesh::BuildOptions::level(level);
            Chf::from_tetrahedra(&volume.tets, volume.n(), &volume.positions, options).unwrap()
        };
        let edits = |chf: &mut Chf| -> Result<(), topomesh::Error> {
            let (nf, ne, nt) = (
                chf.num_faces() as u32,
                chf.num_edges() as u32,
                chf.num_tetrahedra() as u32,
            );
            for t in (0..nt).step_by(9) {
                unless_refused(chf.split_tetrahedron(t, None))?;
            }
            for f in (0..nf).step_by(7) {
                if chf.is_flip_23_ok(f)? {
                    chf.flip_23(f)?;
                }
            }
            for e in (0..ne).step_by(5) {
                if chf.is_flip_32_ok(e)? {
                    chf.flip_32(e)?;
                }
            }
            for f in (1..nf).step_by(23) {
                unless_refused(chf.split_face(f, None))?;
            }
            for e in (2..ne).step_by(29) {
                unless_refused(chf.split_edge(e, None))?;
            }
            for he in (3..12 * nt as u64).step_by(301) {
                unless_refused(chf.collapse_edge(he))?;
            }
            for t in (1..nt).step_by(13) {
                unless_refused(chf.remove_tetrahedron(t))?;
            }
            let x = chf.add_vertex(Some(glam::DVec3::new(-1.0, -1.0, -1.0)))?;
            unless_refused(chf.add_tetrahedron([0, 1, 7, x]))?;
            unless_refused(chf.remove_vertex(100))?;
            chf.garbage_collect()?;
            Ok(())
        };
        let refused = refuse_each_edit(&format!("level {level}"), make, edits, Chf::validate);
        assert!(refused > 10, "level {level}: only {refused} large requests");
    }
}

/// [`refuse_each_edit`] at each of `levels`, the mesh from `make(level)`: at least one
/// large request each.
fn refuse_each_edit_at<M>(
    what: &str, levels: &[u8], make: impl Fn(u8) -> M,
    edits: impl Fn(&mut M) -> Result<(), topomesh::Error>,
    validate: impl Fn(&M) -> Result<(), topomesh::Error>,
) {
    for &level in levels {
        let what = format!("{what}, level {level}");
        let refused = refuse_each_edit(&what, || make(level), &edits, &validate);
        assert!(refused > 0, "{what}: no large request");
    }
}

/// Edits at a vertex of high degree, where the working lists outgrow the stack and the
/// large-request limit: the ring of a surface hub a collapse check gathers. Each refusal
/// is an error that leaves the mesh valid.
#[test]
fn edits_at_a_surface_hub_can_fail() {
    use topomesh::Che;
    // The north pole (vertex 0) of a sphere of 1500 meridians has 1500 neighbours.
    let s = topomesh::generate::sphere(1500, 4);
    let make = |level| {
        let options = topomesh::BuildOptions::level(level);
        Che::from_triangles(&s.triangles, s.positions.len(), &s.positions, options).unwrap()
    };
    let edits = |che: &mut Che| -> Result<(), topomesh::Error> {
        // Half-edge 3i runs from the pole to its i-th neighbour.
        for h in (0..1500 * 3).step_by(3 * 211) {
            if che.is_collapse_ok(h)? {
                che.collapse_edge(h)?;
            }
        }
        Ok(())
    };
    refuse_each_edit_at("surface", &[0, 2], make, edits, Che::validate);
}

/// The same for a volume: the stars a volume edit's check reads and its commit walks.
#[test]
fn edits_at_a_volume_hub_can_fail() {
    use topomesh::Chf;
    // A cone over a sphere of 2320 triangles: its apex has 2320 tetrahedra.
    let sphere = topomesh::generate::sphere(40, 30);
    let apex = sphere.positions.len() as u32;
    let mut positions = sphere.positions.clone();
    positions.push(glam::DVec3::ZERO);
    let cone = sphere.triangles.iter().map(|&[a, b, c]| [a, b, c, apex]);
    let tets: Vec<[u32; 4]> = cone.collect();
    let make = |level| {
        let options = topomesh::BuildOptions::level(level);
        Chf::from_tetrahedra(&tets, positions.len(), &positions, options).unwrap()
    };
    let edits = |chf: &mut Chf| -> Result<(), topomesh::Error> {
        let nt = chf.num_tetrahedra() as u64;
        for he in (5..12 * nt).step_by(12 * nt as usize / 5) {
            unless_refused(chf.collapse_edge(he))?;
        }
        unless_refused(chf.remove_vertex(300))?;
        unless_refused(chf.remove_tetrahedron(17))?;
        unless_refused(chf.add_tetrahedron(tets[17]))?;
        Ok(())
    };
    // Level 0 (a view computed for the check) and 3 (stored tables and the boundary).
    refuse_each_edit_at("volume", &[0, 3], make, edits, Chf::validate);
}
