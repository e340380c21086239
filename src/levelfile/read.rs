//! Reading a level file into owned arrays: the header and the table are checked against
//! the file's length before any section is touched, each section against its checksum
//! (unless trusted) when it is taken, and every length against the counts by the caller
//! (`che.rs`, `chf.rs`) before anything is indexed. A mapped file lends its sections as
//! they lie (`Store::Mapped`); a loaded one copies them out.

use super::format::{self, Elem, Entry, HEADER_BYTES, Header, Kind};
use super::{Mode, OpenOptions, Verify};
use crate::error::{Error, Result};
use crate::util::store::Store;
use memmap2::Mmap;
use std::io::Read;
use std::ops::Deref;
use std::path::Path;
use std::sync::Arc;

/// The bytes of a level file: read into memory, or mapped.
pub(crate) enum Bytes {
    Owned(Vec<u8>),
    Mapped(Arc<Mmap>),
}

impl Deref for Bytes {
    type Target = [u8];
    fn deref(&self) -> &[u8] {
        match self {
            Bytes::Owned(b) => b,
            Bytes::Mapped(m) => m,
        }
    }
}

/// A level file in memory, its header and table checked.
pub(crate) struct LevelFile {
    bytes: Bytes,
    pub header: Header,
    entries: Vec<Entry>,
    checksums: bool,
    pub verify: Verify,
}

fn io_error(path: &Path, e: std::io::Error) -> Error {
    Error::io(format!("{}: {e}", path.display()))
}

/// The whole file, in a buffer sized by the file's own length.
fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    let mut file = std::fs::File::open(path).map_err(|e| io_error(path, e))?;
    let len = file.metadata().map_err(|e| io_error(path, e))?.len();
    let mut bytes = Vec::new();
    usize::try_from(len)
        .ok()
        .and_then(|n| bytes.try_reserve_exact(n).ok())
        .ok_or_else(|| {
            Error::too_large(format!(
                "{}: {len} bytes do not fit in memory",
                path.display()
            ))
        })?;
    file.read_to_end(&mut bytes)
        .map_err(|e| io_error(path, e))?;
    Ok(bytes)
}

impl LevelFile {
    pub(crate) fn open(path: &Path, kind: Kind, options: OpenOptions) -> Result<LevelFile> {
        let bytes = match options.mode {
            Mode::Loaded => Bytes::Owned(read_bytes(path)?),
            Mode::Mapped => Bytes::Mapped(super::map::map_file(path)?),
        };
        Self::parse(bytes, kind, options)
            .map_err(|e| Error::new(e.kind, format!("{}: {}", path.display(), e.message)))
    }

    pub(crate) fn parse(bytes: Bytes, kind: Kind, options: OpenOptions) -> Result<LevelFile> {
        let header = format::decode_header(&bytes, kind)?;
        let n = header.sections as usize;
        let table = &bytes[HEADER_BYTES..HEADER_BYTES + n * format::ENTRY_BYTES];
        let checksums = options.verify != Verify::Trusted;
        if checksums {
            let stored = u32::from_le_bytes([bytes[40], bytes[41], bytes[42], bytes[43]]);
            if format::table_crc(&bytes[..format::CHECKED_HEADER], table) != stored {
                return Err(format::bad(
                    40,
                    "the header or the section table fails its checksum",
                ));
            }
        }
        let mut entries: Vec<Entry> = Vec::new();
        for i in 0..n {
            let e = format::decode_entry(table, i, header.file_len)?;
            if entries.iter().any(|x| x.name == e.name) {
                let at = (HEADER_BYTES + i * format::ENTRY_BYTES) as u64;
                return Err(format::bad(at, format!("section {} appears twice", e.name)));
            }
            entries.push(e);
        }
        Ok(LevelFile {
            bytes,
            header,
            entries,
            checksums,
            verify: options.verify,
        })
    }

    pub(crate) fn has(&self, name: &str) -> bool {
        self.entries.iter().any(|e| e.name == name)
    }

    /// The entry of section `name`, of element type `elem`.
    fn section(&self, name: &str, elem: Elem) -> Result<&Entry> {
        let e = self
            .entries
            .iter()
            .find(|e| e.name == name)
            .ok_or_else(|| Error::parse(format!("section {name} is missing")))?;
        if e.elem != elem {
            return Err(format::bad(
                e.offset,
                format!("section {name} holds {:?}, expected {elem:?}", e.elem),
            ));
        }
        Ok(e)
    }

