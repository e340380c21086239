//! TetGen `.node` + `.ele`: points and tetrahedra (4- or 10-node; ids 0- or 1-based, as the
//! first point says). Given either file, both are read.

use super::MeshData;
use super::text::{self, Lexer};
use super::warning::Warning;
use crate::error::{Error, Result};
use crate::util::alloc::{try_push, try_with_capacity};
use glam::DVec3;
use std::path::{Path, PathBuf};

/// Parses a `.node` file: the points, and the id base (the first point's id, 0 or 1).
/// A warning comes with them when text follows the declared points.
pub(crate) fn parse_node(text: &str, name: &str) -> Result<(Vec<DVec3>, u64, Option<Warning>)> {
    let mut lx = Lexer::new(text, name, true);
    let n = lx.point_count("the number of points")?;
    let dim = lx.u64("the dimension")?;
    if dim != 3 {
        return Err(lx.error(format!("dimension {dim} (only 3 is read)")));
    }
    let nattr = lx.usize("the number of attributes")?;
    let markers = lx.u64("the boundary marker flag (0 or 1)")?;
    if markers > 1 {
        return Err(lx.error(format!("boundary marker flag {markers} (0 or 1)")));
    }
    let extra = nattr.saturating_add(markers as usize);
    let mut positions = try_with_capacity(lx.capacity(n, extra.saturating_add(4)), "the points")?;
    let mut base = 0;
    for i in 0..n as u64 {
        let id = lx.u64("a point id")?;
        if i == 0 {
            if id > 1 {
                return Err(lx.error(format!("first point id {id} (ids start at 0 or 1)")));
            }
            base = id;
        } else if id != base + i {
            return Err(lx.error(format!("point id {id}, expected {}", base + i)));
        }
        try_push(&mut positions, lx.point()?, "the points")?;
        lx.skip(extra, "a point attribute or marker")?;
    }
    Ok((positions, base, trailing(&mut lx, "points")))
}

/// A warning for any token after the `count` declared (`what`: points or tetrahedra).
fn trailing(lx: &mut Lexer, what: &str) -> Option<Warning> {
    let t = lx.next()?;
    Some(lx.warning(format!(
        "text after the declared {what}, from '{}' (ignored)",
        text::quote(t)
    )))
}

/// Parses an `.ele` file over `num_points` points numbered from `base`; a warning comes
/// with the tetrahedra when text follows the declared ones.
pub(crate) fn parse_ele(
    text: &str, name: &str, num_points: usize, base: u64,
) -> Result<(Vec<[u32; 4]>, Option<Warning>)> {
    let mut lx = Lexer::new(text, name, true);
    let n = lx.usize("the number of tetrahedra")?;
    let per = lx.usize("the number of nodes per tetrahedron (4 or 10)")?;
    if per != 4 && per != 10 {
        return Err(lx.error(format!("{per} nodes per tetrahedron (4 or 10)")));
    }
    let nattr = lx.usize("the number of attributes")?;
    let extra = (per - 4).saturating_add(nattr);
    let mut tets = try_with_capacity(lx.capacity(n, extra.saturating_add(5)), "the tetrahedra")?;
    let out_of_range =
        |id| format!("node id {id} out of range ({num_points} points numbered from {base})");
    for _ in 0..n {
        lx.expect("a tetrahedron id")?;
        try_push(
            &mut tets,
            lx.ids("a node id", (base, num_points), out_of_range)?,
            "the tetrahedra",
        )?;
        lx.skip(extra, "a node id or attribute")?;
    }
    Ok((tets, trailing(&mut lx, "tetrahedra")))
}

/// Parses a `.node` and an `.ele` text (names for error messages).
pub(crate) fn parse(node: &str, node_name: &str, ele: &str, ele_name: &str) -> Result<MeshData> {
    let (positions, base, node_warning) = parse_node(node, node_name)?;
    let (tetrahedra, ele_warning) = parse_ele(ele, ele_name, positions.len(), base)?;
    Ok(MeshData {
        positions,
        tetrahedra,
        warnings: node_warning.into_iter().chain(ele_warning).collect(),
        ..MeshData::default()
    })
}

/// The `.node` and `.ele` paths next to `path` (extension case kept: `.NODE` -> `.ELE`).
pub(super) fn sibling_paths(path: &Path) -> (PathBuf, PathBuf) {
    let upper = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| !e.is_empty() && e.bytes().all(|b| b.is_ascii_uppercase()));
    if upper {
        (path.with_extension("NODE"), path.with_extension("ELE"))
    } else {
        (path.with_extension("node"), path.with_extension("ele"))
    }
}

