//! A CHE as named sections (`docs/level-files.md` lists them) and back.

use super::format::{Elem, FLAG_POSITIONS, FLAG_STRICT, Kind};
use super::read::LevelFile;
use super::write::{Contents, Section, save};
use super::{OpenOptions, Verify};
use crate::che::{BuildReport, Che};
use crate::error::{Error, Result};
use crate::util::rank::RankBits;
use crate::util::rank_directory::{RankDirectory, SPAN};
use crate::util::store::Store;
use glam::DVec3;
use std::path::Path;
use std::sync::OnceLock;

super::report_sections!(
    BuildReport,
    counts: [
        input_triangles, input_vertices, dropped_degenerate, duplicate_triangles, input_edges,
        boundary_edges, non_manifold_edges, split_vertices, seam_split_vertices,
        added_vertices, flipped_triangles, non_orientable_components, seam_edges,
    ],
    lists: [
        degenerate_examples => "degenerate",
        duplicate_examples => "duplicate",
        non_manifold_edge_examples => "non_manifold_edge",
        split_vertex_examples => "split_vertex",
        non_orientable_examples => "non_orientable",
    ]
);

/// Every array of `che` at its level, each name after `prefix` (a CHF stores its boundary
/// surface with the prefix `b.`).
pub(crate) fn sections<'a>(che: &'a Che, prefix: &str) -> Vec<Section<'a>> {
    let n = |s: &str| format!("{prefix}{s}");
    let counts = vec![
        che.n_input_vertices as u64,
        che.n_vertices as u64,
        che.num_edges as u64,
        che.v.len() as u64,
    ];
    let mut out = vec![
        Section::u64s(n("counts"), counts),
        Section::u32s(n("V"), &che.v[..]),
        Section::u32s(n("vertex_origin"), &che.vertex_origin[..]),
        Section::u32s(n("triangle_origin"), &che.triangle_origin[..]),
        Section::u32s(n("non_manifold"), &che.non_manifold[..]),
        Section::u32s(n("seams"), &che.seams[..]),
    ];
    if !che.positions.is_empty() {
        out.push(Section::points(n("positions"), &che.positions));
    }
    out.extend(report_sections(&che.report, prefix));
    if che.level >= 1 {
        out.push(Section::u32s(n("O"), &che.o[..]));
    }
    if che.level >= 2 {
        out.push(Section::u32s(n("VH"), &che.vh[..]));
        out.push(Section::u64s(n("edge_ranks"), che.edge_bits.entries()));
        out.push(Section::u32s(n("EH"), &che.eh[..]));
    }
    if che.level >= 3 {
        out.push(Section::u32s(n("CH"), &che.ch[..]));
        out.push(Section::u64s(n("boundary_bits"), che.boundary_bits.words()));
        out.push(Section::u32s(n("curve_of"), &che.curve_of[..]));
    }
    out
}

pub(crate) fn save_che(che: &Che, path: &Path) -> Result<()> {
    let sections = sections(che, "");
    let mut contents = Contents::of(Kind::Che, che.level, &che.positions, sections);
    if che.strict {
        contents.flags |= FLAG_STRICT;
    }
    save(path, &contents)
}

pub(crate) fn open_che(path: &Path, options: OpenOptions) -> Result<Che> {
    let file = LevelFile::open(path, Kind::Che, options)?;
    let level = file.header.level;
    let positions = file.header.flags & FLAG_POSITIONS != 0;
    let strict = file.header.flags & FLAG_STRICT != 0;
    file.alongside_sums(|file| {
        let mut che = read_che(file, "", level, positions)?;
        che.strict = strict;
        if options.verify == Verify::Full {
            che.validate()?;
        }
        Ok(che)
    })
    .map_err(|e| Error::new(e.kind, format!("{}: {}", path.display(), e.message)))
}

/// A count that must fit a `u32` id space (ids are `u32`).
fn id_count(x: u64, what: &str, name: &str) -> Result<usize> {
    if x > u64::from(u32::MAX) {
        return Err(Error::parse(format!(
            "section {name}: {x} {what} do not fit u32 ids"
        )));
    }
    Ok(x as usize)
}

/// The structure's vertices are the input vertices then the copies a split makes, at
/// most one per half-edge (or half-face): checked before any per-vertex array is made.
pub(crate) fn check_vertex_counts(
    input: usize, n: usize, corners: usize, name: &str,
) -> Result<()> {
    if n < input || n - input > corners {
        return Err(Error::parse(format!(
            "section {name}: {n} vertices for {input} input vertices and {corners} corners"
        )));
    }
    Ok(())
}

