//! Reading a file as the kind of mesh the caller asked for: a surface file for CHE, a
//! volume file for CHF (the C API's load calls and any host that wants the same checks).

use super::warning::count;
use super::{MeshData, Warning, read};
use crate::che::{BuildOptions, Che};
use crate::chf::Chf;
use crate::error::{Error, Result};
use std::path::Path;

/// Reads `path` and checks that it holds a surface (no tetrahedra) or points only.
pub fn read_surface(path: &Path) -> Result<MeshData> {
    let data = read(path)?;
    if data.is_volume() {
        return Err(Error::invalid(format!(
            "{}: holds {} tetrahedra (a volume mesh), not a surface",
            path.display(),
            data.tetrahedra.len()
        )));
    }
    Ok(data)
}

/// Reads `path` and checks that it holds a volume (tetrahedra) or points only; triangles
/// beside tetrahedra are reported in a warning, since a volume build ignores them.
pub fn read_volume(path: &Path) -> Result<MeshData> {
    as_volume(read(path)?, &path.display().to_string())
}

/// What `read_volume` checks of data read from `name`: tetrahedra, or nothing but points;
/// triangles beside tetrahedra get a warning.
pub fn as_volume(mut data: MeshData, name: &str) -> Result<MeshData> {
    if !data.is_volume() && !data.triangles.is_empty() {
        return Err(Error::invalid(format!(
            "{name}: holds no tetrahedra ({} triangles: a surface, not a volume mesh)",
            data.triangles.len()
        )));
    }
    if !data.triangles.is_empty() {
        let msg = format!(
            "{} beside the {} ignored (a volume is built from its tetrahedra)",
            count(data.triangles.len() as u64, ("triangle", "triangles")),
            count(data.tetrahedra.len() as u64, ("tetrahedron", "tetrahedra"))
        );
        data.warnings.push(Warning::new(name, None, msg));
    }
    Ok(data)
}

/// A structure built from a file, with what the reader warned of.
pub struct Loaded<T> {
    pub mesh: T,
    pub warnings: Vec<Warning>,
}

/// Reads a surface file and builds its CHE.
pub fn che(path: &Path, options: BuildOptions) -> Result<Che> {
    che_loaded(path, options).map(|l| l.mesh)
}

/// [`che`], with the reader's warnings.
pub fn che_loaded(path: &Path, options: BuildOptions) -> Result<Loaded<Che>> {
    built(read_surface(path)?, |d| {
        Che::from_triangles(&d.triangles, d.num_vertices(), &d.positions, options)
    })
}

/// Reads a volume file and builds its CHF; triangles the file also holds are ignored.
pub fn chf(path: &Path, options: BuildOptions) -> Result<Chf> {
    chf_loaded(path, options).map(|l| l.mesh)
}

/// [`chf`], with the reader's warnings.
pub fn chf_loaded(path: &Path, options: BuildOptions) -> Result<Loaded<Chf>> {
    built(read_volume(path)?, |d| {
        Chf::from_tetrahedra(&d.tetrahedra, d.num_vertices(), &d.positions, options)
    })
}

/// The structure `build` makes of `data`, with the reader's warnings.
fn built<T>(data: MeshData, build: impl FnOnce(&MeshData) -> Result<T>) -> Result<Loaded<T>> {
    Ok(Loaded {
        mesh: build(&data)?,
        warnings: data.warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::text::temp_path;

    fn written(ext: &str, text: &str) -> std::path::PathBuf {
        let path = temp_path("load", ext);
        std::fs::write(&path, text).unwrap();
        path
    }

    #[test]
    fn a_volume_with_triangles_says_it_ignores_them() {
        let path = written("msh", crate::io::gmsh::tests::V22);
        let data = read_volume(&path);
        let _ = std::fs::remove_file(&path);
        let data = data.unwrap();
        let last = data.warnings.last().unwrap().to_string();
        assert_eq!(
            last,
            format!(
                "{}: 2 triangles beside the 2 tetrahedra ignored (a volume is built from its \
                 tetrahedra)",
                path.display()
            )
        );
    }

    #[test]
    fn a_point_set_loads_as_a_surface_and_as_a_volume() {
        let path = written("off", "OFF\n2 0 0\n0 0 0\n1 1 1\n");
        let (surface, volume) = (
            che(&path, BuildOptions::default()),
            chf(&path, BuildOptions::default()),
        );
        let (a, b) = (read_surface(&path), read_volume(&path));
        let _ = std::fs::remove_file(&path);
        assert_eq!(
            (
                surface.unwrap().num_vertices(),
                volume.unwrap().num_vertices()
            ),
            (2, 2)
        );
        let want = format!(
            "{}: no faces or cells: read as a point set of 2 vertices",
            path.display()
        );
        assert_eq!(a.unwrap().warnings[0].to_string(), want);
        assert_eq!(b.unwrap().warnings[0].to_string(), want);
    }
}
