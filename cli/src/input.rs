//! What every subcommand starts from: a mesh read from a file (or the embedded torus) and
//! the structure built over it.

use crate::progress::Progress;
use std::fs::File;
use std::io::{ErrorKind, Read};
use std::path::Path;
use topomesh::io::{self, Format, MeshData};
use topomesh::levelfile::{OpenOptions, Verify};
use topomesh::{BuildOptions, BuildProgress, Che, Chf, Error, chf};

/// Bytes read between two steps of the progress bar.
const CHUNK: u64 = 1 << 22;

/// The mesh `topomesh info` describes when no file is given: a 24 x 12 torus.
const DEFAULT_MESH: &str = include_str!("../../data/default.off");
const DEFAULT_NAME: &str = "<embedded torus>";

/// Reads `file`, or parses the embedded torus when there is none; returns the name to print
/// and the mesh.
pub fn load(file: Option<&Path>, progress: &Progress) -> Result<(String, MeshData), Error> {
    match file {
        None => Ok((
            DEFAULT_NAME.to_string(),
            io::parse(DEFAULT_MESH.as_bytes(), io::Format::Off, DEFAULT_NAME)?,
        )),
        Some(path) => {
            let (name, data) = (path.display().to_string(), read(path, progress)?);
            // A volume: what the library's volume load checks and warns of.
            let data = if data.is_volume() {
                io::load::as_volume(data, &name)?
            } else {
                data
            };
            Ok((name, data))
        }
    }
}

/// Reads `path` under a percentage bar of its bytes, then parses them. The library's
/// reader does both for what cannot be parsed from memory (TetGen's two files, text
/// formats that are not UTF-8, which it reads leniently) and for every failure, so that
/// the messages are its own.
fn read(path: &Path, progress: &Progress) -> Result<MeshData, Error> {
    let name = path.display().to_string();
    let from_path = |progress: &Progress| {
        progress.step(format!("reading {name}"));
        io::read(path)
    };
    let format = match Format::from_path(path) {
        Ok(Format::TetGen) | Err(_) => return from_path(progress),
        Ok(format) => format,
    };
    let bytes = match read_bytes(path, progress) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == ErrorKind::OutOfMemory => {
            return Err(Error::too_large(format!(
                "{name}: the file does not fit in memory"
            )));
        }
        Err(_) => return from_path(progress),
    };
    let text = matches!(format, Format::Medit | Format::Gmsh | Format::Vtk);
    if text && std::str::from_utf8(&bytes).is_err() {
        return from_path(progress);
    }
    progress.step(format!("parsing {name}"));
    io::parse(&bytes, format, &name)
}

/// The bytes of `path`, read in chunks that advance the progress bar.
fn read_bytes(path: &Path, progress: &Progress) -> std::io::Result<Vec<u8>> {
    let mut file = File::open(path)?;
    let size = file.metadata()?.len();
    let mut bytes = Vec::new();
    usize::try_from(size)
        .ok()
        .and_then(|n| bytes.try_reserve_exact(n).ok())
        .ok_or(ErrorKind::OutOfMemory)?;
    progress.start(format!("reading {}", path.display()), size);
    loop {
        match (&mut file).take(CHUNK).read_to_end(&mut bytes)? {
            0 => return Ok(bytes),
            n => progress.advance(n as u64),
        }
    }
}

/// A level file (a built structure saved by `Che::save` / `Chf::save`), by extension: the
/// one place the command tells them from the mesh formats of the library.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LevelFile {
    /// `.che`: a surface.
    Surface,
    /// `.chf`: a volume.
    Volume,
}

impl LevelFile {
    pub fn of(path: &Path) -> Option<LevelFile> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "che" => Some(LevelFile::Surface),
            "chf" => Some(LevelFile::Volume),
            _ => None,
        }
    }
}

/// A structure opened from a level file, mapped (queries answer from the file, paged in as
/// they touch it), every check on (the file may come from anywhere).
pub enum Opened {
    Surface(Box<Che>),
    Volume(Box<Chf>),
}

