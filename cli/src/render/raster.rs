//! The PNG: triangles filled into a depth buffer (one pass, flat colours), then the marks,
//! numbers and legend drawn over them with tiny-skia, encoded by tiny-skia's PNG writer.

use super::colour::{BACKGROUND, Rgb, TEXT};
use super::font;
use super::layout::Layout;
use super::scene::{Dot, Layer, Scene};
use super::view::Camera;
use crate::progress::Progress;
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Rect, Stroke, Transform};

/// Triangles between two steps of the progress bar.
const CHUNK: usize = 1 << 16;

/// The PNG file's bytes.
pub fn png(
    scene: &Scene, cam: &Camera, layout: &Layout, progress: &Progress,
) -> Result<Vec<u8>, String> {
    let mut pixmap = Pixmap::new(layout.width, layout.height)
        .ok_or_else(|| format!("cannot make a {}x{} image", layout.width, layout.height))?;
    pixmap.fill(colour(BACKGROUND));
    shade(&mut pixmap, scene, cam, progress);
    let (numbered, marks) = scene.numbered_then_marks();
    for &layer in &numbered {
        draw_layer(&mut pixmap, layer, cam);
    }
    // Many numbers at full size would hide the mesh.
    let scale = if numbered.len() > 24 { 1 } else { 2 };
    for layer in numbered {
        if let Some((at, text)) = &layer.label {
            let [x, y, _] = cam.project(*at);
            let y = y - 6.0 - (font::HEIGHT * scale) as f64;
            label(&mut pixmap, [x + 6.0, y], scale, text, layer.colour);
        }
    }
    for layer in marks {
        draw_layer(&mut pixmap, layer, cam);
    }
    legend(&mut pixmap, scene, layout);
    encode(&pixmap).map_err(|e| e.to_string())
}

/// The pixels as an RGB PNG (every pixel is opaque), with the filter chosen per row and
/// the strongest compression: flat-shaded meshes compress well so, for a small file.
fn encode(pixmap: &Pixmap) -> Result<Vec<u8>, png::EncodingError> {
    let rgb: Vec<u8> = (pixmap.data().chunks_exact(4))
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Best);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&rgb)?;
    writer.finish()?;
    Ok(bytes)
}

fn colour(c: Rgb) -> Color {
    Color::from_rgba8(c.0, c.1, c.2, 255)
}

fn paint(c: Rgb) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color(colour(c));
    paint.anti_alias = true;
    paint
}

/// The depth buffer and the pixels it guards.
struct Target<'a> {
    width: usize,
    height: usize,
    rgba: &'a mut [u8],
    depth: Vec<f32>,
}

/// Every triangle, flat-shaded, nearest wins.
fn shade(pixmap: &mut Pixmap, scene: &Scene, cam: &Camera, progress: &Progress) {
    let t = &scene.triangles;
    let (width, height) = (pixmap.width() as usize, pixmap.height() as usize);
    let projected: Vec<[f32; 3]> = t
        .positions
        .iter()
        .map(|&p| cam.project(p).map(|c| c as f32))
        .collect();
    let mut target = Target {
        width,
        height,
        rgba: pixmap.data_mut(),
        depth: vec![f32::NEG_INFINITY; width * height],
    };
    progress.start("drawing".to_string(), t.len() as u64);
    for start in (0..t.len()).step_by(CHUNK) {
        for i in start..(start + CHUNK).min(t.len()) {
            let c = &t.corners[3 * i..3 * i + 3];
            let [a, b, d] = t.corners(i);
            let lit = t.colour(i).shaded(cam.light((b - a).cross(d - a)));
            let p = [0, 1, 2].map(|k| projected[c[k] as usize]);
            target.fill(p, [lit.0, lit.1, lit.2, 255]);
        }
        progress.advance((t.len() - start).min(CHUNK) as u64);
    }
}

impl Target<'_> {
    /// Fills the pixels whose centres the triangle covers (ends included) where it is
    /// nearer than what is there.
    fn fill(&mut self, [a, b, c]: [[f32; 3]; 3], rgba: [u8; 4]) {
        let area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if area == 0.0 || !area.is_finite() {
            return;
        }
        let (w, h) = (self.width as f32, self.height as f32);
        let x0 = (a[0].min(b[0]).min(c[0]) - 0.5).ceil().max(0.0);
        let x1 = (a[0].max(b[0]).max(c[0]) - 0.5).floor().min(w - 1.0);
        let y0 = (a[1].min(b[1]).min(c[1]) - 0.5).ceil().max(0.0);
        let y1 = (a[1].max(b[1]).max(c[1]) - 0.5).floor().min(h - 1.0);
        if x0 > x1 || y0 > y1 {
            return;
        }
        let edge = |p: [f32; 3], q: [f32; 3], x: f32, y: f32| {
            ((q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])) / area
        };
        for y in y0 as usize..=y1 as usize {
            let py = y as f32 + 0.5;
            for x in x0 as usize..=x1 as usize {
                let px = x as f32 + 0.5;
                let (l0, l1, l2) = (edge(b, c, px, py), edge(c, a, px, py), edge(a, b, px, py));
                if l0 < 0.0 || l1 < 0.0 || l2 < 0.0 {
                    continue;
                }
                let z = l0 * a[2] + l1 * b[2] + l2 * c[2];
                let i = y * self.width + x;
                if z > self.depth[i] {
                    self.depth[i] = z;
                    self.rgba[4 * i..4 * i + 4].copy_from_slice(&rgba);
                }
            }
        }
    }
}

