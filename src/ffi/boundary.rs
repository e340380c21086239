//! The one boundary every export runs behind (its shapes are the macros of `shapes`):
//! `guard` / `guard_or` run a body under `catch_unwind` and turn a `crate::Error` into its
//! status plus a thread-local detail; the `*_arg` helpers are the null checks, each naming
//! the argument; `Sink` and `CsrSink` write variable-size answers into caller buffers.

use super::status::Status;
use crate::che::{Push, Rows};
use crate::error::{Error, ErrorKind, Result};
use std::cell::RefCell;
use std::ffi::{CStr, c_char};
use std::mem::MaybeUninit;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::ptr::NonNull;
use std::sync::OnceLock;

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Reads the detail of the last failure on this thread.
pub(crate) fn with_last_error<R>(f: impl FnOnce(&str) -> R) -> R {
    LAST_ERROR.with(|e| f(&e.borrow()))
}

/// Records `e` as the last error and returns its status.
fn fail(e: Error) -> Status {
    LAST_ERROR.with(|last| *last.borrow_mut() = e.message);
    super::status::STATUSES[e.kind as usize + 1].0
}

fn caught(payload: Box<dyn std::any::Any + Send>) -> Status {
    // A query without an error in its signature (`util::alloc::or_panic`): its error.
    let payload = match payload.downcast::<Error>() {
        Ok(e) => return fail(*e),
        Err(payload) => payload,
    };
    let what = (payload.downcast_ref::<&str>().map(|s| s.to_string()))
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic payload".to_string());
    let at = crate::util::panics::take_location().map_or(String::new(), |l| format!(" at {l}"));
    fail(Error::new(
        ErrorKind::Panic,
        format!("internal error (please report): {what}{at}"),
    ))
}

/// `catch_unwind` with the panic hook silent: a panic here is the caller's to report (as
/// `TOPOMESH_STATUS_PANIC` and its detail), never text on the host's stderr.
#[inline(always)]
pub(crate) fn catch<R>(body: impl FnOnce() -> R) -> std::thread::Result<R> {
    crate::util::panics::quiet(|| catch_unwind(AssertUnwindSafe(body)))
}

/// Runs an export body: `Ok` -> `TOPOMESH_STATUS_OK`; an error or a panic -> its status,
/// with the detail recorded for `topomesh_last_error`. Nothing unwinds past this, and a
/// panic prints nothing.
#[inline(always)]
pub(crate) fn guard(body: impl FnOnce() -> Result<()>) -> Status {
    match catch(body) {
        Ok(Ok(())) => Status::Ok,
        Ok(Err(e)) => fail(e),
        Err(payload) => caught(payload),
    }
}

/// A panic inside `guard`, in the last of `jobs` jobs run as a build runs them (the first
/// on the calling thread, each other on a thread of its own), for the tests that check it
/// prints nothing and gives `TOPOMESH_STATUS_PANIC` (no export panics on purpose).
#[doc(hidden)]
pub fn guarded_panic(message: &str, jobs: usize) -> Status {
    guard(|| {
        crate::util::par::run_all((0..jobs).collect(), |j| {
            assert!(j + 1 < jobs, "{message}");
        });
        Ok(())
    })
}

/// `guard` for a body that returns a value (counts, views): `fallback` on a failure.
#[inline(always)]
pub(crate) fn guard_or<T>(fallback: T, body: impl FnOnce() -> Result<T>) -> T {
    let mut value = fallback;
    guard(|| {
        value = body()?;
        Ok(())
    });
    value
}

fn null(name: &str) -> Error {
    Error::new(
        ErrorKind::NullArgument,
        format!("argument '{name}' is NULL"),
    )
}

/// A checked, non-NULL out-parameter: written once, never read.
pub(crate) struct Out<T>(NonNull<T>);

impl<T> Out<T> {
    pub(crate) fn set(&self, value: T) {
        // SAFETY: `out_arg`'s contract: valid for one aligned write. `write` does not read
        // or drop the (possibly uninitialised) old value.
        unsafe { self.0.as_ptr().write(value) }
    }
}

// Each `*_arg` below: `p` is NULL or valid for the access its type states during `'a`.