/// Reads a TetGen mesh from its `.node` or `.ele` path (both files must exist).
pub fn read(path: &Path) -> Result<MeshData> {
    let (node_path, ele_path) = sibling_paths(path);
    for p in [&node_path, &ele_path] {
        if !p.is_file() {
            return Err(Error::io(format!(
                "{}: missing file: a TetGen mesh needs both {} and {}",
                p.display(),
                node_path.display(),
                ele_path.display()
            )));
        }
    }
    let node = text::read_text(&node_path)?;
    let ele = text::read_text(&ele_path)?;
    parse(
        &node,
        &node_path.display().to_string(),
        &ele,
        &ele_path.display().to_string(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const NODE1: &str = "# tetgen output\n5 3 0 1\n1 0 0 0 1\n2 1 0 0 1\n3 0 1 0 1\n\
                         4 0 0 1 0  # marker 0\n5 1 1 1 0\n";
    const ELE1: &str = "2 4 1\n1 1 2 3 4 -1\n2 2 3 4 5 -1\n# end\n";

    fn write_pair(tag: &str, node: &str, ele: Option<&str>) -> (PathBuf, PathBuf) {
        let node_path = text::temp_path(tag, "1.node");
        let ele_path = node_path.with_extension("ele");
        std::fs::write(&node_path, node).unwrap();
        if let Some(ele) = ele {
            std::fs::write(&ele_path, ele).unwrap();
        }
        (node_path, ele_path)
    }

    #[test]
    fn reads_one_based_files_from_either_path() {
        let (np, ep) = write_pair("tg1", NODE1, Some(ELE1));
        let a = super::super::read(&np);
        let b = super::super::read(&ep);
        std::fs::remove_file(&np).unwrap();
        std::fs::remove_file(&ep).unwrap();
        let a = a.unwrap();
        assert_eq!(a.positions.len(), 5);
        assert_eq!(a.positions[3], DVec3::new(0.0, 0.0, 1.0));
        assert_eq!(a.tetrahedra, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
        assert!(a.triangles.is_empty());
        assert_eq!(b.unwrap(), a);
    }

    #[test]
    fn reads_zero_based_with_attributes() {
        let node = "4 3 2 0\n0 0 0 0 9 9\n1 1 0 0 9 9\n2 0 1 0 9 9\n3 0 0 1.5e0 9 9\n";
        let ele = "1 4 0\n0 3 2 1 0\n";
        let d = parse(node, "a.node", ele, "a.ele").unwrap();
        assert_eq!(d.positions[3], DVec3::new(0.0, 0.0, 1.5));
        assert_eq!(d.tetrahedra, vec![[3, 2, 1, 0]]);
    }

    #[test]
    fn reads_ten_node_tets() {
        let node = "10 3 0 0\n".to_string()
            + &(1..=10)
                .map(|i| format!("{i} {i} 0 0\n"))
                .collect::<String>();
        let ele = "1 10 0\n1 4 3 2 1 5 6 7 8 9 10\n";
        let d = parse(&node, "a.node", ele, "a.ele").unwrap();
        assert_eq!(d.positions.len(), 10);
        assert_eq!(d.tetrahedra, vec![[3, 2, 1, 0]]);
    }

    #[test]
    fn text_after_the_declared_points_and_tetrahedra_is_reported() {
        let d = parse(
            &(NODE1.to_string() + "6 2 2 2 0\n"),
            "a.node",
            &(ELE1.to_string() + "\n3 1 2 3 5 -1\n"),
            "a.ele",
        )
        .unwrap();
        assert_eq!(d.positions.len(), 5);
        assert_eq!(d.tetrahedra.len(), 2);
        let w: Vec<String> = d.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(
            w,
            [
                "a.node:8: text after the declared points, from '6' (ignored)",
                "a.ele:6: text after the declared tetrahedra, from '3' (ignored)",
            ]
        );
    }

    #[test]
    fn missing_ele_is_named() {
        let (np, ep) = write_pair("tg-missing", NODE1, None);
        let e = read(&np).unwrap_err();
        std::fs::remove_file(&np).unwrap();
        assert!(
            e.message.starts_with(&ep.display().to_string()),
            "{}",
            e.message
        );
        assert!(e.message.contains("missing file"), "{}", e.message);
    }

    #[test]
    fn prefixes_and_mutations_never_panic() {
        // A damaged .node can make the .ele wrong too.
        text::assert_robust(NODE1, "a.", |t| parse(t, "a.node", ELE1, "a.ele"));
        text::assert_robust(ELE1, "a.ele:", |t| parse(NODE1, "a.node", t, "a.ele"));
    }
}
