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
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error {
            kind,
            message: message.into(),
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

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}: {}", self.kind, self.message)
    }
}

impl std::error::Error for Error {}

pub type Result<T> = std::result::Result<T, Error>;
