//! How a refused edit is worded: `refused: ...`, prefixed with the operation and what it
//! was asked of (`flip_23 of face 12: refused: ...`), into one string sized for it.
//!
//! Most checks of a random storm are refusals, and the words cost more than the check of
//! a geometric refusal. A yes-or-no question ([`yes_or_no`], behind `Chf::is_flip_23_ok`
//! and the like) turns the words off for its run on its thread: a refusal is then an
//! error of the right kind with no message, which the question answers `false` to.

use crate::error::{Error, ErrorKind, Result};
use std::cell::Cell;
use std::fmt::Write;

/// Room for the words of most refusals, so that writing them grows no string.
const REFUSAL_WORDS: usize = 96;

thread_local! {
    /// Whether refusals on this thread are worded (off only inside [`yes_or_no`]).
    static WORDED: Cell<bool> = const { Cell::new(true) };
}

fn worded() -> bool {
    WORDED.with(Cell::get)
}

/// A refusal of kind `kind`: `refused: ` and `what`, unworded inside [`yes_or_no`].
pub(super) fn refuse_as(kind: ErrorKind, what: std::fmt::Arguments) -> Error {
    if !worded() {
        return Error::new(kind, String::new());
    }
    let mut m = String::with_capacity(REFUSAL_WORDS);
    m.push_str("refused: ");
    let _ = m.write_fmt(what);
    Error::new(kind, m)
}

/// A refusal of kind `InvalidInput`.
pub(super) fn refuse(what: std::fmt::Arguments) -> Error {
    refuse_as(ErrorKind::InvalidInput, what)
}

/// What an operation works on, as its refusal names it (`face 12`); a pair of words and
/// a number until a refusal writes them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Named(pub &'static str, pub u64);

impl std::fmt::Display for Named {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{} {}", self.0, self.1)
    }
}

/// The corners of a tetrahedron as a refusal names them, `[a, b, c, d]` (the words of
/// `{:?}`, without the list formatter's machinery).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Corners(pub [u32; 4]);

impl std::fmt::Display for Corners {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let [a, b, c, d] = self.0;
        write!(f, "[{a}, {b}, {c}, {d}]")
    }
}

/// An error saying why `op` on `what` was refused, keeping the kind of `e`; `what` is
/// worded only on a refusal (and not inside [`yes_or_no`]), into one string sized for the
/// whole.
pub(crate) fn context(
    op: &'static str, what: impl std::fmt::Display,
) -> impl FnOnce(Error) -> Error {
    move |e| {
        if !worded() {
            return e;
        }
        let mut m = String::with_capacity(op.len() + e.message.len() + 32);
        let _ = write!(m, "{op} of {what}: ");
        m.push_str(&e.message);
        Error::new(e.kind, m)
    }
}

/// Does `check` pass? Asked without words: `Ok(false)` for a refusal (an error of kind
/// `InvalidInput` or `NonManifold`, the kinds of every refusal of an edit); any other
/// error (a bad or removed id, memory) is `check`'s, worded: it runs again to say it.
pub(crate) fn yes_or_no(check: impl Fn() -> Result<()>) -> Result<bool> {
    /// Turns the words back on however `check` ends.
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            WORDED.with(|w| w.set(self.0));
        }
    }
    let answer = {
        let _restore = Restore(WORDED.with(|w| w.replace(false)));
        check()
    };
    match answer {
        Ok(()) => Ok(true),
        Err(e) if matches!(e.kind, ErrorKind::InvalidInput | ErrorKind::NonManifold) => Ok(false),
        Err(_) => check().map(|()| true),
    }
}

#[cfg(test)]
mod tests {
    use super::{context, refuse, yes_or_no};
    use crate::error::{Error, ErrorKind};

    #[test]
    fn a_question_answers_refusals_without_words_and_says_other_errors() {
        let refused = || Err(context("flip_23", "face 1")(refuse(format_args!("no"))));
        assert_eq!(yes_or_no(refused), Ok(false));
        let e = refused().unwrap_err();
        assert_eq!(e.message, "flip_23 of face 1: refused: no");
        assert_eq!(yes_or_no(|| Ok(())), Ok(true));
        let bad = || {
            Err(context("flip_23", "face 9")(Error::out_of_range(
                "face 9 is gone",
            )))
        };
        let e = yes_or_no(bad).unwrap_err();
        assert_eq!(e.kind, ErrorKind::OutOfRange);
        assert_eq!(e.message, "flip_23 of face 9: face 9 is gone");
    }
}
