//! Where things go in the image: the mesh in the drawing area on the left, the legend in
//! a column on the right sized to its longest line.

use super::colour::Rgb;
use super::font;

pub struct Layout {
    pub width: u32,
    pub height: u32,
    pub margin: usize,
    /// Pixels per font pixel.
    pub text_scale: usize,
    pub legend_x: f64,
}

impl Layout {
    pub fn new(width: u32, height: u32, legend: &[(Option<Rgb>, String)]) -> Layout {
        let text_scale = if width >= 600 { 2 } else { 1 };
        let margin = 4 * text_scale + 4;
        let longest = legend.iter().map(|(_, t)| font::width(t, text_scale)).max();
        let column = 3 * font::ADVANCE * text_scale + longest.unwrap_or(0);
        let column = column.min(width as usize * 2 / 5);
        Layout {
            width,
            height,
            margin,
            text_scale,
            legend_x: (width as usize - margin - column) as f64,
        }
    }

    pub fn line_height(&self) -> usize {
        (font::HEIGHT + 3) * self.text_scale
    }

    /// The rectangle the mesh is fitted into: x, y, width, height.
    pub fn drawing_area(&self) -> [f64; 4] {
        let m = self.margin as f64;
        [
            m,
            m,
            (self.legend_x - 2.0 * m).max(1.0),
            (self.height as f64 - 2.0 * m).max(1.0),
        ]
    }
}
