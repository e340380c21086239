//! The TetGen reader (a `.node` and an `.ele` file) on arbitrary bytes: the input is split
//! at its first NUL byte into the two files, written to a temporary folder, and read by
//! path, as TetGen meshes are only read from paths.
#![no_main]

mod common;

use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

fn dir() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("topomesh-fuzz-tetgen-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        dir
    })
}

fuzz_target!(|data: &[u8]| {
    let (node, ele) = match data.iter().position(|&b| b == 0) {
        Some(i) => (&data[..i], &data[i + 1..]),
        None => (data, &[][..]),
    };
    let stem = dir().join("fuzz");
    std::fs::write(stem.with_extension("node"), node).expect("write .node");
    std::fs::write(stem.with_extension("ele"), ele).expect("write .ele");
    if let Ok(mesh) = topomesh::io::read(&stem.with_extension("node")) {
        common::check_mesh(&mesh);
    }
});
