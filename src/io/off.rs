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

use super::MeshData;
use crate::error::{Error, Result};
use glam::DVec3;
use std::path::Path;

/// Reads an OFF file.
pub fn read(path: &Path) -> Result<MeshData> {
    let bytes = super::read_bytes(path)?;
    parse(&bytes, &path.display().to_string())
}

/// Parses OFF text from memory; `name` (usually the file name) prefixes every error.
pub(crate) fn parse(bytes: &[u8], name: &str) -> Result<MeshData> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes); // UTF-8 byte order mark
    let mut tk = Tokens {
        b: bytes,
        pos: 0,
        line: 1,
    };
    let header = read_header(&mut tk, name)?;
    let positions = read_vertices(&mut tk, name, &header)?;
    let triangles = read_faces(&mut tk, name, &header)?;
    Ok(MeshData {
        positions,
        triangles,
        tetrahedra: Vec::new(),
    })
}

/// What the header keyword and the counts line announce.
struct Header {
    /// A prefix (`ST`, `C`, `N`) announces extra columns after each vertex's position.
    prefixed: bool,
    vertices: u64,
    faces: u64,
}

/// Reads the header keyword and the counts `nv nf [ne]`.
fn read_header(tk: &mut Tokens, name: &str) -> Result<Header> {
    let Some((head, line)) = tk.next() else {
        return Err(Error::parse(format!(
            "{name}: empty file (no OFF header; expected 'OFF')"
        )));
    };
    let prefixed = parse_header(head).map_err(|msg| tk.err_at(name, line, &msg))?;
    if tk.token_on_this_line() {
        let save = (tk.pos, tk.line);
        if let Some((word, line)) = tk.next()
            && word.eq_ignore_ascii_case(b"BINARY")
        {
            return Err(tk.err_at(name, line, "binary OFF ('OFF BINARY') is not supported"));
        }
        (tk.pos, tk.line) = save;
    }
    let vertices = tk.count(name, "the number of vertices")?;
    if vertices > u64::from(u32::MAX) {
        return Err(Error::out_of_range(format!(
            "{name}:{}: {vertices} vertices declared; at most {} are supported",
            tk.line,
            u32::MAX
        )));
    }
    let faces = tk.count(name, "the number of faces")?;
    if tk.token_on_this_line() {
        tk.count(name, "the number of edges")?;
    }
    Ok(Header {
        prefixed,
        vertices,
        faces,
    })
}

/// Reads the vertices: 3 numbers each, plus the rest of the line when prefixed.
fn read_vertices(tk: &mut Tokens, name: &str, header: &Header) -> Result<Vec<DVec3>> {
    let nv = header.vertices;
    // At least "0 0 0\n" (6 bytes) each, so the input bounds the reservation.
    let mut positions = Vec::with_capacity((nv as usize).min(tk.b.len() / 6));
    for i in 0..nv {
        let mut p = [0.0f64; 3];
        for (c, axis) in p.iter_mut().zip(["x", "y", "z"]) {
            *c = tk.number(name, || format!("coordinate {axis} of vertex {i}"))?;
        }
        positions.push(DVec3::from_array(p));
        if header.prefixed {
            tk.skip_rest_of_line();
        }
    }
    Ok(positions)
}

/// Reads the faces `k i1 .. ik [colour]`, fan-triangulated.
fn read_faces(tk: &mut Tokens, name: &str, header: &Header) -> Result<Vec<[u32; 3]>> {
    let (nv, nf) = (header.vertices as u32, header.faces);
    // At least "3 0 1 2\n" (8 bytes) each.
    let mut triangles =
        Vec::with_capacity((nf.min(usize::MAX as u64) as usize).min(tk.b.len() / 8));
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
        let first = tk.index(name, f, nv)?;
        let mut prev = tk.index(name, f, nv)?;
        for _ in 2..k {
            let v = tk.index(name, f, nv)?;
            triangles.push([first, prev, v]);
            prev = v;
        }
        // Whatever follows the last index on its line is the face's colour.
        tk.skip_rest_of_line();
    }
    Ok(triangles)
}

/// Checks the header keyword `[ST][C][N][4][n]OFF`; returns whether a prefix announces extra
/// per-vertex columns.
fn parse_header(tok: &[u8]) -> std::result::Result<bool, String> {
    let mut rest = tok;
    let mut prefixed = false;
    for p in [&b"ST"[..], b"C", b"N"] {
        if let Some(r) = rest.strip_prefix(p) {
            rest = r;
            prefixed = true;
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
    Ok(prefixed)
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

    #[test]
    fn point_set_without_faces() {
        let m = p(b"OFF\n2 0 0\n0 0 0\n1 1 1\n").unwrap();
        assert_eq!(m.positions.len(), 2);
        assert!(m.triangles.is_empty());
    }

    #[test]
    fn missing_file_is_an_io_error_naming_it() {
        let e = read(Path::new("/nonexistent/dir/x.off")).unwrap_err();
        assert_eq!(e.kind, ErrorKind::Io);
        assert!(
            e.message.contains("/nonexistent/dir/x.off"),
            "{}",
            e.message
        );
    }
}
