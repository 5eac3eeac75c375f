//! A panel's frame: the Mercator plane's `x`, `y` (radians) to picture coordinates
//! (pixels, `y` down), at one scale on both axes (the Mercator plane is conformal, and so
//! is the picture).

use crate::sphere::Merc;
use std::fmt::Write as _;

/// The Mercator rectangle `b` (`[x0, y0, x1, y1]`) drawn at `k` pixels a radian, its
/// top-left corner at (`left`, `top`).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Frame {
    /// The Mercator bounds shown, `[x0, y0, x1, y1]`.
    pub b: [f64; 4],
    /// Pixels a radian.
    pub k: f64,
    /// The plot's left edge (pixels).
    pub left: f64,
    /// The plot's top edge (pixels).
    pub top: f64,
}

impl Frame {
    /// The point `p` moved `dx` radians east (a whole turn, for the Earth's copies), in
    /// pixels.
    pub fn pt(&self, p: Merc, dx: f64) -> (f64, f64) {
        (
            self.left + (p[0] + dx - self.b[0]) * self.k,
            self.top + (self.b[3] - p[1]) * self.k,
        )
    }

    /// An SVG path of `ring` moved `dx` radians east, closed when `close`.
    pub fn path(&self, ring: &[Merc], dx: f64, close: bool) -> String {
        let mut s = String::new();
        for (i, &p) in ring.iter().enumerate() {
            let (x, y) = self.pt(p, dx);
            let _ = write!(s, "{}{x:.2},{y:.2} ", if i == 0 { "M" } else { "L" });
        }
        if close {
            s.push('Z');
        }
        s
    }

    /// The plot's width (pixels).
    pub fn width(&self) -> f64 {
        (self.b[2] - self.b[0]) * self.k
    }

    /// The plot's height (pixels).
    pub fn height(&self) -> f64 {
        (self.b[3] - self.b[1]) * self.k
    }

    /// The plot's rectangle in pixels, `[x0, y0, x1, y1]`.
    pub fn rect(&self) -> [f64; 4] {
        [
            self.left,
            self.top,
            self.left + self.width(),
            self.top + self.height(),
        ]
    }

    /// How far (radians) the Mercator point (`x`, `y`) lies outside the bounds (0 inside).
    pub fn distance(&self, x: f64, y: f64) -> f64 {
        let dx = (self.b[0] - x).max(x - self.b[2]).max(0.0);
        let dy = (self.b[1] - y).max(y - self.b[3]).max(0.0);
        dx.hypot(dy)
    }
}
