//! Eight `f64` lanes in one AVX-512 register, for x86-64 processors that have AVX-512 (F, DQ and
//! the rest of `pulp`'s x86-64-v4 level; detected at run time by [`Avx8::detect`]). The same
//! construction as `avx.rs`, whose notes apply: explicit instructions behind `pulp`'s feature
//! token, each the IEEE operation of the one-lane code, so eight lanes give bit for bit what one
//! lane gives. Sign-bit selections use AVX-512's mask registers instead of `blendv`.

use core::arch::x86_64::__m512d;
use std::ops::{Add, Div, Mul, Neg, Sub};

use pulp::x86::V4;

use super::real::{vectorize, LanesOp, Real, Width};

/// Eight lanes on AVX-512, with the token that proves the processor has it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx8 {
    simd: V4,
    v: __m512d,
}

impl Avx8 {
    /// Eight zero lanes, or `None` when the processor lacks AVX-512.
    #[inline]
    pub fn detect() -> Option<Avx8> {
        V4::try_new().map(|simd| Avx8 {
            simd,
            v: simd.avx512f._mm512_setzero_pd(),
        })
    }

    /// Runs `op` on eight lanes, compiled for AVX-512 (see `Avx4::vectorize`).
    #[inline(always)]
    pub fn vectorize<Op: LanesOp>(self, op: Op) -> Op::Output {
        vectorize(self.simd, self, op)
    }

    #[inline(always)]
    fn with(self, v: __m512d) -> Avx8 {
        Avx8 { simd: self.simd, v }
    }

    #[inline(always)]
    fn lanes(self) -> [f64; 8] {
        pulp::cast(self.v)
    }

    /// The lanes whose sign bit is set in `bits`, as a mask.
    #[inline(always)]
    fn sign_mask(self, bits: __m512d) -> u8 {
        let f = self.simd.avx512f;
        self.simd
            .avx512dq
            ._mm512_movepi64_mask(f._mm512_castpd_si512(bits))
    }
}

macro_rules! avx512_binary {
    ($($trait:ident $method:ident $op:ident),*) => {$(
        impl $trait for Avx8 {
            type Output = Avx8;
            #[inline(always)]
            fn $method(self, o: Avx8) -> Avx8 {
                self.with(self.simd.avx512f.$op(self.v, o.v))
            }
        }
    )*};
}
avx512_binary!(
    Add add _mm512_add_pd,
    Sub sub _mm512_sub_pd,
    Mul mul _mm512_mul_pd,
    Div div _mm512_div_pd
);

impl Neg for Avx8 {
    type Output = Avx8;
    #[inline(always)]
    fn neg(self) -> Avx8 {
        let (f, dq) = (self.simd.avx512f, self.simd.avx512dq);
        self.with(dq._mm512_xor_pd(self.v, f._mm512_set1_pd(-0.0)))
    }
}

