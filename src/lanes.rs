//! Arithmetic on one `f64` or on several side by side (SIMD lanes: [`Lanes`], and four on AVX in
//! `lanes_avx`), so that the screw kernel is written once and runs either on one screw or on
//! several independent screws at a time.
//!
//! Why several at a time: one screw is a long chain of dependent operations (a square root, two
//! divisions, an arctangent and a sine/cosine in a row), so a single evaluation leaves most of
//! the processor idle. Independent screws side by side fill it, and each lane operation is one
//! SIMD instruction for all of them (SSE2, NEON and wasm SIMD hold two `f64`, AVX four).
//! Batches of screws (the subdivision's spans, `screwPairs` in JavaScript) go through
//! [`run_widest`]; a single call uses `f64`.
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
    /// The value `v` in every lane, of the same kind as `self` (whose value is not used): lanes
    /// that carry a processor-feature token (`lanes_avx`) take it from there.
    fn constant(self, v: f64) -> Self;
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
    // A mask (all ones or zero) and an `and`, not a multiply: 64-bit lane multiplies do not
    // exist before AVX-512, so a multiply here would stop the lanes from being vectorised.
    f64::from_bits((bits >> 63).wrapping_neg() & 1f64.to_bits())
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
    fn constant(self, v: f64) -> f64 {
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

/// `N` `f64` lanes, computed together: one SIMD instruction per operation where the compiler
/// packs them into registers (two lanes on SSE2 and NEON), independent instruction streams
/// otherwise.
#[cfg(portable_lanes)]
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(transparent)]
pub(crate) struct Lanes<const N: usize>(pub [f64; N]);

/// Lanes of a given width `N`, moved to and from plain `f64`s.
#[cfg(lanes)]
pub(crate) trait Width<const N: usize>: Real {
    /// `f(k)` in every lane `k`, of the same kind as `self` (whose value is not used).
    fn gather(self, f: impl Fn(usize) -> f64) -> Self;
    /// Lane `k`.
    fn lane(self, k: usize) -> f64;
}

// Written out lane by lane for each width (rather than with `array::from_fn`, whose loop and
// stack traffic keep the compiler from packing the lanes into SIMD registers).
#[cfg(portable_lanes)]
macro_rules! lanes_of_width {
    ($n:literal: $($k:literal)*) => {
        impl Width<$n> for Lanes<$n> {
            #[inline(always)]
            fn gather(self, f: impl Fn(usize) -> f64) -> Self {
                Lanes([$(f($k)),*])
            }
            #[inline(always)]
            fn lane(self, k: usize) -> f64 {
                self.0[k]
            }
        }

        impl Lanes<$n> {
            /// Applies `f` to each lane.
            #[inline(always)]
            fn map(self, f: impl Fn(f64) -> f64) -> Self {
                Lanes([$(f(self.0[$k])),*])
            }
            /// Applies `f` lane by lane to two operands.
            #[inline(always)]
            fn zip(self, other: Self, f: impl Fn(f64, f64) -> f64) -> Self {
                Lanes([$(f(self.0[$k], other.0[$k])),*])
            }
        }

        impl Add for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                self.zip(o, |a, b| a + b)
            }
        }
        impl Sub for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self {
                self.zip(o, |a, b| a - b)
            }
        }
        impl Mul for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn mul(self, o: Self) -> Self {
                self.zip(o, |a, b| a * b)
            }
        }
        impl Div for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn div(self, o: Self) -> Self {
                self.zip(o, |a, b| a / b)
            }
        }
        impl Neg for Lanes<$n> {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self {
                self.map(|a| -a)
            }
        }

        impl Real for Lanes<$n> {
            #[inline(always)]
            fn constant(self, v: f64) -> Self {
                Lanes([v; $n])
            }
            // Every lane is tested (no early exit): one branch on the combined answer.
            #[inline(always)]
            fn all(self, f: impl Fn(f64) -> bool) -> bool {
                true $(& f(self.0[$k]))*
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                self.map(f64::sqrt)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::min)
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::max)
            }
            #[inline(always)]
            fn sign_one(self) -> Self {
                self.map(<f64 as Real>::sign_one)
            }
            #[inline(always)]
            fn gt_step(self, other: Self) -> Self {
                self.zip(other, <f64 as Real>::gt_step)
            }
            #[inline(always)]
            fn quadrant(rounded: Self, s: Self, c: Self) -> (Self, Self) {
                let lanes = [$(quadrant_lane(rounded.0[$k], s.0[$k], c.0[$k])),*];
                (Lanes([$(lanes[$k].0),*]), Lanes([$(lanes[$k].1),*]))
            }
        }
    };
}
#[cfg(portable_lanes)]
lanes_of_width!(2: 0 1);

