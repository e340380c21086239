//! Medit / INRIA `.mesh` (ASCII): vertices, triangles and tetrahedra (1-based ids); every
//! other section the library knows the entry size of is skipped, with a warning when it
//! holds elements (edges, quadrilaterals, hexahedra, ...). Text after `End` is reported.

use super::MeshData;
use super::text::{self, Lexer};
use super::warning::Warning;
use crate::error::{Error, Result};
use crate::util::alloc::{try_push, try_reserve};
use glam::DVec3;

/// Tokens per entry of the sections that are skipped, for a mesh of dimension `dim`
/// (from libMeshb's keyword table), or `None` for a keyword not known.
fn entry_tokens(keyword: &str, dim: usize) -> Option<usize> {
    const TABLE: &[(&str, usize)] = &[
        ("Edges", 3),
        ("Quadrilaterals", 5),
        ("Prisms", 7),
        ("Pentahedra", 7),
        ("Hexahedra", 9),
        ("Pyramids", 6),
        ("Corners", 1),
        ("Ridges", 1),
        ("RequiredVertices", 1),
        ("RequiredEdges", 1),
        ("RequiredTriangles", 1),
        ("RequiredQuadrilaterals", 1),
        ("TangentAtEdgeVertices", 3),
        ("NormalAtVertices", 2),
        ("NormalAtTriangleVertices", 3),
        ("NormalAtQuadrilateralVertices", 4),
        ("TangentAtVertices", 2),
        ("EdgesP2", 4),
        ("QuadrilateralsQ2", 10),
        ("HexahedraQ2", 28),
        ("VerticesOnGeometricVertices", 2),
        ("VerticesOnGeometricEdges", 4),
        ("VerticesOnGeometricTriangles", 5),
        ("VerticesOnGeometricQuadrilaterals", 5),
        ("EdgesOnGeometricEdges", 2),
        ("TrianglesOnGeometricTriangles", 2),
        ("TrianglesOnGeometricQuadrilaterals", 2),
        ("QuadrilateralsOnGeometricTriangles", 2),
        ("QuadrilateralsOnGeometricQuadrilaterals", 2),
    ];
    if keyword.eq_ignore_ascii_case("Normals") || keyword.eq_ignore_ascii_case("Tangents") {
        return Some(dim);
    }
    TABLE
        .iter()
        .find(|(k, _)| k.eq_ignore_ascii_case(keyword))
        .map(|&(_, n)| n)
}

/// The skipped sections that hold elements (the others hold attributes of what is read):
/// skipping them is reported.
const IGNORED_ELEMENTS: &[&str] = &[
    "Edges",
    "Quadrilaterals",
    "Prisms",
    "Pentahedra",
    "Hexahedra",
    "Pyramids",
    "EdgesP2",
    "QuadrilateralsQ2",
    "HexahedraQ2",
];

/// A section of elements that start with their vertex ids.
struct Elements {
    /// The keyword, as error messages name it.
    keyword: &'static str,
    /// Tokens per element (the ids, then the reference and any higher-order nodes).
    tokens: usize,
}

const TRIANGLES: [Elements; 2] = [
    Elements {
        keyword: "Triangles",
        tokens: 4,
    },
    Elements {
        keyword: "TrianglesP2",
        tokens: 7,
    },
];

const TETRAHEDRA: [Elements; 2] = [
    Elements {
        keyword: "Tetrahedra",
        tokens: 5,
    },
    Elements {
        keyword: "TetrahedraP2",
        tokens: 11,
    },
];

/// The section of `list` that `keyword` names.
fn section_named<'a>(list: &'a [Elements], keyword: &str) -> Option<&'a Elements> {
    list.iter()
        .find(|e| e.keyword.eq_ignore_ascii_case(keyword))
}

