//! `topomesh export` and the Betti numbers of `info`, as a user runs them.

mod common;

use common::{temp, text, topomesh};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Two triangles (0 1 2) and (1 3 2) sharing the edge 1-2.
const STRIP: &str = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n";

fn export(r#as: &str, extra: &[&str]) -> String {
    // One file per call: the tests run at once, and a file rewritten while another test
    // reads it would read as empty.
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, Ordering::Relaxed);
    let input = temp(&format!("strip-{n}.off"), STRIP);
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

/// The `--json` document of a representation of the two triangles.
fn export_json(r#as: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["--json"];
    args.extend_from_slice(extra);
    let out = export(r#as, &args);
    assert_eq!(out.lines().count(), 1, "{as}: one line", as = r#as);
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["schema"], 1, "{out}");
    assert_eq!(json["representation"], r#as, "{out}");
    assert_eq!(
        (&json["vertices"], &json["triangles"], &json["edges"]),
        (&4.into(), &2.into(), &5.into()),
        "{out}"
    );
    json
}

#[test]
fn json_holds_the_arrays_of_the_text_layouts() {
    use serde_json::json;
    let n = serde_json::Value::Null;
    let e = export_json("edges", &[]);
    assert_eq!(e["edge_vertices"], json!([0, 1, 1, 2, 2, 0, 1, 3, 3, 2]));
    let d = export_json("dual", &[]);
    assert_eq!(d["triangle_triangles"], json!([n, 1, n, n, n, 0]));
    let s = export_json("strips", &[]);
    assert_eq!(
        (&s["offsets"], &s["strip_vertices"]),
        (&json!([0, 4]), &json!([0, 1, 2, 3]))
    );
    let c = export_json("corner", &[]);
    assert_eq!(
        (&c["v"], &c["o"]),
        (&json!([0, 1, 2, 1, 3, 2]), &json!([4, n, n, n, 0, n]))
    );
    let h = export_json("halfedge", &[]);
    assert_eq!(h["explicit_boundary"], false);
    // The first two rows of the text layout: "1 2 -1 0 0 0" and "2 0 5 1 0 1".
    let first_two = |k: &str| json!([h[k][0], h[k][1]]);
    let columns = ["next", "prev", "twin", "tail", "face", "edge"].map(first_two);
    assert_eq!(
        json!(columns),
        json!([[1, 2], [2, 0], [n, 5], [0, 1], [0, 0], [0, 1]])
    );
    let x = export_json("halfedge", &["--explicit-boundary"]);
    assert_eq!(x["next"].as_array().unwrap().len(), 10);
    assert_eq!(x["explicit_boundary"], true);
    let w = export_json("winged", &[]);
    // The first text row: "0 1 0 -1 2 1 -1 -1".
    let first = |k: &str, len: usize| json!(w[k].as_array().unwrap()[..len]);
    assert_eq!(first("edge_vertices", 2), json!([0, 1]));
    assert_eq!(first("edge_faces", 2), json!([0, n]));
    assert_eq!(first("wings", 4), json!([2, 1, n, n]));
}

#[test]
fn json_matrices_are_the_csr_of_the_matrix_market_text() {
    for r#as in [
        "d1",
        "d2",
        "laplacian",
        "vertex-adjacency",
        "edge-adjacency",
        "dual-adjacency",
    ] {
        let m = export_json(r#as, &[]);
        let offsets: Vec<usize> = serde_json::from_value(m["offsets"].clone()).unwrap();
        let columns: Vec<usize> = serde_json::from_value(m["columns"].clone()).unwrap();
        let values: Vec<f64> = serde_json::from_value(m["values"].clone()).unwrap();
        assert_eq!(offsets.len(), m["rows"].as_u64().unwrap() as usize + 1, "{as}", as = r#as);
        let mut from_csr = Vec::new();
        for r in 0..offsets.len() - 1 {
            for k in offsets[r]..offsets[r + 1] {
                from_csr.push(format!("{} {} {}", r + 1, columns[k] + 1, values[k]));
            }
        }
        let text = export(r#as, &[]);
        let from_market: Vec<&str> = text.lines().skip(2).collect();
        assert_eq!(from_csr, from_market, "{as}", as = r#as);
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
