//! A byte string read as a sequence of C API calls on one handle, made from Rust through the
//! exported `extern "C"` functions: a build with random options (levels and thread counts
//! out of range, strict or not, ids past the vertex count), then queries with random and
//! out-of-range ids, undersized and NULL buffers, CSR calls with wrong capacities, level
//! changes, star iterations stepped past their end, views read to their last element.
//!
//! Checked on every call: no `TOPOMESH_STATUS_PANIC`; a length written with `OK` fits the
//! buffer and one written with `BUFFER_TOO_SMALL` does not; a relation answers the same at
//! every level (ids never change with the level); CSR rows equal the per-element answers.
//! AddressSanitizer catches any write past a buffer, as every buffer has exactly its
//! stated capacity.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::collections::HashMap;
use std::mem::MaybeUninit;
use std::ptr::{null, null_mut};
use topomesh::ffi::Status;
use topomesh::ffi::che::*;
use topomesh::ffi::chf::*;
use topomesh::ffi::status::topomesh_last_error;

/// The input as a stream of small numbers; zeros once it runs out.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn u8(&mut self) -> u8 {
        let Some((&b, rest)) = self.0.split_first() else {
            return 0;
        };
        self.0 = rest;
        b
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }
    /// An id for a container of `n` elements: mostly in range, sometimes just past the
    /// end, `NONE`, or anything.
    fn id(&mut self, n: usize) -> u32 {
        match self.u8() % 8 {
            0 => n as u32,
            1 => u32::MAX,
            2 => self.u32(),
            _ => (u32::from(self.u8()) | u32::from(self.u8()) << 8) % (n as u32).max(1),
        }
    }
    /// True once in `n` values of the next byte.
    fn one_in(&mut self, n: u8) -> bool {
        self.u8().is_multiple_of(n)
    }
    fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

type CheIds = unsafe extern "C" fn(*const CheMesh, u32, *mut u32, usize, *mut usize) -> Status;
type ChfIds = unsafe extern "C" fn(*const ChfMesh, u32, *mut u32, usize, *mut usize) -> Status;
type CheValue = unsafe extern "C" fn(*const CheMesh, u32, *mut u32) -> Status;
type ChfValue = unsafe extern "C" fn(*const ChfMesh, u32, *mut u32) -> Status;
type Csr<M> = unsafe extern "C" fn(
    *const M,
    *mut u32,
    usize,
    *mut u32,
    usize,
    *mut usize,
    *mut usize,
) -> Status;

/// Calls an id-list query with a buffer of exactly `cap` elements (NULL when `null`) and
/// checks the length contract; the answer when it fit.
fn ids_call(
    call: impl Fn(*mut u32, usize, *mut usize) -> Status, cap: usize, null: bool,
) -> Option<Vec<u32>> {
    let mut buf = vec![0u32; cap];
    let mut len = usize::MAX;
    let p = if null { null_mut() } else { buf.as_mut_ptr() };
    let s = call(p, cap, &mut len);
    assert_ne!(s, Status::Panic);
    match s {
        // NULL with cap 0 is a size query: OK with the full length, nothing written.
        Status::Ok if null => {
            assert_eq!(cap, 0, "a NULL buffer of capacity {cap} accepted");
            None
        }
        Status::Ok => {
            assert!(len <= cap, "OK with {len} > cap {cap}");
            buf.truncate(len);
            Some(buf)
        }
        Status::BufferTooSmall => {
            assert!(len > cap, "BUFFER_TOO_SMALL with {len} <= cap {cap}");
            None
        }
        _ => None,
    }
}

