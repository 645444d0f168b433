//! Arithmetic on one `f64` or on two side by side ([`F2`]), so that the screw kernel is written
//! once and runs either on one screw or on two independent screws at a time.
//!
//! Why two at a time: one screw is a long chain of dependent operations (a square root, two
//! divisions, an arctangent and a sine/cosine in a row), so a single evaluation leaves most of
//! the processor idle. Two independent screws interleaved fill it, and on x86-64 (SSE2) and
//! wasm32 with SIMD each [`F2`] operation is one instruction for both. Batches of screws (the
//! subdivision's spans, `screwPairs` in JavaScript) go through [`F2`]; a single call uses `f64`.
//!
//! The kernel needs no branch on the data: comparisons produce `0.0`/`1.0` steps or bit masks
//! ([`Real::gt_step`], [`Real::quadrant`]) instead, because the angle of one screw says nothing
//! about the next one's and branches on it would be mispredicted half the time.

use std::ops::{Add, Div, Mul, Neg, Sub};

use glam::{DQuat, DVec3};

/// A number, or two lanes of numbers, with the operations the screw kernel needs.
pub(crate) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The value `v` in every lane.
    fn splat(v: f64) -> Self;
    /// Whether `f` holds in every lane.
    fn all(self, f: impl Fn(f64) -> bool) -> bool;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Minimum (of non-NaN values; with a NaN, the second operand).
    fn min(self, other: Self) -> Self;
    /// Maximum (of non-NaN values; with a NaN, the second operand).
    fn max(self, other: Self) -> Self;
    /// `±1` with the sign bit of `self` (so `−1` for `−0`).
    fn sign_one(self) -> Self;
    /// `1.0` where `self > other`, else `0.0`, for non-negative finite operands, computed on the
    /// bit patterns (which order like the numbers) so that no compiler turns it into a branch.
    fn gt_step(self, other: Self) -> Self;
    /// The quadrant step of a sine/cosine: given the kernel values `(s, c)` of the reduced
    /// argument and `rounded = x·2/π + 1.5·2⁵²` (whose lowest mantissa bits hold the quadrant
    /// `q` mod 4), returns `(s, c)`, `(c, −s)`, `(−s, −c)` or `(−c, s)` for `q = 0, 1, 2, 3`.
    fn quadrant(rounded: Self, s: Self, c: Self) -> (Self, Self);
}

/// `0.0` or `1.0` from a bit: `1.0` when the top bit of `bits` is set.
#[inline]
fn step_from_sign_bit(bits: u64) -> f64 {
    f64::from_bits((bits >> 63) * 1f64.to_bits())
}

/// [`Real::quadrant`] on one lane, with bit operations only.
#[inline]
fn quadrant_lane(rounded: f64, s: f64, c: f64) -> (f64, f64) {
    let q = rounded.to_bits();
    let swap = (q & 1).wrapping_neg(); // all ones for odd q
    let (sb, cb) = (s.to_bits(), c.to_bits());
    let sin_bits = (sb & !swap) | (cb & swap);
    let cos_bits = (cb & !swap) | (sb & swap);
    let sin_sign = (q & 2) << 62;
    let cos_sign = (q.wrapping_add(1) & 2) << 62;
    (
        f64::from_bits(sin_bits ^ sin_sign),
        f64::from_bits(cos_bits ^ cos_sign),
    )
}

impl Real for f64 {
    #[inline]
    fn splat(v: f64) -> f64 {
        v
    }
    #[inline]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        f(self)
    }
    #[inline]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    // As comparisons, not `f64::min`/`max`: their NaN rules make them a library call on wasm32
    // (`fmin`, `fmax`); `a < b ? a : b` is one `minsd` on x86-64 and a `select` on wasm32.
    #[inline]
    fn min(self, other: f64) -> f64 {
        if self < other {
            self
        } else {
            other
        }
    }
    #[inline]
    fn max(self, other: f64) -> f64 {
        if self > other {
            self
        } else {
            other
        }
    }
    #[inline]
    fn sign_one(self) -> f64 {
        1f64.copysign(self)
    }
    #[inline]
    fn gt_step(self, other: f64) -> f64 {
        step_from_sign_bit(other.to_bits().wrapping_sub(self.to_bits()))
    }
    #[inline]
    fn quadrant(rounded: f64, s: f64, c: f64) -> (f64, f64) {
        quadrant_lane(rounded, s, c)
    }
}

/// Two `f64` lanes, computed together (one SSE2 / wasm SIMD instruction per operation where the
/// target has them; two independent instruction streams otherwise).
#[cfg(lanes)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub(crate) struct F2(pub [f64; 2]);

