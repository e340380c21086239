//! PLY (Stanford), ASCII and binary little/big endian. The `ply-rs-bw` crate parses the
//! header and decodes binary elements into our own small element types (no per-vertex
//! property map); ASCII element lines are decoded by our own reader, so that an error names
//! the element, its line and the property, and `nan` and `inf` read as numbers (reported,
//! as in every format, by `io::read`). Needed: a `vertex` element with scalar `x`, `y`, `z`
//! of any numeric type; a `face` element (optional: without it the file is a point set)
//! with an integer list property `vertex_indices` or `vertex_index`, with any count type.
//! Other elements are read past with a warning, other properties ignored. Polygons are
//! fan-triangulated (counted in a warning); values after an element's properties on its
//! line, and data after the declared elements, are read past with a warning.
//!
//! Errors are in our words and name the file and, for ASCII, the line; for binary, the
//! byte offset of the element that failed. Declared counts only bound the memory reserved
//! up front by the input's size.

use super::MeshData;
use super::text::quote;
use super::warning::{Noun, Tally, Warning, count};
use crate::error::{Error, ErrorKind, Result};
use crate::util::alloc::{try_push, try_reserve};
use glam::DVec3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{
    ElementDef, Encoding, Header, PropertyAccess, PropertyAccessResult, PropertyType, ScalarType,
};
use std::io::Cursor;

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
        .map_err(|e| header_error(name, bytes, &e, reader.line()))?;
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
    let mut data = MeshData::default();
    let mut tally = Tally::default();
    for (element, def) in &header.elements {
        match element.as_str() {
            "vertex" => {
                // A vertex takes at least "0 0 0\n" in ASCII, 3 bytes in binary.
                let positions = &mut data.positions;
                let room = def.count.min(remaining / if ascii { 6 } else { 3 });
                try_reserve(positions, room, "the vertices")?;
                input.elements::<Vertex>(def, &mut tally, |v, _, _| {
                    try_push(positions, DVec3::from_array(v.0), "the vertices")
                })?;
            }
            "face" => {
                // A triangle takes at least "3 0 1 2\n" in ASCII, 4 bytes in binary.
                let triangles = &mut data.triangles;
                let room = def.count.min(remaining / if ascii { 8 } else { 4 });
                try_reserve(triangles, room, "the triangles")?;
                let fanned = &mut 0u64;
                input.elements::<Face>(def, &mut tally, |f, i, at| {
                    *fanned += u64::from(f.0.len() > 3);
                    triangulate(&f.0, nv, triangles).map_err(|e| match e.kind {
                        ErrorKind::OutOfMemory => e,
                        kind => at.error(kind, &format!("face {i}: {}", e.message)),
                    })
                })?;
                tally.add_n(FANNED, *fanned, None);
            }
            other => {
                input.elements::<Skip>(def, &mut tally, |_, _, _| Ok(()))?;
                let msg = format!(
                    "{} of element '{other}' ignored (only 'vertex' and 'face' are read)",
                    count(def.count as u64, ("entry", "entries"))
                );
                data.warnings.push(Warning::new(name, None, msg));
            }
        }
    }
    tally.into_warnings(name, &mut data.warnings);
    input.trailing(&mut data.warnings);
    Ok(data)
}

/// Polygons of more than 3 vertices, fan-triangulated.
const FANNED: Noun = (
    "polygon of more than 3 vertices fan-triangulated",
    "polygons of more than 3 vertices fan-triangulated",
);

/// ASCII element lines with more values than their element's properties.
const LONG_LINE: Noun = (
    "line with values after its element's properties (ignored)",
    "lines with values after their element's properties (ignored)",
);

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
            "{name}: face property '{}' is {}; a list of integers is expected",
            list.name,
            type_name(other)
        ))),
    }
}

/// A property type as the PLY header writes it: `float`, `list uchar int`, ...
fn type_name(t: &PropertyType) -> String {
    let scalar = |t: &ScalarType| match t {
        ScalarType::Char => "char",
        ScalarType::UChar => "uchar",
        ScalarType::Short => "short",
        ScalarType::UShort => "ushort",
        ScalarType::Int => "int",
        ScalarType::UInt => "uint",
        ScalarType::Float => "float",
        ScalarType::Double => "double",
    };
    match t {
        PropertyType::Scalar(t) => format!("a scalar {}", scalar(t)),
        PropertyType::List(n, t) => format!("a 'list {} {}'", scalar(n), scalar(t)),
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
        try_push(out, [first, prev, v], "the triangles")?;
        prev = v;
    }
    Ok(())
}