/// Calls a CSR query once with the capacities of the input (possibly wrong), then with the
/// sizes it asked for; the rows when they fit.
fn csr_call<M>(m: *const M, f: Csr<M>, b: &mut Bytes) -> Option<(Vec<u32>, Vec<u32>)> {
    let (oc, ic) = (usize::from(b.u8() % 40), usize::from(b.u8()));
    let (mut o, mut i) = (vec![0u32; oc], vec![0u32; ic]);
    let (mut no, mut ni) = (usize::MAX, usize::MAX);
    // SAFETY: the buffers have exactly the capacities passed; `m` is live or NULL.
    let s = unsafe { f(m, o.as_mut_ptr(), oc, i.as_mut_ptr(), ic, &mut no, &mut ni) };
    assert_ne!(s, Status::Panic);
    match s {
        Status::Ok => assert!(no <= oc && ni <= ic),
        Status::BufferTooSmall => assert!(no > oc || ni > ic, "{no} {oc} {ni} {ic}"),
        _ => return None,
    }
    let (mut o, mut i) = (vec![0u32; no], vec![0u32; ni]);
    // SAFETY: as above.
    let s = unsafe { f(m, o.as_mut_ptr(), no, i.as_mut_ptr(), ni, &mut no, &mut ni) };
    assert_eq!(s, Status::Ok);
    Some((o, i))
}

/// Reads every element of a view, so that AddressSanitizer checks the stated length.
fn read_view<T: Copy + Default>(p: *const T, len: usize) {
    if p.is_null() {
        return;
    }
    // SAFETY: the library's view contract: `len` elements at `p` while the mesh lives.
    let s = unsafe { std::slice::from_raw_parts(p, len) };
    std::hint::black_box(s.iter().fold(T::default(), |_, &x| x));
}

/// The last error, read into a buffer of a random (maybe too small) size.
fn last_error(b: &mut Bytes) {
    let cap = usize::from(b.u8() % 64);
    let mut buf = vec![0 as std::ffi::c_char; cap];
    let mut len = 0;
    // SAFETY: `buf` has `cap` elements.
    let s = unsafe { topomesh_last_error(buf.as_mut_ptr(), cap, &mut len) };
    assert!(
        matches!(
            s,
            Status::Ok | Status::BufferTooSmall | Status::NullArgument
        ),
        "{s:?}"
    );
}

/// The answers seen so far, by (call, id): a relation answers the same at every level.
type Seen = HashMap<(u8, u32), Vec<u32>>;

fn remember(seen: &mut Seen, key: (u8, u32), got: Option<Vec<u32>>) {
    if let Some(got) = got {
        let old = seen.entry(key).or_insert_with(|| got.clone());
        assert_eq!(
            *old, got,
            "call {} on id {} changed with the level",
            key.0, key.1
        );
    }
}

/// A CSR answer's rows equal the per-element answers that were seen.
fn csr_matches(seen: &Seen, call: u8, csr: Option<(Vec<u32>, Vec<u32>)>) {
    let Some((o, i)) = csr else { return };
    for (row, w) in o.windows(2).enumerate() {
        if let Some(want) = seen.get(&(call, row as u32)) {
            assert_eq!(
                &i[w[0] as usize..w[1] as usize],
                &want[..],
                "CSR row {row} of call {call}"
            );
        }
    }
}

const CHE_IDS: [CheIds; 10] = [
    che_vertex_vertices,
    che_vertex_edges,
    che_vertex_triangles,
    che_edge_vertices,
    che_edge_edges,
    che_edge_triangles,
    che_triangle_vertices,
    che_triangle_edges,
    che_triangle_triangles,
    che_boundary_curve_vertices,
];
const CHE_VALUES: [CheValue; 5] = [
    che_half_edge_opposite,
    che_half_edge_edge,
    che_half_edge_curve,
    che_vertex_half_edge,
    che_edge_half_edge,
];
/// The CSR calls and the per-element call (index into `CHE_IDS`) their rows equal.
const CHE_CSR: [(Csr<CheMesh>, u8); 4] = [
    (che_mesh_vertex_vertices_csr, 0),
    (che_mesh_vertex_edges_csr, 1),
    (che_mesh_vertex_triangles_csr, 2),
    (che_mesh_triangle_triangles_csr, 8),
];