/// An out-parameter, or a NULL_ARGUMENT error naming it.
pub(crate) unsafe fn out_arg<T>(p: *mut T, name: &str) -> Result<Out<T>> {
    NonNull::new(p).map(Out).ok_or_else(|| null(name))
}

/// A handle (or any input struct) by reference.
pub(crate) unsafe fn handle<'a, T>(p: *const T, name: &str) -> Result<&'a T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_ref() }.ok_or_else(|| null(name))
}

/// A handle by exclusive reference.
pub(crate) unsafe fn handle_mut<'a, T>(p: *mut T, name: &str) -> Result<&'a mut T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_mut() }.ok_or_else(|| null(name))
}

/// An input array of `len` elements (`len * size_of::<T>()` fits `isize`: the callers
/// check sizes first); NULL is accepted (as empty) only when `len == 0`.
pub(crate) unsafe fn slice_arg<'a, T>(p: *const T, len: usize, name: &str) -> Result<&'a [T]> {
    match (len, p.is_null()) {
        (0, _) => Ok(&[]),
        (_, true) => Err(null(name)),
        // SAFETY: non-NULL, valid for `len` reads (contract), and aligned (C arrays of `T`).
        _ => Ok(unsafe { std::slice::from_raw_parts(p, len) }),
    }
}

/// An options struct, or its default when `p` is NULL.
pub(crate) unsafe fn options_arg<T: Copy + Default>(p: *const T) -> T {
    // SAFETY: forwarded contract.
    unsafe { p.as_ref() }.copied().unwrap_or_default()
}

/// A NUL-terminated path: its bytes as they are on Unix, UTF-8 elsewhere.
pub(crate) unsafe fn path_arg<'a>(p: *const c_char, name: &str) -> Result<&'a std::path::Path> {
    if p.is_null() {
        return Err(null(name));
    }
    // SAFETY: non-NULL and NUL-terminated (contract).
    let path = unsafe { CStr::from_ptr(p) };
    #[cfg(unix)]
    let path = <std::ffi::OsStr as std::os::unix::ffi::OsStrExt>::from_bytes(path.to_bytes());
    #[cfg(not(unix))]
    let path = (path.to_str().map(std::ffi::OsStr::new))
        .map_err(|e| Error::invalid(format!("path is not UTF-8: {e}")))?;
    Ok(std::path::Path::new(path))
}

/// A C level as the core's, or OUT_OF_RANGE.
pub(crate) fn level_arg(level: u32) -> Result<u8> {
    match level {
        0..=3 => Ok(level as u8),
        _ => Err(Error::out_of_range(format!("level {level} is not in 0..3"))),
    }
}

/// The `TOPOMESH_WRITE_*` flags as write options, or INVALID_INPUT naming the unknown
/// bits.
pub(crate) fn write_flags_arg(flags: u32) -> Result<crate::io::WriteOptions> {
    use super::{TOPOMESH_WRITE_BINARY, TOPOMESH_WRITE_NO_ORIGIN};
    let unknown = flags & !(TOPOMESH_WRITE_BINARY | TOPOMESH_WRITE_NO_ORIGIN);
    if unknown != 0 {
        return Err(Error::invalid(format!(
            "flags {flags:#x}: unknown bits {unknown:#x} (known: TOPOMESH_WRITE_BINARY, TOPOMESH_WRITE_NO_ORIGIN)"
        )));
    }
    Ok(crate::io::WriteOptions {
        format: None,
        binary: flags & TOPOMESH_WRITE_BINARY != 0,
        no_origin: flags & TOPOMESH_WRITE_NO_ORIGIN != 0,
    })
}

