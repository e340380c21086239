//! The uniform shapes of an export's body, as macros shared by the CHE and CHF exports.
//!
//! cbindgen reads the source without expanding macros, so every export keeps its doc
//! comment and signature written out; only the body comes from here:
//!
//! ```ignore
//! /// VE: the edges around `v`.
//! #[unsafe(no_mangle)]
//! pub unsafe extern "C" fn che_vertex_edges(
//!     m: *const CheMesh, v: u32, buf: *mut u32, cap: usize, out_len: *mut usize,
//! ) -> Status {
//!     ids!(m, buf, cap, out_len, check_vertex(v) => |c| c.vertex_edges(v))
//! }
//! ```
//!
//! Each macro is the guard (null checks, `catch_unwind`, error -> status and detail), the
//! conversion of the arguments and one call into the core, which it reaches through
//! [`Handle::core`](super::boundary::Handle). The pointer arguments are passed by name so
//! that the body stays in the caller's words; every one of them follows the safety
//! contract of the module docs of `ffi`.

/// A count or other plain value returned directly: `fallback` for a NULL handle.
/// `count!(m, 0, |c| c.num_vertices())`.
macro_rules! count {
    ($m:ident, $fallback:expr, |$c:ident| $value:expr) => {
        $crate::ffi::boundary::guard_or($fallback, || {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle.
            let h = unsafe { $crate::ffi::boundary::handle($m, "m")? };
            let $c = $crate::ffi::boundary::Handle::core(h);
            Ok($value)
        })
    };
}

/// One value into the out-parameter `out`: `value!(m, out, |c| result)` (the closure gives
/// a `Result`), or `value!(m, out, check_vertex(v) => |c| value)` (a range check on the
/// core first).
macro_rules! value {
    ($m:ident, $out:ident, |$c:ident| $result:expr) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
        unsafe {
            $crate::ffi::boundary::value_answer($m, $out, |h| {
                let $c = $crate::ffi::boundary::Handle::core(h);
                $result
            })
        }
    };
    ($m:ident, $out:ident, $check:ident($id:expr) => |$c:ident| $value:expr) => {
        value!($m, $out, |$c| {
            $c.$check($id)?;
            Ok($value)
        })
    };
}

/// A variable-size answer into the caller buffer `(buf, cap, *out_len)`:
/// `ids!(m, buf, cap, out_len, |c, s| result)` (the closure pushes into the sink `s`),
/// `ids!(m, buf, cap, out_len, check_vertex(v) => |c, s| c.walk_into(v, s))` (the core
/// writes into the sink), or `ids!(m, buf, cap, out_len, check_vertex(v) => |c| iterable)`.
macro_rules! ids {
    ($m:ident, $buf:ident, $cap:ident, $len:ident, |$c:ident, $s:ident| $result:expr) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
        unsafe {
            $crate::ffi::boundary::ids_answer($m, $buf, $cap, $len, |h, $s| {
                let $c = $crate::ffi::boundary::Handle::core(h);
                $result
            })
        }
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident, $s:ident| $walk:expr) => {
        ids!($m, $buf, $cap, $len, |$c, $s| {
            $c.$check($id)?;
            $walk;
            Ok(())
        })
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident| $items:expr) => {
        ids!($m, $buf, $cap, $len, |$c, s| {
            $c.$check($id)?;
            s.extend($items);
            Ok(())
        })
    };
}

/// A bulk answer in CSR into the caller's `offsets` and `indices`:
/// `csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices, rows)`, where
/// the core's method `rows` writes its rows into the sink (a `crate::che::Rows`), or the
/// same with `|c, s| expression` in place of `rows`.
macro_rules! csr {
    ($m:ident, $o:ident, $oc:ident, $i:ident, $ic:ident, $no:ident, $ni:ident, $rows:ident) => {
        csr!($m, $o, $oc, $i, $ic, $no, $ni, |c, s| c.$rows(s))
    };
    ($m:ident, $o:ident, $oc:ident, $i:ident, $ic:ident, $no:ident, $ni:ident, |$c:ident, $s:ident| $rows:expr) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
        unsafe {
            $crate::ffi::boundary::csr_answer($m, $o, $oc, $i, $ic, $no, $ni, |h, $s| {
                let $c = $crate::ffi::boundary::Handle::core(h);
                $rows;
                Ok(())
            })
        }
    };
}

/// A zero-copy view: the first element of the slice the closure gives (`None`: NULL) and
/// its length into `*len`. The closure gets the handle, which may hold materialised maps.
macro_rules! view {
    ($m:ident, $len:ident, |$h:ident| $slice:expr) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
        unsafe { $crate::ffi::boundary::view_answer($m, $len, |$h| $slice) }
    };
}

/// A new handle into `*out` (NULL on every failure): `made` gives the handle's value.
macro_rules! make {
    ($out:ident, $made:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a writable handle slot.
            let out = unsafe { $crate::ffi::boundary::handle_out($out, "out")? };
            $crate::ffi::boundary::new_handle($made?, &out);
            Ok(())
        })
    };
}

/// Frees a handle; NULL is a no-op. Guarded although dropping plain vectors cannot panic,
/// so that nothing ever unwinds.
macro_rules! free {
    ($m:ident) => {{
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle, freed once.
            unsafe { $crate::ffi::boundary::free_handle($m) };
            Ok(())
        });
    }};
}

/// `From<&Core>` for a C struct that mirrors the core's fields by name (each converted
/// with `as`: the C side widens counts to 64 bits).
macro_rules! mirror {
    ($core:ty => $c:ident { $($field:ident),* $(,)? }) => {
        impl From<&$core> for $c {
            #[allow(clippy::unnecessary_cast, reason = "some fields are already 64-bit")]
            fn from(x: &$core) -> Self {
                $c { $($field: x.$field as _),* }
            }
        }
    };
}

pub(crate) use {count, csr, free, ids, make, mirror, value, view};
