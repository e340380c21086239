//! OFF (Geomview Object File Format): our own reader and writer.
//!
//! The reader is token-based over the raw bytes (no allocation per token) and accepts:
//! - the header keyword `OFF` with the prefixes `ST`, `C`, `N` (`STOFF`, `COFF`, `NOFF`,
//!   `CNOFF`, ...); with a prefix, a vertex is its first 3 numbers and the rest of its line
//!   (texture coordinates, colour, normal) is skipped. `4OFF`, `nOFF` and `OFF BINARY` are
//!   refused with a clear error. Geomview lets the keyword be left out; we require it, so
//!   that a file which is not OFF at all is not read as one;
//! - `#` comments anywhere (to the end of the line) and blank lines;
//! - the counts `nv nf [ne]` (`ne` is read only if it is on the line of `nf`, and ignored);
//! - vertices as 3 numbers, split over lines in any way (plain `OFF`);
//! - faces `k i1 .. ik [colour]`: polygons are fan-triangulated (i1,i2,i3), (i1,i3,i4), ...,
//!   anything after the k-th index on its line (a colour) is skipped; `k < 3` is an error.
//!
//! Every error names the file and the line of the offending token. Declared counts only cap
//! the memory reserved up front by the input's size, so a lying header costs nothing.

mod binary;

use super::MeshData;
use super::text::room;
use super::warning::{Noun, Tally, Warning, count};
use crate::error::{Error, Result};
use crate::util::alloc::{try_push, try_with_capacity};
use binary::Binary;
use glam::DVec3;

/// Parses OFF text from memory; `name` (usually the file name) prefixes every error.
pub(crate) fn parse(bytes: &[u8], name: &str) -> Result<MeshData> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes); // UTF-8 byte order mark
    let mut tk = Tokens {
        b: bytes,
        pos: 0,
        line: 1,
    };
    let mut data = MeshData::default();
    let header = read_header(&mut tk, name)?;
    if header.binary {
        let mut bin = Binary {
            b: bytes,
            pos: tk.pos,
            name,
        };
        binary::read(&mut bin, &header, &mut data)?;
    } else {
        let header = read_counts(&mut tk, name, header)?;
        data.positions = read_vertices(&mut tk, name, &header)?;
        let mut polygons = Tally::default();
        data.triangles = read_faces(&mut tk, name, &header, &mut polygons)?;
        polygons.into_warnings(name, &mut data.warnings);
        trailing_lines(&mut tk, name, header.faces, &mut data.warnings);
    }
    Ok(data)
}

/// What the header keyword and the counts announce.
struct Header {
    /// Extra columns after each vertex's position: `ST` (2), `C` (4 in binary), `N` (3).
    prefixes: Prefixes,
    binary: bool,
    vertices: u64,
    faces: u64,
}

/// The prefixes of the header keyword.
#[derive(Clone, Copy, Default)]
struct Prefixes {
    st: bool,
    c: bool,
    n: bool,
}

impl Prefixes {
    fn any(self) -> bool {
        self.st || self.c || self.n
    }
    /// `f32`s per vertex after its position in binary OFF: normal, colour (RGBA), texture.
    fn binary_extra(self) -> usize {
        3 * usize::from(self.n) + 4 * usize::from(self.c) + 2 * usize::from(self.st)
    }
}

/// Reads the header keyword and, when `BINARY` follows it, the end of its line.
fn read_header(tk: &mut Tokens, name: &str) -> Result<Header> {
    let Some((head, line)) = tk.next() else {
        return Err(Error::parse(format!(
            "{name}: empty file (no OFF header; expected 'OFF')"
        )));
    };
    let prefixes = parse_header(head).map_err(|msg| tk.err_at(name, line, &msg))?;
    let mut binary = false;
    if tk.token_on_this_line() {
        let save = (tk.pos, tk.line);
        match tk.next() {
            Some((word, _)) if word.eq_ignore_ascii_case(b"BINARY") => {
                // The binary data starts after the keyword line's newline.
                tk.skip_rest_of_line();
                tk.pos = (tk.pos + 1).min(tk.b.len());
                binary = true;
            }
            _ => (tk.pos, tk.line) = save,
        }
    }
    Ok(Header {
        prefixes,
        binary,
        vertices: 0,
        faces: 0,
    })
}

/// Reads the ASCII counts `nv nf [ne]`.
fn read_counts(tk: &mut Tokens, name: &str, header: Header) -> Result<Header> {
    let vertices = tk.count(name, "the number of vertices")?;
    check_vertex_count(vertices, name, Some(tk.line))?;
    let faces = tk.count(name, "the number of faces")?;
    if tk.token_on_this_line() {
        tk.count(name, "the number of edges")?;
    }
    Ok(Header {
        vertices,
        faces,
        ..header
    })
}