fn che_build(b: &mut Bytes) -> *mut CheMesh {
    let n_vertices = usize::from(b.u8() % 32);
    let n_triangles = usize::from(b.u8() % 48);
    let bound = n_vertices as u8 + 2;
    let tris: Vec<u32> = (0..3 * n_triangles)
        .map(|_| u32::from(b.u8() % bound))
        .collect();
    let positions: Vec<f64> = (0..3 * n_vertices)
        .map(|i| f64::from(b.u8()) + i as f64)
        .collect();
    let pos = if b.one_in(2) {
        null()
    } else {
        positions.as_ptr()
    };
    let mut options = che_build_options_default();
    options.level = u32::from(b.u8() % 6);
    options.strict = b.one_in(4).into();
    options.threads = u32::from(b.u8() % 3);
    let opt = if b.one_in(8) {
        null()
    } else {
        &options as *const _
    };
    let mut m = null_mut();
    // SAFETY: the arrays hold what the counts say.
    let s = unsafe {
        che_mesh_from_triangles_ex(tris.as_ptr(), n_triangles, n_vertices, pos, opt, &mut m)
    };
    assert_ne!(s, Status::Panic);
    assert_eq!(s == Status::Ok, !m.is_null());
    m
}

/// One CHE call picked by the next byte.
fn che_call(m: *mut CheMesh, b: &mut Bytes, seen: &mut Seen) {
    // SAFETY (every call below): `m` is a live handle; buffers have their stated sizes.
    let (nv, ne, nt, nh) = unsafe {
        (
            che_mesh_num_vertices(m),
            che_mesh_num_edges(m),
            che_mesh_num_triangles(m),
            che_mesh_num_half_edges(m),
        )
    };
    let nc = unsafe { che_mesh_num_boundary_curves(m) };
    let op = b.u8();
    match op % 12 {
        0..=3 => {
            let k = (op / 12) % CHE_IDS.len() as u8;
            let n = [nv, nv, nv, ne, ne, ne, nt, nt, nt, nc][usize::from(k)];
            let id = b.id(n);
            let cap = usize::from(b.u8() % 12);
            let null = b.one_in(16);
            let got = ids_call(
                |p, c, l| unsafe { CHE_IDS[usize::from(k)](m, id, p, c, l) },
                cap,
                null,
            );
            remember(seen, (k, id), got);
        }
        4 => {
            let k = usize::from(op / 12) % CHE_VALUES.len();
            let id = b.id([nh, nh, nh, nv, ne][k]);
            let mut out = 0;
            let s =
                unsafe { CHE_VALUES[k](m, id, if b.one_in(16) { null_mut() } else { &mut out }) };
            assert_ne!(s, Status::Panic);
            remember(
                seen,
                (100 + k as u8, id),
                (s == Status::Ok).then(|| vec![out]),
            );
        }
        5 => {
            let (id, mut out) = (b.id(nv), false);
            let s = unsafe { che_vertex_is_boundary(m, id, &mut out) };
            remember(
                seen,
                (110, id),
                (s == Status::Ok).then(|| vec![u32::from(out)]),
            );
            let (id, mut out) = (b.id(ne), false);
            let s = unsafe { che_edge_is_boundary(m, id, &mut out) };
            remember(
                seen,
                (111, id),
                (s == Status::Ok).then(|| vec![u32::from(out)]),
            );
        }
        6 => che_star(m, b.id(nv), usize::from(b.u8() % 4), seen),
        7 => {
            let (f, k) = CHE_CSR[usize::from(op / 12) % CHE_CSR.len()];
            csr_matches(seen, k, csr_call(m, f, b));
        }
        8 => {
            let (level, before) = (u32::from(b.u8() % 6), unsafe { che_mesh_level(m) });
            let s = unsafe { che_mesh_build_level(m, level) };
            assert_eq!(s == Status::Ok, level <= 3, "{s:?}");
            assert_eq!(
                unsafe { che_mesh_level(m) },
                if level <= 3 { level } else { before }
            );
        }
        9 => unsafe {
            let mut summary = MaybeUninit::zeroed().assume_init();
            assert_eq!(che_mesh_summary(m, &mut summary), Status::Ok);
            let mut report = MaybeUninit::zeroed().assume_init();
            assert_eq!(che_mesh_report(m, &mut report), Status::Ok);
            let mut memory = MaybeUninit::zeroed().assume_init();
            assert_eq!(che_mesh_memory(m, &mut memory), Status::Ok);
            assert_eq!(
                che_mesh_validate(m),
                Status::Ok,
                "a built mesh fails its own validation"
            );
            let kind = b.u32() % 16;
            let cap = usize::from(b.u8() % 20);
            ids_call(
                |p, c, l| che_mesh_report_examples(m, kind, p, c, l),
                cap,
                false,
            );
        },
        10 => unsafe {
            let mut len = 0;
            read_view(che_mesh_half_edge_vertices(m, &mut len), len);
            read_view(che_mesh_opposites(m, &mut len), len);
            read_view(che_mesh_vertex_half_edges(m, &mut len), len);
            read_view(che_mesh_edge_half_edges(m, &mut len), len);
            read_view(che_mesh_curve_half_edges(m, &mut len), len);
            read_view(che_mesh_positions(m, &mut len), len);
            read_view(che_mesh_vertex_origins(m, &mut len), len);
            read_view(che_mesh_triangle_origins(m, null_mut()), 0);
            read_view(che_mesh_edge_ranks(m, &mut len), len);
            // All at once: the same pointers, readable over the lengths the counts give.
            let mut all = MaybeUninit::<CheViews>::zeroed().assume_init();
            assert_eq!(che_mesh_views(m, &mut all), Status::Ok);
            assert_eq!(all.opposites, che_mesh_opposites(m, null_mut()));
            assert_eq!(
                all.vertex_half_edges,
                che_mesh_vertex_half_edges(m, null_mut())
            );
            let (nv, nt) = (all.num_vertices, all.num_triangles);
            read_view(all.half_edge_vertices, 3 * nt);
            read_view(all.opposites, 3 * nt);
            read_view(all.vertex_half_edges, nv);
            read_view(all.edge_half_edges, all.num_edges);
            read_view(all.positions, 3 * nv);
        },
        _ => last_error(b),
    }
}

