//! Reading a level file into owned arrays: the header and the table are checked against
//! the file's length before any section is touched, each section against its checksum
//! (unless trusted) when it is taken, and every length against the counts by the caller
//! (`che.rs`, `chf.rs`) before anything is indexed. A mapped file lends its sections as
//! they lie (`Store::Mapped`); a loaded one reads each section straight into its array,
//! in chunks checksummed while they are in cache, so that opening a file never holds it
//! twice.

use super::format::{self, Elem, Entry, HEADER_BYTES, Header, Kind};
use super::{Mode, OpenOptions, Verify};
use crate::error::{Error, Result};
use crate::util::pages;
use crate::util::store::Store;
use bytemuck::Pod;
use memmap2::Mmap;
use std::cell::Cell;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::ops::Deref;
use std::path::Path;
use std::sync::Arc;

/// The bytes of a level file: mapped, or (a loaded open) its header and section table read
/// and the sections still in the file.
pub(crate) enum Bytes {
    Mapped(Arc<Mmap>),
    File { file: File, head: Vec<u8>, len: u64 },
}

impl Bytes {
    /// The length of the whole file.
    fn file_len(&self) -> u64 {
        match self {
            Bytes::File { len, .. } => *len,
            _ => self.len() as u64,
        }
    }
}

impl Deref for Bytes {
    type Target = [u8];
    /// The bytes in memory: the whole file mapped, or the header and table of a loaded one.
    fn deref(&self) -> &[u8] {
        match self {
            Bytes::Mapped(m) => m,
            Bytes::File { head, .. } => head,
        }
    }
}

/// A level file in memory, its header and table checked.
pub(crate) struct LevelFile {
    bytes: Bytes,
    pub header: Header,
    entries: Vec<Entry>,
    /// Whether each section is checked against its checksum when it is taken (turned on
    /// for the second run of [`LevelFile::alongside_sums`]).
    checksums: Cell<bool>,
    /// Whether the checksums are left to [`LevelFile::alongside_sums`] instead.
    deferred: bool,
    pub verify: Verify,
}

fn io_error(path: &Path, e: std::io::Error) -> Error {
    Error::io(format!("{}: {e}", path.display()))
}

/// The file at `path` opened, with its header and section table read (as much of them as
/// the file holds: `decode_header` says what is missing).
fn read_head(path: &Path) -> Result<Bytes> {
    let io = |e| io_error(path, e);
    let mut file = File::open(path).map_err(io)?;
    let len = file.metadata().map_err(io)?.len();
    let mut head = vec![0u8; (HEADER_BYTES as u64).min(len) as usize];
    file.read_exact(&mut head).map_err(io)?;
    if head.len() == HEADER_BYTES {
        let sections = u32::from_le_bytes([head[28], head[29], head[30], head[31]]);
        let end = HEADER_BYTES as u64 + u64::from(sections) * format::ENTRY_BYTES as u64;
        if end <= len {
            head.resize(end as usize, 0);
            file.read_exact(&mut head[HEADER_BYTES..]).map_err(io)?;
        }
    }
    Ok(Bytes::File { file, head, len })
}

impl LevelFile {
    pub(crate) fn open(path: &Path, kind: Kind, options: OpenOptions) -> Result<LevelFile> {
        let bytes = match options.mode {
            Mode::Loaded => read_head(path)?,
            Mode::Mapped => Bytes::Mapped(super::map::map_file(path)?),
        };
        Self::parse(bytes, kind, options)
            .map_err(|e| Error::new(e.kind, format!("{}: {}", path.display(), e.message)))
    }