#[cfg(lanes)]
impl F2 {
    /// Applies `f` to each lane.
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> F2 {
        F2([f(self.0[0]), f(self.0[1])])
    }
    /// Applies `f` lane by lane to two operands.
    #[inline(always)]
    fn zip(self, other: F2, f: impl Fn(f64, f64) -> f64) -> F2 {
        F2([f(self.0[0], other.0[0]), f(self.0[1], other.0[1])])
    }
}

#[cfg(lanes)]
macro_rules! f2_binary {
    ($($trait:ident $method:ident $op:tt),*) => {$(
        impl $trait for F2 {
            type Output = F2;
            #[inline(always)]
            fn $method(self, o: F2) -> F2 {
                self.zip(o, |a, b| a $op b)
            }
        }
    )*};
}
#[cfg(lanes)]
f2_binary!(Add add +, Sub sub -, Mul mul *, Div div /);

#[cfg(lanes)]
impl Neg for F2 {
    type Output = F2;
    #[inline(always)]
    fn neg(self) -> F2 {
        self.map(|a| -a)
    }
}

#[cfg(lanes)]
impl Real for F2 {
    #[inline(always)]
    fn splat(v: f64) -> F2 {
        F2([v, v])
    }
    #[inline(always)]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        f(self.0[0]) && f(self.0[1])
    }
    #[inline(always)]
    fn sqrt(self) -> F2 {
        self.map(f64::sqrt)
    }
    #[inline(always)]
    fn min(self, other: F2) -> F2 {
        self.zip(other, <f64 as Real>::min)
    }
    #[inline(always)]
    fn max(self, other: F2) -> F2 {
        self.zip(other, <f64 as Real>::max)
    }
    #[inline(always)]
    fn sign_one(self) -> F2 {
        self.map(<f64 as Real>::sign_one)
    }
    #[inline(always)]
    fn gt_step(self, other: F2) -> F2 {
        self.zip(other, <f64 as Real>::gt_step)
    }
    #[inline(always)]
    fn quadrant(rounded: F2, s: F2, c: F2) -> (F2, F2) {
        let (s0, c0) = quadrant_lane(rounded.0[0], s.0[0], c.0[0]);
        let (s1, c1) = quadrant_lane(rounded.0[1], s.0[1], c.0[1]);
        (F2([s0, s1]), F2([c0, c1]))
    }
}

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
        let t = u.cross(v).scale(R::splat(2.0));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_and_signs() {
        assert_eq!(2.0.gt_step(1.0), 1.0);
        assert_eq!(1.0.gt_step(2.0), 0.0);
        assert_eq!(1.0.gt_step(1.0), 0.0);
        assert_eq!(0.0.gt_step(0.0), 0.0);
        assert_eq!(1e-300.gt_step(0.0), 1.0);
        assert_eq!((-0.0f64).sign_one(), -1.0);
        assert_eq!(0.0f64.sign_one(), 1.0);
    }

    #[cfg(lanes)]
    #[test]
    fn lane_steps_and_signs() {
        let two = F2([3.0, 0.5]).gt_step(F2([1.0, 1.0]));
        assert_eq!(two, F2([1.0, 0.0]));
        assert_eq!(F2([-2.0, 2.0]).sign_one(), F2([-1.0, 1.0]));
    }

    #[test]
    fn product_with_the_conjugate_has_an_exactly_zero_vector_part() {
        let mut x = 0.123_456_789f64;
        for _ in 0..1000 {
            x = (x * 3.7 + 0.31).fract();
            let q = Q::new(x - 0.5, 0.3 - x * x, x * 0.7 - 0.2, 0.9 - x).scale(0.8);
            for r in [q, q.scale(-1.0)] {
                let p = r.mul(q.conjugate());
                assert_eq!([p.x, p.y, p.z], [0.0; 3], "{q:?}");
            }
        }
    }

    #[cfg(lanes)]
    #[test]
    fn lanes_agree_with_scalars() {
        let (a, b) = (F2([1.5, -2.0]), F2([0.25, 3.0]));
        for (lane, (x, y)) in [(1.5, 0.25), (-2.0, 3.0)].into_iter().enumerate() {
            assert_eq!((a + b).0[lane], x + y);
            assert_eq!((a - b).0[lane], x - y);
            assert_eq!((a * b).0[lane], x * y);
            assert_eq!((a / b).0[lane], x / y);
            assert_eq!((-a).0[lane], -x);
            assert_eq!(a.min(b).0[lane], x.min(y));
            assert_eq!(a.max(b).0[lane], x.max(y));
            assert_eq!(Real::min(x, y), x.min(y));
            assert_eq!(Real::max(x, y), x.max(y));
        }
    }
}
