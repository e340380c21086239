//! The uniform bodies of the exports, as macros shared by the CHE and CHF exports, for
//! example `ids!(m, buf, cap, out_len, check_vertex(v) => |c| c.vertex_edges(v))`; the
//! signatures of the uniform shapes come from `declare::exports!`.
//!
//! Each macro is the guard (null checks, `catch_unwind`, error -> status and detail), the
//! conversion of the arguments and one call into the core, reached through
//! [`Handle`](super::boundary::Handle). The pointer arguments are passed by name so that
//! the body stays in the caller's words; each follows the safety contract of `ffi`.

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
        $crate::ffi::shapes::value!($m, $out, |$c| $c.$check($id).map(|_| $value))
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
        $crate::ffi::shapes::ids!($m, $buf, $cap, $len, |$c, s| s.extend($items?))
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident, $s:ident| $walk:expr) => {
        $crate::ffi::shapes::ids!($m, $buf, $cap, $len, |$c, $s| ($c.$check($id)?, $walk))
    };
    ($m:ident, $buf:ident, $cap:ident, $len:ident, $check:ident($id:expr) => |$c:ident| $items:expr) => {
        $crate::ffi::shapes::ids!($m, $buf, $cap, $len, |$c, s| (
            $c.$check($id)?,
            s.extend($items)
        ))
    };
}

/// An edit of the mesh behind an exclusive handle (see `Handle::settle_views`), its answer into
/// `out` when that is not NULL: `edit!(m, out_v, |c| c.add_vertex(p))`.
macro_rules! edit {
    ($m:ident, $out:expr, |$c:ident| $result:expr) => {
        $crate::ffi::boundary::guard(|| {
            // SAFETY: caller contract (see `ffi`): NULL or a live handle, not shared, and
            // an out-parameter NULL or valid for one write.
            let (h, out) = unsafe {
                use $crate::ffi::boundary::{handle_mut, optional_out};
                (handle_mut($m, "m")?, optional_out($out))
            };
            let $c = $crate::ffi::boundary::Handle::core_mut(h);
            let answer = $result;
            $crate::ffi::boundary::Handle::settle_views(h);
            let answer = answer?;
            if let Some(out) = out {
                out.set(answer);
            }
            Ok(())
        })
    };
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

/// The Rust side of a handle type and its options struct: `Handle` over the core field
/// (the fields after it are the origin views, each with the count it spans), the handle from a core
/// structure, the options' defaults, conversion and C layout.
macro_rules! handle {
    ($h:ident { $field:ident: $core:ty, $($map:ident: $count:ident),* }, $opt:ident => $core_opt:ident) => {
        impl $crate::ffi::boundary::Handle for $h {
            type Core = $core;
            #[inline(always)]
            fn core(&self) -> &$core {
                &self.$field
            }
            fn core_mut(&mut self) -> &mut $core {
                &mut self.$field
            }
            fn settle_views(&mut self) {
                $(if self.$map.get().is_some_and(|m| m.len() != self.$field.$count()) {
                    self.$map = Default::default();
                })*
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
                $h { $field, warnings: Vec::new(), $($map: Default::default()),* }
            }
        }

        $crate::ffi::shapes::options!($opt => $core_opt {
            level: 0, strict: 4, threads: 8, memory_limit_bytes: 16, weld_tolerance: 24,
        } 32);
    };
}

/// A C build options struct (`che_build_options`, `chf_build_options`): the same fields
/// for both, with what `strict` rejects in the caller's words.
macro_rules! build_options {
    ($(#[$doc:meta])* $name:ident { $(#[$strict:meta])* strict }) => {
        $(#[$doc])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name {
            /// The level, 0..3 (default 2).
            pub level: u32,
            $(#[$strict])*
            /// Any non-zero value is true. (A `uint8_t` rather than a `bool`, with the size and
            /// offset of the `bool` it was: a C `bool` field can hold other values, which Rust
            /// may not read as a `bool`.)
            pub strict: u8,
            /// Threads for the build: 0 (default) for as many as the machine runs at once, 1 for
            /// the calling thread alone; a larger number is capped at what the machine runs at once
            /// and at one thread per 8192 elements. The mesh is the same whatever the number.
            pub threads: u32,
            /// A memory budget for the build, in bytes (0, the default: none). The build
            /// estimates its peak from the input's sizes and, when the estimate exceeds the
            /// budget, returns `TOPOMESH_STATUS_OUT_OF_MEMORY` before allocating (detail: the
            /// estimate and the budget).
            pub memory_limit_bytes: u64,
            /// Weld before building: vertices at most this distance apart (on the positions, which
            /// it needs) become one, the smallest id of each cluster of close vertices winning;
            /// the others keep their ids but lose their elements. 0 (default) is off.
            pub weld_tolerance: f64,
        }
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

pub(crate) use {build, build_options, edit, handle, ids, load, make, open, options, value};
