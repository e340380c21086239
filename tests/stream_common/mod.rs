//! Shared by the streaming build tests (`mod stream_common;`): a scratch folder, the check
//! that a refusal names its place and leaves no file, and the tally of soups streamed or
//! refused.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use topomesh::ErrorKind;
use topomesh::error::Result;

/// An empty folder of this process for `tag`.
pub fn folder(suite: &str, tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("topomesh-{suite}-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `result` is an error of `kind` whose message has every one of `words`, and `dir`
/// (where the file would have been) is left empty; then `dir` is removed.
pub fn assert_refused<T>(result: Result<T>, dir: &Path, kind: ErrorKind, words: &[&str]) {
    let Err(e) = result else {
        panic!("accepted; expected {kind:?} with {words:?}")
    };
    assert_eq!(e.kind, kind, "{}", e.message);
    for w in words {
        assert!(e.message.contains(w), "{:?} lacks {w:?}", e.message);
    }
    let left: Vec<_> = std::fs::read_dir(dir).unwrap().collect();
    assert!(left.is_empty(), "left behind: {left:?}");
    let _ = std::fs::remove_dir_all(dir);
}

/// Soups streamed to the built file, and soups refused.
#[derive(Default)]
pub struct Tally {
    pub same: usize,
    pub refused: usize,
}

impl Tally {
    /// A streamed file must be `want`, byte for byte; a refusal must leave only the built
    /// file in `dir`.
    pub fn record(&mut self, streamed: Result<Vec<u8>>, want: &[u8], dir: &Path, round: u64) {
        match streamed {
            Ok(bytes) => {
                assert!(bytes == want, "round {round}: the files differ");
                self.same += 1;
            }
            Err(e) => {
                let left = std::fs::read_dir(dir).unwrap().count();
                assert_eq!(left, 1, "round {round}: {e}: only the built file stays");
                self.refused += 1;
            }
        }
    }

    /// Both happened.
    pub fn check(&self) {
        println!("{} streamed, {} refused", self.same, self.refused);
        assert!(self.same > 0 && self.refused > 0);
    }
}
