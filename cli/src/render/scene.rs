//! What a render draws, whatever the output: shaded triangles, then layers of marks
//! (lines, dots, crosses, numbers), then the legend. The surface and volume modules fill
//! it from the library's queries; the raster and SVG writers draw it.

use super::colour::Rgb;
use glam::DVec3;
use std::borrow::Cow;

/// The triangles to shade: `corners` holds three ids into `positions` per triangle.
pub struct Triangles<'a> {
    pub positions: Cow<'a, [DVec3]>,
    pub corners: Cow<'a, [u32]>,
    /// Per triangle, its colour; empty when every triangle has `base`.
    pub colours: Vec<Rgb>,
    pub base: Rgb,
}

impl Triangles<'_> {
    pub fn len(&self) -> usize {
        self.corners.len() / 3
    }

    pub fn colour(&self, t: usize) -> Rgb {
        self.colours.get(t).copied().unwrap_or(self.base)
    }

    pub fn corners(&self, t: usize) -> [DVec3; 3] {
        let c = &self.corners[3 * t..3 * t + 3];
        [0, 1, 2].map(|i| self.positions[c[i] as usize])
    }
}

/// How a layer's points are marked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dot {
    Disc,
    Ring,
    Cross,
}

/// One kind of mark in one colour: the SVG class names it, the legend line describes it.
pub struct Layer {
    /// The SVG class (`boundary`, `non-manifold`, ...).
    pub class: &'static str,
    pub colour: Rgb,
    /// The legend's text; `None` for a layer the legend sums up elsewhere.
    pub legend: Option<String>,
    pub width: f64,
    /// The radius of a point's dot, ring or cross.
    pub radius: f64,
    pub segments: Vec<[DVec3; 2]>,
    /// The input ids of each segment's ends (the SVG names them), parallel to `segments`.
    pub segment_ids: Vec<[u32; 2]>,
    pub dot: Dot,
    pub points: Vec<DVec3>,
    /// The id of each point (an input vertex or element), parallel to `points`.
    pub point_ids: Vec<u32>,
    /// A number written next to a point (a boundary curve's).
    pub label: Option<(DVec3, String)>,
}

impl Layer {
    pub fn segment(&mut self, ends: [DVec3; 2], ids: [u32; 2]) {
        self.segments.push(ends);
        self.segment_ids.push(ids);
    }

    pub fn point(&mut self, at: DVec3, id: u32) {
        self.points.push(at);
        self.point_ids.push(id);
    }

    pub fn new(class: &'static str, colour: Rgb, legend: Option<String>) -> Layer {
        Layer {
            class,
            colour,
            legend,
            width: 2.5,
            radius: 5.0,
            segments: Vec::new(),
            segment_ids: Vec::new(),
            dot: Dot::Disc,
            points: Vec::new(),
            point_ids: Vec::new(),
            label: None,
        }
    }
}

/// Everything a render draws.
pub struct Scene<'a> {
    pub title: String,
    pub triangles: Triangles<'a>,
    pub layers: Vec<Layer>,
    /// Legend lines after the layers' (counts with no mark of their own).
    pub notes: Vec<String>,
}

impl Scene<'_> {
    /// The legend: a colour (none for a note) and a line of text each; a layer with no
    /// mark (nothing of its kind in the mesh) has no line.
    pub fn legend(&self) -> Vec<(Option<Rgb>, String)> {
        let mut lines = vec![(None, self.title.clone())];
        let marked = |l: &&Layer| !l.segments.is_empty() || !l.points.is_empty();
        for layer in self.layers.iter().filter(marked) {
            if let Some(text) = &layer.legend {
                lines.push((Some(layer.colour), text.clone()));
            }
        }
        lines.extend(self.notes.iter().map(|n| (None, n.clone())));
        lines
    }

    /// The layers in drawing order around the numbers: the numbered layers (boundary
    /// curves) under them, the marks of problems over them, so that no number hides one.
    pub fn numbered_then_marks(&self) -> (Vec<&Layer>, Vec<&Layer>) {
        self.layers.iter().partition(|l| l.label.is_some())
    }

    /// Every position the camera must see: the triangles' corners and the marks.
    pub fn extent(&self) -> impl Iterator<Item = DVec3> + '_ {
        let t = &self.triangles;
        let mut used = vec![false; t.positions.len()];
        for &c in t.corners.iter() {
            used[c as usize] = true;
        }
        let corners = (t.positions.iter().zip(used)).filter_map(|(p, u)| u.then_some(*p));
        let marks = self.layers.iter().flat_map(|l| {
            let ends = l.segments.iter().flatten().copied();
            ends.chain(l.points.iter().copied())
        });
        corners.chain(marks)
    }
}
