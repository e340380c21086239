//! The orthographic camera: the direction the mesh is seen from (`--view`), and the fit of
//! the mesh's projection into the drawing area.

use glam::DVec3;
use std::str::FromStr;

/// Where the eye is, as a direction from the mesh: `iso`, `front` (+z), `top` (+y),
/// `side` (+x) or `x,y,z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View(pub DVec3);

impl FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<View, String> {
        let d = match s {
            "iso" => DVec3::new(1.0, 0.8, 1.2),
            "front" => DVec3::Z,
            "top" => DVec3::Y,
            "side" => DVec3::X,
            _ => {
                let parts: Vec<f64> = s
                    .split(',')
                    .map(|p| p.trim().parse::<f64>())
                    .collect::<Result<_, _>>()
                    .map_err(|_| bad_view(s))?;
                match parts[..] {
                    [x, y, z] => DVec3::new(x, y, z),
                    _ => return Err(bad_view(s)),
                }
            }
        };
        if !d.is_finite() || d.length() == 0.0 {
            return Err(bad_view(s));
        }
        Ok(View(d.normalize()))
    }
}

fn bad_view(s: &str) -> String {
    format!("'{s}': expected iso, front, top, side or a direction x,y,z (not zero)")
}

/// A projection onto the image: screen x to the right, y down, depth towards the eye.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    right: DVec3,
    up: DVec3,
    eye: DVec3,
    scale: f64,
    /// The screen position of the projected origin.
    offset: (f64, f64),
}

impl Camera {
    /// The camera seeing `points` from `view`, fitted into the rectangle at (`x0`, `y0`)
    /// of `width` x `height` pixels, centred, with the same scale on both axes.
    pub fn fit(view: View, points: impl Iterator<Item = DVec3>, area: [f64; 4]) -> Camera {
        let eye = view.0;
        let hint = if eye.y.abs() > 0.99 {
            -DVec3::Z
        } else {
            DVec3::Y
        };
        let right = hint.cross(eye).normalize();
        let up = eye.cross(right);
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for p in points.filter(|p| p.is_finite()) {
            let (u, v) = (p.dot(right), p.dot(up));
            lo = [lo[0].min(u), lo[1].min(v)];
            hi = [hi[0].max(u), hi[1].max(v)];
        }
        if lo[0] > hi[0] {
            (lo, hi) = ([0.0; 2], [1.0; 2]);
        }
        let [x0, y0, width, height] = area;
        let extent = [(hi[0] - lo[0]).max(1e-300), (hi[1] - lo[1]).max(1e-300)];
        let scale = (width / extent[0]).min(height / extent[1]);
        let cx = x0 + width / 2.0 - scale * (lo[0] + hi[0]) / 2.0;
        let cy = y0 + height / 2.0 + scale * (lo[1] + hi[1]) / 2.0;
        Camera {
            right,
            up,
            eye,
            scale,
            offset: (cx, cy),
        }
    }

    /// Screen x, screen y and depth (larger is nearer) of `p`.
    pub fn project(&self, p: DVec3) -> [f64; 3] {
        [
            self.offset.0 + self.scale * p.dot(self.right),
            self.offset.1 - self.scale * p.dot(self.up),
            p.dot(self.eye),
        ]
    }

    /// The light of a triangle with normal `n` (any length, either side lit): a key light
    /// above and to the right of the eye, and an ambient part.
    pub fn light(&self, n: DVec3) -> f32 {
        let len = n.length();
        if len == 0.0 || !len.is_finite() {
            return 0.5;
        }
        let key = (self.eye + 0.4 * self.up + 0.3 * self.right).normalize();
        (0.3 + 0.7 * (n.dot(key) / len).abs()) as f32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_named_views_and_directions() {
        assert_eq!("front".parse::<View>().unwrap().0, DVec3::Z);
        assert_eq!("0,0,2".parse::<View>().unwrap().0, DVec3::Z);
        for bad in ["", "0,0,0", "1,2", "a,b,c", "nan,0,1", "back"] {
            assert!(bad.parse::<View>().is_err(), "{bad}");
        }
    }

    /// The front view maps x to the right and y up, the box filling the area's height.
    #[test]
    fn fits_the_box_into_the_area() {
        let pts = [DVec3::ZERO, DVec3::new(1.0, 2.0, 0.0)];
        let cam = Camera::fit(View(DVec3::Z), pts.into_iter(), [0.0, 0.0, 100.0, 100.0]);
        let [x, y, _] = cam.project(pts[0]);
        assert!(
            (x - 25.0).abs() < 1e-9 && (y - 100.0).abs() < 1e-9,
            "{x} {y}"
        );
        let [x, y, _] = cam.project(pts[1]);
        assert!((x - 75.0).abs() < 1e-9 && y.abs() < 1e-9, "{x} {y}");
    }
}
