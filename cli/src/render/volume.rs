//! The scene of a volume: its boundary surface shaded, or with `--cut` the half below a
//! plane and the tetrahedra that cross it, and the classes of its vertices and edges
//! (interior, boundary, non-manifold) from the library's queries.

use super::colour;
use super::origins::split_origins;
use super::scene::{Dot, Layer, Scene, Triangles};
use super::show::Show;
use crate::print::count;
use glam::DVec3;
use std::borrow::Cow;
use topomesh::io::MeshData;
use topomesh::{Chf, Error};

/// `--cut AXIS=T`: the plane across axis `axis` (0 x, 1 y, 2 z) at fraction `t` of the
/// mesh's extent along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cut {
    pub axis: usize,
    pub at: f64,
}

impl std::str::FromStr for Cut {
    type Err = String;
    fn from_str(s: &str) -> Result<Cut, String> {
        let bad = || format!("'{s}': expected x=T, y=T or z=T with T from 0 to 1");
        let (axis, t) = s.split_once('=').ok_or_else(bad)?;
        let axis = ["x", "y", "z"]
            .iter()
            .position(|a| *a == axis.trim())
            .ok_or_else(bad)?;
        let at: f64 = t.trim().parse().map_err(|_| bad())?;
        if !(0.0..=1.0).contains(&at) {
            return Err(bad());
        }
        Ok(Cut { axis, at })
    }
}

/// Which side of the cut a point is on: kept (at or below the plane) or not.
struct Side {
    axis: usize,
    plane: f64,
}

impl Side {
    fn new(cut: Option<Cut>, positions: &[DVec3]) -> Option<Side> {
        let cut = cut?;
        let along = positions.iter().map(|p| p[cut.axis]);
        let lo = along.clone().fold(f64::MAX, f64::min);
        let hi = along.fold(f64::MIN, f64::max);
        Some(Side {
            axis: cut.axis,
            plane: lo + cut.at * (hi - lo),
        })
    }

    fn kept(&self, p: DVec3) -> bool {
        p[self.axis] <= self.plane
    }
}

pub fn scene<'a>(
    name: &str, chf: &'a Chf, data: Option<&MeshData>, show: &[Show], cut: Option<Cut>,
) -> Result<Scene<'a>, Error> {
    let s = chf.summary();
    let positions = chf.positions();
    let side = Side::new(cut, positions);
    let (corners, colours) = triangles(chf, side.as_ref())?;
    let mut scene = Scene {
        title: name.to_string(),
        triangles: Triangles {
            positions: Cow::Borrowed(positions),
            corners: Cow::Owned(corners),
            colours,
            base: colour::SURFACE,
        },
        layers: Vec::new(),
        notes: vec![count(s.tetrahedra, "tetrahedron", "tetrahedra")],
    };
    if let Some(side) = &side {
        let axis = ["x", "y", "z"][side.axis];
        scene
            .notes
            .push(format!("cut at {axis} = {:.4}", side.plane));
    }
    let keep = |p: DVec3| side.as_ref().is_none_or(|s| s.kept(p));
    if show.contains(&Show::Classes) {
        classes(chf, &keep, &mut scene.layers, &s);
    }
    if show.contains(&Show::Classes) || show.contains(&Show::NonManifold) {
        non_manifold(chf, data, &mut scene.layers, &s);
    }
    if show.contains(&Show::Dropped) {
        dropped(chf, data, &mut scene.layers, s.dropped_degenerate);
    }
    Ok(scene)
}

/// The boundary triangles (those on the kept side under a cut), in volume vertex ids, and
/// under a cut the faces of the tetrahedra crossing the plane, in the cut colour.
fn triangles(chf: &Chf, side: Option<&Side>) -> Result<(Vec<u32>, Vec<colour::Rgb>), Error> {
    let p = chf.positions();
    let mut corners = Vec::new();
    for &hf in chf.boundary_half_faces().iter() {
        let t = chf.half_face_vertices_of(hf);
        if side.is_none_or(|s| t.iter().all(|&v| s.kept(p[v as usize]))) {
            corners.extend_from_slice(&t);
        }
    }
    let Some(side) = side else {
        return Ok((corners, Vec::new()));
    };
    let mut colours = vec![colour::SURFACE; corners.len() / 3];
    for t in 0..chf.num_tetrahedra() as u32 {
        let v = chf.tetrahedron_vertices(t);
        let below = v.iter().filter(|&&x| side.kept(p[x as usize])).count();
        if below == 0 || below == 4 {
            continue;
        }
        for hf in 4 * t..4 * t + 4 {
            corners.extend_from_slice(&chf.half_face_vertices_of(hf));
            colours.push(colour::CUT);
        }
    }
    Ok((corners, colours))
}

