//! Shared by the ASCII readers of tetgen, medit, gmsh and vtk: a zero-copy token reader that
//! knows its line and reads counts, points and ids; and the readers' test helpers (error
//! tables, robustness). The writers' lines are in `write/text.rs`.

#[cfg(test)]
use super::MeshData;
use crate::error::{Error, Result};
use glam::DVec3;
use std::borrow::Cow;
use std::fmt::Display;
use std::path::Path;

/// Longest piece of a bad token quoted in an error message.
const QUOTE_MAX: usize = 40;

/// Whitespace-separated tokens of a text, with the line of each; optionally `#` starts a
/// comment that runs to the end of the line. Tokens borrow the text: no allocation.
#[derive(Clone, Debug)]
pub(in crate::io) struct Lexer<'a> {
    text: &'a str,
    name: &'a str,
    pos: usize,
    /// Line (1-based) of `pos`.
    pos_line: usize,
    /// Line of the last token handed out, or where the end of the input was met.
    tok_line: usize,
    comments: bool,
}

#[inline]
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c)
}

impl<'a> Lexer<'a> {
    /// `name` is the file name used in error messages.
    pub(in crate::io) fn new(text: &'a str, name: &'a str, comments: bool) -> Self {
        Lexer {
            text,
            name,
            pos: 0,
            pos_line: 1,
            tok_line: 1,
            comments,
        }
    }

    /// Skips blanks (newlines included) and comments.
    #[inline]
    fn skip_blank(&mut self) {
        let b = self.text.as_bytes();
        while let Some(&c) = b.get(self.pos) {
            match c {
                b'\n' => {
                    self.pos_line += 1;
                    self.pos += 1;
                }
                b' ' | b'\t' | b'\r' | 0x0b | 0x0c => self.pos += 1,
                b'#' if self.comments => {
                    while b.get(self.pos).is_some_and(|&c| c != b'\n') {
                        self.pos += 1;
                    }
                }
                _ => return,
            }
        }
    }