/// `TOPOMESH_OPEN_*` flags as open options; an unknown bit is an error.
pub(crate) fn open_flags_arg(flags: u32) -> Result<crate::levelfile::OpenOptions> {
    use super::{TOPOMESH_OPEN_CHECKSUMS_ONLY, TOPOMESH_OPEN_TRUSTED};
    use crate::levelfile::{OpenOptions, Verify};
    let unknown = flags & !(TOPOMESH_OPEN_CHECKSUMS_ONLY | TOPOMESH_OPEN_TRUSTED);
    if unknown != 0 {
        return Err(Error::invalid(format!(
            "flags {flags:#x}: unknown bits {unknown:#x} (known: TOPOMESH_OPEN_CHECKSUMS_ONLY, TOPOMESH_OPEN_TRUSTED)"
        )));
    }
    let verify = if flags & TOPOMESH_OPEN_TRUSTED != 0 {
        Verify::Trusted
    } else if flags & TOPOMESH_OPEN_CHECKSUMS_ONLY != 0 {
        Verify::Checksums
    } else {
        Verify::Full
    };
    Ok(OpenOptions { verify })
}

/// The entry of `all` that C enum value `kind` names (`all` in the C enum's order: report
/// kinds, export arrays), or OUT_OF_RANGE naming the enum.
pub(crate) fn report_kind<T, const N: usize>(all: [T; N], kind: u32, name: &str) -> Result<T> {
    let max = N - 1;
    let error = || Error::out_of_range(format!("kind {kind} is not a {name} (0..{max})"));
    all.into_iter().nth(kind as usize).ok_or_else(error)
}

/// Pairs (or triples) of ids, flattened.
pub(crate) fn flat<const K: usize>(xs: &[[u32; K]]) -> Vec<u32> {
    xs.iter().flatten().copied().collect()
}

/// The core's origin map, or the identity on `0..n` materialised once in `cell`.
pub(crate) fn origins<'a>(
    map: Option<&'a [u32]>, cell: &'a OnceLock<Box<[u32]>>, n: usize,
) -> &'a [u32] {
    map.unwrap_or_else(|| cell.get_or_init(|| (0..n as u32).collect()))
}

/// The core structure behind a handle, or a NULL_ARGUMENT error naming `m`.
pub(crate) unsafe fn core<'a, H: Handle + 'a>(m: *const H) -> Result<&'a H::Core> {
    // SAFETY: forwarded contract.
    Ok(unsafe { handle(m, "m")? }.core())
}

/// An opaque handle over a core structure (`Che`, `Chf`): the macros of `shapes` call the
/// core through it.
pub(crate) trait Handle {
    type Core;
    fn core(&self) -> &Self::Core;
    fn core_mut(&mut self) -> &mut Self::Core;
    /// The reader's warnings, `file:line: message` each (none for a mesh built from arrays).
    fn warnings(&self) -> &[String];
}

/// Copies `text` into `buf` NUL-terminated, truncated to `cap` bytes (`buf` NULL is a size
/// query); `*out_len` gets the capacity needed, NUL included. False when it did not fit.
/// `buf` is NULL or valid for `cap` byte writes (caller contract).
pub(crate) unsafe fn text_out(
    text: &str, buf: *mut c_char, cap: usize, out_len: &Out<usize>,
) -> bool {
    let bytes = text.as_bytes();
    out_len.set(bytes.len() + 1);
    match (buf.is_null(), cap.checked_sub(1)) {
        (true, _) => true,
        (false, None) => false,
        (false, Some(room)) => {
            let n = bytes.len().min(room);
            // SAFETY: `buf` is valid for `cap > n` byte writes (caller contract), and
            // `bytes` is a Rust string that cannot overlap the caller's buffer.
            unsafe {
                std::ptr::copy_nonoverlapping(bytes.as_ptr(), buf.cast::<u8>(), n);
                *buf.add(n) = 0;
            }
            n == bytes.len()
        }
    }
}

/// Warning `i` of handle `m` into `buf` (the buffer rules of `topomesh_last_error`).
pub(crate) unsafe fn warning_out<H: Handle>(
    m: *const H, i: usize, buf: *mut c_char, cap: usize, out_len: *mut usize,
) -> Result<()> {
    // SAFETY: forwarded contract.
    let (h, out_len) = unsafe { (handle(m, "m")?, out_arg(out_len, "out_len")?) };
    if buf.is_null() && cap != 0 {
        return Err(null("buf"));
    }
    let warnings = h.warnings();
    let text = warnings.get(i).ok_or_else(|| {
        let n = warnings.len();
        Error::out_of_range(format!(
            "warning {i} out of range (the mesh has {n} warnings)"
        ))
    })?;
    // SAFETY: forwarded contract.
    if unsafe { text_out(text, buf, cap, &out_len) } {
        return Ok(());
    }
    Err(Error::new(
        ErrorKind::BufferTooSmall,
        format!("buffer 'buf' holds {cap} bytes, {} needed", text.len() + 1),
    ))
}