/// Opens the level file `path` of kind `kind` under the spinner.
pub fn open(path: &Path, kind: LevelFile, progress: &Progress) -> Result<Opened, Error> {
    progress.step(format!("opening {}", path.display()));
    let options = OpenOptions::mapped(Verify::Full);
    Ok(match kind {
        LevelFile::Surface => Opened::Surface(Box::new(Che::open(path, options)?)),
        LevelFile::Volume => Opened::Volume(Box::new(Chf::open(path, options)?)),
    })
}

/// `build_surface` under a percentage bar of the build's steps.
pub fn build_surface_shown(
    data: &MeshData, options: BuildOptions, progress: &Progress,
) -> Result<Che, Error> {
    let hook = progress.build_hook(format!("building level {}", options.level));
    let (triangles, n, positions) = (&data.triangles, data.num_vertices(), &data.positions);
    Che::from_triangles_with_progress(triangles, n, positions, options, BuildProgress::new(&hook))
}

/// `build_volume` under a percentage bar of the build's steps.
pub fn build_volume_shown(
    data: &MeshData, options: chf::BuildOptions, progress: &Progress,
) -> Result<Chf, Error> {
    let hook = progress.build_hook(format!("building level {}", options.level));
    let (tets, n, positions) = (&data.tetrahedra, data.num_vertices(), &data.positions);
    Chf::from_tetrahedra_with_progress(tets, n, positions, options, BuildProgress::new(&hook))
}

pub fn build_surface(data: &MeshData, options: BuildOptions) -> Result<Che, Error> {
    Che::from_triangles(
        &data.triangles,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

pub fn build_volume(data: &MeshData, options: chf::BuildOptions) -> Result<Chf, Error> {
    Chf::from_tetrahedra(
        &data.tetrahedra,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The command reads each format as the library's `io::read` does, from memory or,
    /// for TetGen and text that is not UTF-8, through it.
    #[test]
    fn reads_every_format_as_the_library_does() {
        let dir = std::env::temp_dir().join(format!("topomesh-cli-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let tri = "0 0 0\n1 0 0\n0 1 0\n";
        let files: [(&str, Vec<u8>); 9] = [
            ("a.off", format!("OFF\n3 1 0\n{tri}3 0 1 2\n").into()),
            ("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".into()),
            (
                "a.ply",
                format!(
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n\
                     property float y\nproperty float z\nelement face 1\n\
                     property list uchar int vertex_indices\nend_header\n{tri}3 0 1 2\n"
                )
                .into(),
            ),
            (
                "a.stl",
                "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n\
                 vertex 0 1 0\nendloop\nendfacet\nendsolid a\n"
                    .into(),
            ),
            (
                "t.node",
                "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n".into(),
            ),
            ("t.ele", "1 4 0\n1 1 2 3 4\n".into()),
            (
                "a.mesh",
                // A Latin-1 byte in a comment: not UTF-8, read leniently by the library.
                b"MeshVersionFormatted 2\n# caf\xe9\nDimension 3\nVertices\n4\n0 0 0 0\n\
                  1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n"
                    .to_vec(),
            ),
            (
                "a.msh",
                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n\
                 3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 0 1 2 3\n$EndElements\n"
                    .into(),
            ),
            (
                "a.vtk",
                format!(
                    "# vtk DataFile Version 3.0\na\nASCII\nDATASET UNSTRUCTURED_GRID\n\
                     POINTS 3 double\n{tri}CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\n"
                )
                .into(),
            ),
        ];
        for (name, bytes) in &files {
            std::fs::write(dir.join(name), bytes).unwrap();
        }
        let progress = Progress::new();
        for name in [
            "a.off", "a.obj", "a.ply", "a.stl", "t.ele", "a.mesh", "a.msh", "a.vtk",
        ] {
            let path = dir.join(name);
            let library = io::read(&path).unwrap_or_else(|e| panic!("{name}: {}", e.message));
            assert_eq!(read(&path, &progress).unwrap(), library, "{name}");
            assert!(library.num_vertices() >= 3, "{name}");
        }
        for missing in ["gone.off", "gone.mesh", "gone.xyz"] {
            let path = dir.join(missing);
            assert_eq!(read(&path, &progress), io::read(&path), "{missing}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
