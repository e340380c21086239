//! The colours of a render: the surface's grey, one colour per mark kind, a distinct colour
//! per boundary curve or component, and the flat shading of a triangle.

/// An opaque colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// `#rrggbb`, for SVG.
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }

    /// This colour lit by `light` in [0, 1], in one of 16 steps: few colours make a small
    /// PNG, and flat-shaded triangles show little banding.
    pub fn shaded(self, light: f32) -> Rgb {
        let light = (light * 16.0).round() / 16.0;
        let f = |c: u8| (c as f32 * light).round().clamp(0.0, 255.0) as u8;
        Rgb(f(self.0), f(self.1), f(self.2))
    }
}

pub const BACKGROUND: Rgb = Rgb(255, 255, 255);
pub const SURFACE: Rgb = Rgb(200, 200, 205);
pub const TEXT: Rgb = Rgb(20, 20, 20);
pub const NON_MANIFOLD: Rgb = Rgb(230, 0, 0);
pub const SEAM: Rgb = Rgb(255, 140, 0);
pub const SPLIT: Rgb = Rgb(150, 0, 200);
pub const FLIPPED: Rgb = Rgb(255, 0, 170);
pub const DROPPED: Rgb = Rgb(0, 0, 0);
pub const INTERIOR: Rgb = Rgb(40, 90, 220);
pub const BOUNDARY: Rgb = Rgb(0, 160, 60);
pub const CUT: Rgb = Rgb(240, 190, 60);

/// The `i`-th of a sequence of distinct colours: hues a golden angle apart, so that
/// neighbours in the sequence differ most, and the lightness stepped by another
/// irrational fraction (the plastic number's), so that two colours whose hues come close
/// differ in lightness. Saturated and mid-dark, to stand out on the grey.
pub fn palette(i: usize) -> Rgb {
    let hue = (i as f64 * 137.507_764_050_037_85) % 360.0;
    let lightness = 0.32 + 0.26 * ((i as f64 * 0.754_877_666_246_692_7) % 1.0);
    hsl(hue, 0.85, lightness)
}

/// The colour of hue `h` (degrees), saturation `s` and lightness `l`.
fn hsl(h: f64, s: f64, l: f64) -> Rgb {
    let c = (1.0 - (2.0 * l - 1.0).abs()) * s;
    let x = c * (1.0 - ((h / 60.0) % 2.0 - 1.0).abs());
    let m = l - c / 2.0;
    let (r, g, b) = match (h / 60.0) as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let byte = |v: f64| ((v + m) * 255.0).round().clamp(0.0, 255.0) as u8;
    Rgb(byte(r), byte(g), byte(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first twenty thousand colours are all different, and none is a mark colour.
    #[test]
    fn palette_colours_are_distinct() {
        let mut seen: Vec<Rgb> = (0..20_000).map(palette).collect();
        let n = seen.len();
        seen.sort_by_key(|c| (c.0, c.1, c.2));
        seen.dedup();
        assert_eq!(seen.len(), n);
        for mark in [
            NON_MANIFOLD,
            SEAM,
            SPLIT,
            FLIPPED,
            DROPPED,
            SURFACE,
            BACKGROUND,
        ] {
            assert!(!seen.contains(&mark), "{mark:?}");
        }
    }
}