/// Vertex ids are `u32`.
fn check_vertex_count(vertices: u64, name: &str, line: Option<usize>) -> Result<()> {
    if vertices > u64::from(u32::MAX) {
        let place = line.map_or(String::new(), |l| format!(":{l}"));
        return Err(Error::out_of_range(format!(
            "{name}{place}: {vertices} vertices declared; at most {} are supported",
            u32::MAX
        )));
    }
    Ok(())
}

/// Reads the vertices: 3 numbers each, plus the rest of the line when prefixed.
fn read_vertices(tk: &mut Tokens, name: &str, header: &Header) -> Result<Vec<DVec3>> {
    let nv = header.vertices;
    // At least "0 0 0\n" (6 bytes) each.
    let mut positions = try_with_capacity(room(nv, tk.left(), 6), "the vertices")?;
    for i in 0..nv {
        let mut p = [0.0f64; 3];
        for (c, axis) in p.iter_mut().zip(["x", "y", "z"]) {
            *c = tk.number(name, || format!("coordinate {axis} of vertex {i}"))?;
        }
        try_push(&mut positions, DVec3::from_array(p), "the vertices")?;
        if header.prefixes.any() {
            tk.skip_rest_of_line();
        }
    }
    Ok(positions)
}

/// Polygons of more than 3 vertices, fan-triangulated.
const FANNED: Noun = (
    "polygon of more than 3 vertices fan-triangulated",
    "polygons of more than 3 vertices fan-triangulated",
);

/// Reads the faces `k i1 .. ik [colour]`, fan-triangulated (counted in `polygons`).
fn read_faces(
    tk: &mut Tokens, name: &str, header: &Header, polygons: &mut Tally,
) -> Result<Vec<[u32; 3]>> {
    let (nv, nf) = (header.vertices as u32, header.faces);
    // At least "3 0 1 2\n" (8 bytes) each.
    let mut triangles = try_with_capacity(room(nf, tk.left(), 8), "the triangles")?;
    for f in 0..nf {
        let (tok, line) = tk.expect(name, || format!("the vertex count of face {f}"))?;
        let k: u64 = parse_tok(tok).ok_or_else(|| {
            tk.bad_token(name, tok, line, &format!("the vertex count of face {f}"))
        })?;
        if k < 3 {
            return Err(tk.err_at(
                name,
                line,
                &format!("face {f} has {k} vertices; a face needs at least 3"),
            ));
        }
        if k > 3 {
            polygons.add(FANNED, Some(line));
        }
        let first = tk.index(name, f, nv)?;
        let mut prev = tk.index(name, f, nv)?;
        for _ in 2..k {
            let v = tk.index(name, f, nv)?;
            try_push(&mut triangles, [first, prev, v], "the triangles")?;
            prev = v;
        }
        // Whatever follows the last index on its line is the face's colour: 0 to 4 values.
        if tk.rest_of_line_tokens() > 4 {
            polygons.add(LONG_FACE, Some(line));
        }
    }
    Ok(triangles)
}

/// Face lines with more values after their indices than a colour has.
const LONG_FACE: Noun = (
    "face line with more than 4 values after its indices (not a colour; ignored)",
    "face lines with more than 4 values after their indices (not a colour; ignored)",
);

/// Lines holding tokens after the declared faces: read past, with a warning at the first.
fn trailing_lines(tk: &mut Tokens, name: &str, faces: u64, warnings: &mut Vec<Warning>) {
    let mut first = None;
    let mut lines = 0u64;
    while let Some((_, line)) = tk.next() {
        first.get_or_insert(line);
        lines += 1;
        tk.skip_rest_of_line();
    }
    if let Some(line) = first {
        let msg = format!(
            "{} after the {faces} declared (ignored)",
            count(lines, ("face line", "face lines"))
        );
        warnings.push(Warning::new(name, Some(line), msg));
    }
}

/// Checks the header keyword `[ST][C][N][4][n]OFF`; returns its prefixes.
fn parse_header(tok: &[u8]) -> std::result::Result<Prefixes, String> {
    let mut rest = tok;
    let mut prefixes = Prefixes::default();
    for (p, flag) in [
        (&b"ST"[..], &mut prefixes.st),
        (b"C", &mut prefixes.c),
        (b"N", &mut prefixes.n),
    ] {
        if let Some(r) = rest.strip_prefix(p) {
            rest = r;
            *flag = true;
        }
    }
    let mut unsupported = false;
    for p in [&b"4"[..], b"n"] {
        if let Some(r) = rest.strip_prefix(p) {
            rest = r;
            unsupported = true;
        }
    }
    if rest != b"OFF" {
        return Err(format!(
            "missing OFF header: expected 'OFF' (or COFF, NOFF, STOFF, ...), found '{}'",
            show(tok)
        ));
    }
    if unsupported {
        return Err(format!(
            "'{}': 4D and n-dimensional OFF are not supported",
            show(tok)
        ));
    }
    Ok(prefixes)
}

