//! The body of the sparse-matrix exports (`matrix` entries of `exports!`), shared by CHE
//! and CHF.

use super::boundary::{Handle, core, guard, out_arg, sink, zeroed};
use super::status::Status;
use crate::che::{Assembled, CsrSlices, Storage};
use crate::error::{Error, Result};

/// The body of a matrix export: `bufs` are the offsets (`u64`), columns (`u32`) and
/// values (`f64`) buffers as the caller gave them (all NULL: a size query; some NULL and
/// not all: an error), `lens` the offsets' and entries' out-lengths; `make` gives the
/// matrix from the handle's core, in the caller's buffers when they hold it.
pub(crate) unsafe fn matrix_out<H: Handle>(
    m: *const H, bufs: (*mut u64, *mut u32, *mut f64), caps: [usize; 3], lens: [*mut usize; 2],
    make: impl FnOnce(&H::Core, Storage) -> Result<Assembled>,
) -> Status {
    guard(|| {
        let nulls = [bufs.0.is_null(), bufs.1.is_null(), bufs.2.is_null()];
        if let Some(k) = nulls
            .iter()
            .position(|&n| n)
            .filter(|_| nulls.contains(&false))
        {
            let name = ["offsets", "columns", "values"][k];
            let message = format!("argument '{name}' is NULL while the other buffers are not");
            return Err(Error::new(crate::ErrorKind::NullArgument, message));
        }
        // SAFETY: caller contract (see `ffi`): NULL or valid pointers of the stated sizes.
        let (c, n_offsets, n_entries) = unsafe {
            let lens = (
                out_arg(lens[0], "n_offsets")?,
                out_arg(lens[1], "n_entries")?,
            );
            (core(m)?, lens.0, lens.1)
        };
        let mut offer = |rows: usize, entries: usize| {
            let room = !nulls[0] && caps[0] >= rows && caps[1] >= entries && caps[2] >= entries;
            // SAFETY: each buffer is valid for its capacity (contract), at least the lengths
            // asked; zeroed before it is seen as initialised.
            room.then(|| unsafe {
                CsrSlices {
                    offsets: zeroed(bufs.0, rows),
                    columns: zeroed(bufs.1, entries),
                    values: zeroed(bufs.2, entries),
                }
            })
        };
        match make(c, &mut offer)? {
            Assembled::Written {
                n_offsets: o,
                n_entries: e,
            } => {
                n_offsets.set(o);
                n_entries.set(e);
                Ok(())
            }
            Assembled::Owned(matrix) => {
                let mut n_values = 0usize;
                // SAFETY: as above; the slices offered are no longer in use.
                let sinks = unsafe {
                    (
                        sink(bufs.0, caps[0], lens[0], "offsets")?,
                        sink(bufs.1, caps[1], lens[1], "columns")?,
                        sink(bufs.2, caps[2], &mut n_values, "values")?,
                    )
                };
                matrix.write_into(sinks)
            }
        }
    })
}
