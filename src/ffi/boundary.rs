//! The one boundary every export runs behind, and the helpers it is made of.
//!
//! The pattern of every export, CHE and CHF (the uniform shapes come as macros from
//! `shapes`), is:
//!
//! ```ignore
//! #[unsafe(no_mangle)]
//! pub unsafe extern "C" fn che_thing(m: *const CheMesh, id: u32, out: *mut u32) -> Status {
//!     guard(|| {
//!         // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
//!         let (m, out) = unsafe { (handle(m, "m")?, out_arg(out, "out")?) };
//!         m.che.check_vertex(id)?;
//!         out.set(m.che.something(id));
//!         Ok(())
//!     })
//! }
//! ```
//!
//! - `guard` / `guard_or` run the body under `catch_unwind` and turn a `crate::Error` into
//!   its status (the kinds map one to one) plus a thread-local detail message;
//! - `handle`, `handle_mut`, `out_arg`, `slice_arg`, `cstr_arg` are the null checks, each
//!   naming the argument in the detail;
//! - `Sink` writes a variable-size answer into a caller buffer (size query, too small),
//!   `CsrSink` a bulk offsets + indices answer;
//! - `new_handle` / `free_handle` box and unbox opaque handles; `Handle` gives the core
//!   structure a handle wraps;
//! - `options_arg` and `path_arg` convert an options struct and a path.

use super::status::Status;
use crate::error::{Error, ErrorKind, Result};
use std::any::Any;
use std::cell::RefCell;
use std::ffi::{CStr, c_char};
use std::mem::MaybeUninit;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::ptr::NonNull;

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Records the detail of a failure on this thread.
pub(crate) fn set_last_error(message: String) {
    LAST_ERROR.with(|e| *e.borrow_mut() = message);
}

/// Reads the detail of the last failure on this thread.
pub(crate) fn with_last_error<R>(f: impl FnOnce(&str) -> R) -> R {
    LAST_ERROR.with(|e| f(&e.borrow()))
}

/// The status of an error kind (one to one).
pub(crate) fn status_of(kind: ErrorKind) -> Status {
    match kind {
        ErrorKind::NullArgument => Status::NullArgument,
        ErrorKind::OutOfRange => Status::OutOfRange,
        ErrorKind::InvalidInput => Status::InvalidInput,
        ErrorKind::NonManifold => Status::NonManifold,
        ErrorKind::BufferTooSmall => Status::BufferTooSmall,
        ErrorKind::Io => Status::Io,
        ErrorKind::Parse => Status::Parse,
        ErrorKind::TooLarge => Status::TooLarge,
        ErrorKind::Panic => Status::Panic,
    }
}

fn panic_error(payload: Box<dyn Any + Send>) -> Error {
    let what = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic payload".to_string());
    Error::new(
        ErrorKind::Panic,
        format!("internal error (please report): {what}"),
    )
}

/// Records `e` as the last error and returns its status.
pub(crate) fn fail(e: Error) -> Status {
    let status = status_of(e.kind);
    set_last_error(e.message);
    status
}

/// Runs an export body: `Ok` -> `TOPOMESH_STATUS_OK`; an error or a panic -> its status,
/// with the detail recorded for `topomesh_last_error`. Nothing unwinds past this.
#[inline(always)]
pub(crate) fn guard(body: impl FnOnce() -> Result<()>) -> Status {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => Status::Ok,
        Ok(Err(e)) => fail(e),
        Err(payload) => fail(panic_error(payload)),
    }
}

/// Runs an export body that returns a value rather than a status (counts, views): on an
/// error or a panic, records the detail and returns `fallback`.
#[inline(always)]
pub(crate) fn guard_or<T>(fallback: T, body: impl FnOnce() -> Result<T>) -> T {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(v)) => v,
        Ok(Err(e)) => {
            fail(e);
            fallback
        }
        Err(payload) => {
            fail(panic_error(payload));
            fallback
        }
    }
}

pub(crate) fn null(name: &str) -> Error {
    Error::new(
        ErrorKind::NullArgument,
        format!("argument '{name}' is NULL"),
    )
}

/// A checked, non-NULL out-parameter: written once, never read.
pub(crate) struct Out<T>(NonNull<T>);

impl<T> Out<T> {
    /// # Safety
    /// `p` is NULL or valid for one aligned write of a `T`.
    pub(crate) unsafe fn new(p: *mut T) -> Option<Out<T>> {
        NonNull::new(p).map(Out)
    }
    pub(crate) fn set(&self, value: T) {
        // SAFETY: `new`'s contract: valid for one aligned write. `write` does not read or
        // drop the (possibly uninitialised) old value.
        unsafe { self.0.as_ptr().write(value) }
    }
}

