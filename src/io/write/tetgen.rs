//! TetGen `.node` and `.ele`, both written, whole or neither: points numbered from 1 (as
//! TetGen numbers them), with one attribute, the input vertex, when the mesh carries
//! origins; 4-node tetrahedra without region attributes.

use super::{Mesh, atomic};
use crate::error::Result;
use std::io::Write;
use std::path::Path;

/// Writes the `.node` and `.ele` files beside `path` (either of them, or the stem).
pub(super) fn write_files(path: &Path, mesh: &Mesh) -> Result<()> {
    let (node, ele) = crate::io::tetgen::sibling_paths(path);
    atomic::write_all(&mut [
        (&node, &mut |w: &mut dyn Write| write_node(w, mesh)),
        (&ele, &mut |w: &mut dyn Write| write_ele(w, mesh)),
    ])
}

fn write_node(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    let attributes = mesh.origin.is_some() as u8;
    writeln!(w, "{} 3 {attributes} 0", mesh.positions.len())?;
    for (i, p) in mesh.positions.iter().enumerate() {
        write!(w, "{} {} {} {}", i + 1, p.x, p.y, p.z)?;
        match mesh.origin_of(i) {
            Some(o) => writeln!(w, " {o}")?,
            None => writeln!(w)?,
        }
    }
    Ok(())
}

fn write_ele(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(w, "{} 4 0", mesh.tetrahedra.len())?;
    for (i, t) in mesh.tetrahedra.iter().enumerate() {
        writeln!(
            w,
            "{} {} {} {} {}",
            i + 1,
            t[0] + 1,
            t[1] + 1,
            t[2] + 1,
            t[3] + 1
        )?;
    }
    Ok(())
}
