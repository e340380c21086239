//! PLY (Stanford), ASCII and binary little/big endian, decoded by the `ply-rs-bw` crate.
//!
//! The crate parses the header and decodes one element at a time into our own small element
//! types (no per-vertex property map). Needed: a `vertex` element with scalar `x`, `y`, `z`
//! of any numeric type; a `face` element (optional: without it the file is a point set)
//! with an integer list property `vertex_indices` or `vertex_index`, with any count type.
//! Other elements and properties are read past and ignored. Polygons are fan-triangulated.
//!
//! Errors name the file and, for ASCII, the line; for binary, the byte offset of the
//! element that failed. Declared counts only bound the memory reserved up front by the
//! input's size. The crate's ASCII number grammar has no `nan`, `inf`, `.5` or `5.`: such
//! tokens are parse errors (binary NaN/inf are read as is).

use super::MeshData;
use crate::error::{Error, ErrorKind, Result};
use glam::DVec3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{
    ElementDef, Encoding, Header, PropertyAccess, PropertyAccessResult, PropertyType, ScalarType,
};
use std::io::Cursor;
use std::path::Path;

/// Reads a PLY file (ASCII or binary).
pub fn read(path: &Path) -> Result<MeshData> {
    let bytes = super::read_bytes(path)?;
    parse(&bytes, &path.display().to_string())
}

const INDEX_NAMES: [&str; 2] = ["vertex_indices", "vertex_index"];

/// Parses PLY from memory; `name` (usually the file name) prefixes every error.
pub(crate) fn parse(bytes: &[u8], name: &str) -> Result<MeshData> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes); // UTF-8 byte order mark
    if bytes.is_empty() {
        return Err(Error::parse(format!("{name}: empty file")));
    }
    if !bytes.starts_with(b"ply") {
        return Err(Error::parse(format!(
            "{name}:1: not a PLY file (it does not start with 'ply')"
        )));
    }
    let mut reader = Reader::new(Cursor::new(bytes));
    let header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(|e| crate_error(name, &e, reader.line()))?;
    let cursor = reader.into_inner();
    let nv = check_header(&header, name)?;

    let mut input = Payload {
        bytes,
        pos: cursor.position() as usize,
        line: 0,
        encoding: header.encoding,
        name,
    };
    input.line = 1 + bytes[..input.pos].iter().filter(|&&c| c == b'\n').count();

    let remaining = bytes.len() - input.pos;
    let ascii = header.encoding == Encoding::Ascii;
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for (element, def) in &header.elements {
        match element.as_str() {
            "vertex" => {
                // A vertex takes at least "0 0 0\n" in ASCII, 3 bytes in binary.
                positions.reserve(def.count.min(remaining / if ascii { 6 } else { 3 }));
                input.elements::<Vertex>(def, |v, _, _| {
                    positions.push(DVec3::from_array(v.0));
                    Ok(())
                })?;
            }
            "face" => {
                // A triangle takes at least "3 0 1 2\n" in ASCII, 4 bytes in binary.
                triangles.reserve(def.count.min(remaining / if ascii { 8 } else { 4 }));
                input.elements::<Face>(def, |f, i, at| {
                    triangulate(&f.0, nv, &mut triangles)
                        .map_err(|msg| at.error(msg.kind, &format!("face {i}: {}", msg.message)))
                })?;
            }
            _ => input.elements::<Skip>(def, |_, _, _| Ok(()))?,
        }
    }
    Ok(MeshData {
        positions,
        triangles,
        ..MeshData::default()
    })
}