/// A header the crate could not read, in our words: at its line when known.
fn header_error(name: &str, bytes: &[u8], e: &ParseError, reader_line: usize) -> Error {
    // The crate gives a line for every error but the missing or bad format line.
    let line = e.line();
    if e.kind() == std::io::ErrorKind::UnexpectedEof {
        let line = line.or((reader_line > 0).then_some(reader_line));
        let at = line.map_or(String::new(), |l| format!(":{l}"));
        return Error::parse(format!(
            "{name}{at}: unexpected end of file in the header (no 'end_header' line)"
        ));
    }
    if line.is_none() && e.kind() == std::io::ErrorKind::InvalidData {
        return Error::parse(format!(
            "{name}:{reader_line}: the header holds bytes that are not UTF-8 text"
        ));
    }
    let Some(line) = line else {
        return Error::parse(format!(
            "{name}: the header has no valid 'format' line ('format ascii 1.0', \
             'format binary_little_endian 1.0' or 'format binary_big_endian 1.0')"
        ));
    };
    let text = bytes.split(|&c| c == b'\n').nth(line - 1).unwrap_or(&[]);
    let text = String::from_utf8_lossy(text);
    Error::parse(format!(
        "{name}:{line}: header line '{}' cannot be read (expected 'format', 'comment', \
         'obj_info', 'element', 'property' or 'end_header', in that grammar)",
        quote(text.trim_end())
    ))
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
    fn elements<E: Ascii>(
        &mut self, def: &ElementDef, tally: &mut Tally,
        mut sink: impl FnMut(E, usize, &Located<'a>) -> Result<()>,
    ) -> Result<()> {
        if def.properties.is_empty() {
            return Ok(()); // nothing stored per element; an empty ASCII line is blank anyway
        }
        let parser = Parser::<E>::new();
        for i in 0..def.count {
            let (value, at) = if self.encoding == Encoding::Ascii {
                self.ascii_element(def, i, tally)?
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
    fn ascii_element<E: Ascii>(
        &mut self, def: &ElementDef, i: usize, tally: &mut Tally,
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
        let mut tokens = text.split_ascii_whitespace();
        let value = decode_ascii::<E>(&mut tokens, def).map_err(|e| match e.kind {
            ErrorKind::OutOfMemory => e,
            kind => at.error(kind, &format!("{element} {i}: {}", e.message)),
        })?;
        if tokens.next().is_some() {
            tally.add(LONG_LINE, Some(line));
        }
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
                format!("{element} {i} cannot be decoded as its declared properties")
            };
            at.error(ErrorKind::Parse, &msg)
        })?;
        self.pos = cursor.position() as usize;
        Ok((value, at))
    }
}

impl Payload<'_> {
    /// What follows the declared elements: read past, with a warning.
    fn trailing(&mut self, warnings: &mut Vec<Warning>) {
        if self.encoding == Encoding::Ascii {
            let Some((_, first)) = self.next_line() else {
                return;
            };
            let mut lines = 1;
            while self.next_line().is_some() {
                lines += 1;
            }
            let msg = format!(
                "{} after the declared elements (ignored)",
                count(lines, ("line", "lines"))
            );
            warnings.push(Warning::new(self.name, Some(first), msg));
        } else if self.pos < self.bytes.len() {
            let msg = format!(
                "{} after the declared elements, from byte {} (ignored)",
                count((self.bytes.len() - self.pos) as u64, ("byte", "bytes")),
                self.pos
            );
            warnings.push(Warning::new(self.name, None, msg));
        }
    }
}

/// An element decoded from an ASCII line by our own reader: scalars through the
/// `PropertyAccess` setters as `f64`, integer lists through `list`.
trait Ascii: PropertyAccess {
    /// An integer list property; only faces keep one.
    fn list(&mut self, _name: &str, _items: Vec<i64>) {}
}

/// Decodes the properties of `def` from `tokens`, in order: a scalar is one number, a list
/// its count and that many numbers. `Err` says which property is missing or malformed
/// (or that memory ran out).
fn decode_ascii<'t, E: Ascii>(
    tokens: &mut impl Iterator<Item = &'t str>, def: &ElementDef,
) -> Result<E> {
    let mut value = E::new();
    for (name, p) in &def.properties {
        let mut number = |what: &str| -> Result<f64> {
            let tok = tokens.next().ok_or_else(|| {
                Error::parse(format!("property '{name}' is missing ({what} expected)"))
            })?;
            tok.parse().map_err(|_| {
                Error::parse(format!(
                    "property '{name}': expected {what}, found '{}'",
                    quote(tok)
                ))
            })
        };
        match &p.data_type {
            PropertyType::Scalar(_) => {
                let v = number("a number")?;
                value.set_double(name, v);
            }
            PropertyType::List(..) => {
                let n = number("a list length")?;
                if n < 0.0 || n.fract() != 0.0 {
                    return Err(Error::parse(format!("property '{name}': list length {n}")));
                }
                // Every item takes a token: the line bounds what is reserved.
                let mut items = Vec::new();
                for _ in 0..n as u64 {
                    let v = number("a list item")?;
                    if v.fract() != 0.0 || v.abs() > 9.0e15 {
                        return Err(Error::parse(format!(
                            "property '{name}': expected an integer, found {v}"
                        )));
                    }
                    try_push(&mut items, v as i64, "a face's indices")?;
                }
                value.list(name, items);
            }
        }
    }
    Ok(value)
}

