//! The one place that knows the layout of a level file (`docs/level-files.md` is its
//! description for readers in other languages): a 64-byte header, a table of 64-byte
//! section entries, then the sections, each starting on a 64-byte boundary, every number
//! little-endian.

use crate::error::{Error, Result};

pub(crate) const MAGIC: [u8; 8] = *b"TOPOMESH";
pub(crate) const VERSION: u32 = 1;
/// Written as a little-endian `u32`; a reader that sees it reversed reads a big-endian file.
pub(crate) const ENDIAN: u32 = 0x0102_0304;
pub(crate) const ALIGN: u64 = 64;
pub(crate) const HEADER_BYTES: usize = 64;
pub(crate) const ENTRY_BYTES: usize = 64;
pub(crate) const NAME_BYTES: usize = 32;
/// Header flag: the file holds vertex positions.
pub(crate) const FLAG_POSITIONS: u32 = 1;
/// Header flag (CHE files): the structure was built strict. A file without it (every file
/// written before the flag existed) opens non-strict, the build's default.
pub(crate) const FLAG_STRICT: u32 = 2;
/// The bytes of the header the table checksum covers (the header up to the checksum).
pub(crate) const CHECKED_HEADER: usize = 40;

/// What structure a file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Che,
    Chf,
}

impl Kind {
    pub(crate) fn tag(self) -> [u8; 4] {
        match self {
            Kind::Che => *b"CHE\0",
            Kind::Chf => *b"CHF\0",
        }
    }
    pub(crate) fn name(self) -> &'static str {
        match self {
            Kind::Che => "CHE",
            Kind::Chf => "CHF",
        }
    }
}

/// The element type of a section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Elem {
    U32 = 1,
    U64 = 2,
    F64 = 3,
}

impl Elem {
    pub(crate) fn size(self) -> u64 {
        match self {
            Elem::U32 => 4,
            Elem::U64 | Elem::F64 => 8,
        }
    }
    pub(crate) fn from_code(code: u32) -> Option<Elem> {
        match code {
            1 => Some(Elem::U32),
            2 => Some(Elem::U64),
            3 => Some(Elem::F64),
            _ => None,
        }
    }
}

/// The fixed header.
///
/// | offset | size | field |
/// |---|---|---|
/// | 0 | 8 | magic `TOPOMESH` |
/// | 8 | 4 | kind `CHE\0` or `CHF\0` |
/// | 12 | 4 | format version |
/// | 16 | 4 | endianness marker `0x01020304` |
/// | 20 | 4 | level |
/// | 24 | 4 | flags |
/// | 28 | 4 | section count |
/// | 32 | 8 | file length in bytes |
/// | 40 | 4 | CRC-32 of bytes 0..40 then the section table |
/// | 44 | 20 | zero |
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Header {
    pub kind: Kind,
    pub level: u8,
    pub flags: u32,
    pub sections: u32,
    pub file_len: u64,
}

/// One section table entry.
///
/// | offset | size | field |
/// |---|---|---|
/// | 0 | 32 | name, ASCII, NUL-padded |
/// | 32 | 4 | element type: 1 `u32`, 2 `u64`, 3 `f64` |
/// | 36 | 4 | CRC-32 of the section's bytes |
/// | 40 | 8 | offset of the section from the start of the file |
/// | 48 | 8 | element count |
/// | 56 | 8 | zero |
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    pub name: String,
    pub elem: Elem,
    pub crc: u32,
    pub offset: u64,
    pub count: u64,
}

impl Entry {
    pub(crate) fn byte_len(&self) -> u64 {
        self.count * self.elem.size()
    }
}

/// `x` rounded up to the section alignment.
pub(crate) fn aligned(x: u64) -> u64 {
    x.div_ceil(ALIGN) * ALIGN
}

/// Where the first section may start.
pub(crate) fn table_end(sections: usize) -> u64 {
    aligned((HEADER_BYTES + sections * ENTRY_BYTES) as u64)
}

pub(crate) fn encode_header(h: &Header, table: &[u8]) -> [u8; HEADER_BYTES] {
    let mut b = [0u8; HEADER_BYTES];
    b[0..8].copy_from_slice(&MAGIC);
    b[8..12].copy_from_slice(&h.kind.tag());
    b[12..16].copy_from_slice(&VERSION.to_le_bytes());
    b[16..20].copy_from_slice(&ENDIAN.to_le_bytes());
    b[20..24].copy_from_slice(&u32::from(h.level).to_le_bytes());
    b[24..28].copy_from_slice(&h.flags.to_le_bytes());
    b[28..32].copy_from_slice(&h.sections.to_le_bytes());
    b[32..40].copy_from_slice(&h.file_len.to_le_bytes());
    let crc = table_crc(&b[..CHECKED_HEADER], table);
    b[40..44].copy_from_slice(&crc.to_le_bytes());
    b
}

pub(crate) fn table_crc(header: &[u8], table: &[u8]) -> u32 {
    let mut hasher = crc32fast::Hasher::new();
    hasher.update(header);
    hasher.update(table);
    hasher.finalize()
}

