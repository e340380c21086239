//! What a reader read past or found odd without refusing the file: every reader reports it
//! here instead of dropping it silently, and `io::read` adds the checks all formats share
//! (non-finite coordinates, a file of points only).

use super::MeshData;
use std::fmt;

/// One thing a reader read past or found odd, with the place it was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning {
    /// The file (or the name given to `io::parse`).
    pub file: String,
    /// The 1-based line (text formats), when the warning has one place.
    pub line: Option<usize>,
    pub message: String,
}

impl Warning {
    pub fn new(file: &str, line: Option<usize>, message: impl Into<String>) -> Self {
        Warning {
            file: file.to_string(),
            line,
            message: message.into(),
        }
    }
}

/// `file:line: message`, or `file: message` without a line.
impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{line}: {}", self.file, self.message),
            None => write!(f, "{}: {}", self.file, self.message),
        }
    }
}

/// `0, 1, 5` (and `, ...` when `count` is more than the examples).
pub(crate) fn list_examples(examples: &[u32], count: u64) -> String {
    let mut s = examples
        .iter()
        .map(u32::to_string)
        .collect::<Vec<_>>()
        .join(", ");
    if count > examples.len() as u64 {
        s.push_str(", ...");
    }
    s
}

/// The checks every format shares, appended to what the reader found: non-finite
/// coordinates, and a file of vertices with no element (read as a point set).
pub(super) fn add_common(data: &mut MeshData, file: &str) {
    let (n, examples) = crate::util::non_finite_vertices(&data.positions);
    if n > 0 {
        let msg = format!(
            "{} a NaN or infinite coordinate (0-based ids {}); geometric checks skip them",
            count(n, ("vertex has", "vertices have")),
            list_examples(&examples, n)
        );
        data.warnings.push(Warning::new(file, None, msg));
    }
    if !data.positions.is_empty() && data.triangles.is_empty() && data.tetrahedra.is_empty() {
        let msg = format!(
            "no faces or cells: read as a point set of {}",
            count(data.positions.len() as u64, ("vertex", "vertices"))
        );
        data.warnings.push(Warning::new(file, None, msg));
    }
}

/// A noun with its plural: `("quadrangle ignored", "quadrangles ignored")`.
pub(super) type Noun = (&'static str, &'static str);

/// `{n} {noun}`, singular or plural as `n` asks.
pub(super) fn count(n: u64, (one, many): Noun) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// Counts of things read past or changed, by kind, turned into one warning per kind at
/// the end, at the line of the first.
#[derive(Default)]
pub(super) struct Tally {
    /// (what, count, line of the first)
    kinds: Vec<(Noun, u64, Option<usize>)>,
}

impl Tally {
    /// One more `what`, seen at `line`.
    pub(super) fn add(&mut self, what: Noun, line: Option<usize>) {
        self.add_n(what, 1, line);
    }

    pub(super) fn add_n(&mut self, what: Noun, n: u64, line: Option<usize>) {
        if n == 0 {
            return;
        }
        match self.kinds.iter_mut().find(|(w, _, _)| *w == what) {
            Some((_, total, _)) => *total += n,
            None => self.kinds.push((what, n, line)),
        }
    }

    /// One warning per kind, in the order the kinds were first seen.
    pub(super) fn into_warnings(self, file: &str, out: &mut Vec<Warning>) {
        for (what, n, line) in self.kinds {
            out.push(Warning::new(file, line, count(n, what)));
        }
    }
}

/// Elements skipped by type (Gmsh and VTK number their element types): how many of each
/// type, and the line of the first.
#[derive(Default)]
pub(super) struct SkippedTypes {
    /// (type, count, line of the first), in the order the types were first met.
    types: Vec<(u64, u64, usize)>,
}

impl SkippedTypes {
    pub(super) fn add(&mut self, ty: u64, line: usize) {
        match self.types.iter_mut().find(|(t, _, _)| *t == ty) {
            Some((_, n, _)) => *n += 1,
            None => self.types.push((ty, 1, line)),
        }
    }

    /// One warning per type: `{n} {what} ignored (type {ty})`, `what` naming the type.
    pub(super) fn into_warnings(
        self, file: &str, what: impl Fn(u64) -> Noun, out: &mut Vec<Warning>,
    ) {
        for (ty, n, line) in self.types {
            let msg = format!("{} ignored (type {ty})", count(n, what(ty)));
            out.push(Warning::new(file, Some(line), msg));
        }
    }
}
