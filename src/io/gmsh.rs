//! Gmsh `.msh`, ASCII versions 2.x and 4.1: nodes, triangles and tetrahedra (corner nodes of
//! the higher-order ones); other elements are skipped with a warning per type, other
//! sections (physical names, data) without one. Node tags may be sparse:
//! they are numbered 0.. in order of appearance.

use super::MeshData;
use super::text::{self, Lexer};
use super::warning::{Noun, SkippedTypes, Warning};
use crate::error::Result;
use crate::util::alloc::{try_hash_map, try_push, try_vec, try_with_capacity};
use glam::DVec3;
use std::collections::HashMap;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Version {
    V2,
    V41,
}

/// Number of nodes of a Gmsh element type, for the types Gmsh documents.
fn nodes_per_element(ty: u64) -> Option<usize> {
    const NODES: [usize; 32] = [
        0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10, 12, 15, 15, 21,
        4, 5, 6, 20, 35, 56,
    ];
    match ty {
        1..=31 => Some(NODES[ty as usize]),
        92 => Some(64),
        93 => Some(125),
        _ => None,
    }
}

/// What an element type we skip is, for its warning.
fn type_noun(ty: u64) -> Noun {
    match ty {
        15 => ("point element", "point elements"),
        1 | 8 | 26..=28 => ("line element", "line elements"),
        3 | 10 | 16 => ("quadrangle", "quadrangles"),
        5 | 12 | 17 => ("hexahedron", "hexahedra"),
        6 | 13 | 18 => ("prism", "prisms"),
        7 | 14 | 19 => ("pyramid", "pyramids"),
        _ => ("element of another type", "elements of another type"),
    }
}

/// What a type contributes: 3 corners (triangles of any order) or 4 (tetrahedra of any order).
fn corners(ty: u64) -> usize {
    match ty {
        2 | 9 | 20..=25 => 3,
        4 | 11 | 29..=31 => 4,
        _ => 0,
    }
}

/// Node tag -> 0-based id.
enum TagMap {
    Dense(Vec<u32>),
    Sparse(HashMap<u64, u32>),
}

impl TagMap {
    /// Numbers `tags` in order; a repeated tag is an error (reported at `line`).
    fn new(tags: &[u64], lx: &Lexer, line: usize) -> Result<TagMap> {
        let dup = |t: u64| lx.error_at(line, format!("node tag {t} appears twice in $Nodes"));
        let max = tags.iter().copied().max().unwrap_or(0);
        if max <= 2 * tags.len() as u64 + 1024 {
            let mut map = try_vec(max as usize + 1, u32::MAX, "the node tag map")?;
            for (i, &t) in tags.iter().enumerate() {
                let slot = &mut map[t as usize];
                if *slot != u32::MAX {
                    return Err(dup(t));
                }
                *slot = i as u32;
            }
            Ok(TagMap::Dense(map))
        } else {
            let mut map = try_hash_map(tags.len(), "the node tag map")?;
            for (i, &t) in tags.iter().enumerate() {
                if map.insert(t, i as u32).is_some() {
                    return Err(dup(t));
                }
            }
            Ok(TagMap::Sparse(map))
        }
    }

    #[inline]
    fn get(&self, tag: u64) -> Option<u32> {
        match self {
            TagMap::Dense(v) => v.get(tag as usize).copied().filter(|&i| i != u32::MAX),
            TagMap::Sparse(m) => m.get(&tag).copied(),
        }
    }
}

/// Reads a `$Nodes` section body (after the keyword, up to `$EndNodes` excluded).
fn read_nodes(lx: &mut Lexer, version: Version) -> Result<(Vec<DVec3>, Vec<u64>)> {
    let (blocks, n) = match version {
        Version::V2 => (None, lx.point_count("the number of nodes")?),
        Version::V41 => {
            let blocks = lx.usize("the number of entity blocks")?;
            let n = lx.point_count("the number of nodes")?;
            skip_tag_range(lx, "node")?;
            (Some(blocks), n)
        }
    };
    let cap = lx.capacity(n, 4);
    let mut pos = try_with_capacity(cap, "the node positions")?;
    let mut tags = try_with_capacity(cap, "the node tags")?;
    let Some(blocks) = blocks else {
        // 2.x: one list of `tag x y z`.
        for _ in 0..n {
            try_push(&mut tags, lx.u64("a node tag")?, "the node tags")?;
            try_push(&mut pos, lx.point()?, "the node positions")?;
        }
        return Ok((pos, tags));
    };
    // 4.1: blocks of `count` tags, then their `count` points.
    for _ in 0..blocks {
        let dim = entity_dimension(lx)?;
        let parametric = lx.u64("the parametric flag (0 or 1)")?;
        if parametric > 1 {
            return Err(lx.error(format!("parametric flag {parametric} (0 or 1)")));
        }
        let count = lx.usize("the number of nodes in the block")?;
        if count > n - tags.len() {
            return Err(lx.error(format!("the blocks hold more than the {n} nodes declared")));
        }
        for _ in 0..count {
            try_push(&mut tags, lx.u64("a node tag")?, "the node tags")?;
        }
        let extra = (parametric * dim) as usize;
        for _ in 0..count {
            try_push(&mut pos, lx.point()?, "the node positions")?;
            lx.skip(extra, "a parametric coordinate")?;
        }
    }
    if tags.len() != n {
        return Err(lx.error(format!(
            "the blocks hold {} nodes, {n} declared",
            tags.len()
        )));
    }
    Ok((pos, tags))
}

