//! The writers on small meshes: every format reads back to what was written (positions
//! bit-exact except STL's `f32`), refusals name the file and leave nothing, and the
//! writes are whole or absent.

use super::{Mesh, WriteOptions, write, write_mesh, write_to};
use crate::error::ErrorKind;
use crate::io::text::temp_path;
use crate::io::{Format, MeshData, parse, read};
use glam::DVec3;
use std::path::Path;

/// A mesh whose coordinates are hard to print exactly (thirds, sums that round, -0.0, tiny
/// and huge magnitudes): writers must read back to the same `f64`s.
fn awkward_mesh() -> MeshData {
    MeshData {
        positions: vec![
            DVec3::new(0.1, -2.5e-300, 1.0 / 3.0),
            DVec3::new(1e20, 0.0, -0.0),
            DVec3::new(f64::MIN_POSITIVE, 7.0, 0.1 + 0.2),
            DVec3::new(std::f64::consts::PI, 12345.678901234567, -2.5e-7),
        ],
        triangles: vec![[0, 1, 2], [3, 2, 1]],
        tetrahedra: vec![[0, 1, 2, 3], [3, 2, 1, 0]],
        warnings: vec![],
    }
}

fn surface(data: MeshData) -> MeshData {
    MeshData {
        tetrahedra: vec![],
        ..data
    }
}

fn volume(data: MeshData) -> MeshData {
    MeshData {
        triangles: vec![],
        ..data
    }
}

/// Writes `mesh` to a temporary `.ext` file with `options` and reads it back.
fn round_trip(ext: &str, mesh: &Mesh, options: &WriteOptions) -> MeshData {
    let path = temp_path("round-trip", ext);
    let written = write_mesh(&path, mesh, options);
    let back = read(&path);
    let _ = std::fs::remove_file(&path);
    if ext == "node" {
        let _ = std::fs::remove_file(path.with_extension("ele"));
    }
    written.unwrap();
    back.unwrap()
}

/// Writing `data` as a `.ext` file fails with a message holding `words`, and leaves no file.
fn assert_write_refused(ext: &str, data: &MeshData, words: &str) {
    let path = temp_path("refused", ext);
    let e = write(&path, data).unwrap_err();
    assert!(!path.exists());
    assert!(e.message.contains(words), "{}", e.message);
}

#[test]
fn every_format_reads_back_exactly() {
    let data = awkward_mesh();
    let (surface, volume) = (surface(data.clone()), volume(data.clone()));
    let binary = WriteOptions {
        binary: true,
        ..WriteOptions::default()
    };
    for (ext, d, options) in [
        ("off", &surface, WriteOptions::default()),
        ("obj", &surface, WriteOptions::default()),
        ("ply", &surface, WriteOptions::default()),
        ("ply", &surface, binary),
        ("vtk", &surface, WriteOptions::default()),
        ("mesh", &surface, WriteOptions::default()),
        ("msh", &surface, WriteOptions::default()),
        ("mesh", &volume, WriteOptions::default()),
        ("msh", &volume, WriteOptions::default()),
        ("vtk", &volume, WriteOptions::default()),
        ("node", &volume, WriteOptions::default()),
    ] {
        // The origins, written as an attribute where the format has one, read back as
        // nothing.
        let with_origin = Mesh {
            origin: Some(&[3, 2, 1, 0]),
            ..Mesh::from_data(d)
        };
        for mesh in [Mesh::from_data(d), with_origin] {
            assert_eq!(&round_trip(ext, &mesh, &options), d, "{ext} {options:?}");
        }
    }
    let both = round_trip("vtk", &Mesh::from_data(&data), &WriteOptions::default());
    assert_eq!(both, data);
    let both = round_trip("mesh", &Mesh::from_data(&data), &WriteOptions::default());
    assert_eq!(both, data);
}

