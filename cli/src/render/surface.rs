//! The scene of a surface: its triangles shaded (or coloured by component) and the marks
//! `--show` asks for, every fact from the library's queries and report.

use super::colour;
use super::origins::split_origins;
use super::scene::{Dot, Layer, Scene, Triangles};
use super::show::Show;
use crate::print::count;
use glam::DVec3;
use std::borrow::Cow;
use topomesh::io::MeshData;
use topomesh::{Che, Error, NONE};

/// Boundary curves named one by one in the legend; the rest are summed up.
const LEGEND_CURVES: usize = 12;

pub fn scene<'a>(
    name: &str, che: &'a Che, data: Option<&MeshData>, show: &[Show],
) -> Result<Scene<'a>, Error> {
    let s = che.summary();
    let mut colours = Vec::new();
    let mut notes = vec![count(s.triangles, "triangle", "triangles")];
    if show.contains(&Show::Components) {
        let (labels, n) = che.triangle_components()?;
        colours = labels
            .iter()
            .map(|&c| colour::palette(c as usize))
            .collect();
        notes.push(count(n as u64, "component", "components"));
    }
    let mut scene = Scene {
        title: name.to_string(),
        triangles: Triangles {
            positions: Cow::Borrowed(che.positions()),
            corners: Cow::Borrowed(che.half_edge_vertices()),
            colours,
            base: colour::SURFACE,
        },
        layers: Vec::new(),
        notes,
    };
    let marks = Marks { che, data };
    for item in show {
        match item {
            Show::Boundary => marks.boundary(&mut scene, s.boundary_edges),
            Show::NonManifold => {
                marks.non_manifold(&mut scene.layers, s.non_manifold_edges, s.split_vertices)
            }
            Show::Seams => marks.seams(&mut scene.layers),
            Show::Split => marks.split(&mut scene.layers),
            Show::Flipped => marks.flipped(&mut scene.layers, s.flipped_triangles),
            Show::Dropped => marks.dropped(&mut scene.layers, s.dropped_degenerate),
            Show::Components | Show::Classes => {}
        }
    }
    Ok(scene)
}

struct Marks<'a> {
    che: &'a Che,
    /// The mesh as read, when there is one.
    data: Option<&'a MeshData>,
}

