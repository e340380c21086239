//! Variable-size answers written into storage the caller owns (the C API's `(buf, cap,
//! *out_len)` buffers): the first entries that fit are written, all are counted, and the
//! caller learns the full length, with BUFFER_TOO_SMALL when it did not fit. The C skin
//! only turns its pointers into the slices these take.

use crate::che::{Push, Rows};
use crate::error::{Error, ErrorKind, Result};
use crate::util::sparse::SparseMatrix;
use std::mem::MaybeUninit;

/// A bounded writer: `buf` `None` is a size query (everything is counted, nothing
/// written); `finish` writes the full length into `out_len`.
pub(crate) struct Sink<'a, T = u32> {
    buf: &'a mut [MaybeUninit<T>],
    query: bool,
    len: usize,
    out_len: &'a mut MaybeUninit<usize>,
    name: &'static str,
}

impl<'a, T: Copy> Sink<'a, T> {
    /// `name` names the buffer in the BUFFER_TOO_SMALL detail.
    pub(crate) fn new(
        buf: Option<&'a mut [MaybeUninit<T>]>, out_len: &'a mut MaybeUninit<usize>,
        name: &'static str,
    ) -> Self {
        let query = buf.is_none();
        let buf = buf.unwrap_or_default();
        Sink {
            buf,
            query,
            len: 0,
            out_len,
            name,
        }
    }

    pub(crate) fn extend(&mut self, xs: impl IntoIterator<Item = T>) {
        xs.into_iter().for_each(|x| self.put(x));
    }

    /// One entry: written when it fits, counted always.
    #[inline(always)]
    pub(crate) fn put(&mut self, x: T) {
        if let Some(slot) = self.buf.get_mut(self.len) {
            slot.write(x);
        }
        self.len += 1;
    }

    /// Writes the full length; BUFFER_TOO_SMALL if the answer did not fit.
    pub(crate) fn finish(self) -> Result<()> {
        self.out_len.write(self.len);
        if self.query || self.len <= self.buf.len() {
            return Ok(());
        }
        let (name, cap, len) = (self.name, self.buf.len(), self.len);
        Err(Error::new(
            ErrorKind::BufferTooSmall,
            format!("buffer '{name}' holds {cap} entries, {len} needed"),
        ))
    }
}

// The core's walks write straight into the caller's buffers.
impl Push for Sink<'_> {
    #[inline(always)]
    fn push(&mut self, x: u32) {
        self.put(x);
    }
}

/// A bulk answer in compressed sparse rows: row `i` is `indices[offsets[i] ..
/// offsets[i + 1]]`, so `offsets` has one entry per row plus one. Either sink too small
/// gives BUFFER_TOO_SMALL with both lengths written (the buffers then hold a prefix).
pub(crate) struct CsrSink<'a> {
    offsets: Sink<'a>,
    indices: Sink<'a>,
}

impl<'a> CsrSink<'a> {
    pub(crate) fn new(offsets: Sink<'a>, indices: Sink<'a>) -> Self {
        CsrSink { offsets, indices }
    }

    /// One row.
    pub(crate) fn stream(&mut self, row: impl IntoIterator<Item = u32>) {
        self.row();
        self.indices.extend(row);
    }

    /// The rows of a table computed in full.
    pub(crate) fn copy(&mut self, csr: &crate::chf::Csr) {
        (0..csr.len()).for_each(|i| self.stream(csr.row(i).iter().copied()));
    }

    /// Closes the last row and reports both lengths.
    pub(crate) fn finish(mut self) -> Result<()> {
        self.row();
        if self.indices.len > u32::MAX as usize {
            let n = self.indices.len;
            return Err(Error::too_large(format!(
                "{n} indices do not fit 32-bit offsets"
            )));
        }
        let offsets = self.offsets.finish();
        offsets.and(self.indices.finish())
    }
}

impl Push for CsrSink<'_> {
    #[inline(always)]
    fn push(&mut self, x: u32) {
        self.indices.push(x);
    }
}

impl Rows for CsrSink<'_> {
    #[inline(always)]
    fn row(&mut self) {
        let at = self.indices.len as u32;
        self.offsets.push(at);
    }
}

impl SparseMatrix {
    /// The offsets, columns and values into three sinks; BUFFER_TOO_SMALL when any is
    /// short (all three lengths are written whatever happens).
    pub(crate) fn write_into(
        self, (mut o, mut k, mut v): (Sink<u64>, Sink<u32>, Sink<f64>),
    ) -> Result<()> {
        o.extend(self.offsets);
        k.extend(self.columns);
        v.extend(self.values);
        let (o, k) = (o.finish(), k.finish());
        o.and(k).and(v.finish())
    }
}

/// Copies `text` into `buf` NUL-terminated, truncated to its length (`None` is a size
/// query). Gives the capacity needed, NUL included, and whether it fitted.
pub(crate) fn copy_text(text: &str, buf: Option<&mut [MaybeUninit<u8>]>) -> (usize, bool) {
    let bytes = text.as_bytes();
    let needed = bytes.len() + 1;
    let Some(buf) = buf else {
        return (needed, true);
    };
    let Some(room) = buf.len().checked_sub(1) else {
        return (needed, false);
    };
    let n = bytes.len().min(room);
    buf.iter_mut().zip(&bytes[..n]).for_each(|(s, &b)| {
        s.write(b);
    });
    buf[n].write(0);
    (needed, n == bytes.len())
}

/// The entry of `all` that the C enum value `kind` names (`all` in the C enum's order:
/// report kinds, export arrays), or OUT_OF_RANGE naming the enum.
pub(crate) fn pick<T, const N: usize>(all: [T; N], kind: u32, name: &str) -> Result<T> {
    let max = N - 1;
    let error = || Error::out_of_range(format!("kind {kind} is not a {name} (0..{max})"));
    all.into_iter().nth(kind as usize).ok_or_else(error)
}
