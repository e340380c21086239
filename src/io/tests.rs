//! Every reader's errors on small bad inputs, one table: each names the file and the line,
//! and says what was wrong or missing.

use super::text::{assert_errors, assert_robust, utf8};
use super::{Format, MeshData, gmsh, medit, obj, off, parse, ply, stl, tetgen, vtk};
use crate::error::ErrorKind::{self, OutOfRange, Parse, TooLarge};
use crate::error::Result;

/// A reader of one format on an input in memory, naming the file in its errors.
type Reader = fn(&[u8]) -> Result<MeshData>;

fn off(bytes: &[u8]) -> Result<MeshData> {
    parse(bytes, Format::Off, "t.off")
}

fn obj(bytes: &[u8]) -> Result<MeshData> {
    parse(bytes, Format::Obj, "t.obj")
}

fn medit(bytes: &[u8]) -> Result<MeshData> {
    parse(bytes, Format::Medit, "t.mesh")
}

/// A TetGen `.node` file, read with a valid `.ele` file of no elements.
fn tetgen_node(bytes: &[u8]) -> Result<MeshData> {
    tetgen::parse(utf8(bytes), "a.node", "", "a.ele")
}

/// A TetGen `.ele` file over 5 points numbered from 1.
fn tetgen_ele(bytes: &[u8]) -> Result<MeshData> {
    const NODE: &str = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";
    tetgen::parse(NODE, "a.node", utf8(bytes), "a.ele")
}

