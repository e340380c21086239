//! How to build a CHE.

/// How to build: the level (0..=3) and whether non-manifold input is an error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuildOptions {
    pub level: u8,
    /// Reject non-manifold edges, non-manifold vertices and duplicate triangles instead of
    /// repairing them.
    pub strict: bool,
    /// Threads for the build: 0 (the default) for as many as the machine runs at once, 1
    /// for the calling thread alone. The structure is the same whatever the number.
    pub threads: usize,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            level: 2,
            strict: false,
            threads: 0,
        }
    }
}

impl BuildOptions {
    pub fn level(level: u8) -> Self {
        BuildOptions {
            level,
            ..Self::default()
        }
    }
}

/// Largest triangle count whose half-edge ids fit below `NONE`.
pub const MAX_TRIANGLES: usize = (u32::MAX as usize) / 3;