impl Marks<'_> {
    fn at(&self, v: u32) -> DVec3 {
        self.che.positions()[v as usize]
    }

    /// The segment of half-edge `h`, named by its input vertices.
    fn half_edge(&self, layer: &mut Layer, h: u32) {
        let (a, b) = (self.che.origin(h), self.che.target(h));
        let ids = [self.che.vertex_origin(a), self.che.vertex_origin(b)];
        layer.segment([self.at(a), self.at(b)], ids);
    }

    /// Each boundary curve of the structure in its own colour, numbered from 1 at its
    /// first vertex.
    fn boundary(&self, scene: &mut Scene, edges: u64) {
        let starts = self.che.boundary_curve_starts();
        for (i, &start) in starts.iter().enumerate() {
            let mut layer = Layer::new("boundary", colour::palette(i), None);
            for h in self.che.boundary_curve(start) {
                self.half_edge(&mut layer, h);
            }
            if i < LEGEND_CURVES {
                let n = layer.segments.len() as u64;
                layer.legend = Some(format!(
                    "boundary curve {}: {}",
                    i + 1,
                    count(n, "edge", "edges")
                ));
            }
            layer.label = Some((self.at(self.che.origin(start)), (i + 1).to_string()));
            scene.layers.push(layer);
        }
        if starts.len() > LEGEND_CURVES {
            scene.notes.push(format!(
                "{} more boundary curves",
                starts.len() - LEGEND_CURVES
            ));
        }
        scene
            .notes
            .push(count(edges, "boundary edge", "boundary edges"));
    }

    /// Non-manifold edges (once each, though several half-edges lie on one) and the
    /// vertices the build split into copies.
    fn non_manifold(&self, layers: &mut Vec<Layer>, edges: u64, vertices: u64) {
        let text = count(edges, "non-manifold edge", "non-manifold edges");
        let mut layer = Layer::new("non-manifold", colour::NON_MANIFOLD, Some(text));
        layer.width = 3.0;
        let mut keyed: Vec<([u32; 2], u32)> = (self.che.non_manifold_half_edges().iter())
            .map(|&h| {
                let (a, b) = (self.che.origin(h), self.che.target(h));
                ([a.min(b), a.max(b)], h)
            })
            .collect();
        keyed.sort_unstable();
        keyed.dedup_by_key(|(key, _)| *key);
        for (_, h) in keyed {
            self.half_edge(&mut layer, h);
        }
        layers.push(layer);
        let text = count(vertices, "non-manifold vertex", "non-manifold vertices");
        let mut layer = Layer::new("non-manifold-vertex", colour::NON_MANIFOLD, Some(text));
        for v in split_origins(self.che) {
            layer.point(self.at(v), v);
        }
        layers.push(layer);
    }

    fn seams(&self, layers: &mut Vec<Layer>) {
        let r = self.che.report();
        let text = format!(
            "{} ({})",
            count(r.seam_edges as u64, "seam edge", "seam edges"),
            count(
                r.non_orientable_components as u64,
                "non-orientable component",
                "non-orientable components"
            )
        );
        let mut layer = Layer::new("seam", colour::SEAM, Some(text));
        layer.width = 3.0;
        for &h in self.che.seam_half_edges() {
            self.half_edge(&mut layer, h);
        }
        layers.push(layer);
    }

    /// Rings at the copies the build added, named by the input vertex they copy.
    fn split(&self, layers: &mut Vec<Layer>) {
        let n = self.che.report().added_vertices as u64;
        let text = count(n, "vertex copy added", "vertex copies added");
        let mut layer = Layer::new("split", colour::SPLIT, Some(text));
        layer.dot = Dot::Ring;
        for v in self.che.num_input_vertices()..self.che.num_vertices() {
            layer.point(self.at(v as u32), self.che.vertex_origin(v as u32));
        }
        layers.push(layer);
    }

    /// A dot at the centre of each triangle whose corners run against the input's.
    fn flipped(&self, layers: &mut Vec<Layer>, n: u64) {
        let text = count(n, "flipped triangle", "flipped triangles");
        let mut layer = Layer::new("flipped", colour::FLIPPED, Some(text));
        layer.radius = 3.0;
        let Some(data) = self.data else {
            return layers.push(layer);
        };
        for t in 0..self.che.num_triangles() as u32 {
            let input = self.che.triangle_origin(t);
            let corners = self.che.triangle_vertices(t);
            let kept = corners.map(|v| self.che.vertex_origin(v));
            if reversed(kept, data.triangles[input as usize]) {
                let [a, b, c] = corners.map(|v| self.at(v));
                layer.point((a + b + c) / 3.0, input);
            }
        }
        layers.push(layer);
    }

    /// A cross at each input triangle the structure does not keep, at the centre of its
    /// input corners.
    fn dropped(&self, layers: &mut Vec<Layer>, n: u64) {
        let text = count(n, "dropped triangle", "dropped triangles");
        let mut layer = Layer::new("dropped", colour::DROPPED, Some(text));
        layer.dot = Dot::Cross;
        layer.width = 2.0;
        if let (Some(origins), Some(data)) = (self.che.triangle_origins(), self.data) {
            let p = &data.positions;
            let mut kept = vec![false; data.triangles.len()];
            origins.iter().for_each(|&t| kept[t as usize] = true);
            for (t, tri) in data.triangles.iter().enumerate().filter(|(t, _)| !kept[*t]) {
                let centre = tri.iter().map(|&v| p[v as usize]).sum::<DVec3>() / 3.0;
                layer.point(centre, t as u32);
            }
        }
        layers.push(layer);
    }
}

/// Whether `kept` runs around the triangle the other way from `input` (the same three
/// vertices, reversed); a triangle the weld changed is neither.
fn reversed(kept: [u32; 3], input: [u32; 3]) -> bool {
    let [x, y, z] = input;
    let turned = [[x, z, y], [z, y, x], [y, x, z]];
    !kept.contains(&NONE)
        && turned.contains(&kept)
        && ![[x, y, z], [y, z, x], [z, x, y]].contains(&kept)
}
