//! VTK legacy ASCII `.vtk`: `UNSTRUCTURED_GRID` (triangles and tetrahedra, linear or
//! quadratic; other cells skipped) and `POLYDATA` (polygons fan-triangulated, triangle strips
//! split). Cell arrays in the classic form (`k i1 .. ik`) and the 5.1 form (`OFFSETS` +
//! `CONNECTIVITY`) are both read; point and cell data are ignored. Cells skipped (other
//! types, `VERTICES`, `LINES`, polygons of fewer than 3 points) and polygons
//! fan-triangulated are counted in warnings.

use super::MeshData;
use super::text::{self, Lexer};
use super::warning::{Noun, SkippedTypes, Tally};
use crate::error::Result;
use crate::util::alloc::{try_push, try_reserve, try_with_capacity};

/// A cell array: cell `i` is `conn[offsets[i]..offsets[i + 1]]`.
struct Cells {
    offsets: Vec<usize>,
    conn: Vec<u32>,
}

impl Cells {
    fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }
    fn cell(&self, i: usize) -> &[u32] {
        match (self.offsets.get(i), self.offsets.get(i + 1)) {
            (Some(&a), Some(&b)) => self.conn.get(a..b).unwrap_or(&[]),
            _ => &[],
        }
    }
}

#[inline]
fn point_id(lx: &mut Lexer, num_points: usize) -> Result<u32> {
    lx.id("a point id", (0, num_points), |id| {
        format!("point id {id} out of range ({num_points} points)")
    })
}

/// Reads a cell array after its keyword (`CELLS`, `POLYGONS`, ...), in either form.
fn read_cells(lx: &mut Lexer, num_points: usize) -> Result<Cells> {
    let a = lx.usize("the number of cells")?;
    let b = lx.usize("the size of the cell array")?;
    if lx.peek().is_some_and(|t| t.eq_ignore_ascii_case("OFFSETS")) {
        // VTK 5.1: `a` offsets (cells + 1), `b` connectivity entries.
        lx.next();
        lx.expect("the offsets data type")?;
        let mut offsets = try_with_capacity(lx.capacity(a, 1).max(1), "the cell offsets")?;
        for i in 0..a {
            let o = lx.usize("an offset")?;
            let prev = offsets.last().copied().unwrap_or(0);
            if (i == 0 && o != 0) || o < prev || o > b {
                return Err(lx.error(format!(
                    "offset {o} (offsets start at 0 and grow up to the connectivity size {b})"
                )));
            }
            try_push(&mut offsets, o, "the cell offsets")?;
        }
        if offsets.is_empty() {
            offsets.push(0);
        }
        let last = offsets.last().copied().unwrap_or(0);
        if last != b {
            return Err(lx.error(format!("last offset {last}, connectivity size {b}")));
        }
        lx.keyword("CONNECTIVITY")?;
        lx.expect("the connectivity data type")?;
        let mut conn = try_with_capacity(lx.capacity(b, 1), "the cell connectivity")?;
        for _ in 0..b {
            try_push(
                &mut conn,
                point_id(lx, num_points)?,
                "the cell connectivity",
            )?;
        }
        Ok(Cells { offsets, conn })
    } else {
        // Classic: `a` cells, `b` numbers in all (each cell's size and its ids).
        let mut offsets =
            try_with_capacity(lx.capacity(a, 2).saturating_add(1), "the cell offsets")?;
        offsets.push(0);
        let mut conn = try_with_capacity(lx.capacity(b, 1), "the cell connectivity")?;
        let mut used = 0usize;
        for _ in 0..a {
            let k = lx.usize("a cell size")?;
            used = used.saturating_add(k).saturating_add(1);
            if used > b {
                return Err(lx.error(format!("the cells hold more than the {b} numbers declared")));
            }
            for _ in 0..k {
                try_push(
                    &mut conn,
                    point_id(lx, num_points)?,
                    "the cell connectivity",
                )?;
            }
            try_push(&mut offsets, conn.len(), "the cell offsets")?;
        }
        if used != b {
            return Err(lx.error(format!("the cells hold {used} numbers, {b} declared")));
        }
        Ok(Cells { offsets, conn })
    }
}