/// A star rotation around `v`, stepped `extra` times past its end; the same at every level.
fn che_star(m: *const CheMesh, v: u32, extra: usize, seen: &mut Seen) {
    // SAFETY: `it` is plain data the library fills; `m` is live.
    let mut it = unsafe { MaybeUninit::<CheStarIter>::zeroed().assume_init() };
    if unsafe { che_star_begin(m, v, &mut it) } != Status::Ok {
        return;
    }
    let mut step = CheStarStep::default();
    let mut vertices = Vec::new();
    while unsafe { che_star_advance(&mut it, &mut step) } {
        vertices.push(step.0.vertex);
        assert!(
            vertices.len() <= unsafe { che_mesh_num_half_edges(m) } + 1,
            "a star that never ends"
        );
    }
    for _ in 0..extra {
        assert!(
            !unsafe { che_star_advance(&mut it, &mut step) },
            "a step past the end"
        );
    }
    assert!(!unsafe { che_star_advance(&mut it, null_mut()) });
    remember(seen, (120, v), Some(vertices));
}

const CHF_IDS: [ChfIds; 16] = [
    chf_vertex_vertices,
    chf_vertex_edges,
    chf_vertex_faces,
    chf_vertex_tetrahedra,
    chf_edge_vertices,
    chf_edge_edges,
    chf_edge_faces,
    chf_edge_tetrahedra,
    chf_face_vertices,
    chf_face_edges,
    chf_face_faces,
    chf_face_tetrahedra,
    chf_tetrahedron_vertices,
    chf_tetrahedron_edges,
    chf_tetrahedron_faces,
    chf_tetrahedron_tetrahedra,
];
const CHF_VALUES: [ChfValue; 11] = [
    chf_half_face_opposite,
    chf_half_face_face,
    chf_face_half_face,
    chf_vertex_half_face,
    chf_boundary_triangle_half_face,
    chf_vertex_boundary_vertex,
    chf_boundary_vertex_vertex,
    chf_half_face_boundary_triangle,
    chf_face_boundary_triangle,
    chf_boundary_triangle_face,
    chf_vertex_boundary_component,
];
const CHF_CSR: [(Csr<ChfMesh>, u8); 7] = [
    (chf_mesh_vertex_vertices_csr, 0),
    (chf_mesh_vertex_edges_csr, 1),
    (chf_mesh_vertex_faces_csr, 2),
    (chf_mesh_vertex_tetrahedra_csr, 3),
    (chf_mesh_edge_faces_csr, 6),
    (chf_mesh_edge_tetrahedra_csr, 7),
    (chf_mesh_tetrahedron_tetrahedra_csr, 15),
];

