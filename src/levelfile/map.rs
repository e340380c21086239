//! The `unsafe`s of the level files: mapping a file into memory, read-only to open it, and
//! writable to fill a new file in place (the streaming build writes arrays larger than
//! memory straight into their sections), with its disk blocks reserved first; and giving
//! back the resident pages of a mapping (a sweep over a file larger than memory).

use crate::error::{Error, Result};
use memmap2::{Mmap, MmapMut};
use std::path::Path;
use std::sync::Arc;

/// `path` mapped read-only, shared by every array a mapped structure borrows from it.
pub(crate) fn map_file(path: &Path) -> Result<Arc<Mmap>> {
    let io = |e: std::io::Error| Error::io(format!("{}: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(io)?;
    // SAFETY: the file is opened read-only and mapped read-only (shared with the page
    // cache), so nothing in this process writes through the mapping or aliases it
    // mutably, and every access goes through `&[u8]` slices bounds-checked against the
    // mapping's length (the sections were checked to lie inside it). What Rust cannot
    // rule out is another process changing the file while it is mapped, which memmap2
    // documents as the caveat of every mapping: a write in place changes bytes behind a
    // shared slice (formally undefined behaviour; in practice a query answers as on a
    // damaged trusted file), and a truncation makes an access past the new end raise
    // SIGBUS, which ends the process. Level files are written once, replaced only by
    // atomic rename (which leaves this mapping on the old file), and then only read; the
    // contract is stated on `Mode::Mapped` and `TOPOMESH_OPEN_MAPPED`.
    let map = unsafe { Mmap::map(&file) }.map_err(io)?;
    // A file read from disk through this mapping then comes into the page cache in huge
    // folios, each mapped by one entry (the file system willing); best effort: a kernel
    // without transparent huge pages refuses, and the mapping works as it is.
    #[cfg(target_os = "linux")]
    let _ = map.advise(memmap2::Advice::HugePage);
    Ok(Arc::new(map))
}

/// The new file `file` (at `path`, for errors) mapped writable, to be filled in place.
pub(crate) fn map_new_file_mut(file: &std::fs::File, path: &Path) -> Result<MmapMut> {
    // SAFETY: `file` is a temporary file this process has just created exclusively
    // (`create_new`) under a name of its own, and sized before this call; this mapping is
    // the only one, and every access goes through the `&mut [u8]` it derefs to, bounds-
    // checked against its length. As for `map_file`, another process that truncates or
    // writes the temporary file while it is mapped is outside what Rust can rule out (a
    // truncation raises SIGBUS); nothing else knows the temporary name.
    unsafe { MmapMut::map_mut(file) }.map_err(|e| Error::io(format!("{}: {e}", path.display())))
}

/// Reserves the disk blocks of the first `len` bytes of `file` (at `path`, for errors), so
/// that filling them through a mapping cannot fail for want of space: a full disk would
/// then raise SIGBUS, which ends the process, where here it is an error naming the file.
/// Linux only; elsewhere the mapping is written unreserved.
#[cfg(target_os = "linux")]
pub(crate) fn reserve(file: &std::fs::File, len: u64, path: &Path) -> Result<()> {
    use std::os::fd::AsRawFd;
    let room =
        |e: std::io::Error| Error::io(format!("{}: no room for {len} bytes: {e}", path.display()));
    let n = libc::off_t::try_from(len)
        .map_err(|_| room(std::io::Error::from_raw_os_error(libc::EFBIG)))?;
    // SAFETY: posix_fallocate reads and writes no memory of this process: it takes the
    // descriptor of a file held open (borrowed for the call) and two integers.
    let rc = unsafe { libc::posix_fallocate(file.as_raw_fd(), 0, n) };
    match rc {
        0 => Ok(()),
        e => Err(room(std::io::Error::from_raw_os_error(e))),
    }
}

#[cfg(not(target_os = "linux"))]
pub(crate) fn reserve(_: &std::fs::File, _: u64, _: &Path) -> Result<()> {
    Ok(())
}

/// Takes the pages of `map` out of this process's resident set; they come back from the
/// file (usually still in the page cache) when next read. Elsewhere than on Unix, nothing.
#[cfg(not(unix))]
pub(crate) fn release(_: &Mmap) -> Result<()> {
    Ok(())
}

/// Takes the pages of `map` out of this process's resident set; they come back from the
/// file (usually still in the page cache) when next read.
#[cfg(unix)]
pub(crate) fn release(map: &Mmap) -> Result<()> {
    use memmap2::UncheckedAdvice;
    // SAFETY: `map` is a read-only shared mapping of a file (`map_file`), and nothing writes
    // through it. MADV_DONTNEED on such a mapping only drops the page-table entries: the
    // next access faults the same bytes in again from the file, so every slice into the
    // mapping stays valid and reads what it read before. (What memmap2 guards against with
    // `unsafe` is a private or anonymous mapping, whose written pages would be lost.)
    unsafe { map.unchecked_advise(UncheckedAdvice::DontNeed) }
        .map_err(|e| Error::io(format!("giving back the pages of a mapped file: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::util::store::Store;

    #[test]
    fn a_mapped_range_reads_in_place_and_copies_on_write() {
        let path = std::env::temp_dir().join(format!("topomesh-map-{}", std::process::id()));
        let words: Vec<u8> = (0u32..32).flat_map(|x| x.to_le_bytes()).collect();
        std::fs::write(&path, &words).unwrap();
        let map = map_file(&path).unwrap();
        let mut s: Store<u32> = Store::mapped(&map, 64..128).unwrap();
        assert!(s.is_mapped());
        assert_eq!(&s[..], &(16u32..32).collect::<Vec<_>>()[..]);
        assert!(Store::<u32>::mapped(&map, 2..6).is_none(), "misaligned");
        assert!(
            Store::<u32>::mapped(&map, 64..132).is_none(),
            "past the end"
        );
        let shared = s.clone();
        s.to_mut("test").unwrap()[0] = 7;
        assert!(!s.is_mapped());
        assert_eq!(s[0], 7);
        assert_eq!(shared[0], 16, "the mapping is not written");
        drop((s, shared, map));
        let _ = std::fs::remove_file(&path);
    }
}
