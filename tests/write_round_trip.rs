//! The built mesh written in every format, read back and built again.
//!
//! What the comparison means. A build canonicalises its input: it drops degenerate
//! elements, orients every component and gives each fan of a non-manifold vertex a vertex
//! of its own (the copies numbered after the input vertices, with the position of the
//! vertex they copy). The file holds exactly that: the structure's vertices in id order
//! (copies included, as ordinary vertices), and its triangles or tetrahedra in id order
//! with their corners in the structure's order. Reading the file therefore gives, for
//! every format but STL, the same positions, bit for bit, and an element list equal to the structure's `V`. So
//! building it again (B) from the file of the first build (A) finds nothing to repair (no
//! dropped element, no flip, no split), keeps the vertex ids, and makes:
//! - the same `V` (the same vertices of every element, in the same order);
//! - the same `O`, with one exception: an element A leaves unpaired because its edge
//!   (face) is non-manifold may pair in B, because A's split gave the fans around it
//!   vertices of their own, and in the file two of its triangles (tetrahedra) can meet
//!   alone on their copies. The relations are functions of `V` and `O`, so they agree
//!   wherever `O` does;
//! - the same edge (and face) ids and counts where no pair was freed so (the surface and
//!   volume fixtures here; the boundary test checks `V` and `O` only);
//! - the summary of the complex A's elements form over A's vertices, copies included
//!   (brute force here, [`Complex`]): A's own summary counts the input complex, where a
//!   split vertex is one vertex, so B's vertex, edge, component and Euler counts differ
//!   from A's by what the split separated, and B's repair counts are 0.
//!
//! STL stores `f32` corners and no vertex identity: a reader welds equal corners, so the
//! copies a split made come back as one vertex (and are split again), isolated vertices
//! are lost, and positions are rounded. For STL the test checks the triangles corner by
//! corner, as positions rounded to `f32`, and that nothing is flipped on the rebuild.

mod che_common;
mod chf_common;

use che_common::{Rng, perturb};
use glam::DVec3;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use topomesh::io::{self, WriteOptions};
use topomesh::{BuildOptions, Che, Chf, ErrorKind, chf};

