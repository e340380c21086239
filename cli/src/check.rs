//! `topomesh check`: exit 0 when the mesh is a clean manifold, 1 and one line per kind of
//! problem otherwise (from the level-1 build report).

use crate::input::{build_surface, build_volume, load};
use crate::print::examples;
use crate::progress::Progress;
use std::fmt::Debug;
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, Error, chf};

#[derive(clap::Args)]
pub struct CheckOptions {
    file: PathBuf,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

pub fn run(options: &CheckOptions) -> Result<ExitCode, Error> {
    let progress = Progress::new();
    let (name, data) = load(Some(&options.file), &progress)?;
    drop(progress);
    if data.is_volume() {
        check_volume(&name, &data, options.weld)
    } else {
        check_surface(&name, &data, options.weld)
    }
}

/// The problems found, one line each.
#[derive(Default)]
struct Problems(Vec<String>);

impl Problems {
    fn note<T: Debug>(&mut self, count: usize, what: &str, list: &[T]) {
        if count > 0 {
            self.0.push(format!("{count} {what}{}", examples(list)));
        }
    }

    /// Prints the problems, or `ok` and the description of a clean mesh.
    fn print(self, name: &str, ok: impl FnOnce() -> String) -> ExitCode {
        if self.0.is_empty() {
            println!("{name}: ok: {}", ok());
            return ExitCode::SUCCESS;
        }
        for p in &self.0 {
            println!("{name}: {p}");
        }
        ExitCode::FAILURE
    }
}

fn check_surface(name: &str, data: &MeshData, weld: f64) -> Result<ExitCode, Error> {
    let options = BuildOptions {
        weld_tolerance: weld,
        ..BuildOptions::level(1)
    };
    let che = build_surface(data, options)?;
    let r = che.report();
    let mut problems = Problems::default();
    problems.note(
        r.dropped_degenerate,
        "degenerate triangles",
        &r.degenerate_examples,
    );
    problems.note(
        r.duplicate_triangles,
        "duplicate triangle pairs",
        &r.duplicate_examples,
    );
    problems.note(
        r.non_manifold_edges,
        "non-manifold edges",
        &r.non_manifold_edge_examples,
    );
    problems.note(
        r.split_vertices,
        "non-manifold vertices",
        &r.split_vertex_examples,
    );
    problems.note(
        r.non_orientable_components,
        "non-orientable components",
        &r.non_orientable_examples,
    );
    problems.note::<u32>(
        r.flipped_triangles,
        "triangles oriented against their neighbours",
        &[],
    );
    Ok(problems.print(name, || {
        let s = che.summary();
        format!(
            "a manifold of {} triangles, euler characteristic {}",
            s.triangles, s.euler_characteristic
        )
    }))
}

fn check_volume(name: &str, data: &MeshData, weld: f64) -> Result<ExitCode, Error> {
    let chf = build_volume(
        data,
        chf::BuildOptions {
            level: 1,
            weld_tolerance: weld,
            ..chf::BuildOptions::default()
        },
    )?;
    let r = chf.report();
    let mut problems = Problems::default();
    problems.note(
        r.dropped_degenerate,
        "degenerate tetrahedra",
        &r.degenerate_examples,
    );
    problems.note(
        r.zero_volume,
        "zero-volume tetrahedra",
        &r.zero_volume_examples,
    );
    problems.note(
        r.inverted_tetrahedra,
        "inverted tetrahedra",
        &r.inverted_examples,
    );
    problems.note(
        r.duplicate_tetrahedra,
        "duplicate tetrahedron pairs",
        &r.duplicate_examples,
    );
    problems.note(
        r.non_manifold_faces,
        "non-manifold faces",
        &r.non_manifold_face_examples,
    );
    problems.note(
        r.non_manifold_edges,
        "non-manifold edges",
        &r.non_manifold_edge_examples,
    );
    problems.note(
        r.split_vertices,
        "non-manifold vertices",
        &r.split_vertex_examples,
    );
    problems.note(
        r.non_orientable_components,
        "non-orientable components",
        &r.non_orientable_examples,
    );
    problems.note::<u32>(
        r.flipped_tetrahedra,
        "tetrahedra oriented against their neighbours",
        &[],
    );
    Ok(problems.print(name, || {
        let s = chf.summary();
        format!(
            "a manifold of {} tetrahedra, euler characteristic {}",
            s.tetrahedra, s.euler_characteristic
        )
    }))
}
