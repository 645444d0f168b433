//! Two `f64` lanes in one WebAssembly SIMD register (`v128`), for modules built with `simd128`.
//!
//! Written with explicit instructions for the same reason as `lanes_avx`: the compiler's own
//! packing of `Lanes` leaves much of the kernel in single-lane code. The `simd128` feature is
//! enabled for the whole module, so the instructions are safe to call everywhere.
//!
//! Each operation is the IEEE operation of the one-lane code (`min`/`max` are the
//! `pmin`/`pmax` instructions, which are exactly `a < b ? a : b` and `a > b ? a : b`), so two
//! lanes give bit for bit what one lane gives.

use core::arch::wasm32::*;
use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::lanes::{Real, Width};

/// Two lanes in a `v128`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Wasm2(v128);

impl Wasm2 {
    /// Two zero lanes.
    #[inline(always)]
    pub fn zero() -> Wasm2 {
        Wasm2(f64x2_splat(0.0))
    }
}

macro_rules! wasm_binary {
    ($($trait:ident $method:ident $op:ident),*) => {$(
        impl $trait for Wasm2 {
            type Output = Wasm2;
            #[inline(always)]
            fn $method(self, o: Wasm2) -> Wasm2 {
                Wasm2($op(self.0, o.0))
            }
        }
    )*};
}
wasm_binary!(
    Add add f64x2_add,
    Sub sub f64x2_sub,
    Mul mul f64x2_mul,
    Div div f64x2_div
);

impl Neg for Wasm2 {
    type Output = Wasm2;
    #[inline(always)]
    fn neg(self) -> Wasm2 {
        Wasm2(f64x2_neg(self.0))
    }
}

/// The sign bit of each lane.
#[inline(always)]
fn sign_bits() -> v128 {
    f64x2_splat(-0.0)
}

impl Real for Wasm2 {
    #[inline(always)]
    fn constant(self, v: f64) -> Wasm2 {
        Wasm2(f64x2_splat(v))
    }
    #[inline(always)]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        f(f64x2_extract_lane::<0>(self.0)) & f(f64x2_extract_lane::<1>(self.0))
    }
    #[inline(always)]
    fn sqrt(self) -> Wasm2 {
        Wasm2(f64x2_sqrt(self.0))
    }
    // `pmin(x, y) = y < x ? y : x`, so `pmin(b, a) = a < b ? a : b`, NaN and zeros included.
    #[inline(always)]
    fn min(self, other: Wasm2) -> Wasm2 {
        Wasm2(f64x2_pmin(other.0, self.0))
    }
    // `pmax(x, y) = x < y ? y : x`, so `pmax(b, a) = b < a ? a : b = a > b ? a : b`.
    #[inline(always)]
    fn max(self, other: Wasm2) -> Wasm2 {
        Wasm2(f64x2_pmax(other.0, self.0))
    }
    #[inline(always)]
    fn sign_one(self) -> Wasm2 {
        Wasm2(v128_or(v128_and(self.0, sign_bits()), f64x2_splat(1.0)))
    }
    #[inline(always)]
    fn gt_step(self, other: Wasm2) -> Wasm2 {
        // The sign bit of `bits(other) − bits(self)`, spread over the lane, masks 1.0.
        let mask = i64x2_shr(i64x2_sub(other.0, self.0), 63);
        Wasm2(v128_and(mask, f64x2_splat(1.0)))
    }
    #[inline(always)]
    fn quadrant(rounded: Wasm2, s: Wasm2, c: Wasm2) -> (Wasm2, Wasm2) {
        let q = rounded.0;
        // Bit 0 of q (swap sine and cosine) spread over the lane.
        let swap = i64x2_shr(i64x2_shl(q, 63), 63);
        let (sin, cos) = (
            v128_bitselect(c.0, s.0, swap),
            v128_bitselect(s.0, c.0, swap),
        );
        // Bit 1 of q (resp. of q + 1) moved to the sign bit: the sign flips of sin (resp. cos).
        let sin_sign = v128_and(i64x2_shl(q, 62), sign_bits());
        let cos_sign = v128_and(i64x2_shl(i64x2_add(q, i64x2_splat(1)), 62), sign_bits());
        (
            Wasm2(v128_xor(sin, sin_sign)),
            Wasm2(v128_xor(cos, cos_sign)),
        )
    }
}

impl Width<2> for Wasm2 {
    #[inline(always)]
    fn gather(self, f: impl Fn(usize) -> f64) -> Wasm2 {
        Wasm2(f64x2(f(0), f(1)))
    }
    #[inline(always)]
    fn lane(self, k: usize) -> f64 {
        if k == 0 {
            f64x2_extract_lane::<0>(self.0)
        } else {
            f64x2_extract_lane::<1>(self.0)
        }
    }
}
