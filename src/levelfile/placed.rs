//! A level file laid out first and filled in place: every section's length is known before
//! its contents, so the streaming build writes arrays larger than memory straight into
//! their sections of a mapped temporary file. The checksums are computed once every
//! section is written, and only then does the file take its name (whole or absent, as
//! every save).

use super::format::{Elem, Entry, Kind};
use super::write::{Section, head, place};
use crate::error::{Error, Result};
use crate::io::write::atomic::{create_temp, rename_into_place};
use memmap2::MmapMut;
use std::path::{Path, PathBuf};

/// A section to lay out: written now from its data, or filled later in place.
pub(crate) enum Part<'a> {
    Now(Section<'a>),
    Later {
        name: String,
        elem: Elem,
        count: u64,
    },
}

/// A level file being filled; removed unless [`Placed::finish`] names it.
pub(crate) struct Placed {
    target: PathBuf,
    temp: PathBuf,
    map: MmapMut,
    file: std::fs::File,
    entries: Vec<Entry>,
    kind: Kind,
    level: u8,
    flags: u32,
    file_len: u64,
}

impl Placed {
    /// Lays out `parts` in order in a new temporary file beside `path` and writes the
    /// sections given now.
    pub(crate) fn create(
        path: &Path, (kind, level, flags): (Kind, u8, u32), parts: &[Part],
    ) -> Result<Placed> {
        if cfg!(target_endian = "big") {
            return Err(Error::invalid(
                "a level file is filled in place on little-endian machines only",
            ));
        }
        let shapes = parts.iter().map(|p| match p {
            Part::Now(s) => (s.name.clone(), s.data.elem(), s.data.len() as u64),
            Part::Later { name, elem, count } => (name.clone(), *elem, *count),
        });
        let (entries, file_len) = place(shapes)?;
        let io = |e: std::io::Error| Error::io(format!("{}: {e}", path.display()));
        let (temp, file) = create_temp(path).map_err(io)?;
        let sized = file.set_len(file_len).map_err(io);
        let reserved = sized.and_then(|()| super::map::reserve(&file, file_len, path));
        let map = reserved.and_then(|()| super::map::map_new_file_mut(&file, path));
        let map = map.inspect_err(|_| {
            let _ = std::fs::remove_file(&temp);
        })?;
        let mut placed = Placed {
            target: path.to_path_buf(),
            temp,
            map,
            file,
            entries,
            kind,
            level,
            flags,
            file_len,
        };
        for (p, i) in parts.iter().zip(0..) {
            if let Part::Now(s) = p {
                s.data.copy_to(placed.bytes_mut(i));
            }
        }
        Ok(placed)
    }

    /// The bytes of section `i`.
    fn bytes_mut(&mut self, i: usize) -> &mut [u8] {
        let e = &self.entries[i];
        &mut self.map[e.offset as usize..(e.offset + e.byte_len()) as usize]
    }

    fn index(&self, name: &str) -> usize {
        let i = self.entries.iter().position(|e| e.name == name);
        i.unwrap_or_else(|| panic!("no section {name} was laid out"))
    }

    /// Two sections at once, in either order in the file: the first to read, the second
    /// to fill.
    pub(crate) fn pair_mut<T: bytemuck::Pod, U: bytemuck::Pod>(
        &mut self, first: &str, second: &str,
    ) -> (&[T], &mut [U]) {
        let span = |e: &Entry| (e.offset as usize, (e.offset + e.byte_len()) as usize);
        let ((a0, a1), (b0, b1)) = (
            span(&self.entries[self.index(first)]),
            span(&self.entries[self.index(second)]),
        );
        let (read, fill): (&[u8], &mut [u8]) = if a1 <= b0 {
            let (head, tail) = self.map.split_at_mut(b0);
            (&head[a0..a1], &mut tail[..b1 - b0])
        } else {
            assert!(b1 <= a0, "{first} and {second} overlap");
            let (head, tail) = self.map.split_at_mut(a0);
            (&tail[..a1 - a0], &mut head[b0..b1])
        };
        (bytemuck::cast_slice(read), bytemuck::cast_slice_mut(fill))
    }

    /// The last section holds only its first `count` elements; the file ends after them.
    pub(crate) fn shrink_last(&mut self, count: u64) {
        let last = self.entries.last_mut().expect("a file of sections");
        assert!(count <= last.count, "a section only shrinks");
        last.count = count;
        self.file_len = super::format::aligned(last.offset + last.byte_len());
    }

    /// The section named `name`, to fill, as elements of `T` (the file's little-endian
    /// words, on a little-endian machine).
    pub(crate) fn section_mut<T: bytemuck::Pod>(&mut self, name: &str) -> &mut [T] {
        let i = self.index(name);
        bytemuck::cast_slice_mut(self.bytes_mut(i))
    }

    /// The section named `name` as written so far.
    pub(crate) fn section<T: bytemuck::Pod>(&self, name: &str) -> &[T] {
        let e = &self.entries[self.index(name)];
        bytemuck::cast_slice(&self.map[e.offset as usize..(e.offset + e.byte_len()) as usize])
    }

    /// Checksums every section, writes the header and the table, flushes the mapping and
    /// renames the file into place.
    pub(crate) fn finish(mut self) -> Result<()> {
        for i in 0..self.entries.len() {
            let crc = super::format::section_crc(self.bytes_mut(i));
            self.entries[i].crc = crc;
        }
        let head = head(
            self.kind,
            self.level,
            self.flags,
            &self.entries,
            self.file_len,
        );
        self.map[..head.len()].copy_from_slice(&head);
        let io = |e: std::io::Error| Error::io(format!("{}: {e}", self.target.display()));
        self.map.flush().map_err(io)?;
        // A shrunk last section gives back the file's tail (nothing reads past it).
        self.file.set_len(self.file_len).map_err(io)?;
        self.file.sync_all().map_err(io)?;
        rename_into_place(&self.temp, &self.target, &self.target)?;
        // Named now: dropping must not remove it.
        self.temp = PathBuf::new();
        Ok(())
    }
}

impl Drop for Placed {
    fn drop(&mut self) {
        if !self.temp.as_os_str().is_empty() {
            let _ = std::fs::remove_file(&self.temp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The file's blocks are reserved before anything is written through the mapping, and
    /// a file that is not finished is removed.
    #[test]
    fn a_laid_out_file_has_its_room_and_goes_unless_finished() {
        let dir = std::env::temp_dir().join(format!("topomesh-placed-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("x.che");
        let parts = [Part::Later {
            name: "V".to_string(),
            elem: Elem::U32,
            count: 1 << 20,
        }];
        let placed = Placed::create(&path, (Kind::Che, 0, 0), &parts).unwrap();
        let meta = std::fs::metadata(&placed.temp).unwrap();
        assert_eq!(meta.len(), placed.file_len);
        #[cfg(target_os = "linux")]
        {
            use std::os::unix::fs::MetadataExt;
            assert!(
                meta.blocks() * 512 >= placed.file_len,
                "{} blocks",
                meta.blocks()
            );
        }
        let temp = placed.temp.clone();
        drop(placed);
        assert!(!temp.exists() && !path.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
