//! Writing a file so that it is either whole or absent: the bytes go to a temporary file in
//! the target's folder, which is flushed, synced and then renamed over the target. A
//! failure at any step removes the temporary file and returns an `Io` error naming the
//! target, so a reader never sees a half-written mesh and nothing is left behind.
//!
//! A target that exists and is not a regular file (a device such as `/dev/null` or
//! `/dev/full`, a pipe) is written in place: renaming over it would replace the device
//! node, and writing into it is what the caller asked for.

use super::chunked::Chunked;
use crate::error::{Error, Result};
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// What fills one file.
pub(crate) type Body<'a> = &'a mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>;

/// Writes `path` with `body`, whole or not at all.
pub(crate) fn write(path: &Path, body: Body) -> Result<()> {
    write_all(&mut [(path, body)])
}

/// Writes every file, each with its body: all the temporary files are written and synced
/// before the first rename, so a failure while writing leaves every target as it was.
pub(crate) fn write_all(files: &mut [(&Path, Body)]) -> Result<()> {
    let mut staged: Vec<Staged> = Vec::new();
    for (path, body) in files.iter_mut() {
        match stage(path, *body) {
            Ok(s) => staged.push(s),
            Err(e) => {
                staged.iter().for_each(Staged::discard);
                return Err(e);
            }
        }
    }
    for (i, s) in staged.iter().enumerate() {
        if let Err(e) = s.commit() {
            staged[i..].iter().for_each(Staged::discard);
            return Err(e);
        }
    }
    Ok(())
}

/// A file written to its temporary name (`temp`), or straight into a non-regular target
/// (`temp == None`).
struct Staged {
    target: PathBuf,
    shown: PathBuf,
    temp: Option<PathBuf>,
}

fn io_error(path: &Path, e: std::io::Error) -> Error {
    Error::io(format!("{}: {e}", path.display()))
}

/// Writes `body` to a temporary file beside `path` (or into `path` itself when it is a
/// device or a pipe), flushed and synced.
fn stage(path: &Path, body: Body) -> Result<Staged> {
    let err = |e| io_error(path, e);
    let existing = std::fs::metadata(path).ok();
    if existing.as_ref().is_some_and(|m| !m.is_file()) {
        if existing.as_ref().is_some_and(|m| m.is_dir()) {
            return Err(Error::io(format!("{}: is a folder", path.display())));
        }
        let file = OpenOptions::new().write(true).open(path).map_err(err)?;
        fill(file, body, false, path)?;
        return Ok(Staged {
            target: path.to_path_buf(),
            shown: path.to_path_buf(),
            temp: None,
        });
    }
    // A symbolic link is followed: the file it names is replaced, the link kept.
    let target = match existing {
        Some(_) => std::fs::canonicalize(path).map_err(err)?,
        None => path.to_path_buf(),
    };
    let (temp, file) = create_temp(&target).map_err(err)?;
    if let Some(m) = existing {
        // The replacement keeps the permissions of the file it replaces.
        let _ = file.set_permissions(m.permissions());
    }
    if let Err(e) = fill(file, body, true, path) {
        let _ = std::fs::remove_file(&temp);
        return Err(e);
    }
    Ok(Staged {
        target,
        shown: path.to_path_buf(),
        temp: Some(temp),
    })
}

/// Writes `body` through a buffer of whole 2 MiB writes (`chunked.rs` says why), flushes,
/// and syncs when `sync` (a device may not support it). Errors name `path`.
fn fill(file: File, body: Body, sync: bool, path: &Path) -> Result<()> {
    let io = |e| io_error(path, e);
    let mut w = Chunked::new(file)?;
    body(&mut w).map_err(io)?;
    let file = w.into_inner().map_err(io)?;
    if sync {
        file.sync_all().map_err(io)?;
    }
    Ok(())
}

/// A new file beside `target`, named after it with a tag unique to this process and call
/// (created exclusively, so two writers never share one), open to read and write (a file
/// filled in place is mapped).
pub(crate) fn create_temp(target: &Path) -> std::io::Result<(PathBuf, File)> {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let name = target
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"))?;
    let folder = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut temp_name = std::ffi::OsString::from(".");
    temp_name.push(name);
    temp_name.push(format!(
        ".{}-{}.tmp",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ));
    let temp = folder.join(temp_name);
    let file = OpenOptions::new()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&temp)?;
    Ok((temp, file))
}

/// Renames the written `temp` over `target`, then syncs the folder so that the rename
/// itself survives a crash (best effort: not every file system lets a folder be opened and
/// synced, and the data is already safe). Errors name `shown`.
pub(crate) fn rename_into_place(temp: &Path, target: &Path, shown: &Path) -> Result<()> {
    std::fs::rename(temp, target).map_err(|e| io_error(shown, e))?;
    if let Some(folder) = target.parent().filter(|p| !p.as_os_str().is_empty()) {
        let _ = File::open(folder).and_then(|f| f.sync_all());
    }
    Ok(())
}

impl Staged {
    /// Renames the temporary file over the target ([`rename_into_place`]).
    fn commit(&self) -> Result<()> {
        let Some(temp) = &self.temp else {
            return Ok(());
        };
        rename_into_place(temp, &self.target, &self.shown)
    }

    fn discard(&self) {
        if let Some(temp) = &self.temp {
            let _ = std::fs::remove_file(temp);
        }
    }
}