/// An out-parameter, or a NULL_ARGUMENT error naming it.
///
/// # Safety
/// `p` is NULL or valid for one aligned write of a `T`.
pub(crate) unsafe fn out_arg<T>(p: *mut T, name: &str) -> Result<Out<T>> {
    // SAFETY: forwarded contract.
    unsafe { Out::new(p) }.ok_or_else(|| null(name))
}

/// A handle (or any input struct) by reference, or a NULL_ARGUMENT error naming it.
///
/// # Safety
/// `p` is NULL or points to a live `T` that nobody mutates during `'a`.
pub(crate) unsafe fn handle<'a, T>(p: *const T, name: &str) -> Result<&'a T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_ref() }.ok_or_else(|| null(name))
}

/// A handle by exclusive reference, or a NULL_ARGUMENT error naming it.
///
/// # Safety
/// `p` is NULL or points to a live `T` nobody else accesses during `'a`.
pub(crate) unsafe fn handle_mut<'a, T>(p: *mut T, name: &str) -> Result<&'a mut T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_mut() }.ok_or_else(|| null(name))
}

/// An input array of `len` elements; NULL is accepted (as empty) only when `len == 0`.
///
/// # Safety
/// `p` is NULL or valid for reads of `len` elements during `'a`; `len * size_of::<T>()`
/// fits `isize` (the callers check sizes first).
pub(crate) unsafe fn slice_arg<'a, T>(p: *const T, len: usize, name: &str) -> Result<&'a [T]> {
    if len == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(null(name));
    }
    // SAFETY: non-NULL, valid for `len` reads (contract), and aligned (C arrays of `T`).
    Ok(unsafe { std::slice::from_raw_parts(p, len) })
}

/// A NUL-terminated string argument.
///
/// # Safety
/// `p` is NULL or points to a NUL-terminated string alive during `'a`.
pub(crate) unsafe fn cstr_arg<'a>(p: *const c_char, name: &str) -> Result<&'a CStr> {
    if p.is_null() {
        return Err(null(name));
    }
    // SAFETY: non-NULL and NUL-terminated (contract).
    Ok(unsafe { CStr::from_ptr(p) })
}

/// A handle out-parameter, set to NULL at once so that it is NULL on every failure.
///
/// # Safety
/// `p` is NULL or valid for one aligned write of a pointer.
pub(crate) unsafe fn handle_out<T>(p: *mut *mut T, name: &str) -> Result<Out<*mut T>> {
    // SAFETY: forwarded contract.
    let out = unsafe { out_arg(p, name)? };
    out.set(std::ptr::null_mut());
    Ok(out)
}

/// Boxes `value` as a new handle into `*out`.
pub(crate) fn new_handle<T>(value: T, out: &Out<*mut T>) {
    out.set(Box::into_raw(Box::new(value)));
}

/// Frees a handle made by `new_handle`; NULL is a no-op.
///
/// # Safety
/// `p` is NULL or a handle from `new_handle::<T>` not freed yet.
pub(crate) unsafe fn free_handle<T>(p: *mut T) {
    if !p.is_null() {
        // SAFETY: made by `Box::into_raw` in `new_handle` and not freed (contract).
        drop(unsafe { Box::from_raw(p) });
    }
}

/// An opaque handle over a core structure (`Che`, `Chf`): the macros of `shapes` call the
/// core through it.
pub(crate) trait Handle {
    type Core;
    fn core(&self) -> &Self::Core;
}

/// An options struct, or its default when `p` is NULL.
///
/// # Safety
/// `p` is NULL or valid for one read.
pub(crate) unsafe fn options_arg<T: Copy + Default>(p: *const T) -> T {
    // SAFETY: forwarded contract.
    unsafe { p.as_ref() }.copied().unwrap_or_default()
}

/// A NUL-terminated path as an `OsStr`: its bytes as they are on Unix, UTF-8 elsewhere.
pub(crate) fn os_str(path: &CStr) -> Result<&std::ffi::OsStr> {
    #[cfg(unix)]
    {
        Ok(<std::ffi::OsStr as std::os::unix::ffi::OsStrExt>::from_bytes(path.to_bytes()))
    }
    #[cfg(not(unix))]
    {
        path.to_str()
            .map(std::ffi::OsStr::new)
            .map_err(|e| Error::invalid(format!("path is not UTF-8: {e}")))
    }
}

/// A path argument (see [`os_str`]).
///
/// # Safety
/// `p` is NULL or points to a NUL-terminated string alive during `'a`.
pub(crate) unsafe fn path_arg<'a>(p: *const c_char, name: &str) -> Result<&'a std::path::Path> {
    // SAFETY: forwarded contract.
    let path = unsafe { cstr_arg(p, name)? };
    Ok(std::path::Path::new(os_str(path)?))
}

