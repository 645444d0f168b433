//! The number types the screw kernel is written for: [`Real`] (one `f64`, or several side by
//! side), [`Width`] (lanes of a fixed width, moved to and from plain `f64`s) and [`LanesOp`] (a
//! computation written for any lanes). The backends (`portable`, `avx`, `avx512`, `wasm`)
//! implement these; nothing here names a backend.
//!
//! The kernel needs no branch on the data: comparisons produce `0.0`/`1.0` steps or bit masks
//! ([`Real::gt_step`], [`Real::quadrant`]) instead, because the angle of one screw says nothing
//! about the next one's and branches on it would be mispredicted half the time.

use std::ops::{Add, Div, Mul, Neg, Sub};

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
    /// that carry a processor-feature token (`avx.rs`) take it from there.
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
pub(super) fn quadrant_lane(rounded: f64, s: f64, c: f64) -> (f64, f64) {
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

/// Lanes of a given width `N`, moved to and from plain `f64`s.
#[cfg(lanes)]
pub(crate) trait Width<const N: usize>: Real {
    /// `f(k)` in every lane `k`, of the same kind as `self` (whose value is not used).
    fn gather(self, f: impl Fn(usize) -> f64) -> Self;
    /// Lane `k`.
    fn lane(self, k: usize) -> f64;
    /// Four rows of lanes from `N` rows of four numbers: lane `k` of the result's `j`-th
    /// entry is `row(k)[j]` (a transposition, as [`Width::gather`] of each entry does).
    #[inline(always)]
    fn rows4(self, row: impl Fn(usize) -> [f64; 4]) -> [Self; 4] {
        std::array::from_fn(|j| self.gather(|k| row(k)[j]))
    }
}

/// A computation written for any lanes (see `dispatch::run_widest`).
#[cfg(lanes)]
pub(crate) trait LanesOp {
    /// What the computation returns.
    type Output;
    /// Runs the computation on lanes of kind `L` and width `N`; `proto` is any value of that
    /// kind (for [`Real::constant`] and [`Width::gather`]).
    fn run<L: Width<N>, const N: usize>(self, proto: L) -> Self::Output;
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
