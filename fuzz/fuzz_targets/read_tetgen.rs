//! The TetGen reader (a `.node` and an `.ele` file) on arbitrary bytes: the input is split
//! at its first NUL byte into the two files, written beside each other, and read by
//! path, as TetGen meshes are only read from paths.
#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;

/// The stem of this process's own two files (libFuzzer may run several processes), removed
/// at the end of each input: libFuzzer ends a process without unwinding, so nothing later
/// would.
fn stem() -> PathBuf {
    std::env::temp_dir().join(format!("topomesh-fuzz-tetgen-{}", std::process::id()))
}

fuzz_target!(|data: &[u8]| {
    let (node, ele) = match data.iter().position(|&b| b == 0) {
        Some(i) => (&data[..i], &data[i + 1..]),
        None => (data, &[][..]),
    };
    let (node_path, ele_path) = (stem().with_extension("node"), stem().with_extension("ele"));
    std::fs::write(&node_path, node).expect("write .node");
    std::fs::write(&ele_path, ele).expect("write .ele");
    if let Ok(mesh) = topomesh::io::read(&node_path) {
        common::check_mesh(&mesh);
    }
    let _ = std::fs::remove_file(&node_path);
    let _ = std::fs::remove_file(&ele_path);
});