impl Ascii for Skip {}
impl Ascii for Vertex {}
impl Ascii for Face {
    fn list(&mut self, name: &str, items: Vec<i64>) {
        if INDEX_NAMES.contains(&name) {
            self.0 = Indices::I64(items);
        }
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
    /// Read by our own ASCII decoder.
    I64(Vec<i64>),
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
            Indices::I64(v) => v.len(),
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
            Indices::I64(v) => v[j],
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
pub(super) mod tests {
    use super::*;
    use crate::error::ErrorKind::{OutOfRange, Parse};
    use crate::io::text::{self, assert_errors, parse_error, warning_lines as warnings};

    fn p(bytes: &[u8]) -> Result<MeshData> {
        parse(bytes, "t.ply")
    }

    pub(in crate::io) const ASCII: &str = "ply\nformat ascii 1.0\ncomment a square and a triangle\n\
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
            (edit("uchar int vertex_indices", "uchar float vertex_indices"), Parse, "t.ply: face property 'vertex_indices' is a 'list uchar float'"),
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
    fn errors_are_in_our_words() {
        let edit = |from: &str, to: &str| ASCII.replace(from, to);
        #[rustfmt::skip]
        let cases = [
            (edit("1 1 0 0", "1 x 0 0"), "t.ply:15: vertex 2: property 'y': expected a number, found 'x'"),
            (edit("1 1 0 0", "1 1"), "t.ply:15: vertex 2: property 'z' is missing (a number expected)"),
            (edit("3 1 4 2 1", "3 1 4"), "t.ply:20: face 1: property 'vertex_indices' is missing (a list item expected)"),
            (edit("3 1 4 2 1", "3 1 4.5 2 1"), "t.ply:20: face 1: property 'vertex_indices': expected an integer, found 4.5"),
            (edit("3 1 4 2 1", "-3 1 4 2 1"), "t.ply:20: face 1: property 'vertex_indices': list length -3"),
            (edit("property float y", "property flaot y"), "t.ply:6: header line 'property flaot y' cannot be read (expected 'format', 'comment', 'obj_info', 'element', 'property' or 'end_header', in that grammar)"),
            ("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n".into(), "t.ply:5: unexpected end of file in the header (no 'end_header' line)"),
            ("ply\nelement vertex 1\nproperty float x\nend_header\n".into(), "t.ply: the header has no valid 'format' line ('format ascii 1.0', 'format binary_little_endian 1.0' or 'format binary_big_endian 1.0')"),
        ];
        for (input, want) in cases {
            assert_eq!(parse_error(p, input).message, want);
        }
        let mut b = binary(false);
        let n = b.len();
        // Face 1's count byte says 200 indices: it runs past the end.
        b[n - 13] = 200;
        assert_eq!(
            parse_error(p, b).message,
            format!(
                "t.ply: at byte {}: unexpected end of file (truncated?) in face 1 of 2",
                n - 13
            )
        );
    }

    #[test]
    fn skipped_elements_long_lines_and_trailing_data_are_reported() {
        let m = p(ASCII.as_bytes()).unwrap();
        assert_eq!(
            warnings(&m),
            ["t.ply: 1 polygon of more than 3 vertices fan-triangulated"]
        );
        let text = ASCII.replace("1 0 0 0\n", "1 0 0 0 7 7\n") + "3 0 1 2\n\n3 0 2 1\n";
        let m = p(text.as_bytes()).unwrap();
        assert_eq!(m.triangles, vec![[0, 1, 2], [0, 2, 3], [1, 4, 2]]);
        assert_eq!(
            warnings(&m),
            [
                "t.ply:14: 1 line with values after its element's properties (ignored)",
                "t.ply: 1 polygon of more than 3 vertices fan-triangulated",
                "t.ply:21: 2 lines after the declared elements (ignored)",
            ]
        );
        let mut b = binary(true);
        let n = b.len();
        b.extend([0, 0]);
        let m = p(&b).unwrap();
        assert_eq!(
            warnings(&m),
            [
                "t.ply: 1 entry of element 'edge' ignored (only 'vertex' and 'face' are read)",
                "t.ply: 1 polygon of more than 3 vertices fan-triangulated",
                &format!("t.ply: 2 bytes after the declared elements, from byte {n} (ignored)"),
            ]
        );
    }

    #[test]
    fn ascii_nan_and_inf_are_read_and_reported() {
        let text = ASCII
            .replace("1 0 0 0\n", "nan 0 0 0\n")
            .replace("1 1 0 0", "1 -inf 0 0");
        let m = crate::io::parse(text.as_bytes(), crate::io::Format::Ply, "t.ply").unwrap();
        assert!(m.positions[1].x.is_nan());
        assert_eq!(m.positions[2].y, f64::NEG_INFINITY);
        assert_eq!(
            m.warnings[1].to_string(),
            "t.ply: 2 vertices have a NaN or infinite coordinate (0-based ids 1, 2); geometric \
             checks skip them"
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
        assert_errors(
            p,
            [(
                garbage,
                Parse,
                "t.ply:2: the header holds bytes that are not UTF-8 text",
            )],
        );
    }
}