    /// The token at `pos` (blanks already skipped), or `None` at the end of the input.
    #[inline]
    fn take(&mut self) -> Option<&'a str> {
        let b = self.text.as_bytes();
        let start = self.pos;
        self.tok_line = self.pos_line;
        while let Some(&c) = b.get(self.pos) {
            if is_space(c) || (c == b'#' && self.comments) {
                break;
            }
            self.pos += 1;
        }
        // Tokens start and end next to ASCII bytes (or the text's ends), so both are
        // char boundaries and `get` always succeeds.
        (self.pos > start).then(|| self.text.get(start..self.pos).unwrap_or(""))
    }

    /// The next token, across lines.
    #[inline]
    pub(in crate::io) fn next(&mut self) -> Option<&'a str> {
        self.skip_blank();
        self.take()
    }

    /// The next token without consuming it.
    pub(in crate::io) fn peek(&self) -> Option<&'a str> {
        self.clone().next()
    }

    /// Drops the rest of the current line, newline included.
    pub(in crate::io) fn skip_line(&mut self) {
        let b = self.text.as_bytes();
        while let Some(&c) = b.get(self.pos) {
            self.pos += 1;
            if c == b'\n' {
                self.pos_line += 1;
                return;
            }
        }
    }

    /// The raw rest of the current line (no newline, no trailing `\r`), then moves to the
    /// next line; `None` at the end of the input.
    pub(in crate::io) fn next_line(&mut self) -> Option<&'a str> {
        self.tok_line = self.pos_line;
        if self.pos >= self.text.len() {
            return None;
        }
        let rest = self.text.get(self.pos..).unwrap_or("");
        let len = rest.find('\n').unwrap_or(rest.len());
        let line = rest.get(..len).unwrap_or("");
        self.skip_line();
        Some(line.strip_suffix('\r').unwrap_or(line))
    }

    /// The file name used in error messages.
    pub(in crate::io) fn name(&self) -> &'a str {
        self.name
    }

    /// A warning at the last token's line.
    pub(in crate::io) fn warning(&self, msg: impl Into<String>) -> super::Warning {
        super::Warning::new(self.name, Some(self.tok_line), msg)
    }

    /// Line of the last token (or of the end of the input, once met).
    pub(in crate::io) fn line(&self) -> usize {
        self.tok_line
    }

    /// A parse error at the last token's line: `file:line: msg`.
    pub(in crate::io) fn error(&self, msg: impl Display) -> Error {
        self.error_at(self.tok_line, msg)
    }

    pub(in crate::io) fn error_at(&self, line: usize, msg: impl Display) -> Error {
        Error::parse(format!("{}:{}: {}", self.name, line, msg))
    }

    /// `expected {what}, found '{tok}'` at the last token.
    pub(in crate::io) fn bad(&self, what: &str, tok: &str) -> Error {
        self.error(format!("expected {what}, found '{}'", quote(tok)))
    }

    /// The next token, or an end-of-file error naming what was expected.
    #[inline]
    pub(in crate::io) fn expect(&mut self, what: &str) -> Result<&'a str> {
        match self.next() {
            Some(t) => Ok(t),
            None => Err(self.error(format!("unexpected end of file, expected {what}"))),
        }
    }

    /// Consumes the next token, which must equal `word` (ASCII case ignored).
    pub(in crate::io) fn keyword(&mut self, word: &str) -> Result<()> {
        let t = self.expect(word)?;
        if t.eq_ignore_ascii_case(word) {
            Ok(())
        } else {
            Err(self.bad(word, t))
        }
    }

    #[inline]
    pub(in crate::io) fn f64(&mut self, what: &str) -> Result<f64> {
        let t = self.expect(what)?;
        t.parse().map_err(|_| self.bad(what, t))
    }

    #[inline]
    pub(in crate::io) fn u64(&mut self, what: &str) -> Result<u64> {
        let t = self.expect(what)?;
        t.parse().map_err(|_| self.bad(what, t))
    }

    /// A count or a size: a non-negative integer.
    #[inline]
    pub(in crate::io) fn usize(&mut self, what: &str) -> Result<usize> {
        let t = self.expect(what)?;
        t.parse().map_err(|_| self.bad(what, t))
    }

    /// Consumes `n` tokens, whatever they are.
    #[inline]
    pub(in crate::io) fn skip(&mut self, n: usize, what: &str) -> Result<()> {
        for _ in 0..n {
            self.expect(what)?;
        }
        Ok(())
    }

    /// A capacity for `count` items of `tokens` tokens each that the rest of the input can
    /// actually hold (a token and its separator take at least two bytes): declared counts
    /// are never trusted for allocation.
    pub(in crate::io) fn capacity(&self, count: usize, tokens: usize) -> usize {
        let left = self.text.len().saturating_sub(self.pos);
        room(count as u64, left, tokens.max(1).saturating_mul(2))
    }

    /// A count of points (`what` names it in errors) that `u32` ids can number.
    pub(in crate::io) fn point_count(&mut self, what: &str) -> Result<usize> {
        let count = self.usize(what)?;
        if count > u32::MAX as usize {
            return Err(Error::too_large(format!(
                "{}:{}: {count} points is more than the {} that u32 ids can number",
                self.name,
                self.tok_line,
                u32::MAX
            )));
        }
        Ok(count)
    }

    /// A point: three coordinates `x y z`.
    #[inline]
    pub(in crate::io) fn point(&mut self) -> Result<DVec3> {
        let x = self.f64("a coordinate")?;
        let y = self.f64("a coordinate")?;
        let z = self.f64("a coordinate")?;
        Ok(DVec3::new(x, y, z))
    }

    /// An id of one of `count` points numbered from `base`, returned numbered from 0;
    /// `out_of_range` words the error for any other id.
    #[inline]
    pub(in crate::io) fn id(
        &mut self, what: &str, (base, count): (u64, usize), out_of_range: impl Fn(u64) -> String,
    ) -> Result<u32> {
        let id = self.u64(what)?;
        if id < base || id - base >= count as u64 {
            return Err(self.error(out_of_range(id)));
        }
        Ok((id - base) as u32)
    }

    /// The `K` ids that start an element, read as [`Lexer::id`] reads one.
    #[inline]
    pub(in crate::io) fn ids<const K: usize>(
        &mut self, what: &str, range: (u64, usize), out_of_range: impl Fn(u64) -> String,
    ) -> Result<[u32; K]> {
        let mut ids = [0u32; K];
        for v in &mut ids {
            *v = self.id(what, range, &out_of_range)?;
        }
        Ok(ids)
    }
}

/// The first characters of a token, for an error message.
pub(in crate::io) fn quote(tok: &str) -> String {
    if tok.chars().nth(QUOTE_MAX).is_some() {
        let mut s: String = tok.chars().take(QUOTE_MAX).collect();
        s.push_str("...");
        s
    } else {
        tok.to_string()
    }
}

/// Room for `count` items of at least `min_bytes` each in the `left` bytes of the input:
/// declared counts are never trusted for allocation.
pub(in crate::io) fn room(count: u64, left: usize, min_bytes: usize) -> usize {
    (count.min(usize::MAX as u64) as usize).min(left / min_bytes.max(1))
}

/// Reads a file as text; bytes that are not UTF-8 become U+FFFD so that a binary or
/// damaged file gets a parse error with a line instead of a bare I/O error.
pub(in crate::io) fn read_text(path: &Path) -> Result<String> {
    let bytes = crate::io::read_bytes(path)?;
    match String::from_utf8(bytes) {
        Ok(s) => Ok(s),
        Err(e) => Ok(lossy(e.as_bytes())?.into_owned()),
    }
}

/// `String::from_utf8_lossy`, asking for the copy (when one is needed) fallibly.
pub(in crate::io) fn lossy(bytes: &[u8]) -> Result<Cow<'_, str>> {
    if let Ok(s) = std::str::from_utf8(bytes) {
        return Ok(Cow::Borrowed(s));
    }
    let mut s = String::new();
    for chunk in bytes.utf8_chunks() {
        // A U+FFFD (3 bytes) for each run of invalid bytes.
        s.try_reserve(chunk.valid().len() + 3)
            .map_err(|_| Error::out_of_memory(bytes.len() as u64, "the file's text"))?;
        s.push_str(chunk.valid());
        if !chunk.invalid().is_empty() {
            s.push(char::REPLACEMENT_CHARACTER);
        }
    }
    Ok(Cow::Owned(s))
}