#[test]
fn stl_is_binary_and_rounds_to_f32() {
    let data = MeshData {
        positions: vec![
            DVec3::new(0.1, 0.0, 0.0),
            DVec3::new(1.0, 1.0 / 3.0, 0.0),
            DVec3::new(0.0, 1.0, 0.5),
            DVec3::new(1.0, 1.0, 1.0),
        ],
        triangles: vec![[0, 1, 2], [2, 1, 3]],
        tetrahedra: vec![],
        warnings: vec![],
    };
    let mut buf = Vec::new();
    write_to(
        &mut buf,
        &Mesh::from_data(&data),
        Format::Stl,
        &WriteOptions::default(),
        "s.stl",
    )
    .unwrap();
    assert_eq!(buf.len(), 84 + 50 * 2);
    assert!(!buf.starts_with(b"solid"));
    let back = parse(&buf, Format::Stl, "s.stl").unwrap();
    let rounded: Vec<DVec3> = data
        .positions
        .iter()
        .map(|p| p.as_vec3().as_dvec3())
        .collect();
    assert_eq!(back.positions, rounded);
    assert_eq!(back.triangles, data.triangles);
    // The normal of the first triangle, unit length, pointing by the right-hand rule.
    let n = |k: usize| f32::from_le_bytes(buf[84 + 4 * k..88 + 4 * k].try_into().unwrap());
    let expected = (data.positions[1] - data.positions[0])
        .cross(data.positions[2] - data.positions[0])
        .normalize()
        .as_vec3();
    assert_eq!([n(0), n(1), n(2)], expected.to_array());
}

#[test]
fn origins_are_written_where_the_format_has_an_attribute() {
    let data = surface(awkward_mesh());
    let mesh = Mesh {
        origin: Some(&[7, 8, 9, 10]),
        ..Mesh::from_data(&data)
    };
    let text = |format, options: &WriteOptions| {
        let mut buf = Vec::new();
        write_to(&mut buf, &mesh, format, options, "o").unwrap();
        String::from_utf8(buf).unwrap()
    };
    let plain = WriteOptions::default();
    let no_origin = WriteOptions {
        no_origin: true,
        ..plain
    };
    assert!(text(Format::Ply, &plain).contains("property uint origin\n"));
    assert!(
        text(Format::Ply, &plain).contains("3.141592653589793 12345.678901234567 -0.00000025 10\n")
    );
    assert!(!text(Format::Ply, &no_origin).contains("origin"));
    assert!(text(Format::Vtk, &plain).ends_with(
        "POINT_DATA 4\nSCALARS origin unsigned_int 1\nLOOKUP_TABLE default\n7\n8\n9\n10\n"
    ));
    assert!(!text(Format::Vtk, &no_origin).contains("POINT_DATA"));
    assert!(
        text(Format::Medit, &plain)
            .contains("3.141592653589793 12345.678901234567 -0.00000025 10\n")
    );
    assert!(
        text(Format::Medit, &no_origin)
            .contains("3.141592653589793 12345.678901234567 -0.00000025 0\n")
    );
    let mut buf = Vec::new();
    write_to(
        &mut buf,
        &mesh,
        Format::Ply,
        &WriteOptions {
            binary: true,
            ..plain
        },
        "o",
    )
    .unwrap();
    let at = buf.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    let origin =
        |v: usize| u32::from_le_bytes(buf[at + 28 * v + 24..at + 28 * v + 28].try_into().unwrap());
    assert_eq!((0..4).map(origin).collect::<Vec<_>>(), [7, 8, 9, 10]);
    assert_eq!(buf.len(), at + 28 * 4 + 13 * 2);
}

