//! The uniform signatures of the exports: `exports!` writes the `extern "C"` functions of
//! one mesh type from a list whose entries give the doc comment, the shape, the name, the
//! id arguments and the body (a macro of `shapes`), for example
//!
//! ```text
//! exports! { CheMesh;
//!     /// VE: the edges around `v` ...
//!     ids fn che_vertex_edges(v) { check_vertex(v) => |c, s| c.vertex_edges_into(v, s) }
//!     /// The opposite of half-edge `h` ...
//!     value fn che_half_edge_opposite(h) -> u32 { check_half_edge(h) => |c| c.opposite(h) }
//! }
//! ```
//!
//! The header is generated from the expanded source (see `tests/header_drift.rs`), so what
//! a C user reads is these functions as written out by the macro. The shapes:
//!
//! | shape | C signature after the mesh `m` and the `uint32_t` ids | body |
//! |---|---|---|
//! | `ids` | `uint32_t *buf, size_t cap, size_t *out_len` -> status | `shapes::ids!` |
//! | `value` | `T *out` -> status | `shapes::value!` |
//! | `check` | -> status | `\|c\| result` |
//! | `edit` | (`m` exclusive) an out-parameter named in the entry (`as [u32; N]`: N ids), or none | `shapes::edit!` |
//! | `ask` | (`m` exclusive, for the core's scratch; nothing changes) `bool *out` -> status | `\|c\| result` |
//! | `csr` | the offsets and indices buffers, their capacities and lengths | `\|c, s\| rows` |
//! | `matrix` | `kind`, the offsets, columns and values buffers and lengths | `\|c, offer\| …` |
//! | `count` | -> `T` (0 for a NULL handle) | `\|c\| value` |
//! | `view` | `size_t *len` -> `const T *` (NULL for a NULL handle) | `\|h\| slice` |
//! | `save` | `const char *path` (and `uint32_t flags`, as write options) -> status | `\|c, path\| result` (`\|c, path, options\|`) |
//! | `free` | (`m` exclusive) -> nothing; NULL is a no-op; doc: the macro's | the handle dropped |
//! | `warnings` | two exports: the count; warning `i` into `char *buf, size_t cap, size_t *out_len`; docs: the macro's | the handle's |

/// The exports of one mesh type (see the module docs): each entry, shape by shape, to
/// `export!`.
macro_rules! exports {
    ($mesh:ty; $($entries:tt)*) => {
        $crate::ffi::declare::export!(@ $mesh; $($entries)*);
    };
}