/// A path under the temp dir, unique to this process and call.
#[cfg(test)]
pub(in crate::io) fn temp_path(tag: &str, ext: &str) -> std::path::PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    std::env::temp_dir().join(format!(
        "topomesh-test-{}-{}-{tag}.{ext}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ))
}

/// Writes `bytes` to a temporary `.ext` file and reads it back with [`crate::io::read`].
#[cfg(test)]
pub(in crate::io) fn read_temp(ext: &str, bytes: impl AsRef<[u8]>) -> Result<MeshData> {
    let path = temp_path("read", ext);
    std::fs::write(&path, bytes).unwrap();
    let read = crate::io::read(&path);
    let _ = std::fs::remove_file(&path);
    read
}

/// A mesh's warnings as they are shown.
#[cfg(test)]
pub(in crate::io) fn warning_lines(m: &MeshData) -> Vec<String> {
    m.warnings.iter().map(|w| w.to_string()).collect()
}

/// Test input as text.
#[cfg(test)]
pub(in crate::io) fn utf8(bytes: &[u8]) -> &str {
    std::str::from_utf8(bytes).unwrap()
}

/// The error `parse` gives for `input`; panics if it parses.
#[cfg(test)]
pub(in crate::io) fn parse_error(
    parse: impl Fn(&[u8]) -> Result<MeshData>, input: impl AsRef<[u8]>,
) -> Error {
    let input = input.as_ref();
    match parse(input) {
        Ok(m) => panic!(
            "expected an error for {:?}, got {m:?}",
            String::from_utf8_lossy(input)
        ),
        Err(e) => e,
    }
}

/// Parses each input and checks its error: the kind, and the words the message starts with.
#[cfg(test)]
pub(in crate::io) fn assert_errors<I: AsRef<[u8]>>(
    parse: impl Fn(&[u8]) -> Result<MeshData>,
    cases: impl IntoIterator<Item = (I, crate::error::ErrorKind, &'static str)>,
) {
    let mut wrong = String::new();
    for (input, kind, start) in cases {
        let e = parse_error(&parse, input);
        if e.kind != kind || !e.message.starts_with(start) {
            wrong += &format!("\nexpected a {kind:?} error starting {start:?}, got {e:?}");
        }
    }
    assert!(wrong.is_empty(), "{wrong}");
}

/// Parses every prefix of `src`, and `src` with each token in turn replaced by hostile
/// ones: no panic, and every error starts with `prefix` (the file name and a colon).
#[cfg(test)]
pub(in crate::io) fn assert_robust(
    src: &str, prefix: &str, parse: impl Fn(&str) -> Result<MeshData>,
) {
    let check = |text: &str| {
        if let Err(e) = parse(text) {
            assert!(e.message.starts_with(prefix), "{}", e.message);
        }
    };
    for end in 0..=src.len() {
        check(&src[..end]);
    }
    let mut starts = Vec::new();
    let mut lx = Lexer::new(src, "", false);
    while let Some(t) = lx.next() {
        let start = t.as_ptr() as usize - src.as_ptr() as usize;
        starts.push((start, start + t.len()));
    }
    let hostile = [
        "",
        "-1",
        "x",
        "0",
        "1e999",
        "18446744073709551616",
        "4294967295",
    ];
    for &(a, b) in &starts {
        for h in hostile {
            check(&format!("{}{h}{}", &src[..a], &src[b..]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_lines_and_comments() {
        let mut lx = Lexer::new("a b # c d\n\n  e#f\r\ng", "t", true);
        assert_eq!((lx.next(), lx.line()), (Some("a"), 1));
        assert_eq!((lx.next(), lx.line()), (Some("b"), 1));
        assert_eq!((lx.next(), lx.line()), (Some("e"), 3));
        assert_eq!(lx.peek(), Some("g"));
        assert_eq!((lx.next(), lx.line()), (Some("g"), 4));
        assert_eq!(lx.next(), None);
        let e = lx.expect("a number").unwrap_err();
        assert!(
            e.message.starts_with("t:4: unexpected end"),
            "{}",
            e.message
        );

        let mut lx = Lexer::new("a #x\nb", "t", false);
        assert_eq!(lx.next(), Some("a"));
        assert_eq!(lx.next_line(), Some(" #x"));
        assert_eq!(lx.next_line(), Some("b"));
        assert_eq!(lx.next_line(), None);
    }

    #[test]
    fn numbers_and_capacity() {
        let mut lx = Lexer::new("1.5 -2 x 7", "f.txt", false);
        assert_eq!(lx.f64("x").unwrap(), 1.5);
        let e = lx.usize("a count").unwrap_err();
        assert_eq!(e.message, "f.txt:1: expected a count, found '-2'");
        assert!(lx.f64("y").is_err());
        assert_eq!(lx.capacity(usize::MAX, 1), 1);
        assert_eq!(quote(&"z".repeat(100)).len(), QUOTE_MAX + 3);
    }
}
