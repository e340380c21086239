//! The uniform bodies of the exports, as macros shared by the CHE and CHF exports.
//! cbindgen reads the source without expanding macros, so every export keeps its doc
//! comment and signature written out; only the body comes from here, for example
//! `ids!(m, buf, cap, out_len, check_vertex(v) => |c| c.vertex_edges(v))`.
//!
//! Each macro is the guard (null checks, `catch_unwind`, error -> status and detail), the
//! conversion of the arguments and one call into the core, reached through
//! [`Handle`](super::boundary::Handle). The pointer arguments are passed by name so that
//! the body stays in the caller's words; each follows the safety contract of `ffi`.

/// A count or other plain value returned directly, 0 for a NULL handle:
/// `count!(m, |c| c.num_vertices())`.
macro_rules! count {
    ($m:ident, |$c:ident| $value:expr) => {
        $crate::ffi::boundary::guard_or(0 as _, || {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle.
            let $c = unsafe { $crate::ffi::boundary::core($m)? };
            Ok($value)
        })
    };
}

/// A status alone: `status!(m, |c| result)` (the closure gives a `Result<()>`).
macro_rules! status {
    ($m:ident, |$c:ident| $result:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle.
            let $c = unsafe { $crate::ffi::boundary::core($m)? };
            $result
        })
    };
}

/// One value into the out-parameter `out`: `value!(m, out, |c| result)` (the closure gives
/// a `Result`), or `value!(m, out, check_vertex(v) => |c| value)` (a range check first).
macro_rules! value {
    ($m:ident, $out:ident, |$c:ident| $result:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
            let ($c, out) = unsafe {
                use $crate::ffi::boundary::{core, out_arg};
                (core($m)?, out_arg($out, "out")?)
            };
            Ok(out.set($result?))
        })
    };
    ($m:ident, $out:ident, $check:ident($id:expr) => |$c:ident| $value:expr) => {
        value!($m, $out, |$c| $c.$check($id).map(|_| $value))
    };
}

/// A variable-size answer into the caller buffer `(buf, cap, *out_len)` (see
/// `util::sink::Sink`): `ids!(m, buf, cap, out_len, check_vertex(v) => |c, s| c.walk_into(v,
/// s))` (the core writes into the sink), `ids!(m, buf, cap, out_len, check_vertex(v) => |c|
/// iterable)`, or `ids!(m, buf, cap, out_len, try |c| result)` (a `Result` of an iterable).
macro_rules! ids {
    ($m:ident, $buf:ident, $cap:ident, $len:ident, |$c:ident, $s:ident| $fill:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
            let ($c, mut sink) = unsafe {
                use $crate::ffi::boundary::{core, sink};
                (core($m)?, sink($buf, $cap, $len, "buf")?)
            };
            let $s = &mut sink;
            $fill;
            sink.finish()
        })
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, try |$c:ident| $items:expr) => {
        ids!($m, $buf, $cap, $len, |$c, s| s.extend($items?))
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident, $s:ident| $walk:expr) => {
        ids!($m, $buf, $cap, $len, |$c, $s| ($c.$check($id)?, $walk))
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident| $items:expr) => {
        ids!($m, $buf, $cap, $len, |$c, s| (
            $c.$check($id)?,
            s.extend($items)
        ))
    };
}

/// A bulk answer in CSR into the caller's `offsets` and `indices` (see `CsrSink`):
/// `csr!(m, offsets, offsets_cap, indices, indices_cap, n_offsets, n_indices => rows)`,
/// where the core's method `rows` writes its rows into the sink (a `crate::che::Rows`),
/// or the same with `|c, s| expression` in place of `rows`.
macro_rules! csr {
    ($m:ident, $o:ident, $oc:ident, $i:ident, $ic:ident, $no:ident, $ni:ident => $rows:ident) => {
        csr!($m, $o, $oc, $i, $ic, $no, $ni => |c, s| c.$rows(s))
    };
    ($m:ident, $o:ident, $oc:ident, $i:ident, $ic:ident, $no:ident, $ni:ident => |$c:ident, $s:ident| $rows:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
            let ($c, mut sink) = unsafe {
                use $crate::ffi::boundary::{core, csr_sink};
                (core($m)?, csr_sink([($o, $oc, $no), ($i, $ic, $ni)])?)
            };
            let $s = &mut sink;
            $crate::util::alloc::Done::done($rows)?;
            sink.finish()
        })
    };
}