/// Interior and boundary vertices and edges, each class a colour (the non-manifold class
/// is its own layer).
fn classes(
    chf: &Chf, keep: &impl Fn(DVec3) -> bool, layers: &mut Vec<Layer>, s: &topomesh::chf::Summary,
) {
    let p = chf.positions();
    let interior_v = s.vertices - s.boundary_vertices - s.isolated_vertices;
    let interior_e = s.edges - s.boundary_edges;
    let text = |v: u64, e: u64, what: &str| {
        format!(
            "{what}: {}, {}",
            count(v, "vertex", "vertices"),
            count(e, "edge", "edges")
        )
    };
    let mut interior = Layer::new(
        "interior",
        colour::INTERIOR,
        Some(text(interior_v, interior_e, "interior")),
    );
    let mut boundary = Layer::new(
        "boundary",
        colour::BOUNDARY,
        Some(text(s.boundary_vertices, s.boundary_edges, "boundary")),
    );
    interior.width = 0.75;
    boundary.width = 1.0;
    interior.radius = 1.5;
    boundary.radius = 1.5;
    for e in 0..chf.num_edges() as u32 {
        let [a, b] = chf.edge_vertices(e);
        let (pa, pb) = (p[a as usize], p[b as usize]);
        if keep(pa) && keep(pb) {
            let layer = if chf.is_boundary_edge(e) {
                &mut boundary
            } else {
                &mut interior
            };
            layer.segment([pa, pb], [chf.vertex_origin(a), chf.vertex_origin(b)]);
        }
    }
    for v in 0..chf.num_vertices() as u32 {
        if chf.is_isolated_vertex(v) || !keep(p[v as usize]) {
            continue;
        }
        let layer = if chf.is_boundary_vertex(v) {
            &mut boundary
        } else {
            &mut interior
        };
        layer.point(p[v as usize], chf.vertex_origin(v));
    }
    layers.push(interior);
    layers.push(boundary);
}

/// The non-manifold class: faces of three or more tetrahedra (their edges), the edges the
/// report lists and the structure keeps, and the vertices split into copies.
fn non_manifold(
    chf: &Chf, data: Option<&MeshData>, layers: &mut Vec<Layer>, s: &topomesh::chf::Summary,
) {
    let text = format!(
        "non-manifold: {}, {}, {}",
        count(s.split_vertices, "vertex", "vertices"),
        count(s.non_manifold_edges, "edge", "edges"),
        count(s.non_manifold_faces, "face", "faces")
    );
    let mut layer = Layer::new("non-manifold", colour::NON_MANIFOLD, Some(text));
    layer.width = 3.0;
    layer.radius = 4.0;
    let p = chf.positions();
    let mut edge = |a: u32, b: u32| {
        let ids = [chf.vertex_origin(a), chf.vertex_origin(b)];
        layer.segment([p[a as usize], p[b as usize]], ids);
    };
    for &hf in chf.non_manifold_half_faces() {
        let [a, b, c] = chf.half_face_vertices_of(hf);
        edge(a, b);
        edge(b, c);
        edge(c, a);
    }
    for [a, b] in chf.multi_fan_vertex_pairs() {
        edge(a, b);
    }
    if let Some(data) = data {
        let q = &data.positions;
        for &[a, b] in &chf.report().non_manifold_edge_examples {
            layer.segment([q[a as usize], q[b as usize]], [a, b]);
        }
    }
    for v in split_origins(chf) {
        layer.point(p[v as usize], v);
    }
    layers.push(layer);
}

/// A cross at the centre of each input tetrahedron the structure does not keep.
fn dropped(chf: &Chf, data: Option<&MeshData>, layers: &mut Vec<Layer>, n: u64) {
    let text = count(n, "dropped tetrahedron", "dropped tetrahedra");
    let mut layer = Layer::new("dropped", colour::DROPPED, Some(text));
    layer.dot = Dot::Cross;
    if let (Some(origins), Some(data)) = (chf.tetrahedron_origins(), data) {
        let mut kept = vec![false; data.tetrahedra.len()];
        origins.iter().for_each(|&t| kept[t as usize] = true);
        for (t, tet) in data
            .tetrahedra
            .iter()
            .enumerate()
            .filter(|(t, _)| !kept[*t])
        {
            let centre = tet
                .iter()
                .map(|&v| data.positions[v as usize])
                .sum::<DVec3>()
                / 4.0;
            layer.point(centre, t as u32);
        }
    }
    layers.push(layer);
}