#[test]
fn bad_input_names_the_file_and_line() {
    #[rustfmt::skip]
    let cases: &[(Reader, &str, ErrorKind, &str)] = &[
        (off, "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n", OutOfRange, "t.off:7: face 1: vertex index 3 is out of range"),
        (off, "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", Parse, "t.off:4: expected coordinate y of vertex 1, found 'x'"),
        (off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", Parse, "t.off:6: expected a vertex index of face 0, found '-1'"),
        (off, "OFF\nthree 1 0\n", Parse, "t.off:2: expected the number of vertices"),
        (off, "OFF\n3 1 x\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Parse, "t.off:2: expected the number of edges"),
        (off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 \u{e9}\n", Parse, "t.off:6: "),
        (off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n\n2 0 1\n", Parse, "t.off:7: face 0 has 2 vertices"),
        (off, "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Parse, "t.off:1: missing OFF header"),
        (off, "# only a comment\n\nPLY\n", Parse, "t.off:3: missing OFF header"),
        (off, "", Parse, "t.off: empty file"),
        (off, "  \n# c\n", Parse, "t.off: empty file"),
        (off, "OFF BINARY\n3 1 0\n", Parse, "t.off: at byte 15: unexpected end of file (truncated?): expected the number of faces"),
        (off, "4OFF\n3 1 0\n", Parse, "t.off:1: '4OFF': 4D"),
        (off, "OFF\n4294967296 0 0\n", OutOfRange, "t.off:2: 4294967296 vertices declared"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\nf 1 3 4\n", OutOfRange, "t.obj:6: face vertex 4"),
        (obj, "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", Parse, "t.obj:3: face vertex -3"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", Parse, "t.obj:4: face vertex 0"),
        (obj, "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n", Parse, "t.obj:2: expected a coordinate, found 'zero'"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2/x 3\n", Parse, "t.obj:5: expected a face corner"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/3/4/5 3\n", Parse, "t.obj:4: expected a face corner"),
        (obj, "v 0 0 0 x\n", Parse, "t.obj:1: expected a number"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", Parse, "t.obj:5: face has 2 vertices"),
        (obj, "v 0 0 0\nf\n", Parse, "t.obj:2: face has 0 vertices"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 1", Parse, "t.obj:5: a vertex needs 3"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", Parse, "t.obj:4: face has 2"),
        (obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\", Parse, "t.obj:4: face has 2"),
        (obj, "", Parse, "t.obj: no vertices ('v' lines) and no faces"),
        (obj, "hello\nworld\n", Parse, "t.obj: no vertices ('v' lines) and no faces"),
        (medit, "Dimension 3 Vertices 1 0 0 0 0 Triangles 1\n1 1 0 0", Parse, "t.mesh:2: vertex id 0 out of range"),
        (medit, "Dimension 3\nVertices 2\n0 0 0 0\n1 0", Parse, "t.mesh:4: unexpected end of file"),
        (medit, "Dimension 3\nVertices 1\n0 0 zero 0\n", Parse, "t.mesh:3: expected a coordinate, found 'zero'"),
        (medit, "Dimension 3\nVertices 1\n0 0 0 0\nFoo 3\n", Parse, "t.mesh:4: unknown keyword 'Foo'"),
        (medit, "Dimension 3\nTriangles 1\n1 2 3 0\n", Parse, "t.mesh:2: Triangles before"),
        (medit, "Dimension 4\n", Parse, "t.mesh:1: dimension 4"),
        // Huge counts are read as far as the input goes, never allocated.
        (medit, "Dimension 3\nVertices 4000000000\n0 0 0 0\n", Parse, "t.mesh:4: unexpected end"),
        (medit, "Dimension 3\nVertices 99999999999\n", TooLarge, "t.mesh:2: 99999999999 points is more than"),
        (medit, "Corners 18446744073709551615 1 2", Parse, "t.mesh:1: unexpected end"),
        (medit, "Corners 18446744073709551616", Parse, "t.mesh:1: expected the number of Corners"),
        (tetgen_ele, "1 4 0\n\n1 0 1 2 3\n", Parse, "a.ele:3: node id 0 out of range"),
        (tetgen_ele, "2 4 0\n1 1 2 3 4\n2 1 2 3 6\n", Parse, "a.ele:3: node id 6"),
        (tetgen_ele, "2 4 1\n1 1 2 3 4 0\n2 2 3", Parse, "a.ele:3: unexpected end of file"),
        (tetgen_ele, "1 8 0\n1 1 2 3 4 5 6 7 8", Parse, "a.ele:1: 8 nodes per"),
        (tetgen_node, "1 3 0 0\n2 0 0 0\n", Parse, "a.node:2: first point id 2"),
        (tetgen_node, "2 3 0 0\n0 0 0 0\n2 0 0 0\n", Parse, "a.node:3: point id 2, expected 1"),
        (tetgen_node, "1 2 0 0\n1 0 0\n", Parse, "a.node:1: dimension 2"),
        (tetgen_node, "#\n\n1 3 0 0\n1 0 x 0\n", Parse, "a.node:4: expected a coordinate, found 'x'"),
        (tetgen_node, "9999999999 3 0 0\n", TooLarge, "a.node:1: 9999999999 points"),
        (tetgen_node, "3000000000 3 18446744073709551615 1\n0 0 0 0 1", Parse, "a.node:2: unexpected end"),
    ];
    for &(reader, input, kind, start) in cases {
        assert_errors(reader, [(input, kind, start)]);
    }
}

/// Every prefix of each reader's fixtures, and each fixture with every token replaced by
/// hostile ones: no reader panics, and every error names the file.
#[test]
fn prefixes_and_hostile_tokens_never_panic() {
    let fixtures = [
        (Format::Off, off::tests::TETRA, "t.off"),
        (Format::Obj, obj::tests::CUBE, "t.obj"),
        (Format::Medit, medit::tests::CUBE_CORNER, "t.mesh"),
        (Format::Gmsh, gmsh::tests::V22, "t.msh"),
        (Format::Gmsh, gmsh::tests::V41, "t.msh"),
        (Format::Vtk, vtk::tests::LEGACY, "t.vtk"),
        (Format::Vtk, vtk::tests::V51, "t.vtk"),
        (Format::Vtk, vtk::tests::POLY, "t.vtk"),
        (Format::Ply, ply::tests::ASCII, "t.ply"),
    ];
    for (format, src, name) in fixtures {
        assert_robust(src, &format!("{name}:"), |t| {
            parse(t.as_bytes(), format, name)
        });
    }
    let stl = stl::tests::ascii(&stl::tests::cube()[..2]);
    assert_robust(&stl, "t.stl:", |t| {
        parse(t.as_bytes(), Format::Stl, "t.stl")
    });
}

/// Every prefix of a binary OFF, and the file with each byte in turn set to 0x00, 0x7f and
/// 0xff: no panic, and every error names the file.
#[test]
fn binary_off_prefixes_and_damaged_bytes_never_panic() {
    let src = off::tests::binary("COFF", 4);
    let check = |bytes: &[u8]| {
        if let Err(e) = parse(bytes, Format::Off, "t.off") {
            assert!(e.message.starts_with("t.off"), "{}", e.message);
        }
    };
    for end in 0..=src.len() {
        check(&src[..end]);
    }
    for i in 0..src.len() {
        for b in [0x00, 0x7f, 0xff] {
            let mut damaged = src.clone();
            damaged[i] = b;
            check(&damaged);
        }
    }
}

/// The one rule for files of vertices and no elements: every format reads them as a point
/// set, with the same warning.
#[test]
fn every_format_reads_a_point_set() {
    #[rustfmt::skip]
    let cases: &[(Format, &str, &str)] = &[
        (Format::Off, "t.off", "OFF\n2 0 0\n1 2 3\n4 5 6\n"),
        (Format::Obj, "t.obj", "v 1 2 3\nv 4 5 6\n"),
        (Format::Ply, "t.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n1 2 3\n4 5 6\n"),
        (Format::Medit, "t.mesh", "Dimension 3\nVertices 2\n1 2 3 0\n4 5 6 0\nTriangles 0\nEnd\n"),
        (Format::Gmsh, "t.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 1 2 3\n2 4 5 6\n$EndNodes\n"),
        (Format::Vtk, "t.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n1 2 3 4 5 6\n"),
    ];
    let mut read: Vec<(&str, Result<MeshData>)> = cases
        .iter()
        .map(|&(format, name, text)| (name, parse(text.as_bytes(), format, name)))
        .collect();
    let mut tetgen = tetgen::parse("2 3 0 0\n0 1 2 3\n1 4 5 6\n", "t.node", "0 4 0\n", "t.ele");
    if let Ok(data) = &mut tetgen {
        super::warning::add_common(data, "t.node");
    }
    read.push(("t.node", tetgen));
    for (name, data) in read {
        let data = data.unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            data.positions,
            [
                glam::DVec3::new(1.0, 2.0, 3.0),
                glam::DVec3::new(4.0, 5.0, 6.0)
            ],
            "{name}"
        );
        assert!(
            data.triangles.is_empty() && data.tetrahedra.is_empty(),
            "{name}"
        );
        let warnings: Vec<String> = data.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(
            warnings,
            [format!(
                "{name}: no faces or cells: read as a point set of 2 vertices"
            )]
        );
    }
}

#[test]
#[cfg(unix)]
fn a_missing_file_is_missing_whatever_its_extension() {
    for name in ["no-such-mesh.off", "no-such-mesh.xyz", "no-such-mesh"] {
        let path = std::env::temp_dir().join(name);
        let e = super::read(&path).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io, "{name}: {}", e.message);
        assert!(
            e.message.contains(name) && e.message.contains("No such file or directory"),
            "{}",
            e.message
        );
    }
}
