//! Running the `topomesh` binary and the meshes the CLI tests feed it.

#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

pub fn topomesh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_topomesh"))
        .args(args)
        .output()
        .expect("run topomesh")
}

pub fn text(out: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Writes `contents` to `name` in a directory of this test process; its path.
pub fn temp(name: &str, contents: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topomesh-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// `n` bowties (two triangles sharing only their apex), apart: `n` non-manifold vertices,
/// the apexes 0, 5, 10, ...
pub fn bowties(n: usize) -> String {
    let mut v = String::new();
    let mut f = String::new();
    for i in 0..n {
        let x = 10.0 * i as f64;
        for (dx, dy) in [(0., 0.), (1., 0.), (1., 1.), (-1., 0.), (-1., -1.)] {
            v += &format!("{} {dy} 0\n", x + dx);
        }
        let b = 5 * i;
        f += &format!("3 {b} {} {}\n3 {b} {} {}\n", b + 1, b + 2, b + 3, b + 4);
    }
    format!("OFF\n{} {} 0\n{v}{f}", 5 * n, 2 * n)
}