/// Checks the header has what we need; returns the vertex count.
fn check_header(header: &Header, name: &str) -> Result<u32> {
    let Some(vertex) = header.elements.get("vertex") else {
        return Err(Error::parse(format!(
            "{name}: the header declares no 'vertex' element"
        )));
    };
    for axis in ["x", "y", "z"] {
        match vertex.properties.get(axis).map(|p| &p.data_type) {
            Some(PropertyType::Scalar(_)) => {}
            Some(PropertyType::List(..)) => {
                return Err(Error::parse(format!(
                    "{name}: vertex property '{axis}' is a list; a scalar is expected"
                )));
            }
            None => {
                return Err(Error::parse(format!(
                    "{name}: the 'vertex' element has no property '{axis}'"
                )));
            }
        }
    }
    let nv = u32::try_from(vertex.count).map_err(|_| {
        Error::out_of_range(format!(
            "{name}: {} vertices declared; at most {} are supported",
            vertex.count,
            u32::MAX
        ))
    })?;
    let Some(face) = header.elements.get("face") else {
        if header.elements.contains_key("tristrips") {
            return Err(Error::parse(format!(
                "{name}: triangle strips ('tristrips' element) are not supported; only 'face'"
            )));
        }
        return Ok(nv);
    };
    let lists: Vec<_> = INDEX_NAMES
        .iter()
        .filter_map(|n| face.properties.get(*n))
        .collect();
    let list = match lists[..] {
        [one] => one,
        [] => {
            return Err(Error::parse(format!(
                "{name}: the 'face' element has no list property 'vertex_indices' or 'vertex_index'"
            )));
        }
        _ => {
            return Err(Error::parse(format!(
                "{name}: the 'face' element has both 'vertex_indices' and 'vertex_index'"
            )));
        }
    };
    match &list.data_type {
        PropertyType::List(_, item) if !matches!(item, ScalarType::Float | ScalarType::Double) => {
            Ok(nv)
        }
        other => Err(Error::parse(format!(
            "{name}: face property '{}' has type {other:?}; a list of integers is expected",
            list.name
        ))),
    }
}

/// Appends the fan triangulation of one face, checking its indices.
fn triangulate(idx: &Indices, nv: u32, out: &mut Vec<[u32; 3]>) -> Result<()> {
    let k = idx.len();
    if k < 3 {
        return Err(Error::parse(format!(
            "has {k} vertices; a face needs at least 3"
        )));
    }
    let get = |j: usize| -> Result<u32> {
        let v = idx.get(j);
        if (0..i64::from(nv)).contains(&v) {
            Ok(v as u32)
        } else {
            Err(Error::out_of_range(format!(
                "vertex index {v} is out of range (the file has {nv} vertices)"
            )))
        }
    };
    let first = get(0)?;
    let mut prev = get(1)?;
    for j in 2..k {
        let v = get(j)?;
        out.push([first, prev, v]);
        prev = v;
    }
    Ok(())
}

/// A header error from the crate, at its line if it gives one, else at the reader's line.
fn crate_error(name: &str, e: &ParseError, reader_line: usize) -> Error {
    let text = e.to_string();
    let text = match e.line() {
        Some(line) => text
            .strip_prefix(&format!("Line {line}: "))
            .unwrap_or(&text)
            .to_string(),
        None => text,
    };
    let msg = text
        .replace("\n'", "'")
        .replace("\r'", "'")
        .replace("\n\t", "; ");
    match e.line().or((reader_line > 0).then_some(reader_line)) {
        Some(line) => Error::parse(format!("{name}:{line}: {msg}")),
        None => Error::parse(format!("{name}: {msg}")),
    }
}

/// Where an element starts, for its error messages.
#[derive(Clone, Copy)]
enum At {
    Line(usize),
    Byte(usize),
}

struct Located<'a> {
    name: &'a str,
    at: At,
}

impl Located<'_> {
    fn error(&self, kind: ErrorKind, msg: &str) -> Error {
        let msg = msg.replace("\n\t", "; ");
        Error::new(
            kind,
            match self.at {
                At::Line(l) => format!("{}:{l}: {msg}", self.name),
                At::Byte(b) => format!("{}: at byte {b}: {msg}", self.name),
            },
        )
    }
}

/// The payload after the header, read one element at a time.
struct Payload<'a> {
    bytes: &'a [u8],
    pos: usize,
    /// Line number at `pos` (ASCII only).
    line: usize,
    encoding: Encoding,
    name: &'a str,
}

impl<'a> Payload<'a> {
    /// Decodes the `def.count` elements of `def` as `E`, handing each to `sink` with its
    /// number and location.
    fn elements<E: PropertyAccess>(
        &mut self, def: &ElementDef, mut sink: impl FnMut(E, usize, &Located<'a>) -> Result<()>,
    ) -> Result<()> {
        if def.properties.is_empty() {
            return Ok(()); // nothing stored per element; an empty ASCII line is blank anyway
        }
        let parser = Parser::<E>::new();
        for i in 0..def.count {
            let (value, at) = if self.encoding == Encoding::Ascii {
                self.ascii_element(&parser, def, i)?
            } else {
                self.binary_element(&parser, def, i)?
            };
            sink(value, i, &at)?;
        }
        Ok(())
    }

    fn located(&self, at: At) -> Located<'a> {
        Located {
            name: self.name,
            at,
        }
    }

