//! `topomesh export`: one classic representation of a surface as text, for code written
//! against another structure (`topomesh export --help` states each layout; `concat!`
//! needs them as a literal, so they live in `main.rs`).

use crate::exit::Failure;
use crate::input::{build_surface, load};
use crate::json::{Field, export_document};
use crate::output::Out;
use crate::progress::Progress;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::che::{HalfEdgeOptions, MatrixKind, SparseMatrix};
use topomesh::{BuildOptions, Che, Error, ErrorKind, NONE};

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Representation {
    Halfedge,
    Winged,
    Corner,
    Edges,
    Dual,
    Strips,
    D1,
    D2,
    Laplacian,
    VertexAdjacency,
    EdgeAdjacency,
    DualAdjacency,
}

#[derive(clap::Args)]
pub struct ExportOptions {
    /// The surface mesh file, its format by extension.
    file: PathBuf,
    /// The representation to write (layouts below).
    #[arg(long = "as", value_enum)]
    representation: Representation,
    /// Where to write it ('-': stdout).
    #[arg(short, long)]
    output: PathBuf,
    /// halfedge: boundary half-edges as explicit twins round each hole (OpenMesh style).
    #[arg(long)]
    explicit_boundary: bool,
    /// Structure level to build (the answers are the same at every level).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(0..=3))]
    level: u8,
    /// One JSON object on one line instead of the text layout (fields below).
    #[arg(long)]
    json: bool,
}

pub fn run(options: &ExportOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let (name, data) = load(Some(&options.file), &progress)?;
    if data.is_volume() {
        let message = format!("{name}: export takes a surface (this file holds tetrahedra)");
        return Err(Error::new(ErrorKind::InvalidInput, message).into());
    }
    progress.step(format!("building level {}", options.level));
    let che = build_surface(&data, BuildOptions::level(options.level))?;
    drop(progress);
    if options.output.as_os_str() == "-" {
        // Stdout flushes at every line: a buffer in front of it for the many rows.
        let mut out = BufWriter::new(Out::new());
        write_as_asked(&mut out, &che, options)?;
        out.into_inner().map_err(|e| e.into_error())?.finish()?;
    } else {
        let file = File::create(&options.output)
            .map_err(|e| io::Error::new(e.kind(), format!("{}: {e}", options.output.display())))?;
        let mut out = BufWriter::new(file);
        write_as_asked(&mut out, &che, options)?;
        out.flush()?;
    }
    Ok(ExitCode::SUCCESS)
}

/// The text layout or, with `--json`, the JSON document.
fn write_as_asked(out: &mut impl Write, che: &Che, options: &ExportOptions) -> Result<(), Failure> {
    if options.json {
        json(out, che, options)
    } else {
        write(out, che, options)
    }
}

/// One row of ids, `-1` for none, written straight to the buffered output.
fn row(out: &mut impl Write, ids: &[u32]) -> io::Result<()> {
    for (k, &x) in ids.iter().enumerate() {
        let sep = if k == 0 { "" } else { " " };
        if x == NONE {
            write!(out, "{sep}-1")?;
        } else {
            write!(out, "{sep}{x}")?;
        }
    }
    writeln!(out)
}

/// `chunks` rows of `width` ids each.
fn rows(out: &mut impl Write, ids: &[u32], width: usize) -> io::Result<()> {
    ids.chunks(width).try_for_each(|r| row(out, r))
}

fn write(out: &mut impl Write, che: &Che, options: &ExportOptions) -> Result<(), Failure> {
    let (nv, nt) = (che.num_vertices(), che.num_triangles());
    if let Some(kind) = matrix_kind(options.representation) {
        return Ok(market(out, &che.matrix(kind)?)?);
    }
    match options.representation {
        Representation::Halfedge => {
            let explicit_boundary = options.explicit_boundary;
            let a = che.half_edge_arrays(HalfEdgeOptions { explicit_boundary })?;
            writeln!(out, "halfedge {} {nv} {nt}", a.next.len())?;
            for h in 0..a.next.len() {
                row(
                    out,
                    &[
                        a.next[h],
                        a.prev[h],
                        a.twin[h],
                        a.vertex[h],
                        a.face[h],
                        a.edge[h],
                    ],
                )?;
            }
            rows(out, &a.vertex_half_edge, 1)?;
            rows(out, &a.face_half_edge, 1)?;
        }
        Representation::Winged => {
            let w = che.winged_edges()?;
            writeln!(out, "winged {} {nv} {nt}", che.num_edges())?;
            for e in 0..che.num_edges() {
                let mut r = [0; 8];
                r[..2].copy_from_slice(&w.vertices[2 * e..2 * e + 2]);
                r[2..4].copy_from_slice(&w.faces[2 * e..2 * e + 2]);
                r[4..].copy_from_slice(&w.wings[4 * e..4 * e + 4]);
                row(out, &r)?;
            }
            rows(out, &w.vertex_edge, 1)?;
            rows(out, &w.face_edge, 1)?;
        }
        Representation::Corner => {
            let c = che.corner_table()?;
            writeln!(out, "corner {}", c.v.len())?;
            for (&v, &o) in c.v.iter().zip(&c.o) {
                row(out, &[v, o])?;
            }
        }
        Representation::Edges => {
            writeln!(out, "edges {}", che.num_edges())?;
            rows(out, &che.edge_list()?, 2)?;
        }
        Representation::Dual => {
            writeln!(out, "dual {nt}")?;
            rows(out, &che.all_triangle_triangles()?, 3)?;
        }
        Representation::Strips => {
            let s = che.triangle_strips()?;
            writeln!(out, "strips {}", s.len())?;
            (0..s.len()).try_for_each(|k| row(out, s.strip(k)))?;
        }
        _ => unreachable!("the matrices are written above"),
    }
    Ok(())
}