/// A caller buffer for a variable-size answer. `buf == NULL` with `cap == 0` is a size
/// query; otherwise the first `cap` entries are written, the rest only counted, and
/// `finish` reports the full length in `*out_len` and BUFFER_TOO_SMALL when it did not fit.
pub(crate) struct Sink<'a, T> {
    buf: &'a mut [MaybeUninit<T>],
    query: bool,
    len: usize,
    out_len: Out<usize>,
    name: &'static str,
}

impl<'a, T> Sink<'a, T> {
    /// # Safety
    /// `buf` is NULL or valid for `cap` writes during `'a`; `out_len` is NULL or valid for
    /// one write.
    pub(crate) unsafe fn new(
        buf: *mut T,
        cap: usize,
        out_len: *mut usize,
        name: &'static str,
    ) -> Result<Self> {
        // SAFETY: forwarded contract.
        let out_len = unsafe { out_arg(out_len, "out_len")? };
        let query = buf.is_null();
        if query && cap != 0 {
            return Err(null(name));
        }
        let buf: &mut [MaybeUninit<T>] = if query {
            &mut []
        } else {
            // No object is larger than isize::MAX bytes, so a larger `cap` (say SIZE_MAX for
            // "unbounded") cannot be the real size: clamp it rather than build an invalid slice.
            let cap = cap.min(isize::MAX as usize / std::mem::size_of::<T>().max(1));
            // SAFETY: non-NULL, valid for `cap` writes (contract); viewed as uninitialised.
            unsafe { std::slice::from_raw_parts_mut(buf.cast::<MaybeUninit<T>>(), cap) }
        };
        Ok(Sink {
            buf,
            query,
            len: 0,
            out_len,
            name,
        })
    }

    /// Entries pushed so far.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    #[inline]
    pub(crate) fn push(&mut self, x: T) {
        if let Some(slot) = self.buf.get_mut(self.len) {
            slot.write(x);
        }
        self.len += 1;
    }

    pub(crate) fn extend(&mut self, xs: impl IntoIterator<Item = T>) {
        for x in xs {
            self.push(x);
        }
    }

    /// Has every pushed entry been written?
    fn fits(&self) -> bool {
        self.query || self.len <= self.buf.len()
    }

    fn too_small(&self) -> Error {
        Error::new(
            ErrorKind::BufferTooSmall,
            format!(
                "buffer '{}' holds {} entries, {} needed",
                self.name,
                self.buf.len(),
                self.len
            ),
        )
    }

    /// Writes `*out_len`; BUFFER_TOO_SMALL if the answer did not fit.
    pub(crate) fn finish(self) -> Result<()> {
        let result = if self.fits() {
            Ok(())
        } else {
            Err(self.too_small())
        };
        self.out_len.set(self.len);
        result
    }
}

/// The body of every "answer into a caller buffer" export: checks the handle and the
/// buffer, lets `f` push the answer, then reports the length (and BUFFER_TOO_SMALL).
///
/// # Safety
/// `h` is NULL or a live handle; `buf` NULL or valid for `cap` writes; `out_len` NULL or
/// valid for one write.
#[inline(always)]
pub(crate) unsafe fn ids_answer<H>(
    h: *const H,
    buf: *mut u32,
    cap: usize,
    out_len: *mut usize,
    f: impl FnOnce(&H, &mut Sink<'_, u32>) -> Result<()>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (h, mut sink) = unsafe { (handle(h, "m")?, Sink::new(buf, cap, out_len, "buf")?) };
        f(h, &mut sink)?;
        sink.finish()
    })
}

/// The body of every "one value into an out-parameter" export.
///
/// # Safety
/// `h` is NULL or a live handle; `out` NULL or valid for one write.
#[inline(always)]
pub(crate) unsafe fn value_answer<H, T>(
    h: *const H,
    out: *mut T,
    f: impl FnOnce(&H) -> Result<T>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (h, out) = unsafe { (handle(h, "m")?, out_arg(out, "out")?) };
        out.set(f(h)?);
        Ok(())
    })
}

/// Shared body of the zero-copy views of both meshes: the container's first element and
/// its length, or NULL and 0 for a NULL handle or a container missing at this level.
///
/// # Safety
/// `m` is NULL or a live handle; `len` NULL or valid for one write.
pub(crate) unsafe fn view_answer<M, T>(
    m: *const M,
    len: *mut usize,
    f: impl FnOnce(&M) -> Option<&[T]>,
) -> *const T {
    let (p, n) = guard_or((std::ptr::null(), 0), || {
        // SAFETY: forwarded contract.
        let m = unsafe { handle(m, "m")? };
        Ok(f(m).map_or((std::ptr::null(), 0), |s| (s.as_ptr(), s.len())))
    });
    if !len.is_null() {
        // SAFETY: non-NULL, valid for one write (contract).
        unsafe { len.write(n) };
    }
    p
}