/// A zero-copy view: the first element of the slice the closure gives (`None`: NULL) and
/// its length into `*len` (when not NULL); NULL and 0 for a NULL handle. An empty
/// container may come as a non-NULL pointer with length 0. The closure gets the handle,
/// which may hold materialised maps.
macro_rules! view {
    ($m:ident, $len:ident, |$h:ident| $slice:expr) => {{
        let (p, n) = $crate::ffi::boundary::guard_or((std::ptr::null(), 0), || {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle.
            let $h = unsafe { $crate::ffi::boundary::handle($m, "m")? };
            Ok($slice.map_or((std::ptr::null(), 0), |s| (s.as_ptr(), s.len())))
        });
        // SAFETY: caller contract (see `ffi`): NULL or valid for one write.
        if let Some(len) = unsafe { $len.as_mut() } {
            *len = n;
        }
        p
    }};
}

/// A new handle into `*out` (NULL on every failure): `made` gives the core structure.
macro_rules! make {
    ($out:ident, $made:expr) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
        unsafe { $crate::ffi::boundary::new_handle($out, || Ok(From::from($made?))) }
    };
}

/// A new handle from C arrays, with options (a pointer, NULL: the defaults):
/// `build!(out, options => Che(TRIANGLES, triangles, n_triangles, n_vertices, positions))`.
macro_rules! build {
    ($out:ident, $opt:expr => $core:ident($kind:expr, $ids:ident, $n:ident, $nv:ident, $pos:ident)) => {
        $crate::ffi::shapes::make!($out, {
            let options = $crate::ffi::boundary::options_arg($opt).to_core()?;
            let (ids, points) = $crate::ffi::mesh_arrays::mesh_arrays($kind, $ids, $n, $nv, $pos)?;
            $core::from_flat(ids, $nv, points, options)
        })
    };
}

/// A new handle from a file, with options (a pointer, NULL: the defaults):
/// `load!(out, path, options => crate::io::load::che)`.
macro_rules! load {
    ($out:ident, $path:ident, $opt:expr => $load:path) => {
        $crate::ffi::shapes::make!($out, {
            let options = $crate::ffi::boundary::options_arg($opt).to_core()?;
            $load($crate::ffi::boundary::path_arg($path, "path")?, options)
        })
    };
}

/// A file written from a handle: `save!(m, path => |c, path| c.save(path))`, or with
/// `TOPOMESH_WRITE_*` flags: `save!(m, path, flags => |c, path, options| c.write_with(path,
/// &options))`.
macro_rules! save {
    ($m:ident, $path:ident => |$c:ident, $p:ident| $call:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle and a NUL-terminated
            // path.
            let ($c, $p) = unsafe {
                use $crate::ffi::boundary::{core, path_arg};
                (core($m)?, path_arg($path, "path")?)
            };
            $call
        })
    };
    ($m:ident, $path:ident, $flags:ident => |$c:ident, $p:ident, $o:ident| $call:expr) => {
        save!($m, $path => |$c, $p| {
            let $o = $crate::ffi::boundary::write_flags_arg($flags)?;
            $call
        })
    };
}

/// A new handle from a level file, with `TOPOMESH_OPEN_*` flags:
/// `open!(out, path, flags => Che::open)`.
macro_rules! open {
    ($out:ident, $path:ident, $flags:ident => $open:path) => {
        $crate::ffi::shapes::make!($out, {
            let options = $crate::ffi::boundary::open_flags_arg($flags)?;
            $open($crate::ffi::boundary::path_arg($path, "path")?, options)
        })
    };
}

