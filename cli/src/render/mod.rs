//! `topomesh render`: a picture of a mesh's topology (boundary curves, non-manifold
//! elements, seams, split vertices, flipped and dropped elements, components, the classes
//! of a volume's vertices and edges) as PNG or SVG, and the picture `check --render` makes.
//! Every fact drawn comes from the library's queries and build report.

mod colour;
mod font;
mod layout;
mod origins;
mod raster;
mod scene;
mod show;
mod surface;
mod svg;
mod view;
mod volume;

use crate::exit::Failure;
use crate::input::{LevelFile, Opened, build_surface_shown, build_volume_shown, load, open};
use crate::print::count;
use crate::progress::Progress;
use glam::DVec3;
use layout::Layout;
use scene::Scene;
use show::Show;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use topomesh::io::MeshData;
use topomesh::{BuildOptions, Che, Chf, Error, chf};
use view::{Camera, View};
use volume::Cut;

#[derive(clap::Args)]
pub struct RenderOptions {
    /// The mesh file, its format by extension.
    file: PathBuf,
    /// The image to write: `.png` or `.svg`.
    #[arg(short, long, value_name = "OUT", value_parser = image_path)]
    output: PathBuf,
    #[command(flatten)]
    picture: Picture,
    /// What to mark, comma-separated (default: a surface's boundary and problems, a
    /// volume's classes).
    #[arg(long, value_delimiter = ',')]
    show: Vec<Show>,
    /// Volumes: cut at a plane across an axis, at a fraction of the mesh's extent along
    /// it (`x=0.5` the middle): the half at or below it, and the tetrahedra crossing it.
    #[arg(long, value_name = "AXIS=T")]
    cut: Option<Cut>,
    /// Weld vertices at most TOLERANCE apart before building (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

/// How the picture is taken: the options `render` and `check --render` share.
#[derive(clap::Args, Clone, Copy)]
pub struct Picture {
    /// The direction the mesh is seen from: iso, front (+z), top (+y), side (+x) or x,y,z.
    #[arg(long, default_value = "iso")]
    view: View,
    /// The image's size in pixels, WIDTHxHEIGHT.
    #[arg(long, value_name = "WxH", default_value = "1024x768", value_parser = size)]
    size: (u32, u32),
}

fn image_path(s: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(s);
    match Kind::of(&path) {
        Some(_) => Ok(path),
        None => Err(format!("'{s}': the image must end in .png or .svg")),
    }
}

fn size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("'{s}': expected WIDTHxHEIGHT, each from 64 to 16384");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let parse = |t: &str| {
        t.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (64..=16384).contains(n))
    };
    Ok((parse(w).ok_or_else(bad)?, parse(h).ok_or_else(bad)?))
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Png,
    Svg,
}

impl Kind {
    fn of(path: &Path) -> Option<Kind> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "png" => Some(Kind::Png),
            "svg" => Some(Kind::Svg),
            _ => None,
        }
    }
}

pub fn run(options: &RenderOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let name = short_name(&options.file);
    let request = Request {
        show: &options.show,
        cut: options.cut,
        weld: options.weld,
    };
    let out = &options.output;
    if let Some(kind) = LevelFile::of(&options.file) {
        match open(&options.file, kind, &progress)? {
            Opened::Surface(mut che) => {
                che.build_level(3)?;
                positioned(&name, che.positions())?;
                draw_surface(&name, &che, None, &request, options.picture, out, &progress)?;
            }
            Opened::Volume(mut chf) => {
                chf.build_level(3)?;
                positioned(&name, chf.positions())?;
                draw_volume(&name, &chf, None, &request, options.picture, out, &progress)?;
            }
        }
        return Ok(ExitCode::SUCCESS);
    }
    let (_, data) = load(Some(&options.file), &progress)?;
    drawable(&name, &data)?;
    draw(&name, &data, &request, options.picture, out, &progress)?;
    Ok(ExitCode::SUCCESS)
}

/// `check --render OUT`: the problems `check` lists, marked on the mesh.
pub fn problems(name: &str, data: &MeshData, weld: f64, out: &Path) -> Result<(), Failure> {
    if Kind::of(out).is_none() {
        let message = format!("{}: the image must end in .png or .svg", out.display());
        return Err(Error::invalid(message).into());
    }
    drawable(name, data)?;
    let name = &short_name(Path::new(name));
    let request = Request {
        show: show::PROBLEMS,
        cut: None,
        weld,
    };
    let picture = Picture {
        view: "iso".parse().map_err(Error::invalid)?,
        size: (1024, 768),
    };
    draw(name, data, &request, picture, out, &Progress::new())
}