    /// Element `i` of `def`: the next line that is not blank.
    fn ascii_element<E: PropertyAccess>(
        &mut self, parser: &Parser<E>, def: &ElementDef, i: usize,
    ) -> Result<(E, Located<'a>)> {
        let element = &def.name;
        let (text, line) = self.next_line().ok_or_else(|| {
            self.located(At::Line(self.line)).error(
                ErrorKind::Parse,
                &format!(
                    "unexpected end of file (truncated?): {element} {i} of {} is missing",
                    def.count
                ),
            )
        })?;
        let at = self.located(At::Line(line));
        let text = std::str::from_utf8(text)
            .map_err(|_| at.error(ErrorKind::Parse, &format!("{element} {i}: not UTF-8 text")))?;
        let text = text.strip_suffix('\r').unwrap_or(text);
        let value = parser
            .read_ascii_element(text, def)
            .map_err(|e| at.error(ErrorKind::Parse, &format!("{element} {i}: {e}")))?;
        Ok((value, at))
    }

    /// The next line that is not blank and its number, or `None` at the end of the input.
    fn next_line(&mut self) -> Option<(&'a [u8], usize)> {
        loop {
            let rest = &self.bytes[self.pos..];
            if rest.is_empty() {
                return None;
            }
            let len = rest.iter().position(|&c| c == b'\n');
            let raw = &rest[..len.unwrap_or(rest.len())];
            self.pos += len.map_or(rest.len(), |n| n + 1);
            let line = self.line;
            self.line += 1;
            if !raw.iter().all(u8::is_ascii_whitespace) {
                return Some((raw, line));
            }
        }
    }

    /// Element `i` of `def`, decoded from the bytes at `pos`.
    fn binary_element<E: PropertyAccess>(
        &mut self, parser: &Parser<E>, def: &ElementDef, i: usize,
    ) -> Result<(E, Located<'a>)> {
        let at = self.located(At::Byte(self.pos));
        let mut cursor = Cursor::new(self.bytes);
        cursor.set_position(self.pos as u64);
        let value = match self.encoding {
            Encoding::BinaryBigEndian => parser.read_big_endian_element(&mut cursor, def),
            _ => parser.read_little_endian_element(&mut cursor, def),
        };
        let value = value.map_err(|e| {
            let element = &def.name;
            let msg = if e.kind() == std::io::ErrorKind::UnexpectedEof {
                format!(
                    "unexpected end of file (truncated?) in {element} {i} of {}",
                    def.count
                )
            } else {
                format!("{element} {i}: {e}")
            };
            at.error(ErrorKind::Parse, &msg)
        })?;
        self.pos = cursor.position() as usize;
        Ok((value, at))
    }
}

/// Any other element: decoded (binary needs its size) and dropped.
struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}

/// A vertex: `x`, `y`, `z` of any scalar type.
struct Vertex([f64; 3]);

impl Vertex {
    fn set(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        let i = match name {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => return PropertyAccessResult::Ignored,
        };
        self.0[i] = value;
        PropertyAccessResult::Set
    }
}

/// Setters that hand any scalar type to `Vertex::set` as `f64`.
macro_rules! scalar_setter {
    ($($method:ident: $t:ty),* $(,)?) => {$(
        fn $method(&mut self, name: &str, value: $t) -> PropertyAccessResult {
            self.set(name, value.into())
        }
    )*};
}

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Vertex([0.0; 3])
    }
    scalar_setter! {
        set_char: i8,
        set_uchar: u8,
        set_short: i16,
        set_ushort: u16,
        set_int: i32,
        set_uint: u32,
        set_float: f32,
        set_double: f64,
    }
}

/// A face's vertex list, kept in the integer type of the file (moved, not converted).
enum Indices {
    Missing,
    I8(Vec<i8>),
    U8(Vec<u8>),
    I16(Vec<i16>),
    U16(Vec<u16>),
    I32(Vec<i32>),
    U32(Vec<u32>),
}

impl Indices {
    fn len(&self) -> usize {
        match self {
            Indices::Missing => 0,
            Indices::I8(v) => v.len(),
            Indices::U8(v) => v.len(),
            Indices::I16(v) => v.len(),
            Indices::U16(v) => v.len(),
            Indices::I32(v) => v.len(),
            Indices::U32(v) => v.len(),
        }
    }
    /// Index `j < len()`.
    fn get(&self, j: usize) -> i64 {
        match self {
            Indices::Missing => -1,
            Indices::I8(v) => v[j].into(),
            Indices::U8(v) => v[j].into(),
            Indices::I16(v) => v[j].into(),
            Indices::U16(v) => v[j].into(),
            Indices::I32(v) => v[j].into(),
            Indices::U32(v) => v[j].into(),
        }
    }
}