/// A computation written for any lanes (see [`run_widest`]).
#[cfg(lanes)]
pub(crate) trait LanesOp {
    /// What the computation returns.
    type Output;
    /// Runs the computation on lanes of kind `L` and width `N`; `proto` is any value of that
    /// kind (for [`Real::constant`] and [`Width::gather`]).
    fn run<L: Width<N>, const N: usize>(self, proto: L) -> Self::Output;
}

/// Runs `op` on the widest lanes the processor has: eight ([`crate::lanes_avx512::Avx8`]) where
/// x86-64 has AVX-512, four ([`crate::lanes_avx::Avx4`]) where it has AVX2 (checked at run
/// time; `pulp` compiles the code for them and keeps the `unsafe` of calling it on its side),
/// four in two wasm SIMD registers ([`crate::lanes_wasm::Wasm4`]) on wasm32 built with
/// `simd128`, two ([`Lanes<2>`]: SSE2, NEON) everywhere else. Every
/// kind of lane computes the same IEEE operations in the same order (no fused multiply-add is
/// formed), so the results do not depend on the processor.
#[cfg(lanes)]
#[inline(always)]
pub(crate) fn run_widest<Op: LanesOp>(op: Op) -> Op::Output {
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        if max_width() >= 4 {
            op.run(crate::lanes_wasm::Wasm4::zero())
        } else {
            op.run(crate::lanes_wasm::Wasm2::zero())
        }
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    {
        #[cfg(target_arch = "x86_64")]
        {
            let max = max_width();
            if max >= 8 {
                if let Some(avx512) = crate::lanes_avx512::Avx8::detect() {
                    return avx512.vectorize(op);
                }
            }
            if max >= 4 {
                if let Some(avx) = crate::lanes_avx::Avx4::detect() {
                    return avx.vectorize(op);
                }
            }
        }
        op.run(Lanes([0.0; 2]))
    }
}

/// Runs `op` on lanes of `proto`'s kind inside `pulp`'s dispatch for the feature token `simd`:
/// everything `op` calls inline is then compiled with the token's features (AVX2, AVX-512).
#[cfg(all(lanes, target_arch = "x86_64"))]
#[inline(always)]
pub(crate) fn vectorize<S: pulp::Simd, L: Width<N>, const N: usize, Op: LanesOp>(
    simd: S,
    proto: L,
    op: Op,
) -> Op::Output {
    /// `op` and its lanes, in pulp's dispatch.
    struct OnSimd<Op, L, const N: usize>(Op, L);
    impl<Op: LanesOp, L: Width<N>, const N: usize> pulp::WithSimd for OnSimd<Op, L, N> {
        type Output = Op::Output;
        #[inline(always)]
        fn with_simd<S: pulp::Simd>(self, _: S) -> Op::Output {
            self.0.run::<L, N>(self.1)
        }
    }
    simd.vectorize(OnSimd::<Op, L, N>(op, proto))
}