/// A fresh folder under the temp dir for one test.
fn folder(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topomesh-write-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn che(tris: &[[u32; 3]], positions: &[DVec3]) -> Che {
    Che::from_triangles(tris, positions.len(), positions, BuildOptions::level(2)).unwrap()
}

/// A closed octahedron (shuffled, some triangles flipped), a degenerate triangle, two fans
/// pinched at one vertex (a split), an isolated vertex, a Möbius strip (a seam) and three
/// triangles on one edge.
fn surface_fixture() -> (Vec<[u32; 3]>, Vec<DVec3>) {
    let octahedron = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let mut tris = perturb(&octahedron, 6, &mut Rng(7), 0.4);
    tris.push([0, 0, 1]);
    // Two triangles sharing only vertex 6 (7..=10 around it), one of them flipped.
    tris.extend([[6, 7, 8], [6, 10, 9]]);
    // A Möbius strip over 12..18 (vertex 11 is isolated).
    let (n, base) = (3u32, 12u32);
    for i in 0..n {
        let (t0, b0) = (base + i, base + n + i);
        let (t1, b1) = if i + 1 < n {
            (t0 + 1, b0 + 1)
        } else {
            (base + n, base)
        };
        tris.extend([[t0, b0, b1], [t0, b1, t1]]);
    }
    // Three triangles on the edge (18, 19): a non-manifold edge.
    tris.extend([[18, 19, 20], [19, 18, 21], [18, 19, 22]]);
    let positions = (0..23)
        .map(|i| DVec3::new(i as f64 / 3.0, (i * i) as f64 * 0.1, -(i as f64) * 1e-7))
        .collect();
    (tris, positions)
}

const SURFACE_FORMATS: [(&str, bool); 8] = [
    ("off", false),
    ("obj", false),
    ("ply", false),
    ("ply", true),
    ("vtk", false),
    ("mesh", false),
    ("msh", false),
    ("stl", true),
];

/// A writes, B reads and builds: the comparison of the module documentation.
fn assert_surface_round_trip(a: &Che, path: &Path, binary: bool) {
    let options = WriteOptions {
        binary,
        ..WriteOptions::default()
    };
    a.write_with(path, &options).unwrap();
    let data = io::read(path).unwrap();
    let b = che(&data.triangles, &data.positions);
    let what = format!("{} (binary {binary})", path.display());
    assert_eq!(b.report().flipped_triangles, 0, "{what}");
    assert_eq!(b.report().dropped_degenerate, 0, "{what}");
    if path.extension().unwrap() == "stl" {
        let corners = |m: &Che, i: usize| m.positions()[m.half_edge_vertices()[i] as usize];
        for i in 0..a.num_half_edges() {
            assert_eq!(corners(&b, i), corners(a, i).as_vec3().as_dvec3(), "{what}");
        }
        return;
    }
    assert_eq!(data.positions, a.positions(), "{what}");
    assert_eq!(b.report().split_vertices, 0, "{what}");
    assert_eq!(b.num_vertices(), a.num_vertices(), "{what}");
    assert_eq!(b.half_edge_vertices(), a.half_edge_vertices(), "{what}");
    assert_same_pairing(
        a.opposites(),
        b.opposites(),
        a.non_manifold_half_edges(),
        &what,
    );
    let (sa, sb) = (a.summary(), b.summary());
    let c = Complex::of(a.half_edge_vertices().as_chunks::<3>().0, a.num_vertices());
    let f = a.num_triangles() as u64;
    assert_eq!(
        (sb.vertices, sb.edges, sb.triangles),
        (c.vertices, c.edges, f),
        "{what}"
    );
    assert_eq!(
        sb.euler_characteristic,
        (c.vertices + f) as i64 - c.edges as i64,
        "{what}"
    );
    assert_eq!(
        (sb.components, sb.isolated_vertices),
        (c.components, sa.isolated_vertices),
        "{what}"
    );
    b.validate().unwrap();
}

/// The complex the structure's elements form over its own vertices (a split vertex is as
/// many vertices as it has copies), by brute force: what the summary of a build from the
/// written file counts.
struct Complex {
    vertices: u64,
    edges: u64,
    /// Distinct vertex triples of the elements (for tetrahedra: their faces).
    faces: u64,
    /// Components of the elements, joined through shared vertices.
    components: u64,
}

impl Complex {
    fn of<const K: usize>(elements: &[[u32; K]], n: usize) -> Complex {
        let mut edges = BTreeSet::new();
        let mut faces = BTreeSet::new();
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                x = p[x];
            }
            x
        }
        for e in elements {
            for i in 0..K {
                for j in i + 1..K {
                    edges.insert((e[i].min(e[j]), e[i].max(e[j])));
                    for k in j + 1..K {
                        let mut f = [e[i], e[j], e[k]];
                        f.sort();
                        faces.insert(f);
                    }
                }
                let (x, y) = (
                    root(&mut parent, e[0] as usize),
                    root(&mut parent, e[i] as usize),
                );
                parent[x] = y;
            }
        }
        let used: BTreeSet<u32> = elements.iter().flatten().copied().collect();
        let roots: BTreeSet<usize> = used
            .iter()
            .map(|&v| root(&mut parent, v as usize))
            .collect();
        Complex {
            vertices: n as u64,
            edges: edges.len() as u64,
            faces: faces.len() as u64,
            components: roots.len() as u64,
        }
    }
}

/// `O` of the rebuild (`b`) against the first build's (`a`): every pair of `a` is kept;
/// a half-edge (half-face) `a` leaves unpaired stays so, unless it is one of `a`'s
/// non-manifold ones (`a_non_manifold`, sorted): the split gave the fans around such an
/// element vertices of their own, so in the file two of its triangles (tetrahedra) may
/// meet on their own and pair.
fn assert_same_pairing(a: Option<&[u32]>, b: Option<&[u32]>, a_non_manifold: &[u32], what: &str) {
    let (a, b) = (a.unwrap(), b.unwrap());
    assert_eq!(a.len(), b.len(), "{what}");
    for (h, (&x, &y)) in a.iter().zip(b).enumerate() {
        let freed = x == topomesh::NONE && a_non_manifold.binary_search(&(h as u32)).is_ok();
        assert!(
            x == y || freed,
            "{what}: half-element {h} paired with {x}, then {y}"
        );
    }
}