fn chf_build(b: &mut Bytes) -> *mut ChfMesh {
    let n_vertices = usize::from(b.u8() % 24);
    let n_tets = usize::from(b.u8() % 32);
    let bound = n_vertices as u8 + 2;
    let tets: Vec<u32> = (0..4 * n_tets).map(|_| u32::from(b.u8() % bound)).collect();
    let positions: Vec<f64> = (0..3 * n_vertices)
        .map(|i| f64::from(b.u8()) - i as f64)
        .collect();
    let pos = if b.one_in(2) {
        null()
    } else {
        positions.as_ptr()
    };
    let mut options = chf_build_options_default();
    options.level = u32::from(b.u8() % 6);
    options.strict = b.one_in(4).into();
    options.threads = u32::from(b.u8() % 3);
    let opt = if b.one_in(8) {
        null()
    } else {
        &options as *const _
    };
    let mut m = null_mut();
    // SAFETY: the arrays hold what the counts say.
    let s =
        unsafe { chf_mesh_from_tetrahedra_ex(tets.as_ptr(), n_tets, n_vertices, pos, opt, &mut m) };
    assert_ne!(s, Status::Panic);
    assert_eq!(s == Status::Ok, !m.is_null());
    m
}

/// The element counts a CHF id may range over, by kind.
fn chf_counts(m: *const ChfMesh) -> [usize; 8] {
    // SAFETY: `m` is live.
    unsafe {
        [
            chf_mesh_num_vertices(m),
            chf_mesh_num_edges(m),
            chf_mesh_num_faces(m),
            chf_mesh_num_tetrahedra(m),
            chf_mesh_num_half_faces(m),
            chf_mesh_num_boundary_triangles(m),
            chf_mesh_num_boundary_vertices(m),
            chf_mesh_num_boundary_components(m),
        ]
    }
}