/// The widest lanes the batches may use: all of them, except inside tests' `with_max_width`, so
/// that the narrower routes are covered on machines with wider ones.
#[cfg(lanes)]
#[inline(always)]
fn max_width() -> usize {
    #[cfg(test)]
    return tests::max_width();
    #[cfg(not(test))]
    usize::MAX
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use std::cell::Cell;

    thread_local! {
        static MAX_WIDTH: Cell<usize> = const { Cell::new(usize::MAX) };
    }

    /// Runs `f` with the batches on at most `width` lanes (8, 4 or 2), so that tests cover the
    /// narrower routes on machines that have wider ones.
    pub(crate) fn with_max_width<T>(width: usize, f: impl FnOnce() -> T) -> T {
        MAX_WIDTH.with(|w| w.set(width));
        let result = f();
        MAX_WIDTH.with(|w| w.set(usize::MAX));
        result
    }

    /// The cap set by [`with_max_width`] on this thread.
    pub(crate) fn max_width() -> usize {
        MAX_WIDTH.with(Cell::get)
    }

    /// Every lane operation of `proto`'s kind gives, lane by lane, the bits of the one-lane
    /// operation: NaN, infinities, signed zeros, subnormals and the quadrant bit tricks
    /// included.
    pub(crate) fn lanes_match_one_lane<L: Width<N>, const N: usize>(proto: L) {
        let values = [
            1.5,
            -2.0,
            0.25,
            3.0,
            0.0,
            -0.0,
            1e-300,
            -1e300,
            f64::NAN,
            f64::INFINITY,
            7.0,
            0.1,
            2.5,
            -0.75,
            5e-324,
            -f64::INFINITY,
        ];
        let same = |got: L, want: [f64; N], what: &str| {
            for (k, w) in want.iter().enumerate() {
                assert_eq!(
                    got.lane(k).to_bits(),
                    w.to_bits(),
                    "{what}, lane {k} of {N}"
                );
            }
        };
        for start in 0..values.len() {
            let x: [f64; N] = std::array::from_fn(|k| values[(start + k) % values.len()]);
            let y: [f64; N] = std::array::from_fn(|k| values[(start + 3 * k + 5) % values.len()]);
            let (a, b) = (proto.gather(|k| x[k]), proto.gather(|k| y[k]));
            let each = |f: fn(f64, f64) -> f64| std::array::from_fn(|k| f(x[k], y[k]));
            same(a, x, "gather");
            same(a + b, each(|p, q| p + q), "add");
            same(a - b, each(|p, q| p - q), "sub");
            same(a * b, each(|p, q| p * q), "mul");
            same(a / b, each(|p, q| p / q), "div");
            same(-a, x.map(|p| -p), "neg");
            same(a.sqrt(), x.map(f64::sqrt), "sqrt");
            same(a.min(b), each(Real::min), "min");
            same(a.max(b), each(Real::max), "max");
            same(a.sign_one(), x.map(Real::sign_one), "sign_one");
            same(proto.constant(x[0]), [x[0]; N], "constant");
            // gt_step is specified for non-negative finite operands.
            let (fx, fy) = (x.map(finite_abs), y.map(finite_abs));
            let (fa, fb) = (proto.gather(|k| fx[k]), proto.gather(|k| fy[k]));
            let steps = std::array::from_fn(|k| Real::gt_step(fx[k], fy[k]));
            same(fa.gt_step(fb), steps, "gt_step");
            assert_eq!(a.all(|v| !v.is_nan()), x.iter().all(|v| !v.is_nan()), "all");
            let q: [f64; N] =
                std::array::from_fn(|k| 6755399441055744.0 + ((start + k) % 8) as f64);
            let (gs, gc) = Real::quadrant(proto.gather(|k| q[k]), a, b);
            let want: [(f64, f64); N] = std::array::from_fn(|k| Real::quadrant(q[k], x[k], y[k]));
            same(gs, want.map(|w| w.0), "quadrant sine");
            same(gc, want.map(|w| w.1), "quadrant cosine");
        }
    }

    fn finite_abs(v: f64) -> f64 {
        if v.is_finite() {
            v.abs()
        } else {
            1.0
        }
    }

    #[test]
    fn steps_and_signs() {
        assert_eq!(2.0.gt_step(1.0), 1.0);
        assert_eq!(1.0.gt_step(2.0), 0.0);
        assert_eq!(1.0.gt_step(1.0), 0.0);
        assert_eq!(0.0.gt_step(0.0), 0.0);
        assert_eq!(1e-300.gt_step(0.0), 1.0);
        assert_eq!((-0.0f64).sign_one(), -1.0);
        assert_eq!(0.0f64.sign_one(), 1.0);
        assert_eq!(Real::min(1.0, f64::NAN).to_bits(), f64::NAN.to_bits());
        assert_eq!(Real::max(2.0, 1.0), 2.0);
    }

    #[cfg(portable_lanes)]
    #[test]
    fn two_lanes_match_one_lane() {
        lanes_match_one_lane(Lanes([0.0; 2]));
    }

    #[cfg(all(lanes, target_arch = "x86_64"))]
    #[test]
    fn avx_lanes_match_one_lane() {
        // Run only where the processor has the instructions.
        if let Some(proto) = crate::lanes_avx::Avx4::detect() {
            lanes_match_one_lane(proto);
        }
        if let Some(proto) = crate::lanes_avx512::Avx8::detect() {
            lanes_match_one_lane(proto);
        }
    }

    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    #[wasm_bindgen_test::wasm_bindgen_test]
    fn wasm_lanes_match_one_lane() {
        lanes_match_one_lane(crate::lanes_wasm::Wasm2::zero());
        lanes_match_one_lane(crate::lanes_wasm::Wasm4::zero());
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
}