#[test]
fn surfaces_round_trip_in_every_format() {
    let dir = folder("surfaces");
    let (tris, positions) = surface_fixture();
    let a = che(&tris, &positions);
    let r = a.report();
    assert!(r.flipped_triangles > 0 && r.dropped_degenerate == 1 && r.split_vertices > 0);
    assert!(a.num_vertices() > a.num_input_vertices());
    for (ext, binary) in SURFACE_FORMATS {
        assert_surface_round_trip(&a, &dir.join(format!("fixture.{ext}")), binary);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The origins written beside the positions: VTK's `POINT_DATA origin` is the input vertex
/// of each structure vertex, copies included.
#[test]
fn origins_name_the_input_vertex() {
    let dir = folder("origins");
    let (tris, positions) = surface_fixture();
    let a = che(&tris, &positions);
    let path = dir.join("o.vtk");
    a.write(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let (_, values) = text.split_once("LOOKUP_TABLE default\n").unwrap();
    let written: Vec<u32> = values.lines().map(|l| l.parse().unwrap()).collect();
    let expected: Vec<u32> = (0..a.num_vertices() as u32)
        .map(|v| a.vertex_origin(v))
        .collect();
    assert_eq!(written, expected);
    assert!(
        expected[a.num_input_vertices()..]
            .iter()
            .all(|&o| (o as usize) < a.num_input_vertices())
    );
    let none = WriteOptions {
        no_origin: true,
        ..WriteOptions::default()
    };
    a.write_with(&path, &none).unwrap();
    assert!(
        !std::fs::read_to_string(&path)
            .unwrap()
            .contains("POINT_DATA")
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The repaired `blobby-shuffled.off` (half its triangles flipped in the file) written and
/// read back has no flipped triangle. Skipped, saying so, when the meshes are not fetched
/// (`bash scripts/fetch-meshes.sh`).
#[test]
fn repaired_blobby_shuffled_has_no_flips() {
    // Where scripts/fetch-meshes.sh puts them.
    let dir = std::env::var_os("TOPOMESH_MESH_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            let home = std::env::var_os("HOME").map(PathBuf::from);
            home.unwrap_or_default().join(".cache/topomesh/meshes")
        });
    let path = dir.join("blobby-shuffled.off");
    if !path.is_file() {
        eprintln!(
            "skipped: {} is not fetched (bash scripts/fetch-meshes.sh)",
            path.display()
        );
        return;
    }
    let data = io::read(&path).unwrap();
    let a = che(&data.triangles, &data.positions);
    assert!(a.report().flipped_triangles > 0);
    let dir = folder("blobby");
    for (ext, binary) in SURFACE_FORMATS {
        assert_surface_round_trip(&a, &dir.join(format!("blobby.{ext}")), binary);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A 2 x 2 x 2 box scrambled (local orders permuted: about half the tetrahedra flipped,
/// a fifth of them dropped: pinched vertices to split), with a degenerate tetrahedron.
fn volume_fixture() -> chf_common::Mesh {
    let mut mesh = chf_common::scramble(&chf_common::cube(2, 2, 2, false), 11, 80);
    mesh.tets.push([0, 1, 1, 2]);
    mesh
}

fn chf_of(tets: &[[u32; 4]], positions: &[DVec3]) -> Chf {
    Chf::from_tetrahedra(
        tets,
        positions.len(),
        positions,
        chf::BuildOptions::level(3),
    )
    .unwrap()
}

#[test]
fn volumes_round_trip_in_every_format() {
    let dir = folder("volumes");
    let m = volume_fixture();
    let a = chf_of(&m.tets, &m.positions);
    let r = a.report();
    assert!(
        r.flipped_tetrahedra > 0 && r.dropped_degenerate == 1,
        "{r:?}"
    );
    for ext in ["mesh", "msh", "vtk", "node", "ele"] {
        let path = dir.join(format!("box.{ext}"));
        a.write(&path).unwrap();
        let data = io::read(&path).unwrap();
        assert_eq!(data.positions, a.positions(), "{ext}");
        let b = chf_of(&data.tetrahedra, &data.positions);
        let rb = b.report();
        assert_eq!(
            (
                rb.flipped_tetrahedra,
                rb.dropped_degenerate,
                rb.split_vertices
            ),
            (0, 0, 0),
            "{ext}"
        );
        assert_eq!(b.half_face_vertices(), a.half_face_vertices(), "{ext}");
        assert_same_pairing(
            a.opposites(),
            b.opposites(),
            a.non_manifold_half_faces(),
            ext,
        );
        let (sa, sb) = (a.summary(), b.summary());
        let c = Complex::of(a.half_face_vertices().as_chunks::<4>().0, a.num_vertices());
        let t = a.num_tetrahedra() as u64;
        let counts = [sb.vertices, sb.edges, sb.faces, sb.tetrahedra];
        assert_eq!(counts, [c.vertices, c.edges, c.faces, t], "{ext}");
        let chi = (c.vertices + c.faces) as i64 - (c.edges + t) as i64;
        assert_eq!(sb.euler_characteristic, chi, "{ext}");
        let shape = (sb.components, sb.isolated_vertices);
        assert_eq!(shape, (c.components, sa.isolated_vertices), "{ext}");
        b.validate().unwrap();
    }
    // A volume has no place in a surface format.
    let e = a.write(&dir.join("box.off")).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput);
    assert!(!dir.join("box.off").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The boundary surface written is `boundary_surface()`: read back and built, the same
/// triangles and pairing.
#[test]
fn boundary_surface_round_trips() {
    let dir = folder("boundary");
    let m = volume_fixture();
    let a = chf_of(&m.tets, &m.positions);
    let surface = a.boundary_surface().unwrap();
    for (ext, binary) in SURFACE_FORMATS.into_iter().filter(|(e, _)| *e != "stl") {
        let path = dir.join(format!("skin.{ext}"));
        let options = WriteOptions {
            binary,
            ..WriteOptions::default()
        };
        a.write_boundary_with(&path, &options).unwrap();
        let data = io::read(&path).unwrap();
        assert_eq!(data.positions, surface.positions(), "{ext}");
        let b = che(&data.triangles, &data.positions);
        assert_eq!(
            b.half_edge_vertices(),
            surface.half_edge_vertices(),
            "{ext}"
        );
        let nm = surface.non_manifold_half_edges();
        assert_same_pairing(surface.opposites(), b.opposites(), nm, ext);
        assert_eq!(b.report().flipped_triangles, 0, "{ext}");
    }
    // Its origins are the volume's input vertices.
    let path = dir.join("skin.vtk");
    a.write_boundary(&path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let (_, values) = text.split_once("LOOKUP_TABLE default\n").unwrap();
    let written: Vec<u32> = values.lines().map(|l| l.parse().unwrap()).collect();
    let expected: Vec<u32> = (0..surface.num_vertices() as u32)
        .map(|b| a.vertex_origin(a.boundary_vertex_volume_vertex(b)))
        .collect();
    assert_eq!(written, expected);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn meshes_without_positions_are_refused() {
    let dir = folder("no-positions");
    let a = Che::from_triangles(&[[0, 1, 2]], 3, &[], BuildOptions::default()).unwrap();
    let path = dir.join("t.off");
    let e = a.write(&path).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInput);
    assert!(
        e.message
            .starts_with(&format!("{}: the mesh has no positions", path.display())),
        "{}",
        e.message
    );
    let v = Chf::from_tetrahedra(&[[0, 1, 2, 3]], 4, &[], chf::BuildOptions::default()).unwrap();
    assert_eq!(
        v.write(&dir.join("t.mesh")).unwrap_err().kind,
        ErrorKind::InvalidInput
    );
    assert_eq!(
        v.write_boundary(&dir.join("t.ply")).unwrap_err().kind,
        ErrorKind::InvalidInput
    );
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A write that fails names the path and leaves nothing: a missing folder, a path under a
/// file (which stops root as well, unlike a read-only folder), a full device.
#[test]
fn failed_writes_name_the_path_and_leave_nothing() {
    let dir = folder("atomic");
    let (tris, positions) = surface_fixture();
    let a = che(&tris, &positions);
    let file = dir.join("file");
    std::fs::write(&file, "keep").unwrap();
    let full = WriteOptions {
        format: Some(io::Format::Ply),
        ..WriteOptions::default()
    };
    for (path, options) in [
        (dir.join("missing/m.off"), WriteOptions::default()),
        (file.join("m.off"), WriteOptions::default()),
        (PathBuf::from("/dev/full"), full),
    ] {
        let e = a.write_with(&path, &options).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io, "{}", e.message);
        assert!(
            e.message.starts_with(&format!("{}: ", path.display())),
            "{}",
            e.message
        );
    }
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["file"]);
    assert_eq!(std::fs::read(&file).unwrap(), b"keep");
    read_only_folder(&dir, &a);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A read-only folder refuses the temporary file, unless the test runs as root, whom
/// permissions do not stop: then it is skipped, saying so.
#[cfg(unix)]
fn read_only_folder(dir: &Path, a: &Che) {
    use std::os::unix::fs::PermissionsExt;
    let locked = dir.join("locked");
    std::fs::create_dir(&locked).unwrap();
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o555)).unwrap();
    let probe = locked.join("probe");
    if std::fs::write(&probe, "").is_ok() {
        eprintln!("skipped the read-only folder: permissions do not stop this user (root)");
        std::fs::remove_file(&probe).unwrap();
    } else {
        let path = locked.join("m.off");
        let e = a.write(&path).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(
            e.message.starts_with(&format!("{}: ", path.display())),
            "{}",
            e.message
        );
        assert_eq!(std::fs::read_dir(&locked).unwrap().count(), 0);
    }
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[cfg(not(unix))]
fn read_only_folder(_: &Path, _: &Che) {}