/// `len` bits packed in 64-bit words, none set past `len`.
pub(crate) fn rank_bits(words: Vec<u64>, len: usize, name: &str) -> Result<RankBits> {
    let tail = len % 64;
    if tail != 0 && words.last().is_some_and(|w| w >> tail != 0) {
        return Err(Error::parse(format!("section {name}: bits set past {len}")));
    }
    RankBits::from_words(words, len)
}

/// Positions from `3 * n` coordinates.
pub(crate) fn read_positions(file: &LevelFile, name: &str, n: usize) -> Result<Store<DVec3>> {
    file.store(name, Elem::F64, n, 3)
}

/// The CHE whose sections are named after `prefix`, every length checked against the
/// counts.
pub(crate) fn read_che(file: &LevelFile, prefix: &str, level: u8, positions: bool) -> Result<Che> {
    let n = |s: &str| format!("{prefix}{s}");
    let counts = file.u64s(&n("counts"), 4)?;
    let cname = n("counts");
    let n_input_vertices = id_count(counts[0], "input vertices", &cname)?;
    let n_vertices = id_count(counts[1], "vertices", &cname)?;
    let num_edges = id_count(counts[2], "edges", &cname)?;
    let h = id_count(counts[3], "half-edges", &cname)?;
    if !h.is_multiple_of(3) {
        return Err(Error::parse(format!(
            "section {cname}: {h} half-edges, not 3 per triangle"
        )));
    }
    check_vertex_counts(n_input_vertices, n_vertices, h, &cname)?;
    let maybe = |name: &str, len: usize| -> Result<Vec<u32>> {
        match file.count(name)? {
            0 => Ok(Vec::new()),
            _ => file.u32s(name, len),
        }
    };
    let mut che = Che {
        level,
        n_input_vertices,
        n_vertices,
        v: file.ids(&n("V"), h)?,
        o: Store::default(),
        vh: Store::default(),
        edge_bits: RankDirectory::default(),
        eh: Store::default(),
        lazy_edge_bits: OnceLock::new(),
        ch: Store::default(),
        boundary_bits: RankBits::default(),
        curve_of: Store::default(),
        num_edges,
        positions: Store::default(),
        vertex_origin: maybe(&n("vertex_origin"), n_vertices)?.into(),
        triangle_origin: maybe(&n("triangle_origin"), h / 3)?.into(),
        non_manifold: file.u32s_any(&n("non_manifold"))?,
        seams: file.u32s_any(&n("seams"))?,
        report: read_report(file, prefix)?,
        strict: false,
        edit: None,
        checked: Default::default(),
    };
    if positions {
        che.positions = read_positions(file, &n("positions"), n_vertices)?;
    }
    if level >= 1 {
        che.o = file.ids(&n("O"), h)?;
    }
    if level >= 2 {
        read_level2(&mut che, file, prefix)?;
    }
    if level >= 3 {
        che.ch = file.ids(&n("CH"), file.count(&n("CH"))?)?;
        let name = n("boundary_bits");
        che.boundary_bits = rank_bits(file.u64s(&name, h.div_ceil(64))?, h, &name)?;
        che.curve_of = file.ids(&n("curve_of"), che.boundary_bits.ones())?;
    }
    Ok(che)
}

fn read_level2(che: &mut Che, file: &LevelFile, prefix: &str) -> Result<()> {
    let h = che.v.len();
    che.vh = file.ids(&format!("{prefix}VH"), che.n_vertices)?;
    let name = format!("{prefix}edge_ranks");
    let entries = file.words(&name, h.div_ceil(SPAN))?;
    let directory = if file.verify == Verify::Trusted {
        RankDirectory::from_entries_trusted(entries, h, che.num_edges)
    } else {
        RankDirectory::from_entries(entries, h)
    };
    che.edge_bits = directory
        .filter(|d| d.ones() == che.num_edges)
        .ok_or_else(|| {
            Error::parse(format!(
                "section {name}: the running counts do not match the flags or the {} edges",
                che.num_edges
            ))
        })?;
    che.eh = file.ids(&format!("{prefix}EH"), che.num_edges)?;
    Ok(())
}

impl Che {
    /// Saves the built structure at its level to `path` (a level file, `.che` by
    /// convention), whole or not at all; [`Che::open`] reads it back.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<()> {
        self.check_unchanged("the level file")?;
        save_che(self, path.as_ref())
    }

    /// Opens a level file written by [`Che::save`], checked as `options` says (by
    /// default, fully: a damaged or hostile file gives an error naming the section and
    /// byte, never a panic).
    pub fn open(path: impl AsRef<Path>, options: OpenOptions) -> Result<Che> {
        open_che(path.as_ref(), options)
    }

    /// Whether the structure's arrays are (some of them) a mapped level file's sections.
    pub fn is_mapped(&self) -> bool {
        self.v.is_mapped() || self.o.is_mapped()
    }
}
