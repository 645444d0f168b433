//! Vectors and quaternions of [`Real`]s: one per lane, in the layout the screw kernel reads.

use std::ops::{Add, Sub};

use glam::{DQuat, DVec3};

use super::real::Real;

/// A 3-vector of [`Real`]s (one vector per lane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct V3<R> {
    pub x: R,
    pub y: R,
    pub z: R,
}

impl<R: Real> V3<R> {
    #[inline(always)]
    pub fn new(x: R, y: R, z: R) -> Self {
        V3 { x, y, z }
    }
    #[inline(always)]
    pub fn dot(self, o: Self) -> R {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        V3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    #[inline(always)]
    pub fn scale(self, k: R) -> Self {
        V3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl<R: Real> Add for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        V3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<R: Real> Sub for V3<R> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        V3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

/// A quaternion of [`Real`]s (Hamilton convention, as glam's `DQuat`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Q<R> {
    pub x: R,
    pub y: R,
    pub z: R,
    pub w: R,
}

impl<R: Real> Q<R> {
    /// `self` scaled back to unit length by one Newton step of `1/√n²` around 1: exact to
    /// `O((n² − 1)²)`, enough for inputs that are unit to rounding, and cheaper than a square
    /// root and a division.
    #[inline(always)]
    pub fn renormalized(self) -> Self {
        let n2 = self.length_squared();
        self.scale(n2.constant(1.5) - n2.constant(0.5) * n2)
    }

    #[inline(always)]
    pub fn new(x: R, y: R, z: R, w: R) -> Self {
        Q { x, y, z, w }
    }
    /// The vector part.
    #[inline(always)]
    pub fn xyz(self) -> V3<R> {
        V3::new(self.x, self.y, self.z)
    }
    #[inline(always)]
    pub fn conjugate(self) -> Self {
        Q::new(-self.x, -self.y, -self.z, self.w)
    }
    #[inline(always)]
    pub fn scale(self, k: R) -> Self {
        Q::new(self.x * k, self.y * k, self.z * k, self.w * k)
    }
    #[inline(always)]
    pub fn add(self, o: Self) -> Self {
        Q::new(self.x + o.x, self.y + o.y, self.z + o.z, self.w + o.w)
    }
    #[inline(always)]
    pub fn length_squared(self) -> R {
        self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w
    }
    /// The Hamilton product `self · o`.
    ///
    /// Each vector component sums its terms as `(w·c' + c·w') + (cross terms)`, so that
    /// `q · q̄` (and `(−q) · q̄`) has an exactly zero vector part: the paired products cancel
    /// exactly before anything else is added to them.
    #[inline(always)]
    pub fn mul(self, o: Self) -> Self {
        let (a, b) = (self, o);
        Q::new(
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
        )
    }
    /// The pure quaternion `(v, 0)` times `self`.
    #[inline(always)]
    pub fn premul_vector(self, v: V3<R>) -> Self {
        let b = self;
        Q::new(
            v.x * b.w + v.y * b.z - v.z * b.y,
            -v.x * b.z + v.y * b.w + v.z * b.x,
            v.x * b.y - v.y * b.x + v.z * b.w,
            -(v.x * b.x) - v.y * b.y - v.z * b.z,
        )
    }
    /// Rotates `v` by this unit quaternion: `v + 2w (u × v) + 2 u × (u × v)` with `u = xyz`,
    /// written with one shared cross product.
    #[inline(always)]
    pub fn rotate(self, v: V3<R>) -> V3<R> {
        let u = self.xyz();
        let t = u.cross(v).scale(self.w.constant(2.0));
        v + t.scale(self.w) + u.cross(t)
    }
}

impl From<DVec3> for V3<f64> {
    #[inline(always)]
    fn from(v: DVec3) -> Self {
        V3::new(v.x, v.y, v.z)
    }
}

impl From<V3<f64>> for DVec3 {
    #[inline(always)]
    fn from(v: V3<f64>) -> Self {
        DVec3::new(v.x, v.y, v.z)
    }
}

impl From<DQuat> for Q<f64> {
    #[inline(always)]
    fn from(q: DQuat) -> Self {
        Q::new(q.x, q.y, q.z, q.w)
    }
}

impl From<Q<f64>> for DQuat {
    #[inline(always)]
    fn from(q: Q<f64>) -> Self {
        DQuat::from_xyzw(q.x, q.y, q.z, q.w)
    }
}
