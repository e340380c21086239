//! `topomesh simplify`: the triangle count reached, the topology of a closed surface kept.

mod common;

use common::{temp, text, topomesh};

#[test]
fn simplify_reaches_the_count_and_keeps_the_genus() {
    let src = temp(
        "simplify-torus.off",
        &topomesh::generate::to_off(&topomesh::generate::torus(24, 16)),
    );
    let dst = src.with_file_name("simplify-torus-small.off");
    let (s, d) = (src.to_str().unwrap(), dst.to_str().unwrap());
    let out = topomesh(&["simplify", s, d, "--triangles", "200"]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert!(stdout.contains("768 -> "), "{stdout}");
    let out = topomesh(&["info", "--json", d]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let triangles = json["triangles"].as_u64().unwrap();
    assert!((150..=200).contains(&triangles), "{triangles}");
    assert_eq!(json["genus"], 1);
    assert_eq!(json["manifold"], true);
    assert!(topomesh(&["check", d]).status.success());
    let out = topomesh(&["simplify", s, d, "--ratio", "0.5"]);
    assert!(out.status.success());
    let out = topomesh(&["simplify", s, d, "--ratio", "2"]);
    assert!(!out.status.success());
}
