//! A CHF as named sections (`docs/level-files.md` lists them) and back; at level 3 the
//! boundary surface is a CHE, stored as its own sections under the prefix `b.`.

use super::che::{check_vertex_counts, rank_bits, read_che, read_positions};
use super::format::{FLAG_POSITIONS, Kind};
use super::read::LevelFile;
use super::write::{Contents, Section, save};
use super::{OpenOptions, Verify};
use crate::chf::{Boundary, BuildReport, Chf, MultiFan};
use crate::error::{Error, Result};
use crate::util::alloc::try_collect;
use crate::util::rank::RankBits;
use std::path::Path;

super::report_sections!(
    BuildReport,
    counts: [
        input_tetrahedra, input_vertices, dropped_degenerate, zero_volume, inverted_tetrahedra,
        duplicate_tetrahedra, input_faces, boundary_faces, non_manifold_faces, input_edges,
        non_manifold_edges, kept_non_manifold_edges, split_vertices, seam_split_vertices,
        added_vertices, flipped_tetrahedra, non_orientable_components, seam_faces,
    ],
    lists: [
        degenerate_examples => "degenerate",
        zero_volume_examples => "zero_volume",
        inverted_examples => "inverted",
        duplicate_examples => "duplicate",
        non_manifold_face_examples => "non_manifold_face",
        non_manifold_edge_examples => "non_manifold_edge",
        kept_non_manifold_edge_examples => "kept_non_manifold_edge",
        split_vertex_examples => "split_vertex",
        non_orientable_examples => "non_orientable",
    ]
);

/// Edge slots per tetrahedron (the bits of `edge_bits`).
const SLOTS: usize = 6;

fn sections(chf: &Chf) -> Vec<Section<'_>> {
    let counts = vec![
        chf.n_input_vertices as u64,
        chf.n_vertices as u64,
        chf.num_edges as u64,
        chf.num_faces as u64,
        chf.v.len() as u64,
    ];
    let multi_fan: Vec<u64> = chf
        .multi_fan
        .iter()
        .flat_map(|m| [u64::from(m.a) | u64::from(m.b) << 32, m.first_slot])
        .collect();
    let mut out = vec![
        Section::u64s("counts", counts),
        Section::u32s("V", &chf.v[..]),
        Section::u32s("vertex_origin", &chf.vertex_origin[..]),
        Section::u32s("tetrahedron_origin", &chf.tet_origin[..]),
        Section::u32s("non_manifold", &chf.non_manifold[..]),
        Section::u32s("seams", &chf.seams[..]),
        Section::u64s("multi_fan", multi_fan),
    ];
    if !chf.positions.is_empty() {
        out.push(Section::points("positions", &chf.positions));
    }
    out.extend(report_sections(&chf.report, ""));
    if chf.level >= 1 {
        out.push(Section::u32s("O", &chf.o[..]));
    }
    if chf.level >= 2 {
        out.push(Section::u32s("VH", &chf.vh[..]));
        out.push(Section::u64s("face_bits", chf.face_bits.words()));
        out.push(Section::u32s("FH", &chf.fh[..]));
        out.push(Section::u64s("edge_bits", chf.edge_bits.words()));
        out.push(Section::u32s("EH", &chf.eh[..]));
    }
    if let Some(b) = &chf.boundary {
        let scalars = vec![
            u64::from(b.che.level),
            b.components as u64,
            b.true_faces as u64,
        ];
        out.push(Section::u64s("boundary", scalars));
        // A collected CHF is a fresh build: its boundary keeps both directories.
        fn words(b: &Option<RankBits>) -> &[u64] {
            b.as_ref().map_or(&[], RankBits::words)
        }
        out.push(Section::u64s("boundary_bits", words(&b.bits)));
        out.push(Section::u32s("boundary_half_faces", &b.half_faces[..]));
        out.push(Section::u64s("boundary_vertex_bits", words(&b.vertex_bits)));
        out.push(Section::u32s("boundary_vertices", &b.vertices[..]));
        out.push(Section::u32s("boundary_component", &b.component[..]));
        out.extend(super::che::sections(&b.che, "b."));
    }
    out
}

pub(crate) fn save_chf(chf: &Chf, path: &Path) -> Result<()> {
    let sections = sections(chf);
    save(
        path,
        &Contents::of(Kind::Chf, chf.level, &chf.positions, sections),
    )
}

pub(crate) fn open_chf(path: &Path, options: OpenOptions) -> Result<Chf> {
    let named = |e: Error| Error::new(e.kind, format!("{}: {}", path.display(), e.message));
    let file = LevelFile::open(path, Kind::Chf, options)?;
    file.alongside_sums(|file| {
        let chf = read_chf(file)?;
        if options.verify == Verify::Full {
            chf.validate()?;
        }
        Ok(chf)
    })
    .map_err(named)
}

/// A count that must fit a `u32` id space.
fn id_count(x: u64, what: &str) -> Result<usize> {
    if x > u64::from(u32::MAX) {
        return Err(Error::parse(format!(
            "section counts: {x} {what} do not fit u32 ids"
        )));
    }
    Ok(x as usize)
}

