//! The one boundary every export runs behind (its shapes are the macros of `shapes`):
//! `guard` / `guard_or` run a body under `catch_unwind` and turn a `crate::Error` into its
//! status plus a thread-local detail; the `*_arg` helpers are the null checks, each naming
//! the argument, and turn C pointers into the slices the core's sinks (`util::sink`) write.

use super::status::Status;
use crate::error::{Error, ErrorKind, Result};
pub(crate) use crate::util::sink::{CsrSink, Sink, pick as report_kind};
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
    status_of(e.kind)
}

/// The status of an error kind (they map one to one onto the statuses after `Ok`).
pub(crate) fn status_of(kind: ErrorKind) -> Status {
    super::status::STATUSES[kind as usize + 1].0
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

/// The NULL_ARGUMENT error naming argument `name`.
pub(crate) fn null_argument(name: &str) -> Error {
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
    NonNull::new(p).map(Out).ok_or_else(|| null_argument(name))
}

/// An optional out-parameter: `None` for NULL.
pub(crate) unsafe fn optional_out<T>(p: *mut T) -> Option<Out<T>> {
    NonNull::new(p).map(Out)
}

/// An optional position: NULL, or three doubles x, y, z.
///
/// # Safety
/// `p` is NULL or points to three readable doubles (an export's contract for its position
/// argument).
pub(crate) unsafe fn position_arg(p: *const f64) -> Result<Option<glam::DVec3>> {
    if p.is_null() {
        return Ok(None);
    }
    // SAFETY: forwarded contract: NULL (handled) or three readable doubles.
    let xyz = unsafe { slice_arg(p, 3, "position")? };
    Ok(Some(glam::DVec3::new(xyz[0], xyz[1], xyz[2])))
}

/// `N` ids read from the caller's array, or a NULL_ARGUMENT error naming it.
///
/// # Safety
/// `p` is NULL or points to `N` readable ids (an export's contract for that argument).
pub(crate) unsafe fn ids_arg<const N: usize>(p: *const u32, name: &str) -> Result<[u32; N]> {
    // SAFETY: forwarded contract: NULL (refused) or `N` readable ids.
    let ids = unsafe { slice_arg(p, N, name)? };
    Ok(std::array::from_fn(|i| ids[i]))
}

/// The body of a garbage collection export: the caller's map buffers `(map, cap, name)`,
/// NULL for a map not wanted, each checked for room for `counts` (the counts before the
/// call: BUFFER_TOO_SMALL before anything changes) and against overlapping another, then
/// lent to `collect`, which writes the old -> new maps into them.
pub(crate) unsafe fn collect_garbage<H: Handle, const N: usize>(
    m: *mut H, buffers: [(*mut u32, usize, &str); N], counts: impl FnOnce(&H::Core) -> [usize; N],
    collect: impl FnOnce(&mut H::Core, [Option<&mut [u32]>; N]) -> Result<()>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract: NULL or a live handle, not shared.
        let h = unsafe { handle_mut(m, "m")? };
        let needs = counts(h.core());
        for ((p, cap, name), need) in buffers.into_iter().zip(needs) {
            if !p.is_null() && cap < need {
                let detail = format!("{name}: {need} entries needed, {cap} given");
                return Err(Error::new(ErrorKind::BufferTooSmall, detail));
            }
        }
        check_disjoint(&buffers, &needs)?;
        let lent = std::array::from_fn(|i| {
            let (p, _, _) = buffers[i];
            // SAFETY: forwarded contract: room for `needs[i]` ids (checked above), the
            // caller's own memory, written by nothing else during the call; no two
            // buffers overlap (checked above), so the slices alias nothing.
            (!p.is_null()).then(|| unsafe { std::slice::from_raw_parts_mut(p, needs[i]) })
        });
        let done = collect(h.core_mut(), lent);
        h.settle_views();
        done
    })
}