struct Face(Indices);

macro_rules! index_list_setter {
    ($($method:ident: $t:ty => $variant:ident),* $(,)?) => {$(
        fn $method(&mut self, name: &str, value: Vec<$t>) -> PropertyAccessResult {
            if INDEX_NAMES.contains(&name) {
                self.0 = Indices::$variant(value);
                PropertyAccessResult::Set
            } else {
                PropertyAccessResult::Ignored
            }
        }
    )*};
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Face(Indices::Missing)
    }
    index_list_setter! {
        set_list_char: i8 => I8,
        set_list_uchar: u8 => U8,
        set_list_short: i16 => I16,
        set_list_ushort: u16 => U16,
        set_list_int: i32 => I32,
        set_list_uint: u32 => U32,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind::{OutOfRange, Parse};
    use crate::io::text::{self, assert_errors, parse_error};

    fn p(bytes: &[u8]) -> Result<MeshData> {
        parse(bytes, "t.ply")
    }

    const ASCII: &str = "ply\nformat ascii 1.0\ncomment a square and a triangle\n\
        element vertex 5\nproperty float x\nproperty float y\nproperty double z\nproperty uchar red\n\
        element face 2\nproperty list uchar int vertex_indices\nproperty float quality\nend_header\n\
        0 0 0 255\n1 0 0 0\n1 1 0 0\n0 1 0.5 0\n\n2 2 -2 7\n4 0 1 2 3 0.5\n3 1 4 2 1\n";

    #[test]
    fn ascii_square_and_triangle() {
        let m = p(ASCII.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 5);
        assert_eq!(m.positions[3], DVec3::new(0.0, 1.0, 0.5));
        assert_eq!(m.positions[4], DVec3::new(2.0, 2.0, -2.0));
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [1, 4, 2]]);
        assert!(m.tetrahedra.is_empty());
    }

    #[test]
    fn ascii_vertex_index_name_int_coordinates_crlf() {
        let text = "\u{feff}ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty int x\r\nproperty short y\r\n\
            property uint z\r\nelement face 1\r\nproperty list uint uint vertex_index\r\nend_header\r\n\
            0 0 0\r\n3 0 0\r\n0 -3 0\r\n0 0 3\r\n5 0 1 2 3 1\r\n";
        let m = p(text.as_bytes()).unwrap();
        assert_eq!(m.positions[2], DVec3::new(0.0, -3.0, 0.0));
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 1]]);
    }

    /// A binary PLY: float xyz, an `edge` element to skip, faces with a uchar count and int
    /// indices (one quad, one triangle).
    fn binary(big_endian: bool) -> Vec<u8> {
        let format = if big_endian {
            "binary_big_endian"
        } else {
            "binary_little_endian"
        };
        let mut b = format!(
            "ply\nformat {format} 1.0\nelement vertex 5\nproperty float x\nproperty float y\n\
             property float z\nelement edge 1\nproperty int vertex1\nproperty list uchar int ring\n\
             element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        )
        .into_bytes();
        let f32b = |x: f32| {
            if big_endian {
                x.to_be_bytes()
            } else {
                x.to_le_bytes()
            }
        };
        let i32b = |x: i32| {
            if big_endian {
                x.to_be_bytes()
            } else {
                x.to_le_bytes()
            }
        };
        for p in [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [2.0, 0.5, f32::NAN],
        ] {
            p.iter().for_each(|&x| b.extend(f32b(x)));
        }
        b.extend(i32b(7));
        b.push(2);
        b.extend(i32b(1));
        b.extend(i32b(2));
        b.push(4);
        [0, 1, 2, 3].iter().for_each(|&i| b.extend(i32b(i)));
        b.push(3);
        [1, 4, 2].iter().for_each(|&i| b.extend(i32b(i)));
        b
    }

    #[test]
    fn binary_little_endian_file() {
        let m = text::read_temp("ply", binary(false)).unwrap();
        assert_eq!(m.positions.len(), 5);
        assert_eq!(m.positions[2], DVec3::new(1.0, 1.0, 0.0));
        assert_eq!(m.positions[4].x, 2.0);
        assert!(m.positions[4].z.is_nan());
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [1, 4, 2]]);
    }

    #[test]
    fn binary_big_endian() {
        let m = p(&binary(true)).unwrap();
        assert_eq!(m.positions[1], DVec3::new(1.0, 0.0, 0.0));
        assert_eq!(m.positions[4].y, 0.5);
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [1, 4, 2]]);
    }

    #[test]
    fn point_set_without_faces() {
        let text = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n\
            property float z\nend_header\n1 2 3\n4 5 6\n";
        let m = p(text.as_bytes()).unwrap();
        assert_eq!(
            m.positions,
            vec![DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]
        );
        assert!(m.triangles.is_empty());
    }

    #[test]
    fn bad_ascii_input_names_the_line() {
        let cut = |end: &str, more: usize| ASCII[..ASCII.find(end).unwrap() + more].to_string();
        let edit = |from: &str, to: &str| ASCII.replace(from, to);
        #[rustfmt::skip]
        let cases = [
            (edit("3 1 4 2", "3 1 5 2"), OutOfRange, "t.ply:20: face 1: vertex index 5"),
            (edit("3 1 4 2", "3 1 -1 2"), OutOfRange, "t.ply:20: face 1: vertex index -1"),
            (edit("3 1 4 2", "2 1 4"), Parse, "t.ply:20: face 1: has 2 vertices"),
            (cut("4 0 1 2 3", 0), Parse, "t.ply:19: unexpected end of file (truncated?): face 0 of 2 is missing"),
            (cut("0 1 0.5", 3), Parse, "t.ply:16: vertex 3"),
            (edit("1 1 0 0", "1 x 0 0"), Parse, "t.ply:15: vertex 2"),
            (edit("property float y", "property flaot y"), Parse, "t.ply:6: "),
            (edit("vertex_indices", "corners"), Parse, "t.ply: the 'face' element has no list property 'vertex_indices'"),
            (edit("uchar int vertex_indices", "uchar float vertex_indices"), Parse, "t.ply: face property 'vertex_indices' has type"),
            ("".into(), Parse, "t.ply: empty file"),
            ("OFF\n3 1 0\n".into(), Parse, "t.ply:1: not a PLY file"),
            ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n".into(), Parse, "t.ply:5: "),
            ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n".into(), Parse, "t.ply: the 'vertex' element has no property 'z'"),
            ("ply\nformat ascii 1.0\nelement point 1\nproperty float x\nend_header\n0\n".into(), Parse, "t.ply: the header declares no 'vertex' element"),
            // Faces first, so that their (huge) reservation comes before anything fails.
            ("ply\nformat ascii 1.0\nelement face 18446744073709551615\n\
              property list uchar int vertex_indices\nelement vertex 3\nproperty float x\n\
              property float y\nproperty float z\nend_header\n3 0 1 2\n".into(), Parse, "t.ply:11: unexpected end of file (truncated?): face 1 of 18446744073709551615"),
            ("ply\nformat ascii 1.0\nelement vertex 4294967296\nproperty float x\n\
              property float y\nproperty float z\nend_header\n".into(), OutOfRange, "t.ply: 4294967296 vertices declared"),
        ];
        assert_errors(p, cases);
        let e = parse_error(
            p,
            edit("uchar int vertex_indices", "uchar float vertex_indices"),
        );
        assert!(
            e.message.ends_with("a list of integers is expected"),
            "{}",
            e.message
        );
    }

    #[test]
    fn bad_binary_input_names_the_byte() {
        let b = binary(false);
        let n = b.len();
        let mut bad_index = b.clone();
        bad_index[n - 8..n - 4].copy_from_slice(&9i32.to_le_bytes());
        let header_end = b.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
        let huge_header = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty double x\n\
            property double y\nproperty double z\nelement face 18446744073709551615\n\
            property list uchar int vertex_indices\nend_header\n";
        let huge = [huge_header.as_bytes(), &[0u8; 30]].concat();
        let mut garbage = b"ply\n".to_vec();
        garbage.extend((0..200u32).map(|i| (i * 89 % 256) as u8));
        let eof = "unexpected end of file (truncated?) in";
        let oor = "face 1: vertex index 9 is out of range (the file has 5 vertices)";
        #[rustfmt::skip]
        let cases = [
            (bad_index, OutOfRange, n - 13, oor.to_string()),
            (b[..n - 3].to_vec(), Parse, n - 13, format!("{eof} face 1 of 2")),
            (b[..header_end + 20].to_vec(), Parse, header_end + 12, format!("{eof} vertex 1 of 5")),
            (huge, Parse, huge_header.len() + 24, format!("{eof} vertex 1 of 4000000000")),
        ];
        for (input, kind, byte, words) in cases {
            let e = parse_error(p, input);
            assert_eq!(
                (e.kind, e.message),
                (kind, format!("t.ply: at byte {byte}: {words}"))
            );
        }
        assert_errors(p, [(garbage, Parse, "t.ply:2: ")]);
    }
}
