//! Writing a level file: the layout of `format.rs` over a list of named sections, written
//! whole or not at all (`io::write::atomic`).

use super::format::{self, ALIGN, Elem, Entry, Header, Kind};
use crate::error::{Error, Result};
use glam::DVec3;
use std::borrow::Cow;
use std::io::Write;
use std::path::Path;

/// The elements of one section, borrowed from the structure where it holds them as they
/// are stored.
#[derive(Clone, Debug)]
pub(crate) enum Data<'a> {
    U32(Cow<'a, [u32]>),
    U64(Cow<'a, [u64]>),
    /// Points, stored as their `x, y, z` coordinates (three `f64` each).
    Points(&'a [DVec3]),
}

impl Data<'_> {
    pub(crate) fn elem(&self) -> Elem {
        match self {
            Data::U32(_) => Elem::U32,
            Data::U64(_) => Elem::U64,
            Data::Points(_) => Elem::F64,
        }
    }
    pub(crate) fn len(&self) -> usize {
        match self {
            Data::U32(x) => x.len(),
            Data::U64(x) => x.len(),
            Data::Points(x) => 3 * x.len(),
        }
    }
    /// Writes the little-endian bytes to the start of `out`, which holds at least as many.
    pub(crate) fn copy_to(&self, out: &mut [u8]) {
        let mut at = 0;
        let _ = self.bytes(&mut |b| {
            out[at..at + b.len()].copy_from_slice(b);
            at += b.len();
            Ok(())
        });
    }

    /// Feeds the little-endian bytes to `out`, a chunk at a time, from one buffer on the
    /// stack: a section of any size costs no allocation.
    pub(crate) fn bytes(
        &self, out: &mut dyn FnMut(&[u8]) -> std::io::Result<()>,
    ) -> std::io::Result<()> {
        const CHUNK: usize = 1 << 14;
        let mut buf = [0u8; CHUNK];
        macro_rules! chunks {
            ($xs:expr, $width:expr, $put:expr) => {
                for chunk in $xs.chunks(CHUNK / $width) {
                    for (x, slot) in chunk.iter().zip(buf.chunks_exact_mut($width)) {
                        $put(slot, x);
                    }
                    out(&buf[..chunk.len() * $width])?;
                }
            };
        }
        let le = |slot: &mut [u8], bytes: &[u8]| slot.copy_from_slice(bytes);
        match self {
            Data::U32(x) => chunks!(x, 4, |s, x: &u32| le(s, &x.to_le_bytes())),
            Data::U64(x) => chunks!(x, 8, |s, x: &u64| le(s, &x.to_le_bytes())),
            Data::Points(x) => chunks!(x, 24, |s: &mut [u8], p: &DVec3| {
                for (slot, c) in s.chunks_exact_mut(8).zip(p.to_array()) {
                    le(slot, &c.to_le_bytes());
                }
            }),
        }
        Ok(())
    }
}

/// One named section.
#[derive(Clone, Debug)]
pub(crate) struct Section<'a> {
    pub name: String,
    pub data: Data<'a>,
}

impl<'a> Section<'a> {
    pub(crate) fn u32s(name: impl Into<String>, xs: impl Into<Cow<'a, [u32]>>) -> Self {
        Section {
            name: name.into(),
            data: Data::U32(xs.into()),
        }
    }
    pub(crate) fn u64s(name: impl Into<String>, xs: impl Into<Cow<'a, [u64]>>) -> Self {
        Section {
            name: name.into(),
            data: Data::U64(xs.into()),
        }
    }
    pub(crate) fn points(name: impl Into<String>, xs: &'a [DVec3]) -> Self {
        Section {
            name: name.into(),
            data: Data::Points(xs),
        }
    }
}

/// What the header says besides the sections.
pub(crate) struct Contents<'a> {
    pub kind: Kind,
    pub level: u8,
    pub flags: u32,
    pub sections: Vec<Section<'a>>,
}

impl<'a> Contents<'a> {
    /// The contents of a structure of `kind` at `level`, flagged as holding positions
    /// when `positions` is not empty.
    pub(crate) fn of<T>(
        kind: Kind, level: u8, positions: &[T], sections: Vec<Section<'a>>,
    ) -> Self {
        let flags = if positions.is_empty() {
            0
        } else {
            super::format::FLAG_POSITIONS
        };
        Contents {
            kind,
            level,
            flags,
            sections,
        }
    }
}

/// The table entries of sections of these names, element types and counts, one after
/// the other from the end of the table (checksums zero), and the file length.
pub(crate) fn place(
    sections: impl ExactSizeIterator<Item = (String, Elem, u64)>,
) -> Result<(Vec<Entry>, u64)> {
    let mut at = format::table_end(sections.len());
    let mut entries = Vec::with_capacity(sections.len());
    for (name, elem, count) in sections {
        if name.len() > format::NAME_BYTES || !name.bytes().all(|c| c.is_ascii_graphic()) {
            return Err(Error::invalid(format!("section name {name:?}")));
        }
        let e = Entry {
            name,
            elem,
            crc: 0,
            offset: at,
            count,
        };
        at = format::aligned(at + e.byte_len());
        entries.push(e);
    }
    Ok((entries, at))
}

/// The table entries (with checksums) and the file length.
fn layout(sections: &[Section]) -> Result<(Vec<Entry>, u64)> {
    let shapes = sections
        .iter()
        .map(|s| (s.name.clone(), s.data.elem(), s.data.len() as u64));
    let (mut entries, file_len) = place(shapes)?;
    for (s, e) in sections.iter().zip(&mut entries) {
        let mut hasher = crc32fast::Hasher::new();
        s.data
            .bytes(&mut |b| {
                hasher.update(b);
                Ok(())
            })
            .map_err(|e| Error::io(e.to_string()))?;
        e.crc = hasher.finalize();
    }
    Ok((entries, file_len))
}

/// The header and the section table of a file of `entries`, as they start it.
pub(crate) fn head(kind: Kind, level: u8, flags: u32, entries: &[Entry], file_len: u64) -> Vec<u8> {
    let table: Vec<u8> = entries.iter().flat_map(format::encode_entry).collect();
    let header = format::encode_header(
        &Header {
            kind,
            level,
            flags,
            sections: entries.len() as u32,
            file_len,
        },
        &table,
    );
    [&header[..], &table].concat()
}

/// Writes `contents` to `path`, atomically.
pub(crate) fn save(path: &Path, contents: &Contents) -> Result<()> {
    let (entries, file_len) = layout(&contents.sections)?;
    let head = head(
        contents.kind,
        contents.level,
        contents.flags,
        &entries,
        file_len,
    );
    let zeros = [0u8; ALIGN as usize];
    let mut body = |w: &mut dyn Write| -> std::io::Result<()> {
        w.write_all(&head)?;
        let mut at = head.len() as u64;
        for (s, e) in contents.sections.iter().zip(&entries) {
            w.write_all(&zeros[..(e.offset - at) as usize])?;
            s.data.bytes(&mut |b| w.write_all(b))?;
            at = e.offset + e.byte_len();
        }
        w.write_all(&zeros[..(file_len - at) as usize])
    };
    crate::io::write::atomic::write(path, &mut body)
}
