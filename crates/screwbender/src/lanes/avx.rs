//! Four `f64` lanes in one AVX register, for x86-64 processors that have AVX2 (detected at run
//! time by [`Avx4::detect`]).
//!
//! Written with explicit instructions because the compiler's own packing of `Lanes` falls
//! apart at four lanes (it mixes two-lane and one-lane code with shuffles). The instructions
//! come from `pulp`, whose feature token ([`pulp::x86::V3`], proof that the processor has them)
//! makes them safe to call: every value carries the token, which occupies no space.
//!
//! Each operation is the IEEE operation of the one-lane code (`add`, `mul`, `div`, `sqrt` are
//! correctly rounded in both; `min`/`max` and the bit tricks select exactly the same bits), so
//! four lanes give bit for bit what one lane gives.

use core::arch::x86_64::__m256d;
use std::ops::{Add, Div, Mul, Neg, Sub};

use pulp::x86::V3;

use super::real::{vectorize, LanesOp, Real, Width};

/// Four lanes on AVX, with the token that proves the processor has AVX2.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx4 {
    simd: V3,
    v: __m256d,
}

impl Avx4 {
    /// Four zero lanes, or `None` when the processor lacks AVX2 (or FMA and the other x86-64-v3
    /// features `pulp` requires for its token).
    #[inline]
    pub fn detect() -> Option<Avx4> {
        V3::try_new().map(|simd| Avx4 {
            simd,
            v: simd.avx._mm256_setzero_pd(),
        })
    }

    /// Runs `op` on four lanes, compiled for AVX2 (inside `pulp`'s dispatch, everything `op`
    /// calls inline is compiled with the token's features).
    #[inline(always)]
    pub fn vectorize<Op: LanesOp>(self, op: Op) -> Op::Output {
        vectorize(self.simd, self, op)
    }

    #[inline(always)]
    fn with(self, v: __m256d) -> Avx4 {
        Avx4 { simd: self.simd, v }
    }

    #[inline(always)]
    fn lanes(self) -> [f64; 4] {
        pulp::cast(self.v)
    }
}

macro_rules! avx_binary {
    ($($trait:ident $method:ident $op:ident),*) => {$(
        impl $trait for Avx4 {
            type Output = Avx4;
            #[inline(always)]
            fn $method(self, o: Avx4) -> Avx4 {
                self.with(self.simd.avx.$op(self.v, o.v))
            }
        }
    )*};
}
avx_binary!(
    Add add _mm256_add_pd,
    Sub sub _mm256_sub_pd,
    Mul mul _mm256_mul_pd,
    Div div _mm256_div_pd
);

impl Neg for Avx4 {
    type Output = Avx4;
    #[inline(always)]
    fn neg(self) -> Avx4 {
        let avx = self.simd.avx;
        self.with(avx._mm256_xor_pd(self.v, avx._mm256_set1_pd(-0.0)))
    }
}

impl Real for Avx4 {
    #[inline(always)]
    fn constant(self, v: f64) -> Avx4 {
        self.with(self.simd.avx._mm256_set1_pd(v))
    }
    #[inline(always)]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        let l = self.lanes();
        f(l[0]) & f(l[1]) & f(l[2]) & f(l[3])
    }
    #[inline(always)]
    fn sqrt(self) -> Avx4 {
        self.with(self.simd.avx._mm256_sqrt_pd(self.v))
    }
    // `minpd`/`maxpd` return the second operand unless the first is strictly smaller/larger:
    // exactly the one-lane `a < b ? a : b` and `a > b ? a : b`, NaN and signed zeros included.
    #[inline(always)]
    fn min(self, other: Avx4) -> Avx4 {
        self.with(self.simd.avx._mm256_min_pd(self.v, other.v))
    }
    #[inline(always)]
    fn max(self, other: Avx4) -> Avx4 {
        self.with(self.simd.avx._mm256_max_pd(self.v, other.v))
    }
    #[inline(always)]
    fn sign_one(self) -> Avx4 {
        let avx = self.simd.avx;
        let sign = avx._mm256_and_pd(self.v, avx._mm256_set1_pd(-0.0));
        self.with(avx._mm256_or_pd(sign, avx._mm256_set1_pd(1.0)))
    }
    #[inline(always)]
    fn gt_step(self, other: Avx4) -> Avx4 {
        // The sign bit of `bits(other) − bits(self)` picks 1.0 or 0.0 (`blendv` reads it).
        let (avx, avx2) = (self.simd.avx, self.simd.avx2);
        let difference = avx2._mm256_sub_epi64(
            avx._mm256_castpd_si256(other.v),
            avx._mm256_castpd_si256(self.v),
        );
        self.with(avx._mm256_blendv_pd(
            avx._mm256_setzero_pd(),
            avx._mm256_set1_pd(1.0),
            avx._mm256_castsi256_pd(difference),
        ))
    }
    #[inline(always)]
    fn quadrant(rounded: Avx4, s: Avx4, c: Avx4) -> (Avx4, Avx4) {
        let (avx, avx2) = (rounded.simd.avx, rounded.simd.avx2);
        let q = avx._mm256_castpd_si256(rounded.v);
        // Bit 0 of q (swap sine and cosine) moved to the sign bit, where `blendv` reads it.
        let swap = avx._mm256_castsi256_pd(avx2._mm256_slli_epi64::<63>(q));
        let (sin, cos) = (
            avx._mm256_blendv_pd(s.v, c.v, swap),
            avx._mm256_blendv_pd(c.v, s.v, swap),
        );
        // Bit 1 of q (resp. of q + 1) moved to the sign bit: the sign flips of sin (resp. cos).
        let sign = avx._mm256_set1_pd(-0.0);
        let flip = |bits| avx._mm256_and_pd(avx._mm256_castsi256_pd(bits), sign);
        let sin_sign = flip(avx2._mm256_slli_epi64::<62>(q));
        let plus_one = avx2._mm256_add_epi64(q, avx._mm256_set1_epi64x(1));
        let cos_sign = flip(avx2._mm256_slli_epi64::<62>(plus_one));
        (
            rounded.with(avx._mm256_xor_pd(sin, sin_sign)),
            rounded.with(avx._mm256_xor_pd(cos, cos_sign)),
        )
    }
}

impl Width<4> for Avx4 {
    #[inline(always)]
    fn gather(self, f: impl Fn(usize) -> f64) -> Avx4 {
        self.with(self.simd.avx._mm256_set_pd(f(3), f(2), f(1), f(0)))
    }
    #[inline(always)]
    fn lane(self, k: usize) -> f64 {
        self.lanes()[k]
    }
}