/// INVALID_INPUT when two of the buffers overlap over the entries they will get.
fn check_disjoint<const N: usize>(
    buffers: &[(*mut u32, usize, &str); N], needs: &[usize; N],
) -> Result<()> {
    let span = |i: usize| {
        let start = buffers[i].0 as usize;
        start..start + needs[i] * size_of::<u32>()
    };
    for i in (0..N).filter(|&i| !buffers[i].0.is_null() && needs[i] > 0) {
        for j in (i + 1..N).filter(|&j| !buffers[j].0.is_null() && needs[j] > 0) {
            let (a, b) = (span(i), span(j));
            if a.start < b.end && b.start < a.end {
                let detail = format!("{} and {} overlap", buffers[i].2, buffers[j].2);
                return Err(Error::invalid(detail));
            }
        }
    }
    Ok(())
}

/// The maps a collection returned, copied into the buffers lent for them (`None`: not
/// wanted); each buffer is as long as its map (the counts before the collection).
pub(crate) fn copy_maps<const N: usize>(
    maps: [Vec<u32>; N], out: [Option<&mut [u32]>; N],
) -> Result<()> {
    for (map, buf) in maps.iter().zip(out) {
        if let Some(buf) = buf {
            buf.copy_from_slice(map);
        }
    }
    Ok(())
}

/// A handle (or any input struct) by reference.
pub(crate) unsafe fn handle<'a, T>(p: *const T, name: &str) -> Result<&'a T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_ref() }.ok_or_else(|| null_argument(name))
}

/// A handle by exclusive reference.
pub(crate) unsafe fn handle_mut<'a, T>(p: *mut T, name: &str) -> Result<&'a mut T> {
    // SAFETY: forwarded contract.
    unsafe { p.as_mut() }.ok_or_else(|| null_argument(name))
}