/// The token as text for an error message (lossy, shortened).
fn show(tok: &[u8]) -> String {
    let s = String::from_utf8_lossy(&tok[..tok.len().min(40)]).into_owned();
    if tok.len() > 40 { s + "..." } else { s }
}

fn parse_tok<T: std::str::FromStr>(tok: &[u8]) -> Option<T> {
    std::str::from_utf8(tok).ok()?.parse().ok()
}

/// Whitespace-separated tokens over bytes, with `#` comments and 1-based line numbers.
struct Tokens<'a> {
    b: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Tokens<'a> {
    fn skip_blank(&mut self) {
        while let Some(&c) = self.b.get(self.pos) {
            match c {
                b'\n' => {
                    self.line += 1;
                    self.pos += 1;
                }
                b'#' => self.skip_rest_of_line(),
                c if c.is_ascii_whitespace() || c == 0x0b => self.pos += 1,
                _ => break,
            }
        }
    }

    /// The next token and its line, or `None` at the end of the input.
    fn next(&mut self) -> Option<(&'a [u8], usize)> {
        self.skip_blank();
        let start = self.pos;
        if start >= self.b.len() {
            return None;
        }
        let b = self.b;
        while self.pos < b.len() && !b[self.pos].is_ascii_whitespace() && b[self.pos] != b'#' {
            self.pos += 1;
        }
        Some((&b[start..self.pos], self.line))
    }

    /// Moves to the end of the current line, counting the tokens on the way.
    fn rest_of_line_tokens(&mut self) -> usize {
        let mut n = 0;
        while self.token_on_this_line() {
            self.next();
            n += 1;
        }
        self.skip_rest_of_line();
        n
    }

    /// Bytes not read yet.
    fn left(&self) -> usize {
        self.b.len().saturating_sub(self.pos)
    }

    /// Moves to the end of the current line (its `\n` is left for `skip_blank` to count).
    fn skip_rest_of_line(&mut self) {
        match self.b[self.pos.min(self.b.len())..]
            .iter()
            .position(|&c| c == b'\n')
        {
            Some(n) => self.pos += n,
            None => self.pos = self.b.len(),
        }
    }

    /// Whether another token follows on the current line.
    fn token_on_this_line(&mut self) -> bool {
        while let Some(&c) = self.b.get(self.pos) {
            if c == b'\n' || c == b'#' {
                return false;
            }
            if !(c.is_ascii_whitespace() || c == 0x0b) {
                return true;
            }
            self.pos += 1;
        }
        false
    }

    fn err_at(&self, name: &str, line: usize, msg: &str) -> Error {
        Error::parse(format!("{name}:{line}: {msg}"))
    }

    fn bad_token(&self, name: &str, tok: &[u8], line: usize, what: &str) -> Error {
        self.err_at(
            name,
            line,
            &format!("expected {what}, found '{}'", show(tok)),
        )
    }

    fn expect(&mut self, name: &str, what: impl FnOnce() -> String) -> Result<(&'a [u8], usize)> {
        self.next().ok_or_else(|| {
            self.err_at(
                name,
                self.line,
                &format!("unexpected end of file (truncated?): expected {}", what()),
            )
        })
    }

    fn count(&mut self, name: &str, what: &str) -> Result<u64> {
        let (tok, line) = self.expect(name, || what.to_string())?;
        parse_tok(tok).ok_or_else(|| self.bad_token(name, tok, line, what))
    }

    fn number(&mut self, name: &str, what: impl Fn() -> String) -> Result<f64> {
        let (tok, line) = self.expect(name, &what)?;
        parse_tok(tok).ok_or_else(|| self.bad_token(name, tok, line, &what()))
    }

    fn index(&mut self, name: &str, face: u64, nv: u32) -> Result<u32> {
        let what = || format!("a vertex index of face {face}");
        let (tok, line) = self.expect(name, what)?;
        let v: u64 = parse_tok(tok).ok_or_else(|| self.bad_token(name, tok, line, &what()))?;
        if v >= u64::from(nv) {
            return Err(Error::out_of_range(format!(
                "{name}:{line}: face {face}: vertex index {v} is out of range (the file has {nv} vertices)"
            )));
        }
        Ok(v as u32)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind;
    use crate::io::text::parse_error;
    use std::path::Path;

    fn p(bytes: &[u8]) -> Result<MeshData> {
        parse(bytes, "t.off")
    }

    pub(in crate::io) const TETRA: &str =
        "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

    #[test]
    fn reads_a_tetrahedron() {
        let m = p(TETRA.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 4);
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.positions[3], DVec3::new(0.0, 0.0, 1.0));
        assert_eq!(
            m.triangles,
            vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
        );
        assert!(m.tetrahedra.is_empty());
    }

    #[test]
    fn polygons_are_fan_triangulated() {
        let m =
            p(b"OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n4 0 1 2 3\n5 1 4 5 2 0\n")
                .unwrap();
        assert_eq!(
            m.triangles,
            vec![[0, 1, 2], [0, 2, 3], [1, 4, 5], [1, 5, 2], [1, 2, 0]]
        );
    }

    #[test]
    fn comments_blank_lines_and_split_tokens() {
        let text = "# leading comment\n\n  OFF # header comment\n# between\n4\n 2\n\
                    0 # ne on the next line is not read as a count; it is x of vertex 0\n\
                    0 0\n1 0 0 0 1\n0 # split\n0 0 1\n\n3 0 1 2 # tail\n3\n0\n2\n3\n";
        let m = p(text.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 4);
        assert_eq!(m.positions[0], DVec3::ZERO);
        assert_eq!(m.positions[2], DVec3::new(0.0, 1.0, 0.0));
        assert_eq!(m.positions[3], DVec3::new(0.0, 0.0, 1.0));
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn counts_on_the_header_line_and_crlf() {
        let m =
            p("\u{feff}OFF 3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n".as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 3);
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
    }

    #[test]
    fn variants_skip_extra_columns_and_face_colours() {
        let text = "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0\n0 1 0 0.1 0.2 0.3 1\n\
                    3 0 1 2 1 0 0 1\n";
        let m = p(text.as_bytes()).unwrap();
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.positions[2], DVec3::new(0.0, 1.0, 0.0));
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
        let m = p(b"STCNOFF\n3 1 0\n0 0 0 9 9\n1 0 0 9 9 9\n0 1 0\n3 2 1 0\n").unwrap();
        assert_eq!(m.positions[2], DVec3::new(0.0, 1.0, 0.0));
        assert_eq!(m.triangles, vec![[2, 1, 0]]);
        // Plain OFF is purely token-based: two vertices may share a line.
        let m = p(b"OFF\n3 1 0\n0 0 0 1 0 0\n0 1 0 3 0 1 2\n").unwrap();
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
    }

    #[test]
    fn nan_and_inf_coordinates_are_accepted() {
        let m = p(b"OFF\n3 1 0\nnan 0 0\ninf -inf 0\n0 1 NaN\n3 0 1 2\n").unwrap();
        assert!(m.positions[0].x.is_nan());
        assert_eq!(m.positions[1].y, f64::NEG_INFINITY);
        assert!(m.positions[2].z.is_nan());
    }

    #[test]
    fn truncated_files_name_the_line_and_what_is_missing() {
        #[rustfmt::skip]
        let cases = [
            ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\n", 6, "coordinate z of vertex 2"),
            ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2", 6, "a vertex index of face 0"),
            ("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 7, "the vertex count of face 1"),
            ("OFF\n", 2, "the number of vertices"),
            // Huge declared counts are read as far as the input goes, never allocated.
            ("OFF\n4000000000 1 0\n0 0 0\n", 4, "coordinate x of vertex 1"),
            ("OFF\n3 18446744073709551615 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 7, "the vertex count of face 1"),
            ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", 7, "a vertex index of face 0"),
        ];
        for (input, line, what) in cases {
            assert_eq!(
                parse_error(p, input).message,
                format!("t.off:{line}: unexpected end of file (truncated?): expected {what}")
            );
        }
    }

    /// A binary OFF (big-endian) of the keyword `head`: a square as one quad and a
    /// triangle, with `extra` floats after each position and one RGBA face colour.
    pub(in crate::io) fn binary(head: &str, extra: usize) -> Vec<u8> {
        let mut b = format!("{head} BINARY\n").into_bytes();
        let int = |b: &mut Vec<u8>, x: i32| b.extend(x.to_be_bytes());
        [5, 2, 0].iter().for_each(|&n| int(&mut b, n));
        for p in [
            [0.0f32, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.5],
            [2.0, 2.0, 2.0],
        ] {
            p.iter().for_each(|x| b.extend(x.to_be_bytes()));
            (0..extra).for_each(|_| b.extend(9.0f32.to_be_bytes()));
        }
        [4, 0, 1, 2, 3, 4].iter().for_each(|&n| int(&mut b, n));
        [1.0f32, 0.0, 0.0, 1.0]
            .iter()
            .for_each(|x| b.extend(x.to_be_bytes()));
        [3, 1, 4, 2, 0].iter().for_each(|&n| int(&mut b, n));
        b
    }

    #[test]
    fn binary_off_is_read_as_ascii_is() {
        for (head, extra) in [("OFF", 0), ("COFF", 4), ("NOFF", 3), ("STCNOFF", 9)] {
            let m = p(&binary(head, extra)).unwrap();
            assert_eq!(m.positions.len(), 5, "{head}");
            assert_eq!(m.positions[3], DVec3::new(0.0, 1.0, 0.5), "{head}");
            assert_eq!(m.positions[4], DVec3::splat(2.0), "{head}");
            assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [1, 4, 2]], "{head}");
            let w: Vec<String> = m.warnings.iter().map(|w| w.to_string()).collect();
            assert_eq!(
                w,
                ["t.off: 1 polygon of more than 3 vertices fan-triangulated"]
            );
        }
        let mut b = binary("OFF", 0);
        b.extend([0, 0, 0, 7, 1]);
        let w = p(&b).unwrap().warnings;
        assert_eq!(
            w[1].to_string(),
            "t.off: 5 bytes after the 2 declared faces, from byte 143 (ignored)"
        );
    }

    #[test]
    fn bad_binary_off_names_the_byte() {
        let b = binary("OFF", 0);
        let with = |at: usize, x: i32| {
            let mut b = b.clone();
            b[at..at + 4].copy_from_slice(&x.to_be_bytes());
            b
        };
        // The faces start at byte 11 + 12 + 5 * 12 = 83.
        #[rustfmt::skip]
        let cases = [
            (b[..110].to_vec(), "t.off: at byte 110: unexpected end of file (truncated?): expected a colour component of face 0"),
            (b[..100].to_vec(), "t.off: at byte 99: unexpected end of file (truncated?): expected a vertex index of face 0"),
            (b[..50].to_vec(), "t.off: at byte 47: unexpected end of file (truncated?): expected coordinate x of vertex 2"),
            (with(87, 5), "t.off: at byte 87: face 0: vertex index 5 is out of range (the file has 5 vertices)"),
            (with(87, -1), "t.off: at byte 87: face 0: vertex index -1 is out of range (the file has 5 vertices)"),
            (with(83, 2), "t.off: at byte 83: face 0 has 2 vertices; a face needs at least 3"),
            (with(103, 5), "t.off: at byte 103: face 0 has 5 colour components (0 to 4)"),
            (with(15, -3), "t.off: at byte 15: the number of faces is -3, negative"),
            // A huge count is read as far as the input goes, never allocated.
            (with(11, i32::MAX), "t.off: at byte 143: unexpected end of file (truncated?): expected coordinate x of vertex 10"),
        ];
        for (input, want) in cases {
            assert_eq!(parse_error(p, input).message, want);
        }
    }

    #[test]
    fn face_lines_after_the_declared_ones_are_reported() {
        let m =
            p(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# c\n\n3 0 2 1\n3 1 2 0 # x\n").unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2]]);
        let w: Vec<String> = m.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(w, ["t.off:9: 2 face lines after the 1 declared (ignored)"]);
        let m = p(b"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
        assert_eq!(
            m.warnings[0].to_string(),
            "t.off:6: 1 face line after the 0 declared (ignored)"
        );
    }

    #[test]
    fn face_lines_longer_than_a_colour_are_reported() {
        let m =
            p(b"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 0 0 1\n3 0 2 1 7 7 7 7 7\n").unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 1]]);
        assert_eq!(
            m.warnings[0].to_string(),
            "t.off:7: 1 face line with more than 4 values after its indices (not a colour; ignored)"
        );
    }

    #[test]
    fn point_set_without_faces() {
        let m = p(b"OFF\n2 0 0\n0 0 0\n1 1 1\n").unwrap();
        assert_eq!(m.positions.len(), 2);
        assert!(m.triangles.is_empty());
    }

    #[test]
    fn missing_file_is_an_io_error_naming_it() {
        let e = crate::io::read(Path::new("/nonexistent/dir/x.off")).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(
            e.message.contains("/nonexistent/dir/x.off"),
            "{}",
            e.message
        );
    }
}
