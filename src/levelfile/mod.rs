//! Level files: a built CHE (`.che`) or CHF (`.chf`) saved as its arrays and opened again
//! with no parsing and no build. `format.rs` is the one place that knows the layout
//! (described for other languages in `docs/level-files.md`), `write.rs` and `read.rs`
//! move the sections, and `che.rs` / `chf.rs` list each structure's arrays as named
//! sections.
//!
//! Opening checks, before anything is indexed, that the header and the section table fit
//! the file and that every section holds the count the header's counts imply; with
//! checksums on, every section's CRC-32; with full verification, the structure's
//! invariants ([`Che::validate`](crate::Che::validate), [`Chf::validate`](crate::Chf::validate)).

mod che;
mod chf;
mod format;
pub(crate) mod map;
mod placed;
mod read;
mod stream;

pub use stream::{StreamOptions, save_streamed, save_streamed_chf};
mod write;

/// How much an open checks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Verify {
    /// Checksums, then every invariant of the structure (`validate`): a file from anywhere.
    #[default]
    Full,
    /// Checksums only: a file this program wrote, kept where it could be damaged.
    Checksums,
    /// Neither: a file this process just wrote. The header and every length are still
    /// checked, so opening a damaged file never reads out of bounds; but its ids are not,
    /// so a later query may answer wrongly or panic on an id out of range (a C call
    /// returns `TOPOMESH_STATUS_PANIC`).
    Trusted,
}

/// Where the arrays of an opened level file live.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Mode {
    /// Read into owned arrays, each section straight into its own (the open never holds
    /// the file's bytes beside them): the file can go away, and the structure is editable.
    #[default]
    Loaded,
    /// Memory-mapped, read-only and zero-copy: the structure's big arrays (`V`, `O`, `VH`,
    /// the edge ranks, `EH`, `CH`, the curves, positions) are the file's sections as they
    /// lie, paged in by the system as queries touch them. Opening costs the checks
    /// `verify` asks for and nothing more (with `Trusted`, the header and the table
    /// only). Raising the level or editing copies the arrays it writes into memory first,
    /// and `save` writes a new file. The file must not be truncated or rewritten in place
    /// while it is open (a truncation makes a later access raise `SIGBUS`); `save` replaces
    /// files by renaming, which is safe.
    Mapped,
}

/// How to open a level file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpenOptions {
    pub verify: Verify,
    pub mode: Mode,
}

impl OpenOptions {
    /// Mapped, with `verify`.
    pub fn mapped(verify: Verify) -> OpenOptions {
        OpenOptions {
            verify,
            mode: Mode::Mapped,
        }
    }
    /// Loaded, with `verify`.
    pub fn loaded(verify: Verify) -> OpenOptions {
        OpenOptions {
            verify,
            mode: Mode::Loaded,
        }
    }
}

/// The example lists of a build report: written flat, one section each.
pub(crate) trait Example: Sized + Copy {
    const WIDTH: usize;
    fn flat(xs: &[Self]) -> &[u32];
    fn from_flat(xs: &[u32]) -> crate::error::Result<Vec<Self>>;
}

impl Example for u32 {
    const WIDTH: usize = 1;
    fn flat(xs: &[u32]) -> &[u32] {
        xs
    }
    fn from_flat(xs: &[u32]) -> crate::error::Result<Vec<u32>> {
        crate::util::alloc::try_to_vec(xs, "a report's examples")
    }
}

impl<const N: usize> Example for [u32; N] {
    const WIDTH: usize = N;
    fn flat(xs: &[[u32; N]]) -> &[u32] {
        xs.as_flattened()
    }
    fn from_flat(xs: &[u32]) -> crate::error::Result<Vec<[u32; N]>> {
        let examples = xs.chunks_exact(N).map(|c| std::array::from_fn(|i| c[i]));
        crate::util::alloc::try_collect(examples, "a report's examples")
    }
}

/// The sections of a build report and back: its counts in one `u64` section (`r`), in
/// the order listed, and each example list in its own `u32` section (`r.NAME`).
macro_rules! report_sections {
    ($report:ty, counts: [$($count:ident),* $(,)?], lists: [$($list:ident => $name:literal),* $(,)?]) => {
        pub(crate) fn report_sections<'a>(
            r: &'a $report, prefix: &str,
        ) -> Vec<crate::levelfile::write::Section<'a>> {
            use crate::levelfile::Example;
            use crate::levelfile::write::Section;
            let counts: Vec<u64> = vec![$(r.$count as u64),*];
            let mut out = vec![Section::u64s(format!("{prefix}r"), counts)];
            $(out.push(Section::u32s(
                format!("{prefix}r.{}", $name),
                Example::flat(&r.$list[..]),
            ));)*
            out
        }

        pub(crate) fn read_report(
            file: &crate::levelfile::read::LevelFile, prefix: &str,
        ) -> crate::error::Result<$report> {
            use crate::levelfile::Example;
            let names = [$(stringify!($count)),*];
            let counts = file.u64s(&format!("{prefix}r"), names.len())?;
            let mut next = counts.into_iter().map(|x| x as usize);
            let mut r = <$report>::default();
            $(r.$count = next.next().unwrap_or_default();)*
            $({
                let name = format!("{prefix}r.{}", $name);
                let flat = file.u32s_any(&name)?;
                let width = crate::levelfile::example_width(&r.$list);
                if !flat.len().is_multiple_of(width) {
                    return Err(crate::error::Error::parse(format!(
                        "section {name}: {} ids, not {width} per example", flat.len()
                    )));
                }
                r.$list = Example::from_flat(&flat)?;
            })*
            Ok(r)
        }
    };
}
pub(crate) use report_sections;

/// The ids per example of a list.
pub(crate) fn example_width<T: Example>(_: &[T]) -> usize {
    T::WIDTH
}