/// An input array of `len` elements (`len * size_of::<T>()` fits `isize`: the callers
/// check sizes first); NULL is accepted (as empty) only when `len == 0`.
pub(crate) unsafe fn slice_arg<'a, T>(p: *const T, len: usize, name: &str) -> Result<&'a [T]> {
    match (len, p.is_null()) {
        (0, _) => Ok(&[]),
        (_, true) => Err(null_argument(name)),
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
        return Err(null_argument(name));
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

/// A field of a C options struct (`C`) as the core's field (`Self`) and back. The only
/// `u8` field of the core's options is the level.
pub(crate) trait CField<C>: Sized {
    fn to_c(self) -> C;
    fn from_c(c: C) -> Result<Self>;
}

impl<T> CField<T> for T {
    fn to_c(self) -> T {
        self
    }
    fn from_c(c: T) -> Result<T> {
        Ok(c)
    }
}

impl CField<u32> for u8 {
    fn to_c(self) -> u32 {
        self.into()
    }
    fn from_c(level: u32) -> Result<u8> {
        level_arg(level)
    }
}

/// `strict` and the like: any non-zero C value is true (a C `bool` field can hold values
/// Rust may not read as a `bool`, hence the `u8`).
impl CField<u8> for bool {
    fn to_c(self) -> u8 {
        self.into()
    }
    fn from_c(c: u8) -> Result<bool> {
        Ok(c != 0)
    }
}

impl CField<u32> for usize {
    fn to_c(self) -> u32 {
        self as u32
    }
    fn from_c(c: u32) -> Result<usize> {
        Ok(c as usize)
    }
}

/// `flags` checked against the `known` bits (and their C names), or INVALID_INPUT naming
/// the unknown ones.
fn flags_arg<const N: usize>(flags: u32, known: [(u32, &str); N]) -> Result<u32> {
    let unknown = flags & !known.iter().fold(0, |all, (bit, _)| all | bit);
    if unknown == 0 {
        return Ok(flags);
    }
    let names = known.map(|(_, name)| name).join(", ");
    let detail = format!("flags {flags:#x}: unknown bits {unknown:#x} (known: {names})");
    Err(Error::invalid(detail))
}

/// The `TOPOMESH_WRITE_*` flags as write options.
pub(crate) fn write_flags_arg(flags: u32) -> Result<crate::io::WriteOptions> {
    use super::{TOPOMESH_WRITE_BINARY as B, TOPOMESH_WRITE_NO_ORIGIN as N};
    let f = flags_arg(
        flags,
        [
            (B, "TOPOMESH_WRITE_BINARY"),
            (N, "TOPOMESH_WRITE_NO_ORIGIN"),
        ],
    )?;
    let (binary, no_origin) = (f & B != 0, f & N != 0);
    Ok(crate::io::WriteOptions {
        format: None,
        binary,
        no_origin,
    })
}

/// The `TOPOMESH_OPEN_*` flags as open options (TRUSTED wins over CHECKSUMS_ONLY).
pub(crate) fn open_flags_arg(flags: u32) -> Result<crate::levelfile::OpenOptions> {
    use super::{
        TOPOMESH_OPEN_CHECKSUMS_ONLY as C, TOPOMESH_OPEN_MAPPED as M, TOPOMESH_OPEN_TRUSTED as T,
    };
    use crate::levelfile::{Mode, Verify};
    let f = flags_arg(
        flags,
        [
            (C, "TOPOMESH_OPEN_CHECKSUMS_ONLY"),
            (T, "TOPOMESH_OPEN_TRUSTED"),
            (M, "TOPOMESH_OPEN_MAPPED"),
        ],
    )?;
    let verify = [
        Verify::Full,
        Verify::Checksums,
        Verify::Trusted,
        Verify::Trusted,
    ][(f & (C | T)) as usize];
    let mode = if f & M != 0 {
        Mode::Mapped
    } else {
        Mode::Loaded
    };
    Ok(crate::levelfile::OpenOptions { verify, mode })
}

/// The core's origin map, or the identity on `0..n` materialised once in `cell`.
pub(crate) fn origins<'a>(
    map: Option<&'a [u32]>, cell: &'a OnceLock<Box<[u32]>>, n: usize,
) -> Result<&'a [u32]> {
    if let Some(map) = map.or(cell.get().map(|b| &b[..])) {
        return Ok(map);
    }
    let identity = crate::util::alloc::try_collect(0..n as u32, "the identity origin map")?;
    Ok(cell.get_or_init(|| identity.into_boxed_slice()))
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
    /// After an edit: drops each identity origin view the handle materialised whose length
    /// no longer matches the structure (an edit added or compacted elements); the others,
    /// and every view after a change of level, stay valid.
    fn settle_views(&mut self);
    /// The reader's warnings, `file:line: message` each (none for a mesh built from arrays).
    fn warnings(&self) -> &[String];
}

/// `text` into the caller's `(buf, cap)` NUL-terminated (see `util::sink::copy_text`),
/// the capacity needed into `*out_len`; BUFFER_TOO_SMALL when it was truncated.
pub(crate) unsafe fn text_out(
    text: &str, buf: *mut c_char, cap: usize, out_len: *mut usize,
) -> Result<()> {
    // SAFETY: forwarded contract.
    let (buf, out_len) = unsafe {
        (
            buf_arg(buf.cast::<u8>(), cap, "buf")?,
            out_arg(out_len, "out_len")?,
        )
    };
    let (needed, fits) = crate::util::sink::copy_text(text, buf);
    out_len.set(needed);
    if fits {
        return Ok(());
    }
    let detail = format!("buffer 'buf' holds {cap} bytes, {needed} needed");
    Err(Error::new(ErrorKind::BufferTooSmall, detail))
}

