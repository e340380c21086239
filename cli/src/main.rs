//! The `topomesh` command: summaries, checks, conversions and timings of mesh files.
//! One module per subcommand; `input`, `output`, `progress`, `print`, `report`, `json` and
//! `exit` are shared by them.

mod bench;
mod check;
mod convert;
mod exit;
mod export;
mod generate;
mod info;
mod input;
mod json;
mod output;
mod print;
mod progress;
mod refine;
mod render;
mod report;
mod simplify;

use clap::{Parser, Subcommand};
use exit::exit_code_table;
use output::Verbosity;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "topomesh",
    version,
    about = "Compact half-edge and half-face topology of meshes",
    after_help = concat!("With no subcommand: info on the embedded torus.\n\n", exit_code_table!())
)]
struct Cli {
    /// Print nothing on stdout and no progress: errors only (check answers by its exit
    /// code alone).
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    quiet: bool,
    /// Print the build report in full: every example id it kept (check: the whole report;
    /// info: also the memory of each container; bench: the fastest and slowest runs).
    #[arg(short, long, global = true)]
    verbose: bool,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Topology summary and build report of a mesh (the embedded torus when no file).
    #[command(after_help = concat!(
        "Examples:
  topomesh info                          the embedded torus, level 3
  topomesh info bunny.off --level 1      a surface at level 1
  topomesh info --json part.mesh         a volume, as JSON (\"schema\" first)
  topomesh info --strict scan.ply        exit 1 if it is not manifold\n\n",
        exit_code_table!()
    ))]
    Info(info::InfoOptions),
    /// Exit 0 when the mesh is a clean manifold, 1 and a list of problems otherwise.
    #[command(after_help = concat!(
        "Examples:
  topomesh check scan.obj                one line per kind of problem
  topomesh -q check scan.obj && echo ok  the exit code alone
  topomesh check --json part.msh         ok, and each problem with its first ids
  topomesh -v check scan.obj             and the whole build report\n\n",
        exit_code_table!()
    ))]
    Check(check::CheckOptions),
    /// Write the built (repaired) mesh in another format (off obj ply stl node/ele mesh msh vtk).
    #[command(after_help = concat!(
        "Examples:
  topomesh convert scan.ply scan.off     the repaired mesh
  topomesh convert --as-read a.stl a.off the input as read
  topomesh convert part.node - --format vtk  to standard output
  topomesh convert part.node part.vtk    a TetGen pair (part.node and part.ele)\n\n",
        exit_code_table!()
    ))]
    Convert(convert::ConvertOptions),
    /// Time the build of every level and full sweeps of the relations.
    #[command(after_help = concat!(
        "Examples:
  topomesh bench bunny.off --repeat 9    the median of 9 runs, after a warm-up run
  topomesh bench --threads 1 --json      the embedded torus on one thread, as JSON\n\n",
        exit_code_table!()
    ))]
    Bench(bench::BenchOptions),
    /// Write a surface as half-edge, winged-edge or corner arrays, lists, strips or matrices.
    #[command(after_help = concat!(
        "Examples:
  topomesh export bunny.off --as halfedge -o bunny.he
  topomesh export bunny.off --as laplacian -o L.mtx   Matrix Market, for SciPy or Eigen
  topomesh export bunny.off --as strips -o -          to stdout
  topomesh export bunny.off --as d1 --json -o d1.json CSR arrays as JSON\n\n",
        "Layouts (one header line, then rows of space-separated numbers; ids from 0, -1 for none):
  halfedge   'halfedge H V T', then H rows 'next prev twin tail face edge' (tail: the
             origin; with --explicit-boundary the boundary twins are rows 3T.., face -1),
             V rows 'outgoing half-edge', T rows 'half-edge'
  winged     'winged E V T', then E rows 'a b left right left_prev left_next right_prev
             right_next' (the edge runs a -> b along its left triangle), V rows 'edge',
             T rows 'edge'
  corner     'corner C', then C = 3T rows 'vertex opposite' (corner c is half-edge c)
  edges      'edges E', then E rows 'a b'
  dual       'dual T', then T rows 'n0 n1 n2': the triangle across each edge, -1 on the
             boundary
  strips     'strips S', then S rows: the vertices of one strip (triangle i of a strip
             is (s[i], s[i+1], s[i+2]), its first two swapped when i is odd)
  d1, d2, laplacian, vertex-adjacency, edge-adjacency, dual-adjacency
             Matrix Market: '%%MatrixMarket matrix coordinate real general', then
             'rows columns entries', then one 'row column value' row per entry, from 1,
             sorted by row and column (scipy.io.mmread, Eigen's loadMarket)\n\n",
        "With --json: one object on one line, \"schema\" (1) and \"representation\" first, then
\"vertices\", \"triangles\", \"edges\" and the arrays of the library's export, flat, ids from 0,
null for none:
  halfedge   explicit_boundary, next, prev, twin, tail, face, edge (one per half-edge),
             vertex_half_edge, face_half_edge
  winged     edge_vertices (2 per edge), edge_faces (2: left, right), wings (4: left_prev
             left_next right_prev right_next), vertex_edge, face_edge
  corner     v, o (one per corner)
  edges      edge_vertices (2 per edge)
  dual       triangle_triangles (3 per triangle)
  strips     offsets, strip_vertices (strip k is strip_vertices[offsets[k]..offsets[k+1]])
  matrices   rows, cols, then CSR: offsets (rows + 1), columns, values (scipy.sparse.csr_matrix
             ((values, columns, offsets)), Eigen::Map<SparseMatrix<double, RowMajor>>)\n\n",
        exit_code_table!()
    ))]
    Export(export::ExportOptions),
    /// Draw a mesh's topology as PNG or SVG: boundary curves, problems, classes.
    #[command(after_help = concat!(
        "Examples:
  topomesh render holes.off -o holes.png         boundary curves and problems, iso view
  topomesh render scan.ply -o scan.svg --view front --show boundary,components
  topomesh render part.mesh -o part.png --cut x=0.5   a volume cut in the middle\n\n",
        exit_code_table!()
    ))]
    Render(render::RenderOptions),
    /// Shortest-edge-first collapse until N triangles (or a ratio) remain.
    #[command(after_help = concat!(
        "Examples:
  topomesh simplify bunny.off small.off --triangles 5000
  topomesh simplify bunny.off half.ply --ratio 0.5\n\n",
        exit_code_table!()
    ))]
    Simplify(simplify::SimplifyOptions),
    /// Split the largest tetrahedra (1-4) until every volume is below a bound.
    #[command(after_help = concat!(
        "Examples:
  topomesh refine part.mesh fine.mesh --max-volume 0.001\n\n",
        exit_code_table!()
    ))]
    Refine(refine::RefineOptions),
    /// Write a torus, a sphere or a tetrahedralised box of a chosen size.
    #[command(after_help = concat!(
        "Examples:
  topomesh generate torus --triangles 1000000 -o torus.off
  topomesh generate sphere --triangles 5000 -o sphere.ply --binary
  topomesh generate box --tetrahedra 6000000 -o box.chf   built, saved as a level file\n\n",
        exit_code_table!()
    ))]
    Generate(generate::GenerateOptions),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return exit::usage(e),
    };
    output::set_verbosity(match (cli.quiet, cli.verbose) {
        (true, _) => Verbosity::Quiet,
        (false, true) => Verbosity::Verbose,
        (false, false) => Verbosity::Normal,
    });
    let command = cli
        .command
        .unwrap_or(Command::Info(info::InfoOptions::default()));
    exit::code(match command {
        Command::Info(options) => info::run(&options),
        Command::Check(options) => check::run(&options),
        Command::Convert(options) => convert::run(&options),
        Command::Bench(options) => bench::run(&options),
        Command::Export(options) => export::run(&options),
        Command::Render(options) => render::run(&options),
        Command::Simplify(options) => simplify::run(&options),
        Command::Refine(options) => refine::run(&options),
        Command::Generate(options) => generate::run(&options),
    })
}
