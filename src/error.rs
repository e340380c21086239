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
    /// An allocation failed or a build's estimate exceeded its memory limit; the message
    /// names the bytes and what they were for, [`Error::bytes`] gives the bytes.
    OutOfMemory,
}

/// An error with the place it happened (file and line, or element id) in its message.
///
/// The kind and the message are all most errors carry. An out-of-memory error also
/// carries the bytes it asked for, reachable through [`Error::bytes`]: a detail in the
/// struct rather than an enum variant, so that every error keeps one shape (`kind`,
/// `message`) and maps onto one C status, and private so that a later detail needs no new
/// public field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    pub kind: ErrorKind,
    pub message: String,
    bytes: Option<u64>,
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
            bytes: None,
        }
    }

    /// An [`ErrorKind::OutOfMemory`] error: `bytes` could not be had for `what` (the array
    /// and its structure, such as "the opposites O (level 1)"). Its message is short, so
    /// that reporting a failed allocation asks for little more memory.
    pub fn out_of_memory(bytes: u64, what: &str) -> Self {
        Error {
            kind: ErrorKind::OutOfMemory,
            message: format!("out of memory: {} for {what}", ByteSize(bytes)),
            bytes: Some(bytes),
        }
    }

    /// An [`ErrorKind::OutOfMemory`] error: the estimated `bytes` of `what` exceed the
    /// memory limit `limit`, refused before allocating.
    pub fn over_limit(bytes: u64, limit: u64, what: &str) -> Self {
        Error {
            kind: ErrorKind::OutOfMemory,
            message: format!(
                "out of memory: {what} needs an estimated {}, over the limit of {}",
                ByteSize(bytes),
                ByteSize(limit)
            ),
            bytes: Some(bytes),
        }
    }

    /// The bytes an [`ErrorKind::OutOfMemory`] error asked for or estimated (None for
    /// other kinds).
    pub fn bytes(&self) -> Option<u64> {
        self.bytes
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
    // A control character is a byte below 0x20, 0x7f, or U+0080..U+009F (0xc2 then a
    // byte): a byte scan rules them out without decoding the characters.
    if !message.bytes().any(|b| b < 0x20 || b == 0x7f || b == 0xc2) {
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

/// A byte count for people: "1.2 GiB", "512 B".
pub(crate) struct ByteSize(pub u64);

impl fmt::Display for ByteSize {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const UNITS: [&str; 6] = ["KiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
        if self.0 < 1024 {
            return write!(f, "{} B", self.0);
        }
        let (mut value, mut unit) = (self.0 as f64 / 1024.0, 0);
        while value >= 1024.0 && unit + 1 < UNITS.len() {
            value /= 1024.0;
            unit += 1;
        }
        write!(f, "{value:.1} {}", UNITS[unit])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_of_memory_names_the_bytes_and_the_array() {
        let e = Error::out_of_memory(1_288_490_189, "the opposites O (level 1)");
        assert_eq!(e.kind, ErrorKind::OutOfMemory);
        assert_eq!(e.bytes(), Some(1_288_490_189));
        assert_eq!(
            e.message,
            "out of memory: 1.2 GiB for the opposites O (level 1)"
        );
        assert_eq!(Error::invalid("x").bytes(), None);
        let sizes = [0, 1023, 1024, 1536, 5 << 20, u64::MAX].map(|b| ByteSize(b).to_string());
        assert_eq!(
            sizes,
            ["0 B", "1023 B", "1.0 KiB", "1.5 KiB", "5.0 MiB", "16.0 EiB"]
        );
    }

    /// The byte scan lets through exactly the messages without a control character:
    /// every character of U+0000..U+0200 alone and inside text, against `is_control`.
    #[test]
    fn control_characters_are_escaped_and_nothing_else() {
        for c in (0..0x200).filter_map(char::from_u32) {
            for message in [c.to_string(), format!("é {c} ok")] {
                let escaped = Error::invalid(message.clone()).message;
                let expected: String = message
                    .chars()
                    .map(|c| {
                        if c.is_control() {
                            c.escape_default().collect()
                        } else {
                            c.to_string()
                        }
                    })
                    .collect();
                assert_eq!(escaped, expected, "U+{:04X}", c as u32);
                assert_eq!(escaped == message, !c.is_control(), "U+{:04X}", c as u32);
            }
        }
    }
}