impl Elements {
    /// Reads the count and the elements, keeping the first `K` tokens (1-based vertex ids)
    /// of each.
    fn read<const K: usize>(
        &self, lx: &mut Lexer, num_vertices: usize, out: &mut Vec<[u32; K]>,
    ) -> Result<()> {
        let keyword = self.keyword;
        let n = lx.usize(&format!("the number of {keyword}"))?;
        if n > 0 && num_vertices == 0 {
            return Err(lx.error(format!("{keyword} before (or without) Vertices")));
        }
        try_reserve(out, lx.capacity(n, self.tokens), keyword)?;
        let out_of_range =
            |id| format!("vertex id {id} out of range 1..={num_vertices} in {keyword}");
        for _ in 0..n {
            try_push(
                out,
                lx.ids("a vertex id", (1, num_vertices), out_of_range)?,
                keyword,
            )?;
            lx.skip(self.tokens - K, "the rest of an element")?;
        }
        Ok(())
    }
}

/// Parses the text of a `.mesh` file; `name` is used in error messages.
pub(crate) fn parse(text: &str, name: &str) -> Result<MeshData> {
    let mut lx = Lexer::new(text, name, true);
    let mut sections = Sections {
        data: MeshData::default(),
        dim: 3,
        have_vertices: false,
    };
    // Nothing but blanks and comments is not a mesh file at all: say so rather than give
    // back an empty mesh.
    let Some(first) = lx.next() else {
        let msg = format!("{name}: empty file (no keyword; expected 'MeshVersionFormatted')");
        return Err(Error::parse(msg));
    };
    let mut pending = Some(first);
    while let Some(kw) = pending.take().or_else(|| lx.next()) {
        if kw.eq_ignore_ascii_case("End") {
            if let Some(t) = lx.next() {
                let msg = format!("text after 'End', from '{}' (ignored)", text::quote(t));
                sections.data.warnings.push(lx.warning(msg));
            }
            break;
        }
        sections.read(&mut lx, kw)?;
    }
    Ok(sections.data)
}

/// The sections read so far.
struct Sections {
    data: MeshData,
    /// From `Dimension`: 2 or 3.
    dim: usize,
    have_vertices: bool,
}

impl Sections {
    /// Reads the section that keyword `kw` starts.
    fn read(&mut self, lx: &mut Lexer, kw: &str) -> Result<()> {
        let is = |k: &str| kw.eq_ignore_ascii_case(k);
        let nv = self.data.positions.len();
        if is("MeshVersionFormatted") {
            let v = lx.u64("the format version")?;
            if !(1..=4).contains(&v) {
                return Err(lx.error(format!("unknown MeshVersionFormatted {v}")));
            }
        } else if is("Dimension") {
            let d = lx.usize("the dimension")?;
            if d != 2 && d != 3 {
                return Err(lx.error(format!("dimension {d} (only 2 and 3 are read)")));
            }
            self.dim = d;
        } else if is("Vertices") {
            self.vertices(lx)?;
        } else if let Some(e) = section_named(&TRIANGLES, kw) {
            e.read(lx, nv, &mut self.data.triangles)?;
        } else if let Some(e) = section_named(&TETRAHEDRA, kw) {
            e.read(lx, nv, &mut self.data.tetrahedra)?;
        } else {
            self.skip(lx, kw)?;
        }
        Ok(())
    }

    fn vertices(&mut self, lx: &mut Lexer) -> Result<()> {
        if self.have_vertices {
            return Err(lx.error("a second Vertices section"));
        }
        self.have_vertices = true;
        let n = lx.point_count("the number of vertices")?;
        let positions = &mut self.data.positions;
        try_reserve(positions, lx.capacity(n, self.dim + 1), "the vertices")?;
        for _ in 0..n {
            let p = if self.dim == 3 {
                lx.point()?
            } else {
                DVec3::new(lx.f64("a coordinate")?, lx.f64("a coordinate")?, 0.0)
            };
            try_push(positions, p, "the vertices")?;
            lx.expect("a vertex reference")?;
        }
        Ok(())
    }

