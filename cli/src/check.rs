//! `topomesh check`: exit 0 when the mesh is a clean manifold, 1 and one line per kind of
//! problem otherwise (from the level-1 build report), as text or JSON.

use crate::exit::{Failure, PROBLEM};
use crate::input::{build_surface, build_volume, load};
use crate::json::CHECK_SCHEMA;
use crate::output::{Out, verbose};
use crate::print::{Id, count, ids};
use crate::progress::Progress;
use crate::report;
use serde::Serialize;
use std::io::{self, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, BuildReport, Error, chf};

#[derive(clap::Args)]
pub struct CheckOptions {
    /// The mesh file, its format by extension.
    file: PathBuf,
    /// Print JSON: `ok`, and each problem with its count and first ids.
    #[arg(long)]
    json: bool,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
    /// Also draw the problems it lists on the mesh, to a `.png` or `.svg` image.
    #[arg(long, value_name = "OUT")]
    render: Option<PathBuf>,
}

pub fn run(options: &CheckOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let (name, data) = load(Some(&options.file), &progress)?;
    progress.step("building level 1".to_string());
    let checked = if data.is_volume() {
        check_volume(name, &data, options.weld)?
    } else {
        check_surface(name, &data, options.weld)?
    };
    drop(progress);
    if let Some(image) = &options.render {
        crate::render::problems(&checked.json.file, &data, options.weld, image)?;
    }
    let mut out = Out::new();
    if options.json {
        crate::json::write(&mut out, CHECK_SCHEMA, &checked.json)?;
    } else {
        checked.print(&mut out)?;
    }
    out.finish()?;
    Ok(if checked.json.ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(PROBLEM)
    })
}

/// One kind of problem: its name in JSON, its count and the first offending ids.
#[derive(Serialize)]
struct Problem {
    problem: &'static str,
    count: usize,
    examples: serde_json::Value,
    #[serde(skip)]
    text: String,
}

/// What `check --json` prints.
#[derive(Serialize)]
struct CheckJson {
    file: String,
    kind: &'static str,
    ok: bool,
    /// Triangles or tetrahedra kept by the build.
    elements: u64,
    euler_characteristic: i64,
    problems: Vec<Problem>,
}

/// The outcome, and the build report for `--verbose`.
struct Checked {
    json: CheckJson,
    report: Report,
}

enum Report {
    Surface(BuildReport),
    Volume(chf::BuildReport),
}