/// Raises or lowers the level of a handle in place (exclusive access).
macro_rules! relevel {
    ($m:ident, $level:ident) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared.
            let h = unsafe { $crate::ffi::boundary::handle_mut($m, "m")? };
            let level = $crate::ffi::boundary::level_arg($level)?;
            $crate::ffi::boundary::Handle::core_mut(h).build_level(level)
        })
    };
}

/// The reader's warnings of a handle: `warnings!(m)` counts them (0 for NULL),
/// `warnings!(m, i, buf, cap, out_len)` copies warning `i` (see `boundary::warning_out`).
macro_rules! warnings {
    ($m:ident) => {
        $crate::ffi::boundary::guard_or(0, || {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle.
            let h = unsafe { $crate::ffi::boundary::handle($m, "m")? };
            Ok($crate::ffi::boundary::Handle::warnings(h).len())
        })
    };
    ($m:ident, $i:ident, $buf:ident, $cap:ident, $len:ident) => {
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers.
        $crate::ffi::boundary::guard(|| unsafe {
            $crate::ffi::boundary::warning_out($m, $i, $buf, $cap, $len)
        })
    };
}

/// The Rust side of a handle type and its options struct: `Handle` over the core field,
/// the handle from a core structure, the options' defaults, conversion and C layout.
macro_rules! handle {
    ($h:ident { $field:ident: $core:ty, $($map:ident),* }, $opt:ident => $core_opt:ident) => {
        impl $crate::ffi::boundary::Handle for $h {
            type Core = $core;
            #[inline(always)]
            fn core(&self) -> &$core {
                &self.$field
            }
            fn core_mut(&mut self) -> &mut $core {
                &mut self.$field
            }
            fn warnings(&self) -> &[String] {
                &self.warnings
            }
        }

        /// A handle from a loaded file: the structure and the reader's warnings.
        impl From<$crate::io::load::Loaded<$core>> for $h {
            fn from(loaded: $crate::io::load::Loaded<$core>) -> Self {
                let mut h = $h::from(loaded.mesh);
                h.warnings = loaded.warnings.iter().map(|w| w.to_string()).collect();
                h
            }
        }

        impl From<$core> for $h {
            fn from($field: $core) -> Self {
                $h { $field, $($map: Default::default()),* }
            }
        }

        $crate::ffi::shapes::options!($opt => $core_opt {
            level: 0, strict: 4, threads: 8, memory_limit_bytes: 16, weld_tolerance: 24,
        } 32);
    };
}

/// A C options struct over the core's, field by field with their C offsets (the layout C
/// hosts compile against) and its size: the defaults, `at(level)` and `to_core`, each
/// field converted by `boundary::CField`.
macro_rules! options {
    ($opt:ident => $core_opt:ident { $($f:ident: $at:literal),* $(,)? } $size:literal) => {
        const _: () = {
            assert!(core::mem::size_of::<$opt>() == $size);
            $(assert!(core::mem::offset_of!($opt, $f) == $at);)*
        };

        impl Default for $opt {
            fn default() -> Self {
                use $crate::ffi::boundary::CField;
                let d = $core_opt::default();
                $opt { $($f: d.$f.to_c()),* }
            }
        }

        impl $opt {
            /// The defaults at `level`.
            pub(crate) fn at(level: u32) -> Self {
                $opt { level, ..Self::default() }
            }

            fn to_core(self) -> $crate::error::Result<$core_opt> {
                use $crate::ffi::boundary::CField;
                Ok($core_opt { $($f: CField::from_c(self.$f)?),* })
            }
        }
    };
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

pub(crate) use {
    build, count, csr, handle, ids, load, make, mirror, open, options, relevel, save, status,
    value, view, warnings,
};