/// Marks a layer draws with one path: small paths keep tiny-skia's edge lists short.
const PATH_MARKS: usize = 4096;
/// Above this many marks a layer is drawn thin (hairlines, square dots): at that density
/// the marks are a texture, and the stroker's outlines would cost most of the time.
const DENSE: usize = 50_000;

/// A layer's segments, then its points, in paths of at most `PATH_MARKS` marks.
fn draw_layer(pixmap: &mut Pixmap, layer: &Layer, cam: &Camera) {
    let paint = paint(layer.colour);
    let dense = layer.segments.len() + layer.points.len() > DENSE;
    let stroke = Stroke {
        width: if dense { 0.0 } else { layer.width as f32 },
        line_cap: tiny_skia::LineCap::Round,
        ..Stroke::default()
    };
    let identity = Transform::identity();
    for chunk in layer.segments.chunks(PATH_MARKS) {
        let mut pb = PathBuilder::new();
        for [p, q] in chunk {
            let ([x0, y0, _], [x1, y1, _]) = (cam.project(*p), cam.project(*q));
            pb.move_to(x0 as f32, y0 as f32);
            pb.line_to(x1 as f32, y1 as f32);
        }
        if let Some(path) = pb.finish() {
            pixmap.stroke_path(&path, &paint, &stroke, identity, None);
        }
    }
    let r = layer.radius as f32;
    for chunk in layer.points.chunks(PATH_MARKS) {
        let mut pb = PathBuilder::new();
        for p in chunk {
            let [x, y, _] = cam.project(*p).map(|c| c as f32);
            match layer.dot {
                Dot::Disc | Dot::Ring if dense => {
                    if let Some(rect) = Rect::from_xywh(x - 1.0, y - 1.0, 2.0, 2.0) {
                        pb.push_rect(rect);
                    }
                }
                Dot::Disc | Dot::Ring => pb.push_circle(x, y, r),
                Dot::Cross => {
                    pb.move_to(x - r, y - r);
                    pb.line_to(x + r, y + r);
                    pb.move_to(x - r, y + r);
                    pb.line_to(x + r, y - r);
                }
            }
        }
        let Some(path) = pb.finish() else { continue };
        match layer.dot {
            Dot::Disc => pixmap.fill_path(&path, &paint, FillRule::Winding, identity, None),
            Dot::Ring if dense => {
                pixmap.fill_path(&path, &paint, FillRule::Winding, identity, None)
            }
            Dot::Ring | Dot::Cross => pixmap.stroke_path(&path, &paint, &stroke, identity, None),
        }
    }
}

/// `text` at (`x`, `y`) (its top left) on a white box, in `ink`, each font pixel a
/// `scale`-wide square.
fn label(pixmap: &mut Pixmap, [x, y]: [f64; 2], scale: usize, text: &str, ink: Rgb) {
    let w = font::width(text, scale) as f32;
    let h = (font::HEIGHT * scale) as f32;
    if let Some(r) = Rect::from_xywh(x as f32 - 2.0, y as f32 - 2.0, w + 2.0, h + 4.0) {
        pixmap.fill_rect(r, &paint(BACKGROUND), Transform::identity(), None);
    }
    write(pixmap, x as f32, y as f32, scale, text, ink);
}

/// `text` with its top left at (`x`, `y`), each font pixel a `scale`-wide square.
fn write(pixmap: &mut Pixmap, x: f32, y: f32, scale: usize, text: &str, ink: Rgb) {
    let mut paint = paint(ink);
    paint.anti_alias = false;
    let s = scale as f32;
    for (i, c) in text.chars().enumerate() {
        let left = x + (i * font::ADVANCE * scale) as f32;
        for (cx, cy) in font::pixels(c) {
            if let Some(r) = Rect::from_xywh(left + cx as f32 * s, y + cy as f32 * s, s, s) {
                pixmap.fill_rect(r, &paint, Transform::identity(), None);
            }
        }
    }
}

/// The legend, in its column at the right.
fn legend(pixmap: &mut Pixmap, scene: &Scene, layout: &Layout) {
    let s = layout.text_scale;
    let x = layout.legend_x as f32;
    for (i, (swatch, text)) in scene.legend().iter().enumerate() {
        let y = (layout.margin + i * layout.line_height()) as f32;
        let text_x = x + (3 * font::ADVANCE * s) as f32;
        if let Some(c) = swatch {
            let side = (font::HEIGHT * s) as f32;
            if let Some(r) = Rect::from_xywh(x, y, 2.0 * side, side) {
                pixmap.fill_rect(r, &paint(*c), Transform::identity(), None);
            }
        }
        write(pixmap, text_x, y, s, text, TEXT);
    }
}