/// The entries of `exports!`, one at a time; an argument without a type is a `u32` id.
macro_rules! export {
    (@ $mesh:ty;) => {};
    (@ $mesh:ty; $(#[$doc:meta])*
        ids fn $name:ident($($a:ident $(: $t:ty)?),*) { $($body:tt)* } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, $($a: $crate::ffi::declare::arg!($($t)?),)*
            buf: *mut u32, cap: usize, out_len: *mut usize,
        ) -> $crate::ffi::status::Status {
            $crate::ffi::shapes::ids!(m, buf, cap, out_len, $($body)*)
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        value fn $name:ident($($a:ident $(: $t:ty)?),*) -> $out:ty { $($body:tt)* }
        $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, $($a: $crate::ffi::declare::arg!($($t)?),)* out: *mut $out,
        ) -> $crate::ffi::status::Status {
            $crate::ffi::shapes::value!(m, out, $($body)*)
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        check fn $name:ident($($a:ident $(: $t:ty)?),*) { |$c:ident| $result:expr }
        $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, $($a: $crate::ffi::declare::arg!($($t)?)),*
        ) -> $crate::ffi::status::Status {
            $crate::ffi::boundary::guard(|| {
                // SAFETY: caller contract (see `ffi`): NULL or a live handle.
                let $c = unsafe { $crate::ffi::boundary::core(m)? };
                $result
            })
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        edit fn $name:ident($($a:ident $(: $t:ty)?),*) -> $out:ident: $ot:ty $(as $array:ty)?
        { $($body:tt)* } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *mut $mesh, $($a: $crate::ffi::declare::arg!($($t)?),)* $out: *mut $ot,
        ) -> $crate::ffi::status::Status {
            $crate::ffi::shapes::edit!(m, $out$(.cast::<$array>())?, $($body)*)
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        edit fn $name:ident($($a:ident $(: $t:ty)?),*) { $($body:tt)* } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *mut $mesh, $($a: $crate::ffi::declare::arg!($($t)?)),*
        ) -> $crate::ffi::status::Status {
            $crate::ffi::shapes::edit!(m, std::ptr::null_mut::<()>(), $($body)*)
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        ask fn $name:ident($($a:ident),*) -> bool { |$c:ident| $answer:expr } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *mut $mesh, $($a: u32,)* out: *mut bool,
        ) -> $crate::ffi::status::Status {
            $crate::ffi::boundary::guard(|| {
                // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared, and
                // NULL or one writable bool.
                let (h, out) = unsafe {
                    use $crate::ffi::boundary::{handle_mut, out_arg};
                    (handle_mut(m, "m")?, out_arg(out, "out")?)
                };
                let $c = $crate::ffi::boundary::Handle::core_mut(h);
                Ok(out.set($answer?))
            })
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        csr fn $name:ident() { |$c:ident, $s:ident| $rows:expr } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, offsets: *mut u32, offsets_cap: usize, indices: *mut u32,
            indices_cap: usize, n_offsets: *mut usize, n_indices: *mut usize,
        ) -> $crate::ffi::status::Status {
            $crate::ffi::boundary::guard(|| {
                // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated
                // sizes.
                let ($c, mut sink) = unsafe {
                    use $crate::ffi::boundary::{core, csr_sink};
                    let offsets = (offsets, offsets_cap, n_offsets);
                    (core(m)?, csr_sink([offsets, (indices, indices_cap, n_indices)])?)
                };
                let $s = &mut sink;
                $crate::util::alloc::Done::done($rows)?;
                sink.finish()
            })
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        matrix fn $name:ident($kind:ident) { |$c:ident, $offer:ident| $body:expr }
        $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, $kind: u32, offsets: *mut u64, offsets_cap: usize,
            columns: *mut u32, columns_cap: usize, values: *mut f64, values_cap: usize,
            n_offsets: *mut usize, n_entries: *mut usize,
        ) -> $crate::ffi::status::Status {
            let bufs = (offsets, columns, values);
            let caps = [offsets_cap, columns_cap, values_cap];
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
            unsafe {
                let lens = [n_offsets, n_entries];
                $crate::ffi::matrix::matrix_out(m, bufs, caps, lens, |$c, $offer| $body)
            }
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        count fn $name:ident() -> $ret:ty { |$c:ident| $value:expr } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(m: *const $mesh) -> $ret {
            $crate::ffi::boundary::guard_or(0 as _, || {
                // SAFETY: caller contract (see `ffi`): NULL or a live handle.
                let $c = unsafe { $crate::ffi::boundary::core(m)? };
                Ok($value)
            })
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        view fn $name:ident() -> $ret:ty { |$h:ident| $slice:expr } $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(m: *const $mesh, len: *mut usize) -> *const $ret {
            let (p, n) = $crate::ffi::boundary::guard_or((std::ptr::null(), 0), || {
                // SAFETY: caller contract (see `ffi`): NULL or a live handle.
                let $h = unsafe { $crate::ffi::boundary::handle(m, "m")? };
                Ok($slice.map_or((std::ptr::null(), 0), |s| (s.as_ptr(), s.len())))
            });
            // SAFETY: caller contract (see `ffi`): NULL or valid for one write.
            if let Some(len) = unsafe { len.as_mut() } {
                *len = n;
            }
            p
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; $(#[$doc:meta])*
        save fn $name:ident($($flags:ident)?) { |$c:ident, $p:ident $(, $o:ident)?| $call:expr }
        $($rest:tt)*) => {
        $(#[$doc])*
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            m: *const $mesh, path: *const std::ffi::c_char, $($flags: u32)?
        ) -> $crate::ffi::status::Status {
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
            unsafe {
                $crate::ffi::boundary::to_path(m, path, |$c, $p| {
                    $(let $o = $crate::ffi::boundary::write_flags_arg($flags)?;)?
                    $call
                })
            }
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; free fn $name:ident(); $($rest:tt)*) => {
        /// Frees a mesh; NULL is a no-op. Needs exclusive access.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(m: *mut $mesh) {
            // SAFETY: caller contract: NULL or a live handle, freed once.
            unsafe { $crate::ffi::boundary::free_handle(m) }
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
    (@ $mesh:ty; warnings fn $count:ident(), $one:ident(); $($rest:tt)*) => {
        /// How many warnings the reader gave for the file `m` was loaded from (0 for a mesh
        /// built from arrays, and for NULL). O(1).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $count(m: *const $mesh) -> usize {
            $crate::ffi::boundary::guard_or(0, || {
                // SAFETY: caller contract (see `ffi`): NULL or a live handle.
                let h = unsafe { $crate::ffi::boundary::handle(m, "m")? };
                Ok($crate::ffi::boundary::Handle::warnings(h).len())
            })
        }
        /// Warning `i` ("file:line: message"), NUL-terminated, into `buf`, with the buffer
        /// rules of `topomesh_last_error`: `*out_len` receives the capacity needed, NUL
        /// included; `buf == NULL` with `cap == 0` is a size query; a short `buf` receives a
        /// truncated text and the call returns `TOPOMESH_STATUS_BUFFER_TOO_SMALL`. `i` out of
        /// range gives `TOPOMESH_STATUS_OUT_OF_RANGE`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $one(
            m: *const $mesh, i: usize, buf: *mut std::ffi::c_char, cap: usize,
            out_len: *mut usize,
        ) -> $crate::ffi::status::Status {
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
            $crate::ffi::boundary::guard(|| unsafe {
                $crate::ffi::boundary::warning_out(m, i, buf, cap, out_len)
            })
        }
        $crate::ffi::declare::export!(@ $mesh; $($rest)*);
    };
}

/// The C type of an export's argument: a `u32` id unless the entry names one.
macro_rules! arg {
    () => {
        u32
    };
    ($t:ty) => {
        $t
    };
}

pub(crate) use {arg, export, exports};
