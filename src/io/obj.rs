//! Wavefront OBJ: our own line reader (positions and faces).
//!
//! Vertices keep the numbering of the file: vertex `k` is the `k`-th `v` line, whether a
//! face uses it or not, so ids printed by the library are the file's ids minus one, and
//! isolated vertices survive. Positions are read as `f64`. (tobj, used before, renumbered
//! vertices by first use, dropped unused ones and read `f32`: a topology library must not.)
//!
//! Accepted: `v x y z [w]` and `v x y z r g b` (the first three numbers are the position);
//! `f` with corners `v`, `v/vt`, `v//vn`, `v/vt/vn`, negative (relative) indices, polygons
//! fan-triangulated (i1,i2,i3), (i1,i3,i4), ... (counted in a warning); `\` at the end of a
//! line continues it; `#` comments; a UTF-8 byte order mark. The statements that carry
//! nothing we store (`vt`, `vn`, `vp`, `o`, `g`, `s`, `usemtl`, `mtllib`, the free-form
//! attributes) are skipped; groups therefore never cut the surface apart. Elements we do not
//! store (`l`, `p`, `curv`, `curv2`, `surf`) and unknown statements are skipped with a
//! warning. A file of vertices and no faces is a point set; a file with neither is refused
//! (nothing in it shows it is OBJ). Errors name the file and line.

use super::MeshData;
use super::warning::{Noun, Tally};
use crate::error::{Error, ErrorKind, Result};
use crate::util::alloc::{try_extend, try_push};
use glam::DVec3;

/// Parses OBJ from memory; `name` (usually the file name) prefixes every error.
pub(crate) fn parse(bytes: &[u8], name: &str) -> Result<MeshData> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let mut statements = Statements {
        name,
        data: MeshData::default(),
        forward: Vec::new(),
        corners: Vec::new(),
        tally: Tally::default(),
    };
    let mut joined: Vec<u8> = Vec::new();
    let mut lines = bytes.split(|&c| c == b'\n').enumerate();
    while let Some((i, raw)) = lines.next() {
        let line = logical_line(trim_cr(raw), &mut lines, &mut joined)?;
        statements.read(i + 1, line)?;
    }
    statements.finish()
}

/// `line`, or, when it ends with `\`, `line` joined with the lines that continue it (taken
/// from `rest`) into `joined`.
fn logical_line<'j, 'b: 'j>(
    line: &'b [u8], rest: &mut impl Iterator<Item = (usize, &'b [u8])>, joined: &'j mut Vec<u8>,
) -> Result<&'j [u8]> {
    const WHAT: &str = "a continued line";
    let Some(head) = line.strip_suffix(b"\\") else {
        return Ok(line);
    };
    joined.clear();
    try_extend(joined, head.iter().copied(), WHAT)?;
    for (_, more) in rest {
        let more = trim_cr(more);
        try_push(joined, b' ', WHAT)?;
        match more.strip_suffix(b"\\") {
            Some(head) => try_extend(joined, head.iter().copied(), WHAT)?,
            None => {
                try_extend(joined, more.iter().copied(), WHAT)?;
                break;
            }
        }
    }
    Ok(joined)
}

/// The statements read so far.
struct Statements<'a> {
    name: &'a str,
    data: MeshData,
    /// Faces naming a vertex not read yet: legal if the file defines it later.
    forward: Vec<(usize, u64)>,
    /// The corners of the face being read.
    corners: Vec<u32>,
    /// What was skipped or fan-triangulated.
    tally: Tally,
}

/// Statements that carry nothing we store: skipped without a word.
const ATTRIBUTES: &[&[u8]] = &[
    b"vt",
    b"vn",
    b"vp",
    b"o",
    b"g",
    b"s",
    b"usemtl",
    b"mtllib",
    b"cstype",
    b"deg",
    b"bmat",
    b"step",
    b"parm",
    b"trim",
    b"hole",
    b"scrv",
    b"sp",
    b"end",
    b"con",
    b"mg",
    b"bevel",
    b"c_interp",
    b"d_interp",
    b"lod",
    b"shadow_obj",
    b"trace_obj",
    b"ctech",
    b"stech",
    b"maplib",
    b"usemap",
];

