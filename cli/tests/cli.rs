//! The `topomesh` command as a user runs it.

mod common;

use common::{temp, text, topomesh};
use std::path::PathBuf;
use std::process::Command;

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
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("/nonexistent/mesh.off"));

    let path = temp("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
    let out = topomesh(&["info", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
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
        text(&out).0.contains("1 non-manifold vertex: 0"),
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
    assert!(text(&out).0.contains("split vertices            1: 0"));
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
        text(&out).0.contains("1 non-manifold face: (1, 2, 3)\n"),
        "{}",
        text(&out).0
    );
    let out = topomesh(&["info", "--strict", three.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
}

/// `convert` on a surface with a flipped triangle, a degenerate one and a pinched vertex:
/// the built mesh by default, the input with `--as-read`.
#[test]
fn convert_writes_the_built_mesh_or_the_input() {
    // A tetrahedron surface with its last triangle flipped, a degenerate triangle, and two
    // triangles meeting the tetrahedron at vertex 0 only (two copies of 0 once built).
    let src = temp(
        "flipped.off",
        "OFF\n8 7 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n-1 -1 0\n-2 0 1\n-2 1 1\n\
         3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 0 1\n3 0 4 5\n3 0 6 7\n",
    );
    let built = src.with_file_name("built.ply");
    let out = topomesh(&["convert", src.to_str().unwrap(), built.to_str().unwrap()]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stdout.ends_with("built.ply: 10 vertices, 6 triangles, 0 tetrahedra\n"),
        "{stdout}"
    );
    let info = |path: &PathBuf| {
        let out = topomesh(&["info", "--json", path.to_str().unwrap()]);
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let json = info(&built);
    assert_eq!(json["report"]["flipped_triangles"], 0, "{json}");
    assert_eq!(json["report"]["split_vertices"], 0, "{json}");
    assert_eq!(json["report"]["dropped_degenerate"], 0, "{json}");
    assert!(
        std::fs::read_to_string(&built)
            .unwrap()
            .contains("property uint origin")
    );
    let soup = src.with_file_name("soup.off");
    let out = topomesh(&[
        "convert",
        "--as-read",
        src.to_str().unwrap(),
        soup.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out).1);
    assert!(
        text(&out)
            .0
            .ends_with("soup.off: 8 vertices, 7 triangles, 0 tetrahedra\n")
    );
    let json = info(&soup);
    assert_eq!(json["report"]["dropped_degenerate"], 1, "{json}");
    assert_eq!(json["report"]["split_vertices"], 1, "{json}");
    // A surface has no boundary surface to write.
    let out = topomesh(&[
        "convert",
        "--boundary",
        src.to_str().unwrap(),
        soup.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(3));
    assert!(
        text(&out).1.contains("--boundary needs a volume mesh"),
        "{}",
        text(&out).1
    );
}

#[test]
fn convert_writes_a_boundary_and_uses_standard_streams() {
    let mesh = temp(
        "pair.mesh",
        "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n\
         Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n",
    );
    let skin = mesh.with_file_name("skin.obj");
    let out = topomesh(&[
        "convert",
        "--boundary",
        mesh.to_str().unwrap(),
        skin.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out).1);
    assert!(
        text(&out)
            .0
            .ends_with("skin.obj: 5 vertices, 6 triangles, 0 tetrahedra\n")
    );
    let out = topomesh(&["check", skin.to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out).0);
    // Standard input to standard output: the summary goes to stderr, the mesh to stdout.
    let mut child = Command::new(env!("CARGO_BIN_EXE_topomesh"))
        .args(["convert", "-", "-", "--from", "mesh", "--format", "vtk"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let input = std::fs::read(&mesh).unwrap();
    std::io::Write::write_all(&mut child.stdin.take().unwrap(), &input).unwrap();
    let out = child.wait_with_output().unwrap();
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert_eq!(
        stderr,
        "<stdin> -> <stdout>: 5 vertices, 0 triangles, 2 tetrahedra\n"
    );
    assert!(
        stdout.starts_with("# vtk DataFile Version 3.0\n"),
        "{stdout}"
    );
    assert!(stdout.contains("CELL_TYPES 2\n10\n10\n"), "{stdout}");
    // A stream has no extension: without --format it is refused.
    let out = topomesh(&["convert", mesh.to_str().unwrap(), "-"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("--format EXT"), "{}", text(&out).1);
    assert!(out.stdout.is_empty());
}

#[test]
fn reader_warnings_and_non_finite_vertices_reach_the_user() {
    let mesh = temp(
        "nan.off",
        "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
    );
    let path = mesh.to_str().unwrap();
    let out = topomesh(&["check", path]);
    assert_eq!(out.status.code(), Some(1));
    let want = format!("{path}: 1 vertex with a NaN or infinite coordinate: 1");
    assert!(text(&out).0.contains(&want), "{}", text(&out).0);
    let out = topomesh(&["info", "--json", path]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["report"]["non_finite_vertices"], 1);
    assert_eq!(
        json["warnings"],
        serde_json::json!([
            format!("{path}:7: 1 face line after the 1 declared (ignored)"),
            format!(
                "{path}: 1 vertex has a NaN or infinite coordinate (0-based ids 1); \
                 geometric checks skip them"
            ),
        ])
    );
    let out = topomesh(&["info", path]);
    assert!(
        text(&out).0.contains("reader warnings\n  "),
        "{}",
        text(&out).0
    );
}

#[test]
fn a_huge_thread_count_gives_the_single_threaded_answer() {
    // Large enough for a build to share its work among threads.
    let off = topomesh::generate::to_off(&topomesh::generate::grid(200, 100));
    let path = temp("threads.off", &off);
    let path = path.to_str().unwrap();
    let run = |threads: &str| {
        let out = topomesh(&["info", path, "--json", "--level", "3", "--threads", threads]);
        let (stdout, stderr) = text(&out);
        assert!(out.status.success(), "--threads {threads}: {stderr}");
        let mut json: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        let fields = json.as_object_mut().unwrap();
        // The timings are the one thing that may differ.
        fields.retain(|name, _| !name.ends_with("_seconds"));
        json
    };
    let one = run("1");
    assert_eq!(one["triangles"], 40000);
    assert_eq!(run("100000"), one);
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