/// The CRC-32 of a section's bytes, its parts hashed on every thread the machine runs and
/// combined in order (the same value as one pass): a full open checks every byte of the
/// file, and one thread would make the checksums a large share of it.
pub(crate) fn section_crc(bytes: &[u8]) -> u32 {
    let threads = crate::util::par::planned_threads(0, bytes.len() / 16);
    let part = bytes.len().div_ceil(threads.max(1)).max(1);
    let hashed = crate::util::par::run_all(bytes.chunks(part).collect(), |c| {
        let mut hasher = crc32fast::Hasher::new();
        hasher.update(c);
        hasher
    });
    let mut all = crc32fast::Hasher::new();
    for h in &hashed {
        all.combine(h);
    }
    all.finalize()
}

pub(crate) fn encode_entry(e: &Entry) -> [u8; ENTRY_BYTES] {
    let mut b = [0u8; ENTRY_BYTES];
    b[..e.name.len()].copy_from_slice(e.name.as_bytes());
    b[32..36].copy_from_slice(&(e.elem as u32).to_le_bytes());
    b[36..40].copy_from_slice(&e.crc.to_le_bytes());
    b[40..48].copy_from_slice(&e.offset.to_le_bytes());
    b[48..56].copy_from_slice(&e.count.to_le_bytes());
    b
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}
fn u64_at(b: &[u8], at: usize) -> u64 {
    u64::from(u32_at(b, at)) | u64::from(u32_at(b, at + 4)) << 32
}

/// A format error at byte `at` of the file.
pub(crate) fn bad(at: u64, what: impl std::fmt::Display) -> Error {
    Error::parse(format!("byte {at}: {what}"))
}

/// The header at the start of `file` (the file's bytes, at least its header when it has
/// one), checked against `expected` and the file's length `len`; the table checksum is
/// checked by the caller, which has the table.
pub(crate) fn decode_header(file: &[u8], len: u64, expected: Kind) -> Result<Header> {
    if file.len() < HEADER_BYTES {
        return Err(bad(
            file.len() as u64,
            format!(
                "truncated: {} bytes, the header alone has {HEADER_BYTES}",
                file.len()
            ),
        ));
    }
    let b = &file[..HEADER_BYTES];
    if b[0..8] != MAGIC {
        return Err(bad(0, "not a topomesh level file (no TOPOMESH magic)"));
    }
    if b[8..12] != expected.tag() {
        let found = if b[8..12] == Kind::Che.tag() {
            "a CHE file"
        } else if b[8..12] == Kind::Chf.tag() {
            "a CHF file"
        } else {
            "an unknown kind"
        };
        return Err(bad(
            8,
            format!("expected a {} file, found {found}", expected.name()),
        ));
    }
    let endian = u32_at(b, 16);
    if endian != ENDIAN {
        let what = if endian == ENDIAN.swap_bytes() {
            "big-endian file (only little-endian is read)".to_string()
        } else {
            format!("endianness marker {endian:#010x}, expected {ENDIAN:#010x}")
        };
        return Err(bad(16, what));
    }
    let version = u32_at(b, 12);
    if version != VERSION {
        return Err(bad(
            12,
            format!("format version {version}, this library reads {VERSION}"),
        ));
    }
    let level = u32_at(b, 20);
    if level > 3 {
        return Err(bad(20, format!("level {level} is not in 0..=3")));
    }
    let header = Header {
        kind: expected,
        level: level as u8,
        flags: u32_at(b, 24),
        sections: u32_at(b, 28),
        file_len: u64_at(b, 32),
    };
    if header.file_len != len {
        return Err(bad(
            32,
            format!(
                "the header says {} bytes, the file has {len}",
                header.file_len,
            ),
        ));
    }
    let table = (header.sections as u64) * ENTRY_BYTES as u64;
    if HEADER_BYTES as u64 + table > len {
        return Err(bad(
            28,
            format!("{} sections do not fit in {len} bytes", header.sections),
        ));
    }
    Ok(header)
}

/// Section entry `i` of a table whose bytes are `table` (starting at `HEADER_BYTES`).
pub(crate) fn decode_entry(table: &[u8], i: usize, file_len: u64) -> Result<Entry> {
    let at = i * ENTRY_BYTES;
    let b = &table[at..at + ENTRY_BYTES];
    let place = (HEADER_BYTES + at) as u64;
    let name_len = b[..NAME_BYTES]
        .iter()
        .position(|&c| c == 0)
        .unwrap_or(NAME_BYTES);
    let name = std::str::from_utf8(&b[..name_len])
        .ok()
        .filter(|n| !n.is_empty() && n.bytes().all(|c| c.is_ascii_graphic()))
        .ok_or_else(|| bad(place, format!("section {i}: the name is not ASCII")))?
        .to_string();
    let code = u32_at(b, 32);
    let elem = Elem::from_code(code)
        .ok_or_else(|| bad(place + 32, format!("section {name}: element type {code}")))?;
    let e = Entry {
        name,
        elem,
        crc: u32_at(b, 36),
        offset: u64_at(b, 40),
        count: u64_at(b, 48),
    };
    let end = e
        .count
        .checked_mul(elem.size())
        .and_then(|n| n.checked_add(e.offset));
    if !e.offset.is_multiple_of(ALIGN) || e.offset < table_end(table.len() / ENTRY_BYTES) {
        return Err(bad(
            place + 40,
            format!(
                "section {}: offset {} is not a 64-byte boundary after the table",
                e.name, e.offset
            ),
        ));
    }
    if end.is_none_or(|end| end > file_len) {
        return Err(bad(
            place + 48,
            format!(
                "section {}: {} elements at offset {} run past the end of the file ({file_len} bytes)",
                e.name, e.count, e.offset
            ),
        ));
    }
    Ok(e)
}