    /// Skips a section the library knows the size of; any other keyword is an error.
    fn skip(&mut self, lx: &mut Lexer, kw: &str) -> Result<()> {
        let is = |k: &str| kw.eq_ignore_ascii_case(k);
        if is("AngleOfCornerBound") || is("Iterations") || is("Time") {
            lx.expect("a value")?;
        } else if is("BoundingBox") {
            lx.skip(2 * self.dim, "a bounding box coordinate")?;
        } else if let Some(k) = entry_tokens(kw, self.dim) {
            let line = lx.line();
            let n = lx.usize(&format!("the number of {kw}"))?;
            for _ in 0..n {
                lx.skip(k, kw)?;
            }
            if n > 0 && IGNORED_ELEMENTS.iter().any(|e| e.eq_ignore_ascii_case(kw)) {
                let msg = format!("{n} {kw} ignored (only Triangles and Tetrahedra are read)");
                self.data
                    .warnings
                    .push(Warning::new(lx.name(), Some(line), msg));
            }
        } else {
            return Err(lx.error(format!(
                "unknown keyword '{}' (or an entry count that does not match the entries)",
                text::quote(kw)
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind::Parse;
    use crate::io::text::{assert_errors, utf8};

    pub(in crate::io) const CUBE_CORNER: &str = "\
MeshVersionFormatted 2
# a comment line
Dimension
3
Vertices
5
0 0 0 1
1 0 0 1   # trailing comment
0 1 0 1
0 0 1 2
1 1 1 2
Edges 2
1 2 0
2 3 0
Corners 1 1
Ridges
1
2
Normals 1
0 0 1
NormalAtVertices 1
1 1
Triangles
2
1 2 3 7
2 3 4 7
Quadrilaterals 1
1 2 3 4 0
Tetrahedra 2
1 2 3 4 0
2 3 4 5 1
Hexahedra 1
1 2 3 4 5 1 2 3 0
End
";

    #[test]
    fn reads_with_skipped_sections() {
        let d = parse(CUBE_CORNER, "m.mesh").unwrap();
        assert_eq!(d.positions.len(), 5);
        assert_eq!(d.positions[4], DVec3::new(1.0, 1.0, 1.0));
        assert_eq!(d.triangles, vec![[0, 1, 2], [1, 2, 3]]);
        assert_eq!(d.tetrahedra, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
    }

    #[test]
    fn reads_dimension_2_and_p2_elements() {
        let t = "MeshVersionFormatted 1 Dimension 2\nVertices 3\n0 0 0\n1 0 0\n0 2 0\n\
                 TrianglesP2 1\n1 2 3 1 2 3 0\nBoundingBox 0 1 0 2\nEnd";
        let d = parse(t, "m.mesh").unwrap();
        assert_eq!(d.positions[2], DVec3::new(0.0, 2.0, 0.0));
        assert_eq!(d.triangles, vec![[0, 1, 2]]);
        assert!(d.tetrahedra.is_empty());
    }

    #[test]
    fn skipped_elements_and_text_after_end_are_reported() {
        let t = CUBE_CORNER.replace("End\n", "End\n\nVertices 1\n0 0 0 0\n");
        let d = parse(&t, "m.mesh").unwrap();
        assert_eq!(d.tetrahedra.len(), 2);
        let w: Vec<String> = d.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(
            w,
            [
                "m.mesh:12: 2 Edges ignored (only Triangles and Tetrahedra are read)",
                "m.mesh:27: 1 Quadrilaterals ignored (only Triangles and Tetrahedra are read)",
                "m.mesh:32: 1 Hexahedra ignored (only Triangles and Tetrahedra are read)",
                "m.mesh:36: text after 'End', from 'Vertices' (ignored)",
            ]
        );
    }

    #[test]
    fn a_file_without_a_keyword_is_not_an_empty_mesh() {
        let empty = "m.mesh: empty file (no keyword; expected 'MeshVersionFormatted')";
        assert_errors(
            |b| parse(utf8(b), "m.mesh"),
            [
                ("", Parse, empty),
                ("\n  # only a comment\n\n", Parse, empty),
            ],
        );
        // A file that starts with a keyword is read as before.
        assert!(parse("MeshVersionFormatted 2\nEnd\n", "m.mesh").is_ok());
    }

    #[test]
    fn bad_vertex_id_names_the_line() {
        let t = CUBE_CORNER.replace("2 3 4 5 1", "2 3 4 6 1");
        assert_errors(
            |b| parse(utf8(b), "m.mesh"),
            [(t, Parse, "m.mesh:31: vertex id 6 out of range 1..=5")],
        );
    }
}