/// Reads `CELL_TYPES` (after the keyword) and keeps the triangles and tetrahedra of `cells`.
fn read_cell_types(
    lx: &mut Lexer, cells: &Cells, data: &mut MeshData, skipped: &mut SkippedTypes,
) -> Result<()> {
    let n = lx.usize("the number of cell types")?;
    if n != cells.len() {
        return Err(lx.error(format!("{n} cell types for {} cells", cells.len())));
    }
    for i in 0..n {
        let ty = lx.u64("a cell type")?;
        let (want, corners) = match ty {
            5 => (3, 3),
            22 => (6, 3),
            10 => (4, 4),
            24 => (10, 4),
            _ => {
                skipped.add(ty, lx.line());
                continue;
            }
        };
        let c = cells.cell(i);
        if c.len() != want {
            return Err(lx.error(format!(
                "cell {i} of type {ty} has {} points, expected {want}",
                c.len()
            )));
        }
        if corners == 3 {
            try_push(&mut data.triangles, [c[0], c[1], c[2]], "the triangles")?;
        } else {
            try_push(
                &mut data.tetrahedra,
                [c[0], c[1], c[2], c[3]],
                "the tetrahedra",
            )?;
        }
    }
    Ok(())
}

/// Skips a 5.1 `METADATA` block: up to the first blank line.
fn skip_metadata(lx: &mut Lexer) {
    lx.skip_line();
    while let Some(line) = lx.next_line() {
        if line.trim().is_empty() {
            break;
        }
    }
}

/// Skips `FIELD name n` and its `n` arrays.
fn skip_field(lx: &mut Lexer) -> Result<()> {
    lx.expect("a field name")?;
    let n = lx.usize("the number of arrays")?;
    for _ in 0..n {
        if lx.expect("an array name")? == "NULL_ARRAY" {
            continue;
        }
        let comps = lx.usize("the number of components")?;
        let tuples = lx.usize("the number of tuples")?;
        lx.expect("a data type")?;
        let Some(total) = comps.checked_mul(tuples) else {
            return Err(lx.error(format!("an array of {comps} x {tuples} values")));
        };
        lx.skip(total, "an array value")?;
        if lx
            .peek()
            .is_some_and(|t| t.eq_ignore_ascii_case("METADATA"))
        {
            lx.next();
            skip_metadata(lx);
        }
    }
    Ok(())
}

/// The two datasets read: their cell arrays differ.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Dataset {
    /// `CELLS` then `CELL_TYPES`.
    UnstructuredGrid,
    /// `POLYGONS`, `TRIANGLE_STRIPS`, `VERTICES`, `LINES`.
    PolyData,
}

/// Parses the text of a legacy `.vtk` file; `name` is used in error messages.
pub(crate) fn parse(text: &str, name: &str) -> Result<MeshData> {
    let mut lx = Lexer::new(text, name, false);
    let dataset = read_header(&mut lx)?;
    let mut sections = Sections {
        dataset,
        data: MeshData::default(),
        have_points: false,
        have_cells: false,
        pending: None,
        skipped: SkippedTypes::default(),
        tally: Tally::default(),
    };
    while let Some(kw) = lx.next() {
        if kw.eq_ignore_ascii_case("POINT_DATA") || kw.eq_ignore_ascii_case("CELL_DATA") {
            break;
        }
        sections.read(&mut lx, kw)?;
    }
    if let Some((_, line)) = sections.pending {
        return Err(lx.error_at(line, "CELLS without CELL_TYPES"));
    }
    let mut data = sections.data;
    sections
        .skipped
        .into_warnings(name, cell_noun, &mut data.warnings);
    sections.tally.into_warnings(name, &mut data.warnings);
    Ok(data)
}

/// Reads the magic line, the title, the encoding and the dataset type.
fn read_header(lx: &mut Lexer) -> Result<Dataset> {
    const MAGIC: &str = "# vtk DataFile Version";
    let first = lx.next_line().unwrap_or("").trim_start();
    if !first
        .get(..MAGIC.len())
        .is_some_and(|s| s.eq_ignore_ascii_case(MAGIC))
    {
        return Err(lx.error(format!("not a legacy VTK file (no '{MAGIC}' line)")));
    }
    if lx.next_line().is_none() {
        return Err(lx.error("unexpected end of file, expected the title line"));
    }
    let enc = lx.expect("ASCII or BINARY")?;
    if enc.eq_ignore_ascii_case("BINARY") {
        return Err(lx.error("binary .vtk not supported (save as ASCII)"));
    } else if !enc.eq_ignore_ascii_case("ASCII") {
        return Err(lx.bad("ASCII or BINARY", enc));
    }
    lx.keyword("DATASET")?;
    let kind = lx.expect("a dataset type")?;
    if kind.eq_ignore_ascii_case("UNSTRUCTURED_GRID") {
        Ok(Dataset::UnstructuredGrid)
    } else if kind.eq_ignore_ascii_case("POLYDATA") {
        Ok(Dataset::PolyData)
    } else {
        Err(lx.error(format!(
            "dataset {} not supported (UNSTRUCTURED_GRID and POLYDATA are read)",
            text::quote(kind)
        )))
    }
}

