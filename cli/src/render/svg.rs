//! The SVG, written as text: triangles back to front (painter's order), then the marks
//! (each line and dot naming the input ids it stands for in `data-v`), numbers and legend.

use super::colour::{BACKGROUND, TEXT};
use super::font;
use super::layout::Layout;
use super::scene::{Dot, Layer, Scene};
use super::view::Camera;
use crate::progress::Progress;
use std::fmt::Write;

/// The SVG document.
pub fn svg(scene: &Scene, cam: &Camera, layout: &Layout, progress: &Progress) -> String {
    let (w, h) = (layout.width, layout.height);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#
    );
    let _ = writeln!(
        s,
        r#"<rect width="{w}" height="{h}" fill="{}"/>"#,
        BACKGROUND.hex()
    );
    triangles(&mut s, scene, cam, progress);
    let (numbered, problems) = scene.numbered_then_marks();
    for &layer in &numbered {
        marks(&mut s, layer, cam);
    }
    // Many numbers at full size would hide the mesh.
    let size = if numbered.len() > 24 { 7 } else { 14 };
    for layer in numbered {
        if let Some((at, text)) = &layer.label {
            let [x, y, _] = cam.project(*at);
            let _ = writeln!(
                s,
                r#"<text class="label {}" x="{:.2}" y="{:.2}" fill="{}" font-family="monospace" font-size="{size}">{}</text>"#,
                layer.class,
                x + 6.0,
                y - 6.0,
                layer.colour.hex(),
                escape(text)
            );
        }
    }
    for layer in problems {
        marks(&mut s, layer, cam);
    }
    legend(&mut s, scene, layout);
    s.push_str("</svg>\n");
    s
}

/// The triangles, farthest first (ties in triangle order).
fn triangles(s: &mut String, scene: &Scene, cam: &Camera, progress: &Progress) {
    let t = &scene.triangles;
    let depth: Vec<f64> = (0..t.len())
        .map(|i| t.corners(i).iter().map(|&p| cam.project(p)[2]).sum::<f64>())
        .collect();
    let mut order: Vec<u32> = (0..t.len() as u32).collect();
    order.sort_by(|&a, &b| {
        depth[a as usize]
            .total_cmp(&depth[b as usize])
            .then(a.cmp(&b))
    });
    progress.start("drawing".to_string(), t.len() as u64);
    s.push_str("<g class=\"surface\" stroke-linejoin=\"round\">\n");
    for (k, &i) in order.iter().enumerate() {
        let [a, b, c] = t.corners(i as usize);
        let lit = t
            .colour(i as usize)
            .shaded(cam.light((b - a).cross(c - a)))
            .hex();
        let [p, q, r] = [a, b, c].map(|x| cam.project(x));
        let _ = writeln!(
            s,
            r#"<polygon points="{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}" fill="{lit}" stroke="{lit}" stroke-width="0.5"/>"#,
            p[0], p[1], q[0], q[1], r[0], r[1]
        );
        if k % 65536 == 65535 {
            progress.advance(65536);
        }
    }
    s.push_str("</g>\n");
}

/// One layer as a group of lines and dots.
fn marks(s: &mut String, layer: &Layer, cam: &Camera) {
    let c = layer.colour.hex();
    let _ = writeln!(
        s,
        r#"<g class="{}" stroke="{c}" fill="{c}" stroke-width="{}" stroke-linecap="round">"#,
        layer.class, layer.width
    );
    for ([p, q], [a, b]) in layer.segments.iter().zip(&layer.segment_ids) {
        let ([x1, y1, _], [x2, y2, _]) = (cam.project(*p), cam.project(*q));
        let _ = writeln!(
            s,
            r#"<line data-v="{a} {b}" x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}"/>"#
        );
    }
    let r = layer.radius;
    for (p, id) in layer.points.iter().zip(&layer.point_ids) {
        let [x, y, _] = cam.project(*p);
        let _ = match layer.dot {
            Dot::Disc => writeln!(
                s,
                r#"<circle data-v="{id}" cx="{x:.2}" cy="{y:.2}" r="{r}"/>"#
            ),
            Dot::Ring => writeln!(
                s,
                r#"<circle data-v="{id}" cx="{x:.2}" cy="{y:.2}" r="{r}" fill="none"/>"#
            ),
            Dot::Cross => writeln!(
                s,
                r#"<path data-v="{id}" d="M{:.2},{:.2}L{:.2},{:.2}M{:.2},{:.2}L{:.2},{:.2}" fill="none"/>"#,
                x - r,
                y - r,
                x + r,
                y + r,
                x - r,
                y + r,
                x + r,
                y - r
            ),
        };
    }
    s.push_str("</g>\n");
}

fn legend(s: &mut String, scene: &Scene, layout: &Layout) {
    let scale = layout.text_scale;
    let size = font::HEIGHT * scale;
    let x = layout.legend_x;
    s.push_str("<g class=\"legend\" font-family=\"monospace\">\n");
    for (i, (swatch, text)) in scene.legend().iter().enumerate() {
        let y = (layout.margin + i * layout.line_height()) as f64;
        if let Some(c) = swatch {
            let _ = writeln!(
                s,
                r#"<rect x="{x:.2}" y="{y:.2}" width="{}" height="{size}" fill="{}"/>"#,
                2 * size,
                c.hex()
            );
        }
        let _ = writeln!(
            s,
            r#"<text x="{:.2}" y="{:.2}" font-size="{}" fill="{}">{}</text>"#,
            x + (3 * font::ADVANCE * scale) as f64,
            y + size as f64,
            size + scale,
            TEXT.hex(),
            escape(text)
        );
    }
    s.push_str("</g>\n");
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