/// The file's name without its folder: the legend's title.
fn short_name(path: &Path) -> String {
    path.file_name()
        .unwrap_or(path.as_os_str())
        .to_string_lossy()
        .into_owned()
}

/// What to draw.
struct Request<'a> {
    show: &'a [Show],
    cut: Option<Cut>,
    weld: f64,
}

/// The errors before any build: nothing to draw, or nowhere to draw it.
fn drawable(name: &str, data: &MeshData) -> Result<(), Error> {
    if data.triangles.is_empty() && data.tetrahedra.is_empty() {
        return Err(Error::invalid(format!(
            "{name}: an empty mesh (no triangle or tetrahedron): nothing to draw"
        )));
    }
    positioned(name, &data.positions)
}

/// Positions there are, and all finite.
fn positioned(name: &str, positions: &[DVec3]) -> Result<(), Error> {
    if positions.is_empty() {
        return Err(Error::invalid(format!(
            "{name}: no vertex positions: cannot draw a mesh without them"
        )));
    }
    let (bad, examples) = topomesh::non_finite_vertices(positions);
    if let Some(v) = examples.first() {
        let what = count(bad, "vertex", "vertices");
        return Err(Error::invalid(format!(
            "{name}: {what} with a NaN or infinite coordinate (the first: vertex {v}): \
             cannot draw them"
        )));
    }
    Ok(())
}

/// Builds the structure at level 3, makes the scene and writes the image.
fn draw(
    name: &str, data: &MeshData, request: &Request, picture: Picture, out: &Path,
    progress: &Progress,
) -> Result<(), Failure> {
    if data.is_volume() {
        let options = chf::BuildOptions {
            level: 3,
            weld_tolerance: request.weld,
            ..chf::BuildOptions::default()
        };
        let chf = build_volume_shown(data, options, progress)?;
        draw_volume(name, &chf, Some(data), request, picture, out, progress)
    } else {
        let options = BuildOptions {
            weld_tolerance: request.weld,
            ..BuildOptions::level(3)
        };
        let che = build_surface_shown(data, options, progress)?;
        draw_surface(name, &che, Some(data), request, picture, out, progress)
    }
}

/// `data`: the mesh as read, for the marks of what the build changed (none for a level
/// file, which keeps no input).
fn draw_surface(
    name: &str, che: &Che, data: Option<&MeshData>, request: &Request, picture: Picture,
    out: &Path, progress: &Progress,
) -> Result<(), Failure> {
    let show = defaulted(request.show, show::SURFACE_DEFAULT);
    let scene = surface::scene(name, che, data, show)?;
    write(&scene, picture, out, progress)
}

fn draw_volume(
    name: &str, chf: &Chf, data: Option<&MeshData>, request: &Request, picture: Picture,
    out: &Path, progress: &Progress,
) -> Result<(), Failure> {
    let show = defaulted(request.show, show::VOLUME_DEFAULT);
    let scene = volume::scene(name, chf, data, show, request.cut)?;
    write(&scene, picture, out, progress)
}

fn defaulted<'a>(show: &'a [Show], default: &'a [Show]) -> &'a [Show] {
    if show.is_empty() { default } else { show }
}

/// Fits the camera, draws and writes the file (atomically: a failed render leaves no
/// half-written image).
fn write(scene: &Scene, picture: Picture, out: &Path, progress: &Progress) -> Result<(), Failure> {
    let (width, height) = picture.size;
    let layout = Layout::new(width, height, &scene.legend());
    let camera = Camera::fit(picture.view, scene.extent(), layout.drawing_area());
    let bytes = match Kind::of(out) {
        Some(Kind::Svg) => svg::svg(scene, &camera, &layout, progress).into_bytes(),
        _ => raster::png(scene, &camera, &layout, progress).map_err(Error::invalid)?,
    };
    progress.step(format!("writing {}", out.display()));
    let tmp = out.with_extension("tmp-render");
    std::fs::write(&tmp, &bytes)
        .and_then(|()| std::fs::rename(&tmp, out))
        .map_err(|e| {
            let _ = std::fs::remove_file(&tmp);
            Failure::Mesh(Error::io(format!("{}: {e}", out.display())))
        })
}
