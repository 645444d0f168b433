//! `f64` lanes in WebAssembly SIMD registers (`v128`), for modules built with `simd128`: two in
//! one register ([`Wasm2`]), and four in two ([`Wasm4`]), which the batches use.
//!
//! Written with explicit instructions for the same reason as `avx.rs`: the compiler's own
//! packing of `Lanes` leaves much of the kernel in single-lane code. The `simd128` feature is
//! enabled for the whole module, so the instructions are safe to call everywhere.
//!
//! Each operation is the IEEE operation of the one-lane code (`min`/`max` are the
//! `pmin`/`pmax` instructions, which are exactly `a < b ? a : b` and `a > b ? a : b`), so two
//! lanes give bit for bit what one lane gives.

use core::arch::wasm32::*;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::real::{Real, Width};

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

/// Four lanes in two `v128`s. The batches run on these rather than on [`Wasm2`]: a screw is a
/// long chain of dependent operations (square root, division, two polynomials), and two
/// independent chains side by side keep the processor busy where one leaves it waiting, which
/// the engines' code generators do not arrange by themselves.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Wasm4(Wasm2, Wasm2);

impl Wasm4 {
    /// Four zero lanes.
    #[inline(always)]
    pub fn zero() -> Wasm4 {
        Wasm4(Wasm2::zero(), Wasm2::zero())
    }
}

macro_rules! wasm4_binary {
    ($($trait:ident $method:ident),*) => {$(
        impl $trait for Wasm4 {
            type Output = Wasm4;
            #[inline(always)]
            fn $method(self, o: Wasm4) -> Wasm4 {
                Wasm4(self.0.$method(o.0), self.1.$method(o.1))
            }
        }
    )*};
}
wasm4_binary!(Add add, Sub sub, Mul mul, Div div);

impl Neg for Wasm4 {
    type Output = Wasm4;
    #[inline(always)]
    fn neg(self) -> Wasm4 {
        Wasm4(-self.0, -self.1)
    }
}

impl Real for Wasm4 {
    #[inline(always)]
    fn constant(self, v: f64) -> Wasm4 {
        Wasm4(self.0.constant(v), self.1.constant(v))
    }
    #[inline(always)]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        self.0.all(&f) & self.1.all(&f)
    }
    #[inline(always)]
    fn sqrt(self) -> Wasm4 {
        Wasm4(self.0.sqrt(), self.1.sqrt())
    }
    #[inline(always)]
    fn min(self, other: Wasm4) -> Wasm4 {
        Wasm4(self.0.min(other.0), self.1.min(other.1))
    }
    #[inline(always)]
    fn max(self, other: Wasm4) -> Wasm4 {
        Wasm4(self.0.max(other.0), self.1.max(other.1))
    }
    #[inline(always)]
    fn sign_one(self) -> Wasm4 {
        Wasm4(self.0.sign_one(), self.1.sign_one())
    }
    #[inline(always)]
    fn gt_step(self, other: Wasm4) -> Wasm4 {
        Wasm4(self.0.gt_step(other.0), self.1.gt_step(other.1))
    }
    #[inline(always)]
    fn quadrant(rounded: Wasm4, s: Wasm4, c: Wasm4) -> (Wasm4, Wasm4) {
        let (s0, c0) = Wasm2::quadrant(rounded.0, s.0, c.0);
        let (s1, c1) = Wasm2::quadrant(rounded.1, s.1, c.1);
        (Wasm4(s0, s1), Wasm4(c0, c1))
    }
}

impl Width<4> for Wasm4 {
    #[inline(always)]
    fn gather(self, f: impl Fn(usize) -> f64) -> Wasm4 {
        Wasm4(self.0.gather(&f), self.1.gather(|k| f(k + 2)))
    }
    #[inline(always)]
    fn lane(self, k: usize) -> f64 {
        if k < 2 {
            self.0.lane(k)
        } else {
            self.1.lane(k - 2)
        }
    }
}
