//! Text output shared by the subcommands: aligned `label value` lines, counts with the
//! right noun, and lists of offending ids.

use crate::output::{Out, verbose};
use std::fmt::Display;
use std::io::{self, Write};

/// How many ids a list shows before `... and N more` (under `--verbose`: every id the build
/// report kept).
const SHOWN_IDS: usize = 5;

/// `label` padded to the value column of the summary.
pub fn line(out: &mut Out, label: &str, value: impl Display) -> io::Result<()> {
    writeln!(out, "{label:<21}{value}")
}

/// `1 vertex`, `2 vertices`: the count with the noun that agrees with it.
pub fn count(n: impl Into<u64>, one: &str, many: &str) -> String {
    let n = n.into();
    format!("{n} {}", if n == 1 { one } else { many })
}

/// An offending element as the build report names it: a vertex or element id, or a tuple
/// of ids (an edge's vertices, a pair of duplicate elements).
pub trait Id {
    fn text(&self) -> String;
}

impl Id for u32 {
    fn text(&self) -> String {
        self.to_string()
    }
}

impl<const N: usize> Id for [u32; N] {
    fn text(&self) -> String {
        let ids: Vec<String> = self.iter().map(u32::to_string).collect();
        format!("({})", ids.join(", "))
    }
}

/// `3, 8, 12`, or `3, 8, 12, 14, 20 ... and 7 more` when `total` (the report's count) is
/// more than the ids shown; empty for an empty list.
pub fn ids<T: Id>(list: &[T], total: usize) -> String {
    let cap = if verbose() { list.len() } else { SHOWN_IDS };
    let shown: Vec<String> = list.iter().take(cap).map(Id::text).collect();
    let rest = total.saturating_sub(shown.len());
    match (shown.is_empty(), rest) {
        (true, _) => String::new(),
        (false, 0) => shown.join(", "),
        (false, _) => format!("{} ... and {rest} more", shown.join(", ")),
    }
}

/// One count of a build report, with its first ids.
pub fn report_line<T: Id>(out: &mut Out, label: &str, n: usize, list: &[T]) -> io::Result<()> {
    let list = ids(list, n);
    let sep = if list.is_empty() { "" } else { ": " };
    writeln!(out, "  {label:<26}{n}{sep}{list}")
}

pub fn yes(b: bool) -> &'static str {
    if b { "yes" } else { "no" }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_agree_with_their_noun() {
        assert_eq!(count(0u32, "vertex", "vertices"), "0 vertices");
        assert_eq!(count(1u32, "vertex", "vertices"), "1 vertex");
        assert_eq!(count(2u64, "vertex", "vertices"), "2 vertices");
    }

    #[test]
    fn id_lists_are_capped_with_the_rest_counted() {
        assert_eq!(ids::<u32>(&[], 0), "");
        assert_eq!(ids(&[4u32, 7], 2), "4, 7");
        assert_eq!(ids(&[[1u32, 2], [3, 4]], 2), "(1, 2), (3, 4)");
        let list: Vec<u32> = (0..16).collect();
        assert_eq!(ids(&list, 40), "0, 1, 2, 3, 4 ... and 35 more");
        assert_eq!(ids(&list[..5], 5), "0, 1, 2, 3, 4");
    }
}
