//! `topomesh export` and the Betti numbers of `info`, as a user runs them.

mod common;

use common::{temp, text, topomesh};

/// Two triangles (0 1 2) and (1 3 2) sharing the edge 1-2.
const STRIP: &str = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n";

fn export(r#as: &str, extra: &[&str]) -> String {
    let input = temp("strip.off", STRIP);
    let mut args = vec!["export", input.to_str().unwrap(), "--as", r#as, "-o", "-"];
    args.extend_from_slice(extra);
    let out = topomesh(&args);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{as}: {stderr}", as = r#as);
    stdout
}

#[test]
fn exact_layouts_on_two_triangles() {
    assert_eq!(export("edges", &[]), "edges 5\n0 1\n1 2\n2 0\n1 3\n3 2\n");
    assert_eq!(export("dual", &[]), "dual 2\n-1 1 -1\n-1 -1 0\n");
    assert_eq!(export("strips", &[]), "strips 1\n0 1 2 3\n");
    assert_eq!(
        export("corner", &[]),
        "corner 6\n0 4\n1 -1\n2 -1\n1 -1\n3 0\n2 -1\n"
    );
    let d1 = export("d1", &[]);
    assert!(
        d1.starts_with("%%MatrixMarket matrix coordinate real general\n4 5 10\n1 1 -1\n1 3 1\n"),
        "{d1}"
    );
    let he = export("halfedge", &[]);
    assert!(
        he.starts_with("halfedge 6 4 2\n1 2 -1 0 0 0\n2 0 5 1 0 1\n"),
        "{he}"
    );
    assert_eq!(he.lines().count(), 1 + 6 + 4 + 2);
    let explicit = export("halfedge", &["--explicit-boundary"]);
    assert!(explicit.starts_with("halfedge 10 4 2\n"), "{explicit}");
    assert!(
        explicit.contains("\n7 8 0 1 -1 0\n"),
        "the outside twin of 0 -> 1: {explicit}"
    );
    let winged = export("winged", &[]);
    assert!(
        winged.starts_with("winged 5 4 2\n0 1 0 -1 2 1 -1 -1\n1 2 0 1 0 2 4 3\n"),
        "{winged}"
    );
    for r#as in [
        "d2",
        "laplacian",
        "vertex-adjacency",
        "edge-adjacency",
        "dual-adjacency",
    ] {
        let m = export(r#as, &[]);
        let mut lines = m.lines().skip(1);
        let n: usize = lines
            .next()
            .unwrap()
            .split(' ')
            .nth(2)
            .unwrap()
            .parse()
            .unwrap();
        assert_eq!(lines.count(), n, "{as}: one row per entry", as = r#as);
    }
}

#[test]
fn export_writes_a_file_and_refuses_volumes() {
    let input = temp("strip2.off", STRIP);
    let output = input.with_file_name("strip.edges");
    let out = topomesh(&[
        "export",
        input.to_str().unwrap(),
        "--as",
        "edges",
        "-o",
        output.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    assert_eq!(
        std::fs::read_to_string(&output).unwrap(),
        "edges 5\n0 1\n1 2\n2 0\n1 3\n3 2\n"
    );
    let tet = temp(
        "one.mesh",
        "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n",
    );
    let out = topomesh(&["export", tet.to_str().unwrap(), "--as", "edges", "-o", "-"]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("takes a surface"), "{}", text(&out).1);
    let bad = input.with_file_name("no-such-dir/x.txt");
    let out = topomesh(&[
        "export",
        input.to_str().unwrap(),
        "--as",
        "edges",
        "-o",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(3));
    assert!(text(&out).1.contains("no-such-dir"), "{}", text(&out).1);
}

#[test]
fn info_prints_betti_numbers() {
    let (stdout, _) = text(&topomesh(&["info"]));
    assert!(stdout.contains("betti numbers (Z/2)  1 2 1\n"), "{stdout}");
    let out = topomesh(&["info", "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["betti"], serde_json::json!([1, 2, 1]));
}