/// Elements we do not store, each with its warning.
const ELEMENTS: &[(&[u8], Noun)] = &[
    (
        b"l",
        (
            "'l' statement (polyline) ignored",
            "'l' statements (polylines) ignored",
        ),
    ),
    (
        b"p",
        (
            "'p' statement (points) ignored",
            "'p' statements (points) ignored",
        ),
    ),
    (
        b"curv",
        (
            "'curv' statement (curve) ignored",
            "'curv' statements (curves) ignored",
        ),
    ),
    (
        b"curv2",
        (
            "'curv2' statement (curve) ignored",
            "'curv2' statements (curves) ignored",
        ),
    ),
    (
        b"surf",
        (
            "'surf' statement (surface) ignored",
            "'surf' statements (surfaces) ignored",
        ),
    ),
];

const LONG_VERTEX: Noun = (
    "'v' line with values other than 'w' or 'r g b' after the position (ignored)",
    "'v' lines with values other than 'w' or 'r g b' after the position (ignored)",
);

const UNKNOWN: Noun = ("unknown statement ignored", "unknown statements ignored");

/// Polygons of more than 3 vertices, fan-triangulated.
const FANNED: Noun = (
    "polygon of more than 3 vertices fan-triangulated",
    "polygons of more than 3 vertices fan-triangulated",
);

impl Statements<'_> {
    /// Reads the statement on line `line_no` (comments included); keeps `v` and `f`.
    fn read(&mut self, line_no: usize, line: &[u8]) -> Result<()> {
        let line = line.split(|&c| c == b'#').next().unwrap_or(&[]);
        let mut words = line
            .split(|c| c.is_ascii_whitespace())
            .filter(|w| !w.is_empty());
        match words.next() {
            Some(b"v") => self.vertex(line_no, words),
            Some(b"f") => self.face(line_no, words),
            Some(word) => {
                if let Some(&(_, noun)) = ELEMENTS.iter().find(|(k, _)| *k == word) {
                    self.tally.add(noun, Some(line_no));
                } else if !ATTRIBUTES.contains(&word) {
                    self.tally.add(UNKNOWN, Some(line_no));
                }
                Ok(())
            }
            None => Ok(()),
        }
    }

    fn err(&self, line_no: usize, msg: String) -> Error {
        Error::parse(format!("{}:{line_no}: {msg}", self.name))
    }

    fn vertex<'w>(
        &mut self, line_no: usize, mut words: impl Iterator<Item = &'w [u8]>,
    ) -> Result<()> {
        let mut p = [0.0f64; 3];
        for (k, slot) in p.iter_mut().enumerate() {
            let w = words.next().ok_or_else(|| {
                self.err(line_no, format!("a vertex needs 3 coordinates, found {k}"))
            })?;
            *slot = number(w).ok_or_else(|| {
                self.err(
                    line_no,
                    format!("expected a coordinate, found '{}'", quote(w)),
                )
            })?;
        }
        let mut extra = 0;
        for w in words {
            if number(w).is_none() {
                return Err(self.err(
                    line_no,
                    format!("expected a number after the position, found '{}'", quote(w)),
                ));
            }
            extra += 1;
        }
        // After the position: nothing, `w`, or a colour `r g b`; anything else is unknown.
        if ![0, 1, 3].contains(&extra) {
            self.tally.add(LONG_VERTEX, Some(line_no));
        }
        if self.data.positions.len() == u32::MAX as usize {
            return Err(Error::too_large(format!(
                "{}:{line_no}: more than {} vertices",
                self.name,
                u32::MAX - 1
            )));
        }
        try_push(
            &mut self.data.positions,
            DVec3::from_array(p),
            "the vertices",
        )
    }

    /// A polygon, fan-triangulated (i1,i2,i3), (i1,i3,i4), ...
    fn face<'w>(&mut self, line_no: usize, words: impl Iterator<Item = &'w [u8]>) -> Result<()> {
        self.corners.clear();
        let n = self.data.positions.len() as u64;
        for w in words {
            let index = corner(w, n).map_err(|msg| self.err(line_no, msg))?;
            if index >= n {
                try_push(
                    &mut self.forward,
                    (line_no, index),
                    "the forward references",
                )?;
            }
            try_push(
                &mut self.corners,
                index.min(u32::MAX as u64) as u32,
                "a face's corners",
            )?;
        }
        let corners = &self.corners;
        if corners.len() < 3 {
            return Err(self.err(
                line_no,
                format!(
                    "face has {} vertices; a face needs at least 3",
                    corners.len()
                ),
            ));
        }
        if corners.len() > 3 {
            self.tally.add(FANNED, Some(line_no));
        }
        for k in 1..corners.len() - 1 {
            let t = [corners[0], corners[k], corners[k + 1]];
            try_push(&mut self.data.triangles, t, "the triangles")?;
        }
        Ok(())
    }

    /// Checks the forward references and that there is a vertex.
    fn finish(mut self) -> Result<MeshData> {
        let name = self.name;
        let n = self.data.positions.len() as u64;
        if let Some(&(line_no, index)) = self.forward.iter().find(|&&(_, index)| index >= n) {
            return Err(Error::new(
                ErrorKind::OutOfRange,
                format!(
                    "{name}:{line_no}: face vertex {} is out of range (the file has {n} vertices)",
                    index + 1
                ),
            ));
        }
        if self.data.positions.is_empty() {
            return Err(Error::parse(format!(
                "{name}: no vertices ('v' lines) and no faces: empty, or not an OBJ file"
            )));
        }
        self.tally.into_warnings(name, &mut self.data.warnings);
        Ok(self.data)
    }
}