/// One CHF call picked by the next byte.
fn chf_call(m: *mut ChfMesh, b: &mut Bytes, seen: &mut Seen) {
    let [nv, ne, nf, nt, nh, nb, nbv, _] = chf_counts(m);
    let op = b.u8();
    // SAFETY (every call below): `m` is a live handle; buffers have their stated sizes.
    match op % 10 {
        0..=3 => {
            let k = (op / 10) % CHF_IDS.len() as u8;
            let id = b.id([nv, ne, nf, nt][usize::from(k / 4)]);
            let cap = usize::from(b.u8() % 24);
            let null = b.one_in(16);
            let got = ids_call(
                |p, c, l| unsafe { CHF_IDS[usize::from(k)](m, id, p, c, l) },
                cap,
                null,
            );
            remember(seen, (k, id), got);
        }
        4 => {
            let k = usize::from(op / 10) % CHF_VALUES.len();
            let id = b.id([nh, nh, nf, nv, nb, nv, nbv, nh, nf, nb, nv][k]);
            let mut out = 0;
            let s =
                unsafe { CHF_VALUES[k](m, id, if b.one_in(16) { null_mut() } else { &mut out }) };
            assert_ne!(s, Status::Panic);
            remember(
                seen,
                (100 + k as u8, id),
                (s == Status::Ok).then(|| vec![out]),
            );
        }
        5 => {
            let (f, k) = CHF_CSR[usize::from(op / 10) % CHF_CSR.len()];
            csr_matches(seen, k, csr_call(m, f, b));
        }
        6 => {
            let (level, before) = (u32::from(b.u8() % 6), unsafe { chf_mesh_level(m) });
            let s = unsafe { chf_mesh_build_level(m, level) };
            assert_eq!(s == Status::Ok, level <= 3, "{s:?}");
            assert_eq!(
                unsafe { chf_mesh_level(m) },
                if level <= 3 { level } else { before }
            );
        }
        7 => unsafe {
            let mut summary = MaybeUninit::zeroed().assume_init();
            assert_eq!(chf_mesh_summary(m, &mut summary), Status::Ok);
            let mut report = MaybeUninit::zeroed().assume_init();
            assert_eq!(chf_mesh_report(m, &mut report), Status::Ok);
            let mut memory = MaybeUninit::zeroed().assume_init();
            assert_eq!(chf_mesh_memory(m, &mut memory), Status::Ok);
            assert_eq!(
                chf_mesh_validate(m),
                Status::Ok,
                "a built mesh fails its own validation"
            );
            let kind = b.u32() % 16;
            let cap = usize::from(b.u8() % 20);
            ids_call(
                |p, c, l| chf_mesh_report_examples(m, kind, p, c, l),
                cap,
                false,
            );
            let mut surface = null_mut();
            let s = chf_mesh_boundary(m, &mut surface);
            assert_eq!(s == Status::Ok, !surface.is_null(), "{s:?}");
            if !surface.is_null() {
                assert_eq!(che_mesh_num_triangles(surface), nb);
                assert_eq!(che_mesh_validate(surface), Status::Ok);
                che_mesh_free(surface);
            }
        },
        8 => unsafe {
            let mut len = 0;
            read_view(chf_mesh_half_face_vertices(m, &mut len), len);
            read_view(chf_mesh_opposites(m, &mut len), len);
            read_view(chf_mesh_vertex_half_faces(m, &mut len), len);
            read_view(chf_mesh_face_half_faces(m, &mut len), len);
            read_view(chf_mesh_positions(m, &mut len), len);
            read_view(chf_mesh_vertex_origins(m, &mut len), len);
            read_view(chf_mesh_tetrahedron_origins(m, &mut len), len);
            read_view(chf_mesh_boundary_half_faces(m, &mut len), len);
            read_view(chf_mesh_boundary_vertices(m, &mut len), len);
            read_view(chf_mesh_boundary_vertex_components(m, &mut len), len);
            let mut out = false;
            for (f, n) in [
                (
                    chf_vertex_is_boundary as unsafe extern "C" fn(_, _, _) -> _,
                    nv,
                ),
                (chf_edge_is_boundary, ne),
                (chf_face_is_boundary, nf),
            ] {
                let id = b.id(n);
                assert_ne!(f(m, id, &mut out), Status::Panic);
            }
        },
        _ => last_error(b),
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let mut seen = Seen::new();
    if b.one_in(2) {
        let m = che_build(&mut b);
        if m.is_null() {
            return last_error(&mut b);
        }
        while !b.is_empty() {
            che_call(m, &mut b, &mut seen);
        }
        // SAFETY: `m` is live and no longer used.
        unsafe { che_mesh_free(m) };
    } else {
        let m = chf_build(&mut b);
        if m.is_null() {
            return last_error(&mut b);
        }
        while !b.is_empty() {
            chf_call(m, &mut b, &mut seen);
        }
        // SAFETY: `m` is live and no longer used.
        unsafe { chf_mesh_free(m) };
    }
});