/// The nouns of one kind of problem: the JSON name, and the text for one and for many.
type Nouns = (&'static str, &'static str, &'static str);

/// The problems both kinds of mesh can have.
const NON_MANIFOLD_EDGES: Nouns = (
    "non_manifold_edges",
    "non-manifold edge",
    "non-manifold edges",
);
const NON_MANIFOLD_VERTICES: Nouns = (
    "non_manifold_vertices",
    "non-manifold vertex",
    "non-manifold vertices",
);
const NON_ORIENTABLE: Nouns = (
    "non_orientable_components",
    "non-orientable component",
    "non-orientable components",
);
const NON_FINITE: Nouns = (
    "non_finite_vertices",
    "vertex with a NaN or infinite coordinate",
    "vertices with a NaN or infinite coordinate",
);

#[derive(Default)]
struct Problems(Vec<Problem>);

/// The problems surfaces and volumes share: counts and examples, listed in this order.
struct Shared<'a> {
    non_manifold_edges: (usize, &'a [[u32; 2]]),
    split_vertices: (usize, &'a [u32]),
    non_orientable: (usize, &'a [u32]),
    non_finite: (usize, &'a [u32]),
}

impl Problems {
    fn note_shared(&mut self, s: Shared) {
        self.note(
            s.non_manifold_edges.0,
            NON_MANIFOLD_EDGES,
            s.non_manifold_edges.1,
        );
        self.note(
            s.split_vertices.0,
            NON_MANIFOLD_VERTICES,
            s.split_vertices.1,
        );
        self.note(s.non_orientable.0, NON_ORIENTABLE, s.non_orientable.1);
        self.note(s.non_finite.0, NON_FINITE, s.non_finite.1);
    }

    fn note<T: Id + Serialize>(&mut self, n: usize, (key, one, many): Nouns, list: &[T]) {
        if n == 0 {
            return;
        }
        let list_text = ids(list, n);
        let sep = if list_text.is_empty() { "" } else { ": " };
        self.0.push(Problem {
            problem: key,
            count: n,
            examples: serde_json::to_value(list).unwrap_or_default(),
            text: format!("{}{sep}{list_text}", count(n as u64, one, many)),
        });
    }
}

impl Checked {
    /// One line per problem, or `ok` and the description of a clean mesh; then the build
    /// report under `--verbose`.
    fn print(&self, out: &mut Out) -> io::Result<()> {
        let j = &self.json;
        if j.ok {
            let (one, many) = match j.kind {
                "volume" => ("tetrahedron", "tetrahedra"),
                _ => ("triangle", "triangles"),
            };
            writeln!(
                out,
                "{}: ok: a manifold of {}, euler characteristic {}",
                j.file,
                count(j.elements, one, many),
                j.euler_characteristic
            )?;
        }
        for p in &j.problems {
            writeln!(out, "{}: {}", j.file, p.text)?;
        }
        if verbose() {
            match &self.report {
                Report::Surface(r) => report::surface(out, r)?,
                Report::Volume(r) => report::volume(out, r)?,
            }
        }
        Ok(())
    }
}

fn check_surface(file: String, data: &MeshData, weld: f64) -> Result<Checked, Error> {
    let options = BuildOptions {
        weld_tolerance: weld,
        ..BuildOptions::level(1)
    };
    let che = build_surface(data, options)?;
    let r = che.report().clone();
    let mut p = Problems::default();
    let deg = (
        "degenerate_triangles",
        "degenerate triangle",
        "degenerate triangles",
    );
    p.note(r.dropped_degenerate, deg, &r.degenerate_examples);
    let dup = (
        "duplicate_triangle_pairs",
        "duplicate triangle pair",
        "duplicate triangle pairs",
    );
    p.note(r.duplicate_triangles, dup, &r.duplicate_examples);
    p.note_shared(Shared {
        non_manifold_edges: (r.non_manifold_edges, &r.non_manifold_edge_examples),
        split_vertices: (r.split_vertices, &r.split_vertex_examples),
        non_orientable: (r.non_orientable_components, &r.non_orientable_examples),
        non_finite: (
            r.non_finite_vertices as usize,
            &r.non_finite_vertex_examples,
        ),
    });
    let flip = (
        "flipped_triangles",
        "triangle oriented against its neighbours",
        "triangles oriented against their neighbours",
    );
    p.note::<u32>(r.flipped_triangles, flip, &[]);
    let s = che.summary();
    let json = CheckJson {
        file,
        kind: "surface",
        ok: p.0.is_empty(),
        elements: s.triangles,
        euler_characteristic: s.euler_characteristic,
        problems: p.0,
    };
    let report = Report::Surface(r);
    Ok(Checked { json, report })
}

fn check_volume(file: String, data: &MeshData, weld: f64) -> Result<Checked, Error> {
    let options = chf::BuildOptions {
        level: 1,
        weld_tolerance: weld,
        ..chf::BuildOptions::default()
    };
    let chf = build_volume(data, options)?;
    let r = chf.report().clone();
    let mut p = Problems::default();
    let deg = (
        "degenerate_tetrahedra",
        "degenerate tetrahedron",
        "degenerate tetrahedra",
    );
    p.note(r.dropped_degenerate, deg, &r.degenerate_examples);
    let zero = (
        "zero_volume_tetrahedra",
        "zero-volume tetrahedron",
        "zero-volume tetrahedra",
    );
    p.note(r.zero_volume, zero, &r.zero_volume_examples);
    let inv = (
        "inverted_tetrahedra",
        "inverted tetrahedron",
        "inverted tetrahedra",
    );
    p.note(r.inverted_tetrahedra, inv, &r.inverted_examples);
    let dup = (
        "duplicate_tetrahedron_pairs",
        "duplicate tetrahedron pair",
        "duplicate tetrahedron pairs",
    );
    p.note(r.duplicate_tetrahedra, dup, &r.duplicate_examples);
    let nmf = (
        "non_manifold_faces",
        "non-manifold face",
        "non-manifold faces",
    );
    p.note(r.non_manifold_faces, nmf, &r.non_manifold_face_examples);
    p.note_shared(Shared {
        non_manifold_edges: (r.non_manifold_edges, &r.non_manifold_edge_examples),
        split_vertices: (r.split_vertices, &r.split_vertex_examples),
        non_orientable: (r.non_orientable_components, &r.non_orientable_examples),
        non_finite: (
            r.non_finite_vertices as usize,
            &r.non_finite_vertex_examples,
        ),
    });
    let flip = (
        "flipped_tetrahedra",
        "tetrahedron oriented against its neighbours",
        "tetrahedra oriented against their neighbours",
    );
    p.note::<u32>(r.flipped_tetrahedra, flip, &[]);
    let s = chf.summary();
    let json = CheckJson {
        file,
        kind: "volume",
        ok: p.0.is_empty(),
        elements: s.tetrahedra,
        euler_characteristic: s.euler_characteristic,
        problems: p.0,
    };
    let report = Report::Volume(r);
    Ok(Checked { json, report })
}
