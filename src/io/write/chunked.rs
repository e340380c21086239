//! A buffered writer that writes only whole chunks of 2 MiB (and the rest at the end), so
//! that every write but the last covers one 2 MiB-aligned stretch of the file. A file
//! system with large page-cache folios (ext4, XFS) then caches each stretch as one huge
//! folio, and a mapping of the file (a mapped open of a level file written just before)
//! maps it with one page-table entry and one fault instead of 512 of each. A
//! `BufWriter` flushes whatever it holds when a write does not fit, which leaves the
//! writes, and so the folios, unaligned.

use crate::error::Result;
use crate::util::alloc::try_with_capacity;
use std::io::Write;

/// The size of every write but the last: the huge page of x86-64 and most of AArch64.
const CHUNK: usize = 2 << 20;

pub(crate) struct Chunked<W: Write> {
    inner: W,
    buf: Vec<u8>,
}

impl<W: Write> Chunked<W> {
    /// A writer into `inner`, its buffer reserved fallibly.
    pub(crate) fn new(inner: W) -> Result<Chunked<W>> {
        let buf = try_with_capacity(CHUNK, "the write buffer")?;
        Ok(Chunked { inner, buf })
    }

    /// Writes what is buffered and hands back the inner writer.
    pub(crate) fn into_inner(mut self) -> std::io::Result<W> {
        self.flush()?;
        Ok(self.inner)
    }
}

impl<W: Write> Write for Chunked<W> {
    fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
        let n = (CHUNK - self.buf.len()).min(data.len());
        self.buf.extend_from_slice(&data[..n]);
        if self.buf.len() == CHUNK {
            self.inner.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.inner.write_all(&self.buf)?;
        self.buf.clear();
        self.inner.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::{CHUNK, Chunked};
    use std::io::Write;

    /// Records the length of every write it is given.
    struct Writes(Vec<usize>, Vec<u8>);

    impl Write for Writes {
        fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
            self.0.push(data.len());
            self.1.extend_from_slice(data);
            Ok(data.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    /// Pieces of odd sizes arrive as whole chunks then the rest, bytes unchanged.
    #[test]
    fn writes_whole_chunks_then_the_rest() {
        let mut w = Chunked::new(Writes(Vec::new(), Vec::new())).unwrap();
        let mut expected = Vec::new();
        for i in 0..700usize {
            let piece: Vec<u8> = (0..(i * 37) % 16_411).map(|j| (i + j) as u8).collect();
            w.write_all(&piece).unwrap();
            expected.extend_from_slice(&piece);
        }
        let inner = w.into_inner().unwrap();
        let (last, whole) = inner.0.split_last().unwrap();
        assert!(whole.iter().all(|&n| n == CHUNK), "{whole:?}");
        assert_eq!(*last, expected.len() % CHUNK);
        assert_eq!(inner.1, expected);
    }
}
