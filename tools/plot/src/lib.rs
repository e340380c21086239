//! The charts of the benchmark pages (BENCHMARKS.md, BENCHMARKS-volumes.md), written as SVG
//! from the results the benchmark scripts extract. A tool of the repository, not part of
//! the library: it has no dependencies and the library does not depend on it.

pub mod charts;
pub mod results;
pub mod svg;

use std::path::{Path, PathBuf};

/// Writes `<prefix>-memory.svg`, `<prefix>-build.svg` and `<prefix>-ratios.svg` into `dir`;
/// returns their paths.
pub fn write_charts(
    res: &results::Results, dir: &Path, prefix: &str, element: &str,
) -> Result<Vec<PathBuf>, String> {
    let labels = charts::Labels { element };
    let made = [
        ("memory", charts::memory_chart(res, &labels)?),
        ("build", charts::build_chart(res, &labels)?),
        ("ratios", charts::ratio_chart(res)?),
    ];
    let mut paths = Vec::new();
    for (name, svg) in made {
        let path = dir.join(format!("{prefix}-{name}.svg"));
        std::fs::write(&path, svg).map_err(|e| format!("{}: {e}", path.display()))?;
        paths.push(path);
    }
    Ok(paths)
}