/// The matrix a representation is, if it is one.
fn matrix_kind(r: Representation) -> Option<MatrixKind> {
    Some(match r {
        Representation::D1 => MatrixKind::D1,
        Representation::D2 => MatrixKind::D2,
        Representation::Laplacian => MatrixKind::Laplacian,
        Representation::VertexAdjacency => MatrixKind::VertexAdjacency,
        Representation::EdgeAdjacency => MatrixKind::EdgeAdjacency,
        Representation::DualAdjacency => MatrixKind::DualAdjacency,
        _ => return None,
    })
}

/// A matrix in Matrix Market coordinate format (1-based).
fn market(out: &mut impl Write, m: &SparseMatrix) -> io::Result<()> {
    writeln!(out, "%%MatrixMarket matrix coordinate real general")?;
    writeln!(out, "{} {} {}", m.n_rows, m.n_cols, m.nnz())?;
    for r in 0..m.n_rows {
        let (cols, vals) = m.row(r);
        for (&c, &x) in cols.iter().zip(vals) {
            writeln!(out, "{} {} {}", r + 1, c + 1, x)?;
        }
    }
    Ok(())
}

/// The JSON document of a representation: the arrays of the Rust and C exports under their
/// names there, flat (`stride` entries per element where it says so).
fn json(out: &mut impl Write, che: &Che, options: &ExportOptions) -> Result<(), Failure> {
    use Field::*;
    let name = clap::ValueEnum::to_possible_value(&options.representation)
        .map(|v| v.get_name().to_owned())
        .unwrap_or_default();
    let (nv, nt, ne) = (che.num_vertices(), che.num_triangles(), che.num_edges());
    let counts = [
        ("vertices", Count(nv)),
        ("triangles", Count(nt)),
        ("edges", Count(ne)),
    ];
    let doc = |out: &mut _, fields: &[(&str, Field)]| -> Result<(), Failure> {
        let all: Vec<(&str, Field)> = counts.iter().chain(fields).copied().collect();
        Ok(export_document(out, &name, &all)?)
    };
    if let Some(kind) = matrix_kind(options.representation) {
        let m = che.matrix(kind)?;
        let shape = [("rows", Count(m.n_rows)), ("cols", Count(m.n_cols))];
        let csr = [
            ("offsets", Offsets64(&m.offsets)),
            ("columns", Ids(&m.columns)),
            ("values", Values(&m.values)),
        ];
        return doc(out, &[&shape[..], &csr[..]].concat());
    }
    match options.representation {
        Representation::Halfedge => {
            let explicit_boundary = options.explicit_boundary;
            let a = che.half_edge_arrays(HalfEdgeOptions { explicit_boundary })?;
            doc(
                out,
                &[
                    ("explicit_boundary", Flag(explicit_boundary)),
                    ("next", Ids(&a.next)),
                    ("prev", Ids(&a.prev)),
                    ("twin", Ids(&a.twin)),
                    ("tail", Ids(&a.vertex)),
                    ("face", Ids(&a.face)),
                    ("edge", Ids(&a.edge)),
                    ("vertex_half_edge", Ids(&a.vertex_half_edge)),
                    ("face_half_edge", Ids(&a.face_half_edge)),
                ],
            )
        }
        Representation::Winged => {
            let w = che.winged_edges()?;
            doc(
                out,
                &[
                    ("edge_vertices", Ids(&w.vertices)),
                    ("edge_faces", Ids(&w.faces)),
                    ("wings", Ids(&w.wings)),
                    ("vertex_edge", Ids(&w.vertex_edge)),
                    ("face_edge", Ids(&w.face_edge)),
                ],
            )
        }
        Representation::Corner => {
            let c = che.corner_table()?;
            doc(out, &[("v", Ids(c.v)), ("o", Ids(&c.o))])
        }
        Representation::Edges => doc(out, &[("edge_vertices", Ids(&che.edge_list()?))]),
        Representation::Dual => doc(
            out,
            &[("triangle_triangles", Ids(&che.all_triangle_triangles()?))],
        ),
        Representation::Strips => {
            let s = che.triangle_strips()?;
            doc(
                out,
                &[
                    ("offsets", Offsets(&s.offsets)),
                    ("strip_vertices", Ids(&s.vertices)),
                ],
            )
        }
        _ => unreachable!("the matrices are written above"),
    }
}
