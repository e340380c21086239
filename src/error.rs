//! One error type for the whole crate; its kind maps one-to-one onto the C status codes.

use std::fmt;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    NullArgument,
    OutOfRange,
    InvalidInput,
    NonManifold,
    BufferTooSmall,
    Io,
    Parse,
    TooLarge,
    Panic,
}

/// An error with the place it happened (file and line, or element id) in its message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    pub kind: ErrorKind,
    pub message: String,
}

/// One constructor per error kind: `Error::parse(message)` for `ErrorKind::Parse`, ...
macro_rules! kind_constructors {
    ($($name:ident => $kind:ident,)*) => {
        $(
            #[doc = concat!("An error of kind [`ErrorKind::", stringify!($kind), "`].")]
            pub fn $name(message: impl Into<String>) -> Self {
                Self::new(ErrorKind::$kind, message)
            }
        )*
    };
}

impl Error {
    /// An error of kind `kind`. Control characters in `message` (which may come from a
    /// file's name or content) are escaped (`\u{1b}`), so that printing the message cannot
    /// send escape sequences to a terminal.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error {
            kind,
            message: escape_controls(message.into()),
        }
    }
    kind_constructors! {
        out_of_range => OutOfRange,
        invalid => InvalidInput,
        parse => Parse,
        io => Io,
        too_large => TooLarge,
        non_manifold => NonManifold,
    }
}

/// `message` with every control character written as its Rust escape (`\n`, `\u{1b}`).
fn escape_controls(message: String) -> String {
    if !message.chars().any(char::is_control) {
        return message;
    }
    let escape = |c: char| -> String {
        if c.is_control() {
            c.escape_default().collect()
        } else {
            c.into()
        }
    };
    message.chars().map(escape).collect()
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}: {}", self.kind, self.message)
    }
}

impl std::error::Error for Error {}

pub type Result<T> = std::result::Result<T, Error>;
