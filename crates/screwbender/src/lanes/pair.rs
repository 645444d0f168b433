//! Two `f64` side by side ([`P`]): one wasm SIMD register where the target has it, else a plain
//! pair. Every operation is lane by lane and IEEE-exact, so results are the same bits either way.
//! Used by the L-BFGS minimiser's dot products and by the quaternion spline's objective, which
//! works on the pairs `[x, y]`, `[z, w]` of its points in R⁴.
//!
//! A type of its own beside the lanes of the screw kernel: those serve native SIMD widths chosen
//! at run time and have no two-lane type for wasm32 without SIMD, which the methods also build
//! for; the methods need only these few operations.

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
use core::arch::wasm32::{
    f64x2, f64x2_add, f64x2_div, f64x2_extract_lane, f64x2_mul, f64x2_splat, f64x2_sub,
    i64x2_shuffle, v128,
};

/// `[a, b]`: one wasm SIMD register.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
#[derive(Clone, Copy)]
pub(crate) struct P(v128);

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
impl P {
    /// `[a, b]`.
    #[inline(always)]
    pub(crate) fn new(a: f64, b: f64) -> P {
        P(f64x2(a, b))
    }
    /// `[a, a]`.
    #[inline(always)]
    pub(crate) fn splat(a: f64) -> P {
        P(f64x2_splat(a))
    }
    /// The two lanes.
    #[inline(always)]
    pub(crate) fn lanes(self) -> [f64; 2] {
        [
            f64x2_extract_lane::<0>(self.0),
            f64x2_extract_lane::<1>(self.0),
        ]
    }
    /// Lane by lane `self + o`.
    #[inline(always)]
    pub(crate) fn add(self, o: P) -> P {
        P(f64x2_add(self.0, o.0))
    }
    /// Lane by lane `self − o`.
    #[inline(always)]
    pub(crate) fn sub(self, o: P) -> P {
        P(f64x2_sub(self.0, o.0))
    }
    /// Lane by lane `self · o`.
    #[inline(always)]
    pub(crate) fn mul(self, o: P) -> P {
        P(f64x2_mul(self.0, o.0))
    }
    /// Lane by lane `self / o`.
    #[inline(always)]
    pub(crate) fn div(self, o: P) -> P {
        P(f64x2_div(self.0, o.0))
    }
    /// `[a₀, a₀]` of `self = [a₀, a₁]` (one shuffle).
    #[inline(always)]
    pub(crate) fn first_twice(self) -> P {
        P(i64x2_shuffle::<0, 0>(self.0, self.0))
    }
    /// `[a₁, a₁]` of `self = [a₀, a₁]` (one shuffle).
    #[inline(always)]
    pub(crate) fn second_twice(self) -> P {
        P(i64x2_shuffle::<1, 1>(self.0, self.0))
    }
    /// `[a₀ + a₁, b₀ + b₁]` of `self = [a₀, a₁]` and `o = [b₀, b₁]`: each pair's two lanes added
    /// (two shuffles and one addition).
    #[inline(always)]
    pub(crate) fn lane_sums(self, o: P) -> P {
        P(f64x2_add(
            i64x2_shuffle::<0, 2>(self.0, o.0),
            i64x2_shuffle::<1, 3>(self.0, o.0),
        ))
    }
}

/// `[a, b]`: a plain pair (the wasm SIMD version's operations on scalars).
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
#[derive(Clone, Copy)]
pub(crate) struct P([f64; 2]);

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
impl P {
    /// `[a, b]`.
    #[inline(always)]
    pub(crate) fn new(a: f64, b: f64) -> P {
        P([a, b])
    }
    /// `[a, a]`.
    #[inline(always)]
    pub(crate) fn splat(a: f64) -> P {
        P([a, a])
    }
    /// The two lanes.
    #[inline(always)]
    pub(crate) fn lanes(self) -> [f64; 2] {
        self.0
    }
    /// `op` lane by lane.
    #[inline(always)]
    fn zip(self, o: P, op: impl Fn(f64, f64) -> f64) -> P {
        P([op(self.0[0], o.0[0]), op(self.0[1], o.0[1])])
    }
    /// Lane by lane `self + o`.
    #[inline(always)]
    pub(crate) fn add(self, o: P) -> P {
        self.zip(o, |a, b| a + b)
    }
    /// Lane by lane `self − o`.
    #[inline(always)]
    pub(crate) fn sub(self, o: P) -> P {
        self.zip(o, |a, b| a - b)
    }
    /// Lane by lane `self · o`.
    #[inline(always)]
    pub(crate) fn mul(self, o: P) -> P {
        self.zip(o, |a, b| a * b)
    }
    /// Lane by lane `self / o`.
    #[inline(always)]
    pub(crate) fn div(self, o: P) -> P {
        self.zip(o, |a, b| a / b)
    }
    /// `[a₀, a₀]` of `self = [a₀, a₁]`.
    #[inline(always)]
    pub(crate) fn first_twice(self) -> P {
        P([self.0[0]; 2])
    }
    /// `[a₁, a₁]` of `self = [a₀, a₁]`.
    #[inline(always)]
    pub(crate) fn second_twice(self) -> P {
        P([self.0[1]; 2])
    }
    /// `[a₀ + a₁, b₀ + b₁]` of `self = [a₀, a₁]` and `o = [b₀, b₁]`.
    #[inline(always)]
    pub(crate) fn lane_sums(self, o: P) -> P {
        P([self.0[0] + self.0[1], o.0[0] + o.0[1]])
    }
}