#[test]
fn writers_refuse_what_the_format_cannot_hold() {
    let data = awkward_mesh();
    for ext in ["off", "obj", "ply", "stl"] {
        assert_write_refused(
            ext,
            &data,
            "holds surfaces only, but the mesh has 2 tetrahedra",
        );
    }
    assert_write_refused(
        "node",
        &data,
        "holds tetrahedra only, but the mesh has 2 triangles",
    );
    assert_write_refused("off", &MeshData::default(), "no vertices");
    let bad = MeshData {
        positions: vec![DVec3::ZERO; 3],
        triangles: vec![[0, 1, 3]],
        tetrahedra: vec![],
        warnings: vec![],
    };
    assert_write_refused(
        "mesh",
        &bad,
        "triangle 0 names vertex 3, but there are 3 vertices",
    );
    let bad = MeshData {
        positions: vec![DVec3::ZERO; 4],
        triangles: vec![],
        tetrahedra: vec![[0, 1, 2, 4]],
        warnings: vec![],
    };
    assert_write_refused("vtk", &bad, "tetrahedron 0 names vertex 4");
    let path = temp_path("binary", "off");
    let options = WriteOptions {
        binary: true,
        ..WriteOptions::default()
    };
    let e = write_mesh(&path, &Mesh::from_data(&surface(data.clone())), &options).unwrap_err();
    assert!(e.message.contains("written as text only"), "{}", e.message);
    assert!(!path.exists());
    let mut buf = Vec::new();
    let e = write_to(
        &mut buf,
        &Mesh::from_data(&volume(data)),
        Format::TetGen,
        &WriteOptions::default(),
        "-",
    )
    .unwrap_err();
    assert!(
        e.message.starts_with("-: a TetGen mesh is two files"),
        "{}",
        e.message
    );
    assert!(buf.is_empty());
}

/// The files in `folder` whose name starts with `stem`.
fn files_like(folder: &Path, stem: &str) -> Vec<String> {
    std::fs::read_dir(folder)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.contains(stem))
        .collect()
}

#[test]
fn failed_writes_leave_nothing_and_name_the_path() {
    let data = surface(awkward_mesh());
    let folder = temp_path("atomic", "d");
    std::fs::create_dir(&folder).unwrap();
    let not_a_folder = folder.join("file");
    std::fs::write(&not_a_folder, "x").unwrap();
    for path in [
        folder.join("missing").join("m.off"),
        not_a_folder.join("m.off"),
        Path::new("/dev/full").to_path_buf(),
        folder.clone(),
    ] {
        let options = WriteOptions {
            format: Some(Format::Off),
            ..WriteOptions::default()
        };
        let e = write_mesh(&path, &Mesh::from_data(&data), &options).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io, "{}", e.message);
        assert!(
            e.message.starts_with(&format!("{}: ", path.display())),
            "{}",
            e.message
        );
    }
    assert_eq!(files_like(&folder, ""), ["file"]);
    assert_eq!(std::fs::read(&not_a_folder).unwrap(), b"x");
    // A successful write replaces the file whole and leaves no temporary file.
    let target = folder.join("m.off");
    std::fs::write(&target, "old").unwrap();
    write(&target, &data).unwrap();
    assert_eq!(read(&target).unwrap(), data);
    let mut names = files_like(&folder, "");
    names.sort();
    assert_eq!(names, ["file", "m.off"]);
    // A device is written in place, never replaced.
    let options = WriteOptions {
        format: Some(Format::Off),
        ..WriteOptions::default()
    };
    write_mesh(Path::new("/dev/null"), &Mesh::from_data(&data), &options).unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let null = Path::new("/dev/null").metadata().unwrap();
        assert!(null.file_type().is_char_device());
    }
    // A TetGen mesh whose second file cannot be written leaves neither.
    let volume = volume(awkward_mesh());
    std::fs::create_dir(folder.join("t.ele")).unwrap();
    let e = write(&folder.join("t.node"), &volume).unwrap_err();
    assert!(
        e.message
            .starts_with(&format!("{}: ", folder.join("t.ele").display())),
        "{}",
        e.message
    );
    let mut names = files_like(&folder, "");
    names.sort();
    assert_eq!(names, ["file", "m.off", "t.ele"]);
    std::fs::remove_dir_all(&folder).unwrap();
}
