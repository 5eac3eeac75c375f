//! The 2D vectors of paper A §I: sums, scalar multiples, dot product, square, and the
//! right perpendicular.

use core::ops::{Add, Mul, Neg, Sub};

/// A 2D vector or point of paper A §I (bold-face letters in the paper).
///
/// `#[repr(C)]` with two `f64`s, so a `&[[f64; 2]]` and a `&[Vect2]` have the same layout.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Vect2 {
    /// The first coordinate.
    pub x: f64,
    /// The second coordinate.
    pub y: f64,
}

impl Vect2 {
    /// The zero vector **0** of §I.
    pub const ZERO: Vect2 = Vect2 { x: 0.0, y: 0.0 };

    /// The vector (x, y).
    #[inline(always)]
    pub const fn new(x: f64, y: f64) -> Self {
        Vect2 { x, y }
    }

    /// Dot product s·v (§I).
    #[inline(always)]
    pub fn dot(self, o: Vect2) -> f64 {
        self.x * o.x + self.y * o.y
    }

    /// Square s² = s·s (§I).
    #[inline(always)]
    pub fn sq(self) -> f64 {
        self.dot(self)
    }

    /// Right perpendicular v⊥ = (v_y, −v_x) (§I; the OCR'd text lost the minus sign).
    #[inline(always)]
    pub fn perp(self) -> Vect2 {
        Vect2::new(self.y, -self.x)
    }

    /// Scalar multiple k·v (§I).
    #[inline(always)]
    pub fn scale(self, k: f64) -> Vect2 {
        Vect2::new(self.x * k, self.y * k)
    }

    /// p + t·v, the position at time t of a point moving linearly (§II).
    #[inline(always)]
    pub fn at(self, vel: Vect2, t: f64) -> Vect2 {
        Vect2::new(self.x + t * vel.x, self.y + t * vel.y)
    }

    /// Both coordinates are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

impl Add for Vect2 {
    type Output = Vect2;
    #[inline(always)]
    fn add(self, o: Vect2) -> Vect2 {
        Vect2::new(self.x + o.x, self.y + o.y)
    }
}

impl Sub for Vect2 {
    type Output = Vect2;
    #[inline(always)]
    fn sub(self, o: Vect2) -> Vect2 {
        Vect2::new(self.x - o.x, self.y - o.y)
    }
}

impl Neg for Vect2 {
    type Output = Vect2;
    #[inline(always)]
    fn neg(self) -> Vect2 {
        Vect2::new(-self.x, -self.y)
    }
}

impl Mul<Vect2> for f64 {
    type Output = Vect2;
    #[inline(always)]
    fn mul(self, v: Vect2) -> Vect2 {
        v.scale(self)
    }
}

impl From<[f64; 2]> for Vect2 {
    #[inline]
    fn from(a: [f64; 2]) -> Self {
        Vect2::new(a[0], a[1])
    }
}

impl From<Vect2> for [f64; 2] {
    #[inline]
    fn from(v: Vect2) -> Self {
        [v.x, v.y]
    }
}

#[cfg(feature = "nalgebra")]
mod nalgebra_interop {
    use super::Vect2;
    use nalgebra::{Point2, Vector2};

    impl From<Point2<f64>> for Vect2 {
        fn from(p: Point2<f64>) -> Self {
            Vect2::new(p.x, p.y)
        }
    }
    impl From<Vector2<f64>> for Vect2 {
        fn from(v: Vector2<f64>) -> Self {
            Vect2::new(v.x, v.y)
        }
    }
    impl From<Vect2> for Point2<f64> {
        fn from(v: Vect2) -> Self {
            Point2::new(v.x, v.y)
        }
    }
    impl From<Vect2> for Vector2<f64> {
        fn from(v: Vect2) -> Self {
            Vector2::new(v.x, v.y)
        }
    }
}

/// Square root in `no_std` builds too.
#[inline(always)]
pub(crate) fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}