/// Skips the smallest and the largest tag of a 4.1 section (`kind`: node or element).
fn skip_tag_range(lx: &mut Lexer, kind: &str) -> Result<()> {
    lx.u64(&format!("the smallest {kind} tag"))?;
    lx.u64(&format!("the largest {kind} tag"))?;
    Ok(())
}

/// The header of a 4.1 entity block up to its tag: the entity's dimension (0 to 3).
fn entity_dimension(lx: &mut Lexer) -> Result<u64> {
    let dim = lx.u64("an entity dimension")?;
    if dim > 3 {
        return Err(lx.error(format!("entity dimension {dim}")));
    }
    lx.expect("an entity tag")?;
    Ok(dim)
}

/// The mesh read so far, and the element types skipped.
struct Read {
    data: MeshData,
    skipped: SkippedTypes,
}

/// Reads the nodes of one element of type `ty`, keeping its corners if it is a triangle or
/// a tetrahedron; an unknown type is skipped to the end of its line. Skipped elements are
/// counted.
#[inline]
fn read_element(lx: &mut Lexer, ty: u64, map: &TagMap, read: &mut Read) -> Result<()> {
    let k = corners(ty);
    if k == 0 {
        read.skipped.add(ty, lx.line());
    }
    let Some(n) = nodes_per_element(ty) else {
        lx.skip_line();
        return Ok(());
    };
    let data = &mut read.data;
    let mut ids = [0u32; 4];
    for id in ids.iter_mut().take(k) {
        let tag = lx.u64("a node tag")?;
        *id = map
            .get(tag)
            .ok_or_else(|| lx.error(format!("unknown node tag {tag}")))?;
    }
    lx.skip(n - k, "a node tag")?;
    match k {
        3 => try_push(
            &mut data.triangles,
            [ids[0], ids[1], ids[2]],
            "the triangles",
        ),
        4 => try_push(&mut data.tetrahedra, ids, "the tetrahedra"),
        _ => Ok(()),
    }
}

/// Reads an `$Elements` section body.
fn read_elements(lx: &mut Lexer, version: Version, map: &TagMap, read: &mut Read) -> Result<()> {
    match version {
        Version::V2 => {
            let n = lx.usize("the number of elements")?;
            for _ in 0..n {
                lx.u64("an element tag")?;
                let ty = lx.u64("an element type")?;
                let ntags = lx.usize("the number of element tags")?;
                lx.skip(ntags, "an element tag")?;
                read_element(lx, ty, map, read)?;
            }
        }
        Version::V41 => {
            let blocks = lx.usize("the number of entity blocks")?;
            let declared = lx.usize("the number of elements")?;
            let line = lx.line();
            skip_tag_range(lx, "element")?;
            let mut held = 0usize;
            for _ in 0..blocks {
                entity_dimension(lx)?;
                let ty = lx.u64("an element type")?;
                let count = lx.usize("the number of elements in the block")?;
                held = held.saturating_add(count);
                for _ in 0..count {
                    lx.u64("an element tag")?;
                    read_element(lx, ty, map, read)?;
                }
            }
            if held != declared {
                let msg =
                    format!("the blocks hold {held} elements, {declared} declared (all read)");
                read.data
                    .warnings
                    .push(Warning::new(lx.name(), Some(line), msg));
            }
        }
    }
    Ok(())
}

