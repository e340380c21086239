//! Text output shared by the subcommands: aligned `label value` lines and the first
//! offending ids of a build report.

use std::fmt::{Debug, Display};

/// `label` padded to the value column of the summary.
pub fn line(label: &str, value: impl Display) {
    println!("{label:<21}{value}");
}

/// One count of a build report, with its first examples.
pub fn report_line<T: Debug>(label: &str, count: usize, list: &[T]) {
    println!("  {label:<26}{count}{}", examples(list));
}

/// `  (first: [...])`, or nothing for an empty list.
pub fn examples<T: Debug>(list: &[T]) -> String {
    if list.is_empty() {
        String::new()
    } else {
        format!("  (first: {list:?})")
    }
}

pub fn yes(b: bool) -> &'static str {
    if b { "yes" } else { "no" }
}