fn read_chf(file: &LevelFile) -> Result<Chf> {
    let counts = file.u64s("counts", 5)?;
    let mut chf = Chf::empty();
    chf.level = file.header.level;
    chf.n_input_vertices = id_count(counts[0], "input vertices")?;
    chf.n_vertices = id_count(counts[1], "vertices")?;
    chf.num_edges = id_count(counts[2], "edges")?;
    chf.num_faces = id_count(counts[3], "faces")?;
    let h = id_count(counts[4], "half-faces")?;
    if !h.is_multiple_of(4) {
        return Err(Error::parse(format!(
            "section counts: {h} half-faces, not 4 per tetrahedron"
        )));
    }
    check_vertex_counts(chf.n_input_vertices, chf.n_vertices, h, "counts")?;
    let maybe = |name: &str, len: usize| -> Result<Vec<u32>> {
        match file.count(name)? {
            0 => Ok(Vec::new()),
            _ => file.u32s(name, len),
        }
    };
    chf.v = file.ids("V", h)?;
    chf.vertex_origin = maybe("vertex_origin", chf.n_vertices)?.into();
    chf.tet_origin = maybe("tetrahedron_origin", h / 4)?.into();
    chf.non_manifold = file.u32s_any("non_manifold")?;
    chf.seams = file.u32s_any("seams")?;
    let fans = file.count("multi_fan")?;
    if !fans.is_multiple_of(2) {
        return Err(Error::parse(
            "section multi_fan: not two words per vertex pair",
        ));
    }
    let words = file.u64s("multi_fan", fans)?;
    let multi_fan = words.chunks_exact(2).map(|w| MultiFan {
        a: w[0] as u32,
        b: (w[0] >> 32) as u32,
        first_slot: w[1],
    });
    chf.multi_fan = try_collect(multi_fan, "the multi-fan pairs")?;
    if file.header.flags & FLAG_POSITIONS != 0 {
        chf.positions = read_positions(file, "positions", chf.n_vertices)?;
    }
    chf.report = read_report(file, "")?;
    if chf.level >= 1 {
        chf.o = file.ids("O", h)?;
    }
    if chf.level >= 2 {
        chf.vh = file.ids("VH", chf.n_vertices)?;
        chf.face_bits = counted_bits(file, "face_bits", h, chf.num_faces)?;
        chf.fh = file.ids("FH", chf.num_faces)?;
        chf.edge_bits = counted_bits(file, "edge_bits", SLOTS * (h / 4), chf.num_edges)?;
        chf.eh = file.ids("EH", chf.num_edges)?;
    }
    if chf.level >= 3 {
        chf.boundary = Some(read_boundary(file, h, chf.n_vertices)?);
    }
    Ok(chf)
}

/// `len` bits of which `ones` are set.
fn counted_bits(file: &LevelFile, name: &str, len: usize, ones: usize) -> Result<RankBits> {
    let bits = rank_bits(file.u64s(name, len.div_ceil(64))?, len, name)?;
    if bits.ones() != ones {
        return Err(Error::parse(format!(
            "section {name}: {} bits set, the counts say {ones}",
            bits.ones()
        )));
    }
    Ok(bits)
}

fn read_boundary(file: &LevelFile, h: usize, n_vertices: usize) -> Result<Boundary> {
    let scalars = file.u64s("boundary", 3)?;
    let level = u8::try_from(scalars[0])
        .ok()
        .filter(|&l| l <= 3)
        .ok_or_else(|| Error::parse(format!("section boundary: level {}", scalars[0])))?;
    let name = "boundary_bits";
    let bits = rank_bits(file.u64s(name, h.div_ceil(64))?, h, name)?;
    let half_faces = file.u32s("boundary_half_faces", bits.ones())?;
    let name = "boundary_vertex_bits";
    let vertex_bits = rank_bits(file.u64s(name, n_vertices.div_ceil(64))?, n_vertices, name)?;
    let vertices = file.u32s("boundary_vertices", vertex_bits.ones())?;
    let component = file.u32s("boundary_component", vertices.len())?;
    let che = read_che(file, "b.", level, file.has("b.positions"))?;
    Ok(Boundary {
        che,
        bits: Some(bits),
        half_faces,
        vertex_bits: Some(vertex_bits),
        vertices,
        component,
        components: scalars[1] as usize,
        true_faces: scalars[2] as usize,
    })
}

impl Chf {
    /// Saves the built structure at its level to `path` (a level file, `.chf` by
    /// convention), whole or not at all; [`Chf::open`] reads it back.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<()> {
        self.check_unchanged("the level file")?;
        save_chf(self, path.as_ref())
    }

    /// Opens a level file written by [`Chf::save`], checked as `options` says (by
    /// default, fully: a damaged or hostile file gives an error naming the section and
    /// byte, never a panic).
    pub fn open(path: impl AsRef<Path>, options: OpenOptions) -> Result<Chf> {
        open_chf(path.as_ref(), options)
    }

    /// Whether the structure's arrays are (some of them) a mapped level file's sections.
    pub fn is_mapped(&self) -> bool {
        self.v.is_mapped() || self.o.is_mapped()
    }
}