/// The sections after the header, read one keyword at a time.
struct Sections {
    dataset: Dataset,
    data: MeshData,
    have_points: bool,
    have_cells: bool,
    /// CELLS read, waiting for their CELL_TYPES (with the line of the keyword).
    pending: Option<(Cells, usize)>,
    /// Cell types skipped (unstructured grid).
    skipped: SkippedTypes,
    /// Polydata cells skipped or fan-triangulated.
    tally: Tally,
}

impl Sections {
    /// Reads the section that keyword `kw` starts.
    fn read(&mut self, lx: &mut Lexer, kw: &str) -> Result<()> {
        let is = |k: &str| kw.eq_ignore_ascii_case(k);
        let grid = self.dataset == Dataset::UnstructuredGrid;
        let is_cell_array = if grid {
            is("CELLS")
        } else {
            is("POLYGONS") || is("TRIANGLE_STRIPS") || is("VERTICES") || is("LINES")
        };
        if is("POINTS") {
            self.points(lx)
        } else if is_cell_array {
            self.cell_array(lx, kw)
        } else if grid && is("CELL_TYPES") {
            let Some((cells, _)) = self.pending.take() else {
                return Err(lx.error("CELL_TYPES before CELLS"));
            };
            read_cell_types(lx, &cells, &mut self.data, &mut self.skipped)
        } else if is("METADATA") {
            skip_metadata(lx);
            Ok(())
        } else if is("FIELD") {
            skip_field(lx)
        } else {
            Err(lx.error(format!("unexpected keyword '{}'", text::quote(kw))))
        }
    }

    fn points(&mut self, lx: &mut Lexer) -> Result<()> {
        if self.have_points {
            return Err(lx.error("a second POINTS section"));
        }
        self.have_points = true;
        let n = lx.point_count("the number of points")?;
        lx.expect("the points' data type")?;
        let positions = &mut self.data.positions;
        try_reserve(positions, lx.capacity(n, 3), "the points")?;
        for _ in 0..n {
            try_push(positions, lx.point()?, "the points")?;
        }
        Ok(())
    }

    /// `CELLS` (kept until `CELL_TYPES`) or a POLYDATA cell array (triangulated now).
    fn cell_array(&mut self, lx: &mut Lexer, kw: &str) -> Result<()> {
        if !self.have_points {
            return Err(lx.error(format!("{kw} before POINTS")));
        }
        let grid = self.dataset == Dataset::UnstructuredGrid;
        if grid && self.have_cells {
            return Err(lx.error("a second CELLS section"));
        }
        self.have_cells = true;
        let line = lx.line();
        let cells = read_cells(lx, self.data.positions.len())?;
        let tally = &mut self.tally;
        if grid {
            self.pending = Some((cells, line));
        } else if kw.eq_ignore_ascii_case("POLYGONS") {
            fan_polygons(&cells, &mut self.data.triangles, (tally, line))?;
        } else if kw.eq_ignore_ascii_case("TRIANGLE_STRIPS") {
            split_strips(&cells, &mut self.data.triangles, (tally, line))?;
        } else if kw.eq_ignore_ascii_case("VERTICES") {
            tally.add_n(VERTEX_CELLS, cells.len() as u64, Some(line));
        } else {
            tally.add_n(LINE_CELLS, cells.len() as u64, Some(line));
        }
        Ok(())
    }
}

/// What a skipped unstructured-grid cell type is, for its warning.
fn cell_noun(ty: u64) -> Noun {
    match ty {
        1 | 2 => ("vertex cell", "vertex cells"),
        3 | 4 | 21 => ("line cell", "line cells"),
        6..=9 | 23 => ("polygon or quad cell", "polygon or quad cells"),
        11 | 12 | 25 => ("hexahedron", "hexahedra"),
        13 | 26 => ("wedge", "wedges"),
        14 | 27 => ("pyramid", "pyramids"),
        _ => ("cell of another type", "cells of another type"),
    }
}

