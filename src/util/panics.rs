//! Panics that the library catches and reports itself: the C boundary turns a panic into
//! `TOPOMESH_STATUS_PANIC` with a detail, and the library never writes to the host's
//! stderr, so the panic hook must not print those. The hook is process-wide and the host
//! may have set its own: the library's hook, installed once, is silent only on a thread
//! that runs inside [`quiet`] (or a build thread started from one, see `par::run_all`)
//! and hands every other panic to the hook that was there before.

use std::cell::{Cell, RefCell};
use std::sync::Once;

thread_local! {
    /// How many `quiet` calls this thread is inside.
    static DEPTH: Cell<u32> = const { Cell::new(0) };
    /// Where the last panic silenced on this thread happened, for the error's detail.
    static LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Runs `f` with the panics of this thread silenced (the caller catches them).
pub(crate) fn quiet<R>(f: impl FnOnce() -> R) -> R {
    /// Leaves the quiet section on the way out, unwinding or not.
    struct Leave;
    impl Drop for Leave {
        fn drop(&mut self) {
            DEPTH.with(|d| d.set(d.get() - 1));
        }
    }
    install();
    DEPTH.with(|d| d.set(d.get() + 1));
    let _leave = Leave;
    f()
}

/// `quiet(f)` when `silenced` (a thread started from a quiet one), else `f()`.
pub(crate) fn quiet_if<R>(silenced: bool, f: impl FnOnce() -> R) -> R {
    if silenced { quiet(f) } else { f() }
}

/// Whether this thread is inside `quiet`.
pub(crate) fn is_quiet() -> bool {
    DEPTH.try_with(|d| d.get() > 0).unwrap_or(false)
}

/// Where the last silenced panic of this thread happened ("file:line:column"), once.
pub(crate) fn take_location() -> Option<String> {
    LOCATION.try_with(|l| l.borrow_mut().take()).ok().flatten()
}

/// Installs the library's hook in front of the current one, once per process.
fn install() {
    static INSTALLED: Once = Once::new();
    INSTALLED.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if is_quiet() {
                let at = info.location().map(ToString::to_string);
                let _ = LOCATION.try_with(|l| *l.borrow_mut() = at);
            } else {
                previous(info);
            }
        }));
    });
}
