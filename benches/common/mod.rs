//! What both benchmarks share.

/// Where the meshes are: $TOPOMESH_MESH_DIR, else the cache the fetch scripts fill.
pub fn mesh_dir() -> std::path::PathBuf {
    match std::env::var_os("TOPOMESH_MESH_DIR") {
        Some(dir) => dir.into(),
        None => std::path::Path::new(&std::env::var_os("HOME").unwrap_or_default())
            .join(".cache/topomesh/meshes"),
    }
}
