//! A small SVG writer for charts: axes (linear or logarithmic), points, lines, bars, text.

use std::fmt::Write;

/// Escapes text for an attribute or an element's content.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A tick label: short, without trailing zeros.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if a >= 1e6 {
        format!("{}M", short(v / 1e6))
    } else if a >= 1e4 {
        format!("{}k", short(v / 1e3))
    } else if a == 0.0 || a >= 1.0 {
        format!("{}", (v * 100.0).round() / 100.0)
    } else {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// One axis: its range, its scale and its label.
#[derive(Clone, Debug)]
pub struct Axis {
    pub min: f64,
    pub max: f64,
    pub log: bool,
    pub label: String,
}

fn nice_step(span: f64) -> f64 {
    let raw = span / 5.0;
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag)
}

impl Axis {
    /// From zero to a round number above every value.
    pub fn linear(values: &[f64], label: &str) -> Axis {
        let top = values.iter().copied().fold(0.0, f64::max);
        let top = if top > 0.0 { top * 1.08 } else { 1.0 };
        let step = nice_step(top);
        Axis {
            min: 0.0,
            max: (top / step).ceil() * step,
            log: false,
            label: label.to_string(),
        }
    }

    /// Whole decades around every (positive) value, and `extra` (e.g. 1 for ratios).
    pub fn log(values: &[f64], extra: &[f64], label: &str) -> Axis {
        let pos = values.iter().chain(extra).copied().filter(|v| *v > 0.0);
        let (lo, hi) = pos.fold((f64::INFINITY, 0.0f64), |(l, h), v| (l.min(v), h.max(v)));
        let (lo, hi) = if lo.is_finite() {
            (lo, hi)
        } else {
            (1.0, 10.0)
        };
        let (a, b) = (lo.log10().floor(), hi.log10().ceil());
        let b = if b <= a { a + 1.0 } else { b };
        Axis {
            min: 10f64.powf(a),
            max: 10f64.powf(b),
            log: true,
            label: label.to_string(),
        }
    }

    /// Where `v` falls, 0 at `min` and 1 at `max`.
    pub fn frac(&self, v: f64) -> f64 {
        if self.log {
            (v.max(self.min * 1e-3).log10() - self.min.log10())
                / (self.max.log10() - self.min.log10())
        } else {
            (v - self.min) / (self.max - self.min)
        }
    }

    pub fn ticks(&self) -> Vec<f64> {
        if self.log {
            let (a, b) = (
                self.min.log10().round() as i32,
                self.max.log10().round() as i32,
            );
            let mults: &[f64] = if b - a <= 2 { &[1.0, 2.0, 5.0] } else { &[1.0] };
            let mut t = Vec::new();
            for e in a..=b {
                for m in mults {
                    let v = m * 10f64.powi(e);
                    if v <= self.max * 1.0001 {
                        t.push(v);
                    }
                }
            }
            t
        } else {
            let step = nice_step(self.max - self.min);
            let n = ((self.max - self.min) / step).round() as usize;
            (0..=n).map(|i| self.min + step * i as f64).collect()
        }
    }
}

/// The plotting area inside the picture and its two axes.
#[derive(Clone, Debug)]
pub struct Frame {
    pub left: f64,
    pub top: f64,
    pub width: f64,
    pub height: f64,
    pub x: Axis,
    pub y: Axis,
}

impl Frame {
    pub fn px(&self, x: f64) -> f64 {
        self.left + self.x.frac(x) * self.width
    }
    pub fn py(&self, y: f64) -> f64 {
        self.top + (1.0 - self.y.frac(y)) * self.height
    }
}

pub const PALETTE: [&str; 10] = [
    "#d62728", "#ff7f0e", "#8c564b", "#1f77b4", "#2ca02c", "#9467bd", "#17becf", "#e377c2",
    "#7f7f7f", "#bcbd22",
];

/// An SVG picture being written.
pub struct Svg {
    out: String,
}

impl Svg {
    pub fn new(width: f64, height: f64, title: &str) -> Svg {
        let mut out = String::new();
        let _ = write!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
             viewBox=\"0 0 {width} {height}\" font-family=\"sans-serif\" font-size=\"12\">\n\
             <rect width=\"{width}\" height=\"{height}\" fill=\"white\"/>\n\
             <text class=\"title\" x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
            width / 2.0,
            esc(title)
        );
        Svg { out }
    }

    pub fn raw(&mut self, s: &str) {
        self.out.push_str(s);
        self.out.push('\n');
    }

    pub fn text(&mut self, x: f64, y: f64, anchor: &str, s: &str) {
        self.raw(&format!(
            "<text x=\"{x:.1}\" y=\"{y:.1}\" text-anchor=\"{anchor}\">{}</text>",
            esc(s)
        ));
    }

    pub fn line(&mut self, (x1, y1): (f64, f64), (x2, y2): (f64, f64), style: &str) {
        self.raw(&format!(
            "<line x1=\"{x1:.1}\" y1=\"{y1:.1}\" x2=\"{x2:.1}\" y2=\"{y2:.1}\" {style}/>"
        ));
    }

    /// The frame, grid lines at the ticks, tick labels and axis labels.
    pub fn axes(&mut self, f: &Frame) {
        self.axes_with(f, true);
    }

    /// As `axes`, without the x ticks when the caller labels the x axis itself (bars).
    pub fn axes_with(&mut self, f: &Frame, x_ticks: bool) {
        let (l, t, r, b) = (f.left, f.top, f.left + f.width, f.top + f.height);
        for v in f.x.ticks().into_iter().filter(|_| x_ticks) {
            let x = f.px(v);
            self.line((x, t), (x, b), "stroke=\"#e4e4e4\"");
            self.text(x, b + 16.0, "middle", &short(v));
        }
        for v in f.y.ticks() {
            let y = f.py(v);
            self.line((l, y), (r, y), "stroke=\"#e4e4e4\"");
            self.text(l - 6.0, y + 4.0, "end", &short(v));
        }
        self.raw(&format!(
            "<rect x=\"{l:.1}\" y=\"{t:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" stroke=\"#444\"/>",
            f.width, f.height
        ));
        self.text((l + r) / 2.0, b + 36.0, "middle", &f.x.label);
        self.raw(&format!(
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\" transform=\"rotate(-90 {:.1} {:.1})\">{}</text>",
            l - 52.0,
            (t + b) / 2.0,
            l - 52.0,
            (t + b) / 2.0,
            esc(&f.y.label)
        ));
    }

    /// A legend: one coloured square and label per entry, from (x, y) down.
    pub fn legend(&mut self, x: f64, y: f64, entries: &[(String, &str)]) {
        for (i, (label, colour)) in entries.iter().enumerate() {
            let yy = y + 18.0 * i as f64;
            self.raw(&format!(
                "<rect class=\"legend\" x=\"{x:.1}\" y=\"{:.1}\" width=\"10\" height=\"10\" fill=\"{colour}\"/>",
                yy - 9.0
            ));
            self.text(x + 15.0, yy, "start", label);
        }
    }

    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}