impl Real for Avx8 {
    #[inline(always)]
    fn constant(self, v: f64) -> Avx8 {
        self.with(self.simd.avx512f._mm512_set1_pd(v))
    }
    #[inline(always)]
    fn all(self, f: impl Fn(f64) -> bool) -> bool {
        self.lanes().iter().fold(true, |all, &x| all & f(x))
    }
    #[inline(always)]
    fn sqrt(self) -> Avx8 {
        self.with(self.simd.avx512f._mm512_sqrt_pd(self.v))
    }
    // As `minpd`/`maxpd`: the second operand unless the first is strictly smaller/larger.
    #[inline(always)]
    fn min(self, other: Avx8) -> Avx8 {
        self.with(self.simd.avx512f._mm512_min_pd(self.v, other.v))
    }
    #[inline(always)]
    fn max(self, other: Avx8) -> Avx8 {
        self.with(self.simd.avx512f._mm512_max_pd(self.v, other.v))
    }
    #[inline(always)]
    fn sign_one(self) -> Avx8 {
        let (f, dq) = (self.simd.avx512f, self.simd.avx512dq);
        let sign = dq._mm512_and_pd(self.v, f._mm512_set1_pd(-0.0));
        self.with(dq._mm512_or_pd(sign, f._mm512_set1_pd(1.0)))
    }
    #[inline(always)]
    fn gt_step(self, other: Avx8) -> Avx8 {
        let f = self.simd.avx512f;
        let difference = f._mm512_sub_epi64(
            f._mm512_castpd_si512(other.v),
            f._mm512_castpd_si512(self.v),
        );
        let mask = self.sign_mask(f._mm512_castsi512_pd(difference));
        self.with(f._mm512_mask_blend_pd(mask, f._mm512_setzero_pd(), f._mm512_set1_pd(1.0)))
    }
    #[inline(always)]
    fn quadrant(rounded: Avx8, s: Avx8, c: Avx8) -> (Avx8, Avx8) {
        let (f, dq) = (rounded.simd.avx512f, rounded.simd.avx512dq);
        let q = f._mm512_castpd_si512(rounded.v);
        // Bit 0 of q: swap sine and cosine.
        let swap = rounded.sign_mask(f._mm512_castsi512_pd(f._mm512_slli_epi64::<63>(q)));
        let (sin, cos) = (
            f._mm512_mask_blend_pd(swap, s.v, c.v),
            f._mm512_mask_blend_pd(swap, c.v, s.v),
        );
        // Bit 1 of q (resp. of q + 1) moved to the sign bit: the sign flips of sin (resp. cos).
        let sign = f._mm512_set1_pd(-0.0);
        let flip = |bits| dq._mm512_and_pd(f._mm512_castsi512_pd(bits), sign);
        let sin_sign = flip(f._mm512_slli_epi64::<62>(q));
        let plus_one = f._mm512_add_epi64(q, f._mm512_set1_epi64(1));
        let cos_sign = flip(f._mm512_slli_epi64::<62>(plus_one));
        (
            rounded.with(dq._mm512_xor_pd(sin, sin_sign)),
            rounded.with(dq._mm512_xor_pd(cos, cos_sign)),
        )
    }
}

impl Width<8> for Avx8 {
    #[inline(always)]
    fn gather(self, f: impl Fn(usize) -> f64) -> Avx8 {
        let lanes: [f64; 8] = std::array::from_fn(f);
        self.with(pulp::cast(lanes))
    }
    #[inline(always)]
    fn lane(self, k: usize) -> f64 {
        self.lanes()[k]
    }
    // Rows of four into lanes in whole registers: each pair of rows is one 512-bit register
    // (two 256-bit loads and an insert), and eight shuffles transpose the four registers: 12
    // shuffles in all, where the default's `gather` of each entry loads and inserts the 32
    // numbers one or two at a time (about 40 instructions). The same numbers in the same lanes.
    #[inline(always)]
    fn rows4(self, row: impl Fn(usize) -> [f64; 4]) -> [Avx8; 4] {
        let f = self.simd.avx512f;
        let half = |k: usize| -> core::arch::x86_64::__m256d { pulp::cast(row(k)) };
        let pair = |k: usize, l: usize| {
            f._mm512_insertf64x4::<1>(f._mm512_castpd256_pd512(half(k)), half(l))
        };
        // z = [row k | row l]; after unpacking t0 = [x0 x1 z0 z1 | x2 x3 z2 z3], t1 likewise
        // with y and w, t2 and t3 with rows 4 to 7; the 128-bit blocks 0 and 2 (or 1 and 3) of
        // a pair of them are then one entry of all eight rows, in order.
        let (z0, z1, z2, z3) = (pair(0, 2), pair(1, 3), pair(4, 6), pair(5, 7));
        let (t0, t1) = (f._mm512_unpacklo_pd(z0, z1), f._mm512_unpackhi_pd(z0, z1));
        let (t2, t3) = (f._mm512_unpacklo_pd(z2, z3), f._mm512_unpackhi_pd(z2, z3));
        [
            f._mm512_shuffle_f64x2::<0x88>(t0, t2),
            f._mm512_shuffle_f64x2::<0x88>(t1, t3),
            f._mm512_shuffle_f64x2::<0xDD>(t0, t2),
            f._mm512_shuffle_f64x2::<0xDD>(t1, t3),
        ]
        .map(|v| self.with(v))
    }
}