/// Reads a `$MeshFormat` section body and its end: the version, in ASCII.
fn read_format(lx: &mut Lexer) -> Result<Version> {
    let v = lx.expect("the format version")?;
    let version = if v == "2" || v.starts_with("2.") {
        Version::V2
    } else if v == "4.1" {
        Version::V41
    } else {
        return Err(lx.error(format!(
            "unsupported .msh version {} (2.x and 4.1 are read)",
            text::quote(v)
        )));
    };
    match lx.u64("the file type (0 = ASCII)")? {
        0 => {}
        1 => return Err(lx.error("binary .msh not supported (save as ASCII)")),
        t => return Err(lx.error(format!("unknown file type {t}"))),
    }
    lx.expect("the data size")?;
    lx.keyword("$EndMeshFormat")?;
    Ok(version)
}

/// Parses the text of a `.msh` file; `name` is used in error messages.
pub(crate) fn parse(text: &str, name: &str) -> Result<MeshData> {
    let mut lx = Lexer::new(text, name, false);
    let mut version = None;
    let mut map = None;
    let mut read = Read {
        data: MeshData::default(),
        skipped: SkippedTypes::default(),
    };
    while let Some(tok) = lx.next() {
        let start = lx.line();
        match tok {
            "$MeshFormat" => version = Some(read_format(&mut lx)?),
            "$Nodes" => {
                let Some(v) = version else {
                    return Err(lx.error("$Nodes before $MeshFormat"));
                };
                if map.is_some() {
                    return Err(lx.error("a second $Nodes section"));
                }
                let (positions, tags) = read_nodes(&mut lx, v)?;
                lx.keyword("$EndNodes")?;
                map = Some(TagMap::new(&tags, &lx, start)?);
                read.data.positions = positions;
            }
            "$Elements" => {
                let (Some(v), Some(m)) = (version, &map) else {
                    return Err(lx.error("$Elements before $MeshFormat and $Nodes"));
                };
                read_elements(&mut lx, v, m, &mut read)?;
                lx.keyword("$EndElements")?;
            }
            _ if tok.starts_with('$') && version.is_some() => {
                let section = tok.get(1..).unwrap_or("");
                loop {
                    match lx.next() {
                        Some(t) if t.strip_prefix("$End") == Some(section) => break,
                        Some(_) => {}
                        None => {
                            return Err(lx.error_at(
                                start,
                                format!("section ${0} has no $End{0}", text::quote(section)),
                            ));
                        }
                    }
                }
            }
            _ => {
                let what = if version.is_some() {
                    "a $Section"
                } else {
                    "$MeshFormat"
                };
                return Err(lx.bad(what, tok));
            }
        }
    }
    if version.is_none() {
        return Err(lx.error("no $MeshFormat: not a Gmsh file"));
    }
    let mut data = read.data;
    read.skipped
        .into_warnings(name, type_noun, &mut data.warnings);
    Ok(data)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind::Parse;
    use crate::io::text::{assert_errors, utf8, warning_lines};

    /// Two tets and a boundary triangle over sparse tags, plus a point, a line, a quad, a
    /// 10-node tet and a 6-node triangle, and sections to skip.
    pub(in crate::io) const V22: &str = "\
$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
2 1 \"skin surface\"
3 2 \"volume\"
$EndPhysicalNames
$Nodes
6
10 0 0 0
20 1 0 0
30 0 1 0
40 0 0 1
1000000 1 1 1
7 0.5 0.5 0.5
$EndNodes
$Elements
7
1 15 2 0 1 10
2 1 2 0 1 10 20
3 2 2 1 1 10 20 30
4 3 2 0 1 10 20 30 40
5 4 2 2 1 10 20 30 40
6 11 3 2 1 0 20 30 40 1000000 7 7 7 7 7 7
7 9 2 0 1 10 30 40 7 7 7
$EndElements
$NodeData
1
\"a view\"
0
$EndNodeData
";

    pub(in crate::io) const V41: &str = "\
$MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
1 0 0 1
1 0 0 0 0
1 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
3 6 5 900
0 1 0 1
5
0 0 0
2 1 1 3
6
9
10
1 0 0 0.25 0.75
0 1 0 0.5 0.5
0 0 1 0.75 0.25
3 1 0 2
800
900
1 1 1
0.5 0.5 0.5
$EndNodes
$Elements
4 5 1 5
0 1 15 1
1 5
2 1 2 1
2 5 6 9
3 1 4 2
3 5 6 9 10
4 6 9 10 800
3 1 7 1
5 5 6 9 10 800
$EndElements
";

    #[test]
    fn reads_v22_and_v41_sparse_tags_blocks_and_skipped_types() {
        let (v22, v41) = (parse(V22, "g.msh").unwrap(), parse(V41, "g.msh").unwrap());
        for d in [&v22, &v41] {
            assert_eq!(d.positions.len(), 6);
            assert_eq!(d.positions[5], DVec3::splat(0.5));
            // In 4.1, type 7 (pyramid) is skipped.
            assert_eq!(d.tetrahedra, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
        }
        assert_eq!(v22.positions[4], DVec3::new(1.0, 1.0, 1.0));
        assert_eq!(v22.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(v41.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(v41.triangles, vec![[0, 1, 2]]);
    }

    #[test]
    fn skipped_element_types_are_reported() {
        assert_eq!(
            warning_lines(&parse(V22, "g.msh").unwrap()),
            [
                "g.msh:20: 1 point element ignored (type 15)",
                "g.msh:21: 1 line element ignored (type 1)",
                "g.msh:23: 1 quadrangle ignored (type 3)",
            ]
        );
        assert_eq!(
            warning_lines(&parse(V41, "g.msh").unwrap()),
            [
                "g.msh:30: 1 point element ignored (type 15)",
                "g.msh:37: 1 pyramid ignored (type 7)",
            ]
        );
        let t = V22.replace("1 15 2 0 1 10\n", "1 99 2 0 1 10 20 30\n");
        assert_eq!(
            warning_lines(&parse(&t, "g.msh").unwrap())[0],
            "g.msh:20: 1 element of another type ignored (type 99)"
        );
    }

    #[test]
    fn a_wrong_element_total_is_reported() {
        let d = parse(&V41.replace("4 5 1 5", "4 6 1 5"), "g.msh").unwrap();
        assert_eq!(d.tetrahedra.len(), 2);
        assert_eq!(
            d.warnings[0].to_string(),
            "g.msh:28: the blocks hold 5 elements, 6 declared (all read)"
        );
    }

    #[test]
    fn reads_v2_from_file() {
        let d = text::read_temp("msh", V22.replace('\n', "\r\n"));
        assert_eq!(d.unwrap().tetrahedra.len(), 2);
    }

    #[test]
    fn bad_input_names_the_line() {
        let v22 = |from: &str, to: &str| V22.replace(from, to);
        let v41 = |from: &str, to: &str| V41.replace(from, to);
        let cut = |end: &str, more: usize| V22[..V22.find(end).unwrap() + more].to_string();
        #[rustfmt::skip]
        let cases = [
            (v22("5 4 2 2 1 10 20 30 40", "5 4 2 2 1 10 20 31 40"), "g.msh:24: unknown node tag 31"),
            (v41("4 6 9 10 800", "4 6 9 10 801"), "g.msh:35: unknown node tag 801"),
            (v22("7 0.5 0.5 0.5", "40 0.5 0.5 0.5"), "g.msh:9: node tag 40 appears twice"),
            ("$MeshFormat\n4.1 1 8\n\u{1}\u{0}\u{0}\u{0}\n$EndMeshFormat\n".into(), "g.msh:2: binary .msh not supported (save as ASCII)"),
            ("$MeshFormat\n4 0 8\n$EndMeshFormat\n".into(), "g.msh:2: unsupported .msh version 4"),
            ("hello".into(), "g.msh:1: expected $MeshFormat, found 'hello'"),
            ("\n\n".into(), "g.msh:3: no $MeshFormat"),
            (cut("$EndElements", 0), "g.msh:27: unexpected end of file, expected $EndElements"),
            (cut("40 0 0 1", 6), "g.msh:14: unexpected end of file"),
            (v22("$EndNodeData\n", ""), "g.msh:28: section $NodeData has no $EndNodeData"),
            (v41("0.5 0.5 0.5", "0.5 0.5 half"), "g.msh:25: expected a coordinate, found 'half'"),
            (v41("3 6 5 900", "3 7 5 900"), "g.msh:25: the blocks hold 6 nodes, 7 declared"),
            (v22("\n6\n10 0 0 0", "\n4000000000\n10 0 0 0"), "g.msh:17: expected a node tag, found '$EndNodes'"),
            (v22("\n7\n1 15", "\n99999999999999\n1 15"), "g.msh:27: expected an element tag"),
        ];
        assert_errors(
            |b| parse(utf8(b), "g.msh"),
            cases.map(|(input, start)| (input, Parse, start)),
        );
    }

    #[test]
    fn huge_sparse_tags_use_a_map() {
        let t = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n18446744073709551615 0 0 0\n\
                 5 1 0 0\n4000000000 0 1 0\n$EndNodes\n$Elements\n1\n\
                 1 2 0 4000000000 5 18446744073709551615\n$EndElements\n";
        let d = parse(t, "g.msh").unwrap();
        assert_eq!(d.triangles, vec![[2, 1, 0]]);
    }
}
