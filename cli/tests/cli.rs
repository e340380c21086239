//! The `topomesh` command as a user runs it.

use std::path::PathBuf;
use std::process::{Command, Output};

fn topomesh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_topomesh"))
        .args(args)
        .output()
        .expect("run topomesh")
}

fn text(out: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp(name: &str, contents: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topomesh-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

#[test]
fn info_on_the_embedded_torus() {
    for args in [&[][..], &["info"][..]] {
        let out = topomesh(args);
        let (stdout, _) = text(&out);
        assert!(out.status.success());
        assert!(stdout.contains("euler characteristic 0"), "{stdout}");
        assert!(stdout.contains("genus                1"), "{stdout}");
    }
}

#[test]
fn info_json_has_the_summary_fields() {
    let out = topomesh(&["info", "--json", "--level", "2"]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["vertices"], 288);
    assert_eq!(json["triangles"], 576);
    assert_eq!(json["genus"], 1);
    assert_eq!(json["orientable"], true);
    assert_eq!(json["level"], 2);
    for field in [
        "edges",
        "boundary_edges",
        "boundary_curves",
        "components",
        "isolated_vertices",
        "euler_characteristic",
        "manifold",
        "dropped_degenerate",
        "non_manifold_edges",
        "split_vertices",
        "flipped_triangles",
        "non_orientable_components",
    ] {
        assert!(json.get(field).is_some(), "missing {field}");
    }
}

#[test]
fn bad_input_is_a_clear_error() {
    let out = topomesh(&["info", "/nonexistent/mesh.off"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out).1.contains("/nonexistent/mesh.off"));

    let path = temp("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
    let out = topomesh(&["info", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let (_, stderr) = text(&out);
    assert!(
        stderr.contains("bad.off:6:") && stderr.contains("vertex index 9"),
        "{stderr}"
    );

    let out = topomesh(&["info", "--level", "7"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn check_and_strict_reject_non_manifold_input() {
    let bowtie = temp(
        "bowtie.off",
        "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n",
    );
    let path = bowtie.to_str().unwrap();
    let out = topomesh(&["check", path]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out).0.contains("1 non-manifold vertices"),
        "{}",
        text(&out).0
    );
    let out = topomesh(&["info", "--strict", path]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out).1.contains("non-manifold vertex 0"),
        "{}",
        text(&out).1
    );
    let out = topomesh(&["info", path]);
    assert!(out.status.success());
    assert!(text(&out).0.contains("split vertices            1"));
}

#[test]
fn convert_round_trip() {
    let src = temp(
        "torus.off",
        &topomesh::generate::to_off(&topomesh::generate::torus(5, 4)),
    );
    let dst = src.with_file_name("torus.vtk");
    let out = topomesh(&["convert", src.to_str().unwrap(), dst.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).1);
    let out = topomesh(&["info", "--json", dst.to_str().unwrap()]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["triangles"], 40);
    assert_eq!(json["genus"], 1);
    let out = topomesh(&["check", src.to_str().unwrap()]);
    assert!(out.status.success());
}

#[test]
fn volumes_info_check_and_convert() {
    // Two tetrahedra sharing the face (1, 2, 3), 1-based as Medit writes them.
    let mesh = temp(
        "two.mesh",
        "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n\
         Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n",
    );
    let out = topomesh(&["info", "--json", mesh.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).1);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["kind"], "volume");
    assert_eq!(
        (json["vertices"].as_u64(), json["edges"].as_u64()),
        (Some(5), Some(9))
    );
    assert_eq!(
        (json["faces"].as_u64(), json["tetrahedra"].as_u64()),
        (Some(7), Some(2))
    );
    assert_eq!(json["boundary_faces"], 6);
    assert_eq!(json["euler_characteristic"], 1);
    let out = topomesh(&["check", mesh.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).0);
    let vtk = mesh.with_file_name("two.vtk");
    let out = topomesh(&["convert", mesh.to_str().unwrap(), vtk.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).1);
    let out = topomesh(&["info", vtk.to_str().unwrap()]);
    assert!(
        text(&out).0.contains("euler characteristic 1"),
        "{}",
        text(&out).0
    );
    // Three tetrahedra on one face: check fails, strict refuses.
    let three = temp(
        "three.mesh",
        "MeshVersionFormatted 2\nDimension 3\nVertices\n6\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n-1 -1 -1 0\n\
         Tetrahedra\n3\n1 2 3 4 0\n2 3 4 5 0\n2 3 4 6 0\nEnd\n",
    );
    let out = topomesh(&["check", three.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out).0.contains("non-manifold faces"),
        "{}",
        text(&out).0
    );
    let out = topomesh(&["info", "--strict", three.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
}

/// Two triangles of a square as an STL-like OFF: each triangle with its own corners, the
/// shared ones a few units in the last place apart.
const SPLIT_SQUARE: &str = "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n1.0000000000000002 0 0\n1 1 0\n0 1.0000000000000004 0\n3 0 1 2\n3 3 4 5\n";

#[test]
fn weld_joins_nearly_equal_corners() {
    let input = temp("split-square.off", SPLIT_SQUARE);
    let path = input.to_str().unwrap();
    let (loose, _) = text(&topomesh(&["info", path]));
    assert!(loose.contains("boundary curves      2"), "{loose}");
    let (welded, _) = text(&topomesh(&["info", "--weld", "1e-9", path]));
    assert!(welded.contains("boundary curves      1"), "{welded}");
    assert!(welded.contains("vertices             4"), "{welded}");
    assert!(welded.contains("welded vertices           2"), "{welded}");
    let out = input.with_file_name("welded-square.off");
    let run = topomesh(&["convert", "--weld", "1e-9", path, out.to_str().unwrap()]);
    let (stdout, _) = text(&run);
    assert!(
        run.status.success() && stdout.contains("4 vertices, 2 triangles"),
        "{stdout}"
    );
    let bad = topomesh(&["check", "--weld", "nan", path]);
    let (_, stderr) = text(&bad);
    assert!(
        !bad.status.success() && stderr.contains("weld_tolerance"),
        "{stderr}"
    );
}