/// Boxes a new handle into `*out`, which is NULL on every failure of `made`.
pub(crate) unsafe fn new_handle<T>(out: *mut *mut T, made: impl FnOnce() -> Result<T>) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let out = unsafe { out_arg(out, "out")? };
        out.set(std::ptr::null_mut());
        out.set(Box::into_raw(Box::new(made()?)));
        Ok(())
    })
}

/// Frees a handle made by `new_handle`; NULL is a no-op. Guarded although dropping plain
/// vectors cannot panic, so that nothing ever unwinds.
pub(crate) unsafe fn free_handle<T>(p: *mut T) {
    guard(|| {
        if !p.is_null() {
            // SAFETY: made by `Box::into_raw` in `new_handle` and not freed (contract).
            drop(unsafe { Box::from_raw(p) });
        }
        Ok(())
    });
}

/// A caller buffer for a variable-size answer. `buf == NULL` with `cap == 0` is a size
/// query; otherwise the first `cap` entries are written, the rest only counted, and
/// `finish` reports the full length in `*out_len` and BUFFER_TOO_SMALL when it did not fit.
pub(crate) struct Sink<'a, T = u32> {
    buf: &'a mut [MaybeUninit<T>],
    query: bool,
    len: usize,
    out_len: Out<usize>,
    name: &'static str,
}

impl<'a, T: Copy> Sink<'a, T> {
    /// `buf` is NULL or valid for `cap` writes during `'a`; `out_len` NULL or writable.
    pub(crate) unsafe fn new(
        buf: *mut T, cap: usize, out_len: *mut usize, name: &'static str,
    ) -> Result<Self> {
        // SAFETY: forwarded contract.
        let out_len = unsafe { out_arg(out_len, "out_len")? };
        let query = buf.is_null();
        if query && cap != 0 {
            return Err(null(name));
        }
        // No object is larger than isize::MAX bytes, so a larger `cap` (say SIZE_MAX for
        // "unbounded") cannot be the real size: clamp it rather than build an invalid slice.
        let cap = cap.min(isize::MAX as usize / size_of::<T>().max(1));
        let buf = if query {
            &mut []
        } else {
            // SAFETY: non-NULL, valid for `cap` writes (contract); viewed as uninitialised.
            unsafe { std::slice::from_raw_parts_mut(buf.cast(), cap) }
        };
        Ok(Sink {
            buf,
            query,
            len: 0,
            out_len,
            name,
        })
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

    /// Writes `*out_len`; BUFFER_TOO_SMALL if the answer did not fit.
    pub(crate) fn finish(self) -> Result<()> {
        self.out_len.set(self.len);
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
/// offsets[i + 1]]`, so `offsets` has one entry per row plus one. Both buffers NULL
/// (capacities 0) is a size query; exactly one NULL is an error; either too small gives
/// BUFFER_TOO_SMALL with both needed lengths written (the buffers then hold a prefix).
pub(crate) struct CsrSink<'a> {
    offsets: Sink<'a>,
    indices: Sink<'a>,
}

impl CsrSink<'_> {
    /// `(offsets, offsets_cap, n_offsets)` and the same for the indices, checked.
    pub(crate) unsafe fn new(bufs: [(*mut u32, usize, *mut usize); 2]) -> Result<Self> {
        let [(o, oc, no), (i, ic, ni)] = bufs;
        if o.is_null() != i.is_null() {
            return Err(null(if o.is_null() { "offsets" } else { "indices" }));
        }
        // SAFETY: forwarded contract.
        let (offsets, indices) = unsafe {
            (
                Sink::new(o, oc, no, "offsets")?,
                Sink::new(i, ic, ni, "indices")?,
            )
        };
        Ok(CsrSink { offsets, indices })
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