/// Shared body of the CSR calls of both meshes: the handle and the buffers checked, the
/// rows filled, the lengths written (see `che/csr.rs` for the contract).
///
/// # Safety
/// `m` NULL or a live handle; each buffer NULL or valid for its capacity; each length
/// pointer NULL or valid for one write.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn csr_answer<M>(
    m: *const M,
    offsets: *mut u32,
    offsets_cap: usize,
    indices: *mut u32,
    indices_cap: usize,
    n_offsets: *mut usize,
    n_indices: *mut usize,
    fill: impl FnOnce(&M, &mut CsrSink<'_>) -> Result<()>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (m, mut sink) = unsafe {
            (
                handle(m, "m")?,
                CsrSink::new(
                    offsets,
                    offsets_cap,
                    indices,
                    indices_cap,
                    n_offsets,
                    n_indices,
                )?,
            )
        };
        fill(m, &mut sink)?;
        sink.finish()
    })
}

/// A bulk answer in compressed sparse rows: `offsets` (one per row, plus the end) and
/// `indices`. Both buffers NULL (capacities 0) is a size query; exactly one NULL is an
/// error.
pub(crate) struct CsrSink<'a> {
    pub(crate) offsets: Sink<'a, u32>,
    pub(crate) indices: Sink<'a, u32>,
}

impl<'a> CsrSink<'a> {
    /// # Safety
    /// Each buffer is NULL or valid for its capacity in writes during `'a`; each length
    /// pointer is NULL or valid for one write.
    pub(crate) unsafe fn new(
        offsets: *mut u32,
        offsets_cap: usize,
        indices: *mut u32,
        indices_cap: usize,
        n_offsets: *mut usize,
        n_indices: *mut usize,
    ) -> Result<Self> {
        if offsets.is_null() != indices.is_null() {
            return Err(null(if offsets.is_null() {
                "offsets"
            } else {
                "indices"
            }));
        }
        // SAFETY: forwarded contract.
        unsafe {
            Ok(CsrSink {
                offsets: Sink::new(offsets, offsets_cap, n_offsets, "offsets")?,
                indices: Sink::new(indices, indices_cap, n_indices, "indices")?,
            })
        }
    }

    /// Starts the next row.
    #[inline]
    pub(crate) fn row(&mut self) {
        let at = self.indices.len();
        self.offsets.push(at as u32);
    }

    #[inline]
    pub(crate) fn push(&mut self, x: u32) {
        self.indices.push(x);
    }

    /// Closes the last row and reports both lengths.
    pub(crate) fn finish(mut self) -> Result<()> {
        self.row();
        if self.indices.len() > u32::MAX as usize {
            return Err(Error::too_large(format!(
                "{} indices do not fit 32-bit offsets",
                self.indices.len()
            )));
        }
        let a = self.offsets.finish();
        let b = self.indices.finish();
        a.and(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn last() -> String {
        with_last_error(|s| s.to_string())
    }

    #[test]
    fn a_panic_becomes_a_status() {
        let s = guard(|| panic!("boom"));
        assert_eq!(s, Status::Panic);
        assert!(last().contains("boom"), "{}", last());
        let v: u32 = guard_or(7, || panic!("{}", String::from("bang")));
        assert_eq!(v, 7);
        assert!(last().contains("bang"));
    }

    #[test]
    fn errors_map_one_to_one() {
        use ErrorKind::*;
        let kinds = [
            NullArgument,
            OutOfRange,
            InvalidInput,
            NonManifold,
            BufferTooSmall,
            Io,
            Parse,
            TooLarge,
            Panic,
        ];
        for (i, k) in kinds.into_iter().enumerate() {
            let s = guard(|| Err(Error::new(k, format!("kind {i}"))));
            assert_eq!(s as u32, i as u32 + 1);
            assert_eq!(last(), format!("kind {i}"));
        }
    }

    #[test]
    fn sinks_count_past_capacity() {
        let mut buf = [0u32; 2];
        let mut len = 0usize;
        // SAFETY: local buffers of the stated sizes.
        let mut s = unsafe { Sink::new(buf.as_mut_ptr(), 2, &mut len, "buf") }.unwrap();
        s.extend([1, 2, 3]);
        let e = s.finish().unwrap_err();
        assert_eq!(e.kind, ErrorKind::BufferTooSmall);
        assert_eq!((len, buf), (3, [1, 2]));
        // SAFETY: a size query writes only `len`.
        let mut s = unsafe { Sink::<u32>::new(std::ptr::null_mut(), 0, &mut len, "buf") }.unwrap();
        s.extend([1, 2, 3, 4]);
        s.finish().unwrap();
        assert_eq!(len, 4);
    }
}
