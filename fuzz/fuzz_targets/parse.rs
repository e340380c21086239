//! Every reader on arbitrary bytes (the first byte picks the format), then a level-3 build
//! of whatever parsed: errors are fine, panics are not.
#![no_main]

use libfuzzer_sys::fuzz_target;
use topomesh::io::{Format, parse};
use topomesh::{BuildOptions, Che, Chf, chf};

const FORMATS: [Format; 7] = [
    Format::Off,
    Format::Obj,
    Format::Ply,
    Format::Stl,
    Format::Medit,
    Format::Gmsh,
    Format::Vtk,
];

fuzz_target!(|data: &[u8]| {
    let Some((&pick, bytes)) = data.split_first() else {
        return;
    };
    let format = FORMATS[pick as usize % FORMATS.len()];
    let Ok(mesh) = parse(bytes, format, "fuzz") else {
        return;
    };
    if mesh.num_vertices() > 1 << 16 {
        return;
    }
    if !mesh.triangles.is_empty() {
        if let Ok(che) = Che::from_triangles(
            &mesh.triangles,
            mesh.num_vertices(),
            &mesh.positions,
            BuildOptions::level(3),
        ) {
            let _ = che.summary();
        }
    }
    if !mesh.tetrahedra.is_empty() {
        if let Ok(chf) = Chf::from_tetrahedra(
            &mesh.tetrahedra,
            mesh.num_vertices(),
            &mesh.positions,
            chf::BuildOptions::level(3),
        ) {
            let _ = chf.summary();
        }
    }
});
