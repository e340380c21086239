//! `topomesh refine`: every tetrahedron below the bound, the total volume and the topology
//! of the ball kept.

mod common;

use common::{temp, text, topomesh};

/// The unit cube in 5 tetrahedra, as a Medit file.
const CUBE: &str = "MeshVersionFormatted 1\nDimension 3\nVertices\n8\n\
0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n0 0 1 0\n1 0 1 0\n0 1 1 0\n1 1 1 0\n\
Tetrahedra\n5\n1 2 3 5 0\n4 3 2 8 0\n6 2 5 8 0\n7 5 3 8 0\n2 3 5 8 0\nEnd\n";

#[test]
fn refine_splits_below_the_bound_and_keeps_the_ball() {
    let src = temp("refine-cube.mesh", CUBE);
    let dst = src.with_file_name("refine-cube-fine.mesh");
    let (s, d) = (src.to_str().unwrap(), dst.to_str().unwrap());
    let out = topomesh(&["refine", s, d, "--max-volume", "0.01"]);
    let (stdout, stderr) = text(&out);
    assert!(out.status.success(), "{stderr}");
    assert!(stdout.contains(": 5 -> "), "{stdout}");
    assert!(stdout.contains("euler 1 manifold true"), "{stdout}");
    let text = std::fs::read_to_string(&dst).unwrap();
    let words: Vec<&str> = text.split_whitespace().collect();
    let at = |key: &str| words.iter().position(|w| *w == key).unwrap();
    let nv: usize = words[at("Vertices") + 1].parse().unwrap();
    let xyz: Vec<[f64; 3]> = (0..nv)
        .map(|i| {
            let b = at("Vertices") + 2 + 4 * i;
            [0, 1, 2].map(|k| words[b + k].parse().unwrap())
        })
        .collect();
    let nt: usize = words[at("Tetrahedra") + 1].parse().unwrap();
    assert!(nt > 5 * 16, "{nt}");
    let mut total = 0.0;
    for t in 0..nt {
        let b = at("Tetrahedra") + 2 + 5 * t;
        let p: Vec<[f64; 3]> = (0..4)
            .map(|k| xyz[words[b + k].parse::<usize>().unwrap() - 1])
            .collect();
        let d = |i: usize, k: usize| p[i][k] - p[0][k];
        let v = (d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1))
            - d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0))
            + d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0)))
            / 6.0;
        assert!(v > 0.0 && v < 0.01, "tetrahedron {t}: volume {v}");
        total += v;
    }
    assert!((total - 1.0).abs() < 1e-9, "{total}");
    assert!(topomesh(&["check", d]).status.success());
    let out = topomesh(&["refine", s, d, "--max-volume", "-1"]);
    assert!(!out.status.success());
}