    /// Section `name` of `u32`s, holding exactly `expected` elements (checked before its
    /// checksum, so that the error says what is wrong).
    pub(crate) fn u32s(&self, name: &str, expected: usize) -> Result<Vec<u32>> {
        let (e, b) = self.checked(name, Elem::U32, expected)?;
        collect(
            e,
            b.chunks_exact(4)
                .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])),
        )
    }

    /// Section `name` of `u32`s, of any length (the file's size bounds it).
    pub(crate) fn u32s_any(&self, name: &str) -> Result<Vec<u32>> {
        let n = self.count(name)?;
        self.u32s(name, n)
    }

    pub(crate) fn u64s(&self, name: &str, expected: usize) -> Result<Vec<u64>> {
        let (e, b) = self.checked(name, Elem::U64, expected)?;
        collect(
            e,
            b.chunks_exact(8)
                .map(|c| u64::from_le_bytes(c.try_into().unwrap_or_default())),
        )
    }

    /// Section `name` of `T`s (stored as `elem`), holding exactly `expected` elements of
    /// `T` (`width` file elements each): lent from a mapped file as it lies when the host
    /// is little-endian, else copied out.
    pub(crate) fn store<T: bytemuck::Pod>(
        &self, name: &str, elem: Elem, expected: usize, width: usize,
    ) -> Result<Store<T>> {
        debug_assert_eq!(size_of::<T>() as u64, width as u64 * elem.size());
        let count = expected
            .checked_mul(width)
            .ok_or_else(|| Error::parse(format!("section {name}: {expected} elements")))?;
        let (e, b) = self.checked(name, elem, count)?;
        if let Bytes::Mapped(map) = &self.bytes
            && cfg!(target_endian = "little")
        {
            let start = e.offset as usize;
            if let Some(s) = Store::mapped(map, start..start + b.len()) {
                return Ok(s);
            }
        }
        let mut out = Vec::new();
        out.try_reserve_exact(expected).map_err(|_| {
            Error::too_large(format!(
                "section {}: {} elements do not fit in memory",
                e.name, e.count
            ))
        })?;
        out.extend(
            b.chunks_exact(size_of::<T>())
                .map(|c| from_le::<T>(c, elem.size() as usize)),
        );
        Ok(Store::Owned(out))
    }

    /// Section `name` of `u32` ids, `expected` of them, as [`LevelFile::store`] lends them.
    pub(crate) fn ids(&self, name: &str, expected: usize) -> Result<Store<u32>> {
        self.store(name, Elem::U32, expected, 1)
    }

    /// Section `name` of `u64` words, `expected` of them, as [`LevelFile::store`] lends them.
    pub(crate) fn words(&self, name: &str, expected: usize) -> Result<Store<u64>> {
        self.store(name, Elem::U64, expected, 1)
    }

    /// The element count of section `name`.
    pub(crate) fn count(&self, name: &str) -> Result<usize> {
        self.entries
            .iter()
            .find(|e| e.name == name)
            .map(|e| e.count as usize)
            .ok_or_else(|| Error::parse(format!("section {name} is missing")))
    }

    fn checked(&self, name: &str, elem: Elem, expected: usize) -> Result<(&Entry, &[u8])> {
        let e = self.section(name, elem)?;
        if e.count != expected as u64 {
            return Err(format::bad(
                e.offset,
                format!(
                    "section {name} holds {} elements, the counts say {expected}",
                    e.count
                ),
            ));
        }
        let bytes = &self.bytes[e.offset as usize..(e.offset + e.byte_len()) as usize];
        if self.checksums && format::section_crc(bytes) != e.crc {
            return Err(format::bad(
                e.offset,
                format!("section {name} fails its checksum"),
            ));
        }
        Ok((e, bytes))
    }
}

/// One `T` from its little-endian bytes, `word` bytes per file element.
fn from_le<T: bytemuck::Pod>(c: &[u8], word: usize) -> T {
    let mut x = T::zeroed();
    let out = bytemuck::bytes_of_mut(&mut x);
    out.copy_from_slice(c);
    if cfg!(target_endian = "big") {
        out.chunks_exact_mut(word).for_each(|w| w.reverse());
    }
    x
}

/// The elements into a vector reserved fallibly (its length is bounded by the file's).
fn collect<T>(e: &Entry, xs: impl Iterator<Item = T>) -> Result<Vec<T>> {
    let mut out = Vec::new();
    out.try_reserve_exact(e.count as usize).map_err(|_| {
        Error::too_large(format!(
            "section {}: {} elements do not fit in memory",
            e.name, e.count
        ))
    })?;
    out.extend(xs);
    Ok(out)
}