    pub(crate) fn parse(bytes: Bytes, kind: Kind, options: OpenOptions) -> Result<LevelFile> {
        let header = format::decode_header(&bytes, bytes.file_len(), kind)?;
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
        // Only where a second thread pays: a machine with one, or a small file, would
        // only wait for the thread to start.
        let deferred = options.verify == Verify::Full
            && matches!(bytes, Bytes::Mapped(_))
            && crate::util::par::planned_threads(0, bytes.len() / 16) > 1;
        Ok(LevelFile {
            bytes,
            header,
            entries,
            checksums: Cell::new(checksums && !deferred),
            deferred,
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
        self.elements(self.checked(name, Elem::U32, expected)?, 1)
    }

    /// Section `name` of `u32`s, of any length (the file's size bounds it).
    pub(crate) fn u32s_any(&self, name: &str) -> Result<Vec<u32>> {
        let n = self.count(name)?;
        self.u32s(name, n)
    }

    pub(crate) fn u64s(&self, name: &str, expected: usize) -> Result<Vec<u64>> {
        self.elements(self.checked(name, Elem::U64, expected)?, 1)
    }

    /// Section `name` of `T`s (stored as `elem`), holding exactly `expected` elements of
    /// `T` (`width` file elements each): lent from a mapped file as it lies when the host
    /// is little-endian, else read or copied out.
    pub(crate) fn store<T: Pod>(
        &self, name: &str, elem: Elem, expected: usize, width: usize,
    ) -> Result<Store<T>> {
        debug_assert_eq!(size_of::<T>() as u64, width as u64 * elem.size());
        let count = expected
            .checked_mul(width)
            .ok_or_else(|| Error::parse(format!("section {name}: {expected} elements")))?;
        let e = self.checked(name, elem, count)?;
        if let Bytes::Mapped(map) = &self.bytes
            && cfg!(target_endian = "little")
        {
            let start = e.offset as usize;
            let len = self.in_memory(e)?.len();
            if let Some(s) = Store::mapped(map, start..start + len) {
                return Ok(s);
            }
        }
        Ok(Store::Owned(self.elements(e, width)?))
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

    /// The entry of section `name`, of element type `elem`, holding `expected` elements.
    fn checked(&self, name: &str, elem: Elem, expected: usize) -> Result<&Entry> {
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
        Ok(e)
    }

    /// `work` on this file, with every section's checksum computed meanwhile on a thread
    /// of its own when they were left to it (a mapped open with full verification: the
    /// checksums stream the file while the structural checks wait on scattered reads, so
    /// that each runs in the other's gaps). The answer is the one an open that checks
    /// each section as it is taken gives: when a checksum fails, `work` runs again so,
    /// and its error names the first damaged section it takes (as a loaded open does).
    pub(crate) fn alongside_sums<T>(&self, work: impl Fn(&LevelFile) -> Result<T>) -> Result<T> {
        if !self.deferred {
            return work(self);
        }
        // On one thread: `work` has the others.
        let (entries, bytes) = (&self.entries, &self.bytes);
        let sums_hold = || {
            entries
                .iter()
                .all(|e| mapped_bytes(bytes, e).is_ok_and(|b| crc32fast::hash(b) == e.crc))
        };
        std::thread::scope(|s| {
            let on_thread = std::thread::Builder::new().spawn_scoped(s, sums_hold).ok();
            let done = work(self);
            let held = match on_thread {
                Some(h) => h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)),
                None => sums_hold(),
            };
            if held {
                return done;
            }
            self.checksums.set(true);
            work(self)
        })
    }

    fn checksum_failed(e: &Entry) -> Error {
        format::bad(e.offset, format!("section {} fails its checksum", e.name))
    }

    /// The bytes of section `e` of a mapped file, checked against its checksum unless
    /// checksums are off or deferred to [`LevelFile::alongside_sums`].
    fn in_memory(&self, e: &Entry) -> Result<&[u8]> {
        let bytes = mapped_bytes(&self.bytes, e)?;
        if self.checksums.get() && format::section_crc(bytes) != e.crc {
            return Err(Self::checksum_failed(e));
        }
        Ok(bytes)
    }

    /// Section `e` of a loaded file, read in chunks from the file: each goes into the
    /// checksum while it is in cache, then to `take`; the checksum is compared at the end.
    fn read_section(&self, file: &File, e: &Entry, mut take: impl FnMut(&[u8])) -> Result<()> {
        // A multiple of every element's size (4, 8, and 24 for a point).
        const CHUNK: usize = 3 << 18;
        let io = |err: std::io::Error| format::bad(e.offset, format!("section {}: {err}", e.name));
        let room = e.byte_len().min(CHUNK as u64).div_ceil(8) as usize;
        let mut words = crate::util::alloc::try_vec(room, 0u64, "the read buffer")?;
        // Aligned for every element type, so that `take` can cast instead of copying.
        let buf: &mut [u8] = bytemuck::cast_slice_mut(&mut words);
        let mut file = file;
        file.seek(SeekFrom::Start(e.offset)).map_err(io)?;
        let mut crc = crc32fast::Hasher::new();
        let mut left = e.byte_len();
        while left > 0 {
            let n = left.min(CHUNK as u64) as usize;
            file.read_exact(&mut buf[..n]).map_err(io)?;
            if self.checksums.get() {
                crc.update(&buf[..n]);
            }
            take(&buf[..n]);
            left -= n as u64;
        }
        if self.checksums.get() && crc.finalize() != e.crc {
            return Err(Self::checksum_failed(e));
        }
        Ok(())
    }

    /// The elements of section `e` in a vector of their own, as `T`s of `width` file
    /// elements each, reserved fallibly (the file's length bounds their number).
    fn elements<T: Pod>(&self, e: &Entry, width: usize) -> Result<Vec<T>> {
        // On huge pages where the kernel has them: a loaded file is written fresh, and
        // with small pages a page fault every 4 KiB is a large share of reading it.
        let what = format!("section {}", e.name);
        let mut out = pages::with_capacity(e.count as usize / width, &what)?;
        let word = e.elem.size() as usize;
        let mut take = |b: &[u8]| match bytemuck::try_cast_slice::<u8, T>(b) {
            Ok(xs) if cfg!(target_endian = "little") => out.extend_from_slice(xs),
            _ => out.extend(
                b.chunks_exact(size_of::<T>())
                    .map(|c| from_le::<T>(c, word)),
            ),
        };
        match &self.bytes {
            Bytes::File { file, .. } => self.read_section(file, e, take)?,
            _ => take(self.in_memory(e)?),
        }
        Ok(out)
    }
}

/// The bytes of section `e` of a mapped file.
fn mapped_bytes<'a>(bytes: &'a Bytes, e: &Entry) -> Result<&'a [u8]> {
    usize::try_from(e.offset)
        .ok()
        .zip(usize::try_from(e.offset + e.byte_len()).ok())
        .and_then(|(a, b)| bytes.get(a..b))
        .ok_or_else(|| format::bad(e.offset, format!("section {} is not in memory", e.name)))
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