const VERTEX_CELLS: Noun = ("VERTICES cell ignored", "VERTICES cells ignored");
const LINE_CELLS: Noun = ("LINES cell ignored", "LINES cells ignored");
const SHORT: Noun = (
    "polygon or strip of fewer than 3 points ignored",
    "polygons or strips of fewer than 3 points ignored",
);
const FANNED: Noun = (
    "polygon of more than 3 vertices fan-triangulated",
    "polygons of more than 3 vertices fan-triangulated",
);

/// Fan-triangulates every polygon: (c0, c1, c2), (c0, c2, c3), ...; counts the polygons
/// fanned and those too short, at the line of their section.
fn fan_polygons(
    cells: &Cells, out: &mut Vec<[u32; 3]>, (tally, line): (&mut Tally, usize),
) -> Result<()> {
    for i in 0..cells.len() {
        let c = cells.cell(i);
        if c.len() != 3 {
            tally.add(if c.len() < 3 { SHORT } else { FANNED }, Some(line));
        }
        for j in 2..c.len() {
            try_push(out, [c[0], c[j - 1], c[j]], "the triangles")?;
        }
    }
    Ok(())
}

/// Splits every triangle strip, every other triangle turned to keep one orientation;
/// counts the strips too short.
fn split_strips(
    cells: &Cells, out: &mut Vec<[u32; 3]>, (tally, line): (&mut Tally, usize),
) -> Result<()> {
    for i in 0..cells.len() {
        let c = cells.cell(i);
        if c.len() < 3 {
            tally.add(SHORT, Some(line));
        }
        for j in 2..c.len() {
            let t = if j % 2 == 0 {
                [c[j - 2], c[j - 1], c[j]]
            } else {
                [c[j - 1], c[j - 2], c[j]]
            };
            try_push(out, t, "the triangles")?;
        }
    }
    Ok(())
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind::Parse;
    use crate::io::text::{assert_errors, utf8, warning_lines};
    use glam::DVec3;

    /// A tet, a triangle, a quadratic tet and triangle, and a vertex, a line and a hex to skip;
    /// point coordinates wrap lines anyhow.
    pub(in crate::io) const LEGACY: &str = "\
# vtk DataFile Version 2.0
mixed cells

ASCII
DATASET UNSTRUCTURED_GRID
POINTS 10 float
0 0 0 1 0 0 0 1 0
0 0 1
1 1 1 2 2 2 3 3 3 4 4 4 5 5
5 6
6 6
CELLS 7 41
4 0 1 2 3
3 0 1 2
10 1 2 3 4 5 6 7 8 9 0
6 0 1 2 5 6 7
1 9
2 8 9
8 0 1 2 3 4 5 6 7
CELL_TYPES 7
10
5
24
22
1
3
12
POINT_DATA 10
SCALARS s float 1
LOOKUP_TABLE default
0 1 2 3 4 5 6 7 8 9
";

    pub(in crate::io) const V51: &str = "\
# vtk DataFile Version 5.1
vtk output
ASCII
DATASET UNSTRUCTURED_GRID
FIELD FieldData 2
TIME 1 1 double
0.5
CYCLE 1 1 int
3
POINTS 5 double
0 0 0 1 0 0 0 1 0
0 0 1 1 1 1
METADATA
INFORMATION 0

CELLS 4 11
OFFSETS vtktypeint64
0 4 8 11
CONNECTIVITY vtktypeint64
0 1 2 3 1 2 3 4
0 1 2
CELL_TYPES 3
10
10
5

CELL_DATA 3
";

    pub(in crate::io) const POLY: &str = "\
# vtk DataFile Version 3.0
surface
ASCII
DATASET POLYDATA
POINTS 6 float
0 0 0 1 0 0 1 1 0 0 1 0 2 0 0 2 1 0
VERTICES 1 2
1 5
LINES 1 3
2 0 1
POLYGONS 3 12
4 0 1 2 3
3 1 4 5
2 0 1
TRIANGLE_STRIPS 1 5
4 0 1 3 2
";

    #[test]
    fn reads_legacy_mixed_cells() {
        let d = parse(LEGACY, "v.vtk").unwrap();
        assert_eq!(d.positions.len(), 10);
        assert_eq!(d.positions[3], DVec3::new(0.0, 0.0, 1.0));
        assert_eq!(d.positions[8], DVec3::splat(5.0));
        assert_eq!(d.positions[9], DVec3::splat(6.0));
        assert_eq!(d.tetrahedra, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
        assert_eq!(d.triangles, vec![[0, 1, 2], [0, 1, 2]]);
    }

    #[test]
    fn reads_v51_offsets_form() {
        let d = parse(V51, "v.vtk").unwrap();
        assert_eq!(d.positions.len(), 5);
        assert_eq!(d.positions[4], DVec3::splat(1.0));
        assert_eq!(d.tetrahedra, vec![[0, 1, 2, 3], [1, 2, 3, 4]]);
        assert_eq!(d.triangles, vec![[0, 1, 2]]);
    }

    #[test]
    fn reads_polydata() {
        let d = parse(POLY, "v.vtk").unwrap();
        assert_eq!(d.positions.len(), 6);
        assert!(d.tetrahedra.is_empty());
        assert_eq!(
            d.triangles,
            vec![[0, 1, 2], [0, 2, 3], [1, 4, 5], [0, 1, 3], [3, 1, 2]]
        );
    }

    #[test]
    fn skipped_cells_and_polygons_are_reported() {
        assert_eq!(
            warning_lines(&parse(LEGACY, "v.vtk").unwrap()),
            [
                "v.vtk:25: 1 vertex cell ignored (type 1)",
                "v.vtk:26: 1 line cell ignored (type 3)",
                "v.vtk:27: 1 hexahedron ignored (type 12)",
            ]
        );
        assert_eq!(
            warning_lines(&parse(POLY, "v.vtk").unwrap()),
            [
                "v.vtk:7: 1 VERTICES cell ignored",
                "v.vtk:9: 1 LINES cell ignored",
                "v.vtk:11: 1 polygon of more than 3 vertices fan-triangulated",
                "v.vtk:11: 1 polygon or strip of fewer than 3 points ignored",
            ]
        );
    }

    #[test]
    fn bad_input_names_the_line() {
        let legacy = |from: &str, to: &str| LEGACY.replace(from, to);
        let v51 = |from: &str, to: &str| V51.replace(from, to);
        let head = "# vtk DataFile Version 3.0";
        #[rustfmt::skip]
        let cases = [
            (format!("{head}\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n"), "v.vtk:3: binary .vtk not supported (save as ASCII)"),
            ("ply\nformat ascii 1.0\n".into(), "v.vtk:1: not a legacy VTK file"),
            (format!("{head}\nt\nASCII\nDATASET STRUCTURED_POINTS\n"), "v.vtk:4: dataset STRUCTURED_POINTS not supported"),
            (head.into(), "v.vtk:1: unexpected end of file"),
            (format!("{head}\ntitle\n"), "v.vtk:3: unexpected end of file, expected ASCII"),
            (legacy("6 0 1 2 5 6 7", "6 0 1 2 5 6 10"), "v.vtk:16: point id 10 out of range (10 points)"),
            (v51("0 1 2\nCELL_TYPES", "0 1 5\nCELL_TYPES"), "v.vtk:21: point id 5 out of range (5 points)"),
            (legacy("CELLS 7 41", "CELLS 7 42"), "v.vtk:19: the cells hold 41 numbers, 42 declared"),
            (legacy("CELLS 7 41", "CELLS 7 30"), "v.vtk:18: the cells hold more than the 30"),
            (legacy("CELL_TYPES 7\n10\n5", "CELL_TYPES 7\n5\n10"), "v.vtk:21: cell 0 of type 5 has 4 points, expected 3"),
            (legacy("CELL_TYPES 7", "CELL_TYPES 6"), "v.vtk:20: 6 cell types for 7 cells"),
            (v51("0 4 8 11", "0 8 4 11"), "v.vtk:18: offset 4"),
            (v51("0 4 8 11", "0 4 8 10"), "v.vtk:18: last offset 10, connectivity size 11"),
            (v51("CELL_TYPES 3\n10\n10\n5\n", ""), "v.vtk:16: CELLS without CELL_TYPES"),
            (LEGACY[..LEGACY.find("5 6\n6 6").unwrap()].into(), "v.vtk:10: unexpected end of file"),
            (legacy("0 0 1\n", "0 0 one\n"), "v.vtk:8: expected a coordinate, found 'one'"),
            (POLY.replace("VERTICES", "VERTEXES"), "v.vtk:7: unexpected keyword 'VERTEXES'"),
            (legacy("POINTS 10 float", "POINTS 3000000000 float"), "v.vtk:12: expected a coordinate, found 'CELLS'"),
            (legacy("CELLS 7 41", "CELLS 18446744073709551615 41"), "v.vtk:20: expected a cell size, found 'CELL_TYPES'"),
        ];
        assert_errors(
            |b| parse(utf8(b), "v.vtk"),
            cases.map(|(input, start)| (input, Parse, start)),
        );
    }
}