fn trim_cr(line: &[u8]) -> &[u8] {
    line.strip_suffix(b"\r").unwrap_or(line)
}

fn number(word: &[u8]) -> Option<f64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// The 0-based vertex of a face corner `v[/vt[/vn]]`; `n` vertices were read so far
/// (negative indices count back from there).
fn corner(word: &[u8], n: u64) -> std::result::Result<u64, String> {
    let bad = || {
        format!(
            "expected a face corner v, v/vt, v//vn or v/vt/vn, found '{}'",
            quote(word)
        )
    };
    let mut parts = word.split(|&c| c == b'/');
    let index: i64 = parts
        .next()
        .and_then(|p| std::str::from_utf8(p).ok()?.parse().ok())
        .ok_or_else(bad)?;
    let mut count = 1;
    for p in parts {
        count += 1;
        let ok = p.is_empty() || std::str::from_utf8(p).is_ok_and(|s| s.parse::<i64>().is_ok());
        if count > 3 || !ok {
            return Err(bad());
        }
    }
    match index {
        0 => Err("face vertex 0: OBJ indices start at 1 (or count back from -1)".into()),
        i if i > 0 => Ok(i as u64 - 1),
        i => n.checked_sub(i.unsigned_abs()).ok_or_else(|| {
            format!("face vertex {i} reaches before the first vertex ({n} read so far)")
        }),
    }
}