/// The body of an export that writes the mesh behind `m` to the file `path`.
pub(crate) unsafe fn to_path<H: Handle>(
    m: *const H, path: *const c_char, write: impl FnOnce(&H::Core, &std::path::Path) -> Result<()>,
) -> Status {
    guard(|| {
        // SAFETY: forwarded contract.
        let (c, path) = unsafe { (core(m)?, path_arg(path, "path")?) };
        write(c, path)
    })
}

/// Warning `i` of handle `m` into `buf` (the buffer rules of `topomesh_last_error`).
pub(crate) unsafe fn warning_out<H: Handle>(
    m: *const H, i: usize, buf: *mut c_char, cap: usize, out_len: *mut usize,
) -> Result<()> {
    // SAFETY: forwarded contract.
    let warnings = unsafe { handle(m, "m")? }.warnings();
    let n = warnings.len();
    let missing = || {
        Error::out_of_range(format!(
            "warning {i} out of range (the mesh has {n} warnings)"
        ))
    };
    // SAFETY: forwarded contract.
    unsafe { text_out(warnings.get(i).ok_or_else(missing)?, buf, cap, out_len) }
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

/// A caller buffer `(buf, cap)` as the core's sinks take it: NULL with `cap == 0` is a size
/// query (`None`), NULL with another `cap` a NULL_ARGUMENT error naming it.
pub(crate) unsafe fn buf_arg<'a, T>(
    buf: *mut T, cap: usize, name: &str,
) -> Result<Option<&'a mut [MaybeUninit<T>]>> {
    if buf.is_null() {
        return if cap == 0 {
            Ok(None)
        } else {
            Err(null_argument(name))
        };
    }
    // No object is larger than isize::MAX bytes, so a larger `cap` (say SIZE_MAX for
    // "unbounded") cannot be the real size: clamp it rather than build an invalid slice.
    let cap = cap.min(isize::MAX as usize / size_of::<T>().max(1));
    // SAFETY: non-NULL, valid for `cap` writes (contract); viewed as uninitialised.
    Ok(Some(unsafe {
        std::slice::from_raw_parts_mut(buf.cast(), cap)
    }))
}

/// The caller's `buf` as `len` initialised elements: zeroed first (every bit pattern of
/// the ids and values given this way, all zeros included, is valid). `buf` is non-NULL and
/// valid for `len` writes.
pub(crate) unsafe fn zeroed<'a, T: bytemuck::Zeroable>(buf: *mut T, len: usize) -> &'a mut [T] {
    // SAFETY: forwarded contract; all zeros is a valid `T` (`Zeroable`).
    unsafe {
        buf.write_bytes(0, len);
        std::slice::from_raw_parts_mut(buf, len)
    }
}

/// The core's sink over the caller's `(buf, cap, *out_len)`.
pub(crate) unsafe fn sink<'a, T: Copy>(
    buf: *mut T, cap: usize, out_len: *mut usize, name: &'static str,
) -> Result<Sink<'a, T>> {
    // SAFETY: forwarded contract; `out_len` is written, never read.
    let out_len = unsafe { out_arg(out_len, "out_len")?.0.cast().as_mut() };
    // SAFETY: forwarded contract.
    Ok(Sink::new(
        unsafe { buf_arg(buf, cap, name)? },
        out_len,
        name,
    ))
}

/// The core's CSR sink over `(offsets, offsets_cap, n_offsets)` and the same for the
/// indices: both NULL (capacities 0) is a size query, exactly one NULL an error.
pub(crate) unsafe fn csr_sink<'a>(bufs: [(*mut u32, usize, *mut usize); 2]) -> Result<CsrSink<'a>> {
    let [(o, oc, no), (i, ic, ni)] = bufs;
    if o.is_null() != i.is_null() {
        return Err(null_argument(if o.is_null() {
            "offsets"
        } else {
            "indices"
        }));
    }
    // SAFETY: forwarded contract.
    unsafe {
        Ok(CsrSink::new(
            sink(o, oc, no, "offsets")?,
            sink(i, ic, ni, "indices")?,
        ))
    }
}