fn quote(word: &[u8]) -> String {
    let text = String::from_utf8_lossy(word);
    match text.char_indices().nth(40) {
        Some((end, _)) => format!("{}...", &text[..end]),
        None => text.into_owned(),
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind::Parse;
    use crate::io::text::{self, assert_errors, warning_lines as warnings};
    use std::path::Path;

    fn p(bytes: &[u8]) -> Result<MeshData> {
        parse(bytes, "t.obj")
    }

    /// A unit cube as 6 quads, each face in its own group with its own material.
    pub(in crate::io) const CUBE: &str = "# cube\nmtllib cube.mtl\no cube\n\
        v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n\
        vt 0 0\nvn 0 0 1\n\
        g bottom\nusemtl a\nf 1 3 4 2\ng top\nusemtl b\nf 5/1 6/1 8/1 7/1\n\
        g front\nf 1//1 2//1 6//1 5//1\ng back\nf 3 7 8 4\n\
        g left\nf 1 5 7 3\ng right\ns 1\nf 2/1/1 4/1/1 8/1/1 6/1/1\nl 1 2 3\n";

    #[test]
    fn cube_groups_stay_connected_in_file_numbering() {
        let m = p(CUBE.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 8);
        assert_eq!(m.positions[3], DVec3::new(1.0, 1.0, 0.0));
        // First face, fan-triangulated in file numbering minus one.
        assert_eq!(&m.triangles[..2], &[[0, 2, 3], [0, 3, 1]]);
        assert_eq!(m.triangles[11], [1, 7, 5]);
        assert_eq!(m.triangles.len(), 12);
        let mut edges = std::collections::HashMap::new();
        for t in &m.triangles {
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        assert_eq!(edges.len(), 18);
        assert!(edges.values().all(|&n| n == 2));
    }

    #[test]
    fn unused_vertices_keep_their_ids_and_positions_are_f64() {
        let m = p(b"v 9 9 9\nv 0 0 0.1\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 2 3 4\n").unwrap();
        assert_eq!(m.positions.len(), 5);
        assert_eq!(m.triangles, vec![[1, 2, 3]]);
        assert_eq!(m.positions[1].z, 0.1);
    }

    #[test]
    fn pentagon_is_fanned_and_relative_indices_work() {
        let m = p(
            "\u{feff}v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf -5 -4 -3 -2 -1\n".as_bytes(),
        )
        .unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
        assert_eq!(m.positions[4], DVec3::new(0.0, 1.0, 0.0));
    }

    #[test]
    fn colours_w_continuations_crlf_and_forward_references() {
        let m = p(b"f 1 2 \\\r\n 3\r\nv 0 0 0 1 0 0\r\nv 1 0 0 2\r\nv 0 1 0 # c\r\n").unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.positions[2], DVec3::new(0.0, 1.0, 0.0));
    }

    #[test]
    fn skipped_elements_unknown_statements_and_polygons_are_reported() {
        let m = p(CUBE.as_bytes()).unwrap();
        assert_eq!(
            warnings(&m),
            [
                "t.obj:16: 6 polygons of more than 3 vertices fan-triangulated",
                "t.obj:29: 1 'l' statement (polyline) ignored",
            ]
        );
        let m =
            p(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nfo 1 2 3\np 1\nf 1 2 3\np 2 3\nsurf 0 1\nfo\n").unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
        assert_eq!(
            warnings(&m),
            [
                "t.obj:4: 2 unknown statements ignored",
                "t.obj:5: 2 'p' statements (points) ignored",
                "t.obj:8: 1 'surf' statement (surface) ignored",
            ]
        );
    }

    #[test]
    fn vertex_lines_with_unknown_values_are_reported() {
        let m = p(b"v 0 0 0 1\nv 1 0 0 1 0 0\nv 0 1 0 1 2\nv 0 0 1 1 2 3 4 5\nf 1 2 3\n").unwrap();
        assert_eq!(m.positions[3], DVec3::new(0.0, 0.0, 1.0));
        assert_eq!(
            warnings(&m),
            [
                "t.obj:3: 2 'v' lines with values other than 'w' or 'r g b' after the position (ignored)"
            ]
        );
    }

    #[test]
    fn vertices_without_faces_are_a_point_set() {
        let m = crate::io::parse(
            b"v 1 2 3\nv 4 5 6\nl 1 2\n",
            crate::io::Format::Obj,
            "t.obj",
        )
        .unwrap();
        assert_eq!(
            m.positions,
            vec![DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]
        );
        assert!(m.triangles.is_empty());
        assert_eq!(
            warnings(&m),
            [
                "t.obj:3: 1 'l' statement (polyline) ignored",
                "t.obj: no faces or cells: read as a point set of 2 vertices",
            ]
        );
    }

    #[test]
    fn nan_coordinates_are_accepted() {
        let m = p(b"v nan 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        assert!(m.positions[0].x.is_nan());
        assert!(m.positions[1].x.is_infinite());
    }

    #[test]
    fn invalid_utf8_in_a_comment_is_fine_and_in_a_number_names_the_line() {
        let mut b = b"v 0 0 0\nv 1 0 0\nv 0 1 0\n# caf".to_vec();
        b.extend([0xe9, b'\n']);
        b.extend(b"f 1 2 3\n");
        assert_eq!(p(&b).unwrap().triangles.len(), 1);
        b.extend(b"v 1 ");
        b.extend([0xe9, b'\n']);
        assert_errors(p, [(b, Parse, "t.obj:6: expected a coordinate")]);
    }

    #[test]
    fn reads_a_file_and_names_it() {
        assert_eq!(text::read_temp("obj", CUBE).unwrap().triangles.len(), 12);
        let e = crate::io::read(Path::new("/nonexistent/y.obj")).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(e.message.contains("/nonexistent/y.obj"), "{}", e.message);
    }
}
