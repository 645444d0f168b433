//! Sine/cosine and arctangent kernels for the screw hot path.
//!
//! A screw evaluation needs one `atan` (its half angle) and one `sin_cos` (of `t` times it); with
//! the platform's general-purpose routines these were over a third of a screw's cost. The
//! arguments here are tame (`atan` of a ratio in `[0, 1]`; `sin_cos` of a few radians), so short
//! polynomials (evaluated by Estrin's scheme, for a short dependency chain) after one exact
//! range reduction reach the same accuracy — within 3 ulp of the
//! correctly rounded result, checked against `std` in the tests — in a fraction of the time.
//! Arguments outside the fast range go to `std`. (Plain multiply-adds, not `mul_add`: without
//! a hardware FMA target feature, and on wasm32, `mul_add` is a slow library call.)

use std::f64::consts::{FRAC_PI_2, FRAC_PI_6};

use super::real::Real;

/// `|x|` up to which [`sin_cos`] reduces by multiples of π/2 itself (the reduction below is
/// exact for `|k| < 2²⁷`, far beyond this); larger arguments use `f64::sin_cos`.
const FAST_SIN_COS_LIMIT: f64 = 1.0e5;

/// π/2 split into a high part with 27 trailing zero bits (so `k · PIO2_HI` is exact for
/// `|k| < 2²⁷`) and the rest. `FRAC_PI_2 − PIO2_HI` is exact; the true π/2 exceeds `FRAC_PI_2`
/// by 6.123233995736766e-17.
const PIO2_HI: f64 = f64::from_bits(FRAC_PI_2.to_bits() & 0xFFFF_FFFF_F800_0000);
const PIO2_LO: f64 = (FRAC_PI_2 - PIO2_HI) + 6.123_233_995_736_766e-17;

/// Taylor coefficients `(−1)^k / (2k+1)!` and `(−1)^k / (2k)!`: on `|r| ≤ π/4` the first omitted
/// terms are below 1e-19, far under half an ulp.
const SIN: [f64; 8] = [
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];
const COS: [f64; 8] = [
    -1.0 / 2.0,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
];

/// `1.5 · 2⁵²`: adding and subtracting it rounds any `|y| < 2⁵¹` to the nearest integer (ties
/// to even) in the current rounding mode, without the library call `f64::round` compiles to on
/// x86-64 targets without SSE4.1.
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// `(sin x, cos x)`: [`sin_cos_kernel_one`] for `|x| ≤ 10⁵`, `std` beyond (and for NaN).
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if !in_sin_cos_range(x) {
        return x.sin_cos();
    }
    sin_cos_kernel_one(x)
}

/// `|x|` up to which `x · 2/π` is below ½ in magnitude, so that [`sin_cos_kernel`] rounds it to
/// the quadrant `k = 0`, reduces to exactly `r = x` and leaves the quadrant step unchanged.
const NO_REDUCTION_LIMIT: f64 = 0.78;

/// [`sin_cos_kernel`] on one `f64`, bit for bit, natively [`sin_cos_kernel_lanes`] on its one
/// lane: a branch around the reduction where it is the identity (`|x| ≤ 0.78`, about π/4): the series start without waiting for the
/// reduction's six dependent operations (18 cycles of a one-at-a-time screw's chain). Unlike the
/// quadrant, this branch is predictable: `tθ/2` stays below 0.78 for spans up to 89° at
/// `t ∈ [0, 1]`, and for most evaluations of larger ones. (Generic over the lanes only so that
/// the kernel's one body can name it; its callers pass one `f64`.)
#[inline(always)]
pub(crate) fn sin_cos_kernel_one<R: Real>(x: R) -> (R, R) {
    // Not on wasm32: the second copy of the series would add about 260 bytes gzip to the math
    // module, whose size is budgeted.
    if cfg!(target_arch = "wasm32") {
        sin_cos_kernel(x)
    } else {
        sin_cos_kernel_lanes(x)
    }
}

/// Whether [`sin_cos_kernel`] applies to `x` (false for NaN).
#[inline]
pub(crate) fn in_sin_cos_range(x: f64) -> bool {
    x.abs() <= FAST_SIN_COS_LIMIT
}

/// `(sin x, cos x)` for `|x| ≤ 10⁵`, on one or two lanes, without a branch: an exact reduction
/// by the nearest multiple `k` of π/2, two short series, then the quadrant `k mod 4` only swaps
/// and negates them, done with bit operations (the quadrant of `tθ/2` changes from one screw to
/// the next when `t` leaves `[0, 1]`, and a branch on it would be mispredicted half the time).
#[inline(always)]
pub(crate) fn sin_cos_kernel<R: Real>(x: R) -> (R, R) {
    let rounded = x * x.constant(std::f64::consts::FRAC_2_PI) + x.constant(ROUND_MAGIC);
    let k = rounded - rounded.constant(ROUND_MAGIC);
    let r = (x - k * k.constant(PIO2_HI)) - k * k.constant(PIO2_LO);
    let (s, c) = sin_cos_series(r);
    R::quadrant(rounded, s, c)
}

/// [`sin_cos_kernel`] on lanes, bit for bit, straight to the series when every lane is within
/// [`NO_REDUCTION_LIMIT`] (as [`sin_cos_kernel_one`] does for one `f64`): there the reduction
/// is the identity and the quadrant step changes nothing. In a subdivision's finer levels every
/// span is short, so every group goes this way, and the branch is predictable; for the batch's
/// random pairs at `t = 0.3`, too (`|tθ/2| ≤ 0.3·π/2`). Unlike the one-`f64` route, on wasm32
/// too, where with the append that needs no growth call (`screw/batch.rs`) it shortens the
/// subdivisions (`benches/wasm/compare.mjs`) for the small price of a second copy of the series.
#[inline(always)]
pub(crate) fn sin_cos_kernel_lanes<R: Real>(x: R) -> (R, R) {
    if x.all(|v| v.abs() <= NO_REDUCTION_LIMIT) {
        sin_cos_series(x)
    } else {
        sin_cos_kernel(x)
    }
}

/// The two series of [`sin_cos_kernel`] on the reduced argument `r` (`|r| ≤ π/4`).
#[inline(always)]
fn sin_cos_series<R: Real>(r: R) -> (R, R) {
    let r2 = r * r;
    let s = r + r * r2 * estrin8(r2, &SIN);
    let c = r2.constant(1.0) + r2 * estrin8(r2, &COS);
    (s, c)
}

/// `tan(π/12)`: beyond it [`atan_ratio`] shifts the argument by π/6.
const TAN_PI_12: f64 = 0.267_949_192_431_122_7;
/// `√3`.
const SQRT_3: f64 = 1.732_050_807_568_877_2;
/// Taylor coefficients `(−1)^k / (2k+1)` of `atan y = y + y³·P(y²)`; on `|y| ≤ tan(π/12)` the
/// first omitted term is below 1e-19.
const ATAN: [f64; 15] = [
    -1.0 / 3.0,
    1.0 / 5.0,
    -1.0 / 7.0,
    1.0 / 9.0,
    -1.0 / 11.0,
    1.0 / 13.0,
    -1.0 / 15.0,
    1.0 / 17.0,
    -1.0 / 19.0,
    1.0 / 21.0,
    -1.0 / 23.0,
    1.0 / 25.0,
    -1.0 / 27.0,
    1.0 / 29.0,
    -1.0 / 31.0,
];

/// `atan2(y, x)` for `y ≥ 0`, `x ≥ 0`, not both zero (an angle in `[0, π/2]`): the branch-free
/// [`atan2_kernel`] when both are finite, `std` otherwise.
#[inline]
pub(crate) fn atan2_quadrant(y: f64, x: f64) -> f64 {
    if !in_atan2_range(y, x) {
        return y.atan2(x);
    }
    atan2_kernel(y, x)
}

/// Whether [`atan2_kernel`] applies to `(y, x)` (false for NaN).
#[inline]
pub(crate) fn in_atan2_range(y: f64, x: f64) -> bool {
    y >= 0.0 && x >= 0.0 && (y > 0.0 || x > 0.0) && y < f64::INFINITY && x < f64::INFINITY
}

/// `atan2(y, x)` for finite `y ≥ 0`, `x ≥ 0`, not both zero, on one or two lanes, without a
/// branch.
///
/// The smaller of the two over the larger is in `[0, 1]`; beyond `tan(π/12)` the identity
/// `atan(n/d) = π/6 + atan((n√3 − d)/(n + d√3))` brings it within `tan(π/12)` of zero, where
/// the series converges fast. Both choices (which octant, whether to shift) are `0`/`1` steps
/// that weight the two cases exactly, not branches: the angle of one screw tells nothing about
/// the next one's (and compilers turn plain selects that guard a division back into branches).
#[inline(always)]
pub(crate) fn atan2_kernel<R: Real>(y: R, x: R) -> R {
    let one = y.constant(1.0);
    let (y, x) = (plus_zero(y), plus_zero(x));
    let (n, d) = (y.min(x), y.max(x));
    // shift = 1: (n√3 − d)/(n + d√3) and π/6; shift = 0: n/d and 0. `√3 − 1` and `1 + (√3 − 1)`
    // are exact, so both cases are computed with exactly the roundings of their own formula.
    let shift = n.gt_step(d * d.constant(TAN_PI_12));
    let root = one + shift * shift.constant(SQRT_3 - 1.0);
    let z = (n * root - d * shift) / (n * shift + d * root);
    let angle = shift * shift.constant(FRAC_PI_6) + atan_series(z);
    // Above the diagonal the angle is π/2 minus that of the mirrored point.
    let steep = y.gt_step(x);
    steep * steep.constant(FRAC_PI_2) + (one - steep - steep) * angle
}

/// [`atan2_kernel`] on lanes, bit for bit, straight to `y/x` and the series when no lane needs
/// either step (`y ≤ x·tan(π/12)` in every lane: angles up to 15°, spans up to 30°). There both
/// `0`/`1` steps are `0`, and the kernel's formula reduces exactly: `1 + 0·(√3 − 1) = 1`,
/// `(n·1 − d·0)/(n·0 + d·1) = n/d` with `n = y`, `d = x`, and adding `0·π/6` or `0·π/2` to the
/// non-negative angle, or multiplying it by `1 − 0 − 0`, changes no bit. In a subdivision's
/// finer levels every span is short, so every group goes this way (the branch is predictable),
/// and the quotient starts without waiting for the min/max and the shift test. `x·tan(π/12) − y`
/// is the kernel's own comparison: its sign is that of `fl(x·tan(π/12)) − y`.
#[inline(always)]
pub(crate) fn atan2_kernel_lanes<R: Real>(y: R, x: R) -> R {
    if (x * x.constant(TAN_PI_12) - y).all(|m| m >= 0.0) {
        atan_series(plus_zero(y) / plus_zero(x))
    } else {
        atan2_kernel(y, x)
    }
}

/// `y + 0`: −0 becomes +0 (whose bit pattern `gt_step` needs), every other value stays.
#[inline(always)]
fn plus_zero<R: Real>(y: R) -> R {
    y + y.constant(0.0)
}

/// `atan(z)` for `|z| ≤ tan(π/12)` by its series: the arctangent kernels' last step, shared so
/// that the shortcut and the kernel keep the same operations in the same order.
#[inline(always)]
fn atan_series<R: Real>(z: R) -> R {
    let z2 = z * z;
    z + z * z2 * estrin15(z2, &ATAN)
}

/// `Σ c[i] xⁱ` for 8 coefficients by Estrin's scheme: the same terms as Horner's rule but a
/// dependency chain of depth 3 instead of 8 (the polynomials sit on the screw's critical path).
#[inline(always)]
fn estrin8<R: Real>(x: R, c: &[f64; 8]) -> R {
    let k = |i: usize| x.constant(c[i]);
    let x2 = x * x;
    let x4 = x2 * x2;
    let a = (k(0) + k(1) * x) + (k(2) + k(3) * x) * x2;
    let b = (k(4) + k(5) * x) + (k(6) + k(7) * x) * x2;
    a + b * x4
}

/// `Σ c[i] xⁱ` for 15 coefficients by Estrin's scheme (depth 4 instead of 15).
#[inline(always)]
fn estrin15<R: Real>(x: R, c: &[f64; 15]) -> R {
    let k = |i: usize| x.constant(c[i]);
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let a = (k(0) + k(1) * x) + (k(2) + k(3) * x) * x2;
    let b = (k(4) + k(5) * x) + (k(6) + k(7) * x) * x2;
    let d = (k(8) + k(9) * x) + (k(10) + k(11) * x) * x2;
    let e = (k(12) + k(13) * x) + k(14) * x2;
    (a + b * x4) + (d + e * x4) * x8
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Distance in units in the last place, relative to the larger magnitude.
    fn ulps(a: f64, b: f64) -> f64 {
        let scale = a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
        (a - b).abs() / (scale * f64::EPSILON)
    }

    #[test]
    fn sin_cos_matches_std() {
        let mut worst: f64 = 0.0;
        let mut x = -40.0;
        while x < 40.0 {
            let (s, c) = sin_cos(x);
            let (es, ec) = x.sin_cos();
            // Near zeros of sin/cos compare absolutely (relative ulps blow up there).
            worst = worst.max((s - es).abs().max((c - ec).abs()) / f64::EPSILON);
            x += 0.000_731;
        }
        assert!(worst <= 3.0, "worst error {worst} ulp (absolute, of 1)");
        for x in [
            0.0, -0.0, 1e-300, 1e-8, FRAC_PI_2, -FRAC_PI_2, 3.0, 1e5, 1e6, -2e7,
        ] {
            let (s, c) = sin_cos(x);
            let (es, ec) = x.sin_cos();
            assert!(
                (s - es).abs() <= 2.0 * f64::EPSILON * es.abs().max(1e-300) + 1e-300
                    || (s - es).abs() < 4e-16,
                "{x}"
            );
            assert!((c - ec).abs() < 4e-16, "{x}");
        }
        assert!(sin_cos(f64::NAN).0.is_nan());
        assert!(sin_cos(f64::INFINITY).1.is_nan());
    }

    #[test]
    fn small_angles_keep_relative_accuracy() {
        for x in [1e-15, 3e-10, 2e-6, 1e-3, 0.1] {
            let (s, _) = sin_cos(x);
            assert!(ulps(s, x.sin()) <= 1.0, "{x}");
        }
    }

    #[test]
    fn atan_matches_std() {
        let mut worst: f64 = 0.0;
        for i in 0..=200_000 {
            let x = i as f64 / 200_000.0;
            // Both octants (y ≤ x and y ≥ x), and the same angle from a scaled pair.
            worst = worst.max(ulps(atan2_quadrant(x, 1.0), x.atan()));
            worst = worst.max(ulps(atan2_quadrant(3.0 * x, 3.0), x.atan()));
            worst = worst.max(ulps(atan2_quadrant(1.0, x), 1f64.atan2(x)));
            let (s, c) = (0.7 * x).sin_cos();
            worst = worst.max(ulps(atan2_quadrant(s, c), s.atan2(c)));
        }
        assert!(worst <= 3.0, "worst error {worst} ulp");
        for x in [0.0, 1e-300, 1e-12, TAN_PI_12, 1.0] {
            assert!(ulps(atan2_quadrant(x, 1.0), x.atan()) <= 1.0, "{x}");
        }
        assert_eq!(atan2_quadrant(1.0, 0.0), FRAC_PI_2);
        assert_eq!(atan2_quadrant(1.0, -0.0), FRAC_PI_2);
        assert_eq!(atan2_quadrant(-0.0, 1.0), 0.0);
        assert_eq!(atan2_quadrant(0.0, 2.0), 0.0);
        // Outside the first quadrant: `std`.
        assert_eq!(atan2_quadrant(0.5, -1.0), 0.5f64.atan2(-1.0));
        assert_eq!(atan2_quadrant(-0.5, 1.0), (-0.5f64).atan2(1.0));
        assert!(atan2_quadrant(f64::NAN, 1.0).is_nan());
        assert!(atan2_quadrant(0.0, 0.0) == 0.0);
    }

    /// `f` gives [`sin_cos_kernel`]'s bits on both sides of [`NO_REDUCTION_LIMIT`], across it
    /// into the next quadrant, and at the edges.
    fn same_bits_as_the_kernel(f: impl Fn(f64) -> (f64, f64)) {
        let bits = |(s, c): (f64, f64)| (s.to_bits(), c.to_bits());
        let same = |x: f64| assert_eq!(bits(f(x)), bits(sin_cos_kernel(x)), "{x}");
        let mut x = -1.2;
        while x < 1.2 {
            same(x);
            x += 0.000_137;
        }
        let limit = NO_REDUCTION_LIMIT;
        for x in [
            0.0,
            -0.0,
            5e-324,
            -1e-300,
            1e-8,
            limit,
            -limit,
            FRAC_PI_2 / 2.0,
        ] {
            same(x);
            same(f64::from_bits(x.to_bits() + 1));
        }
    }

    #[test]
    fn the_unreduced_branch_is_the_kernel_bit_for_bit() {
        same_bits_as_the_kernel(sin_cos_kernel_one);
        assert!(sin_cos_kernel_one(f64::NAN).0.is_nan());
        // The branch is taken only where the kernel's quadrant is 0.
        let limit = NO_REDUCTION_LIMIT;
        assert!(limit * std::f64::consts::FRAC_2_PI < 0.5);
    }

    #[test]
    fn the_arctangent_shortcut_is_the_kernel_bit_for_bit() {
        let same = |y: f64, x: f64| {
            assert_eq!(
                atan2_kernel_lanes(y, x).to_bits(),
                atan2_kernel(y, x).to_bits(),
                "atan2({y}, {x})"
            )
        };
        // Ratios across both sides of the shortcut's limit and of the diagonal, at several
        // magnitudes, and the neighbours of the limit itself.
        for x in [1e-12, 0.3, 1.0, 7.5, 1e150] {
            let mut r = 0.0;
            while r < 1.5 {
                same(r * x, x);
                same(x, r * x);
                r += 0.000_173;
            }
            let edge = x * TAN_PI_12;
            for k in 0..4u64 {
                same(f64::from_bits(edge.to_bits() - k), x);
                same(f64::from_bits(edge.to_bits() + k), x);
            }
        }
        same(0.0, 1.0);
        same(5e-324, 1.0);
        // Two lanes: the shortcut only when both are within the limit; lane by lane the bits are
        // the kernel's either way.
        #[cfg(portable_lanes)]
        {
            use super::super::portable::Lanes;
            for (y, x) in [
                ([0.1, 0.2], [1.0, 1.0]),
                ([0.1, 0.9], [1.0, 1.0]),
                ([2.0, 0.01], [1.0, 3.0]),
                ([TAN_PI_12, 0.0], [1.0, 2.0]),
            ] {
                let a = atan2_kernel_lanes(Lanes(y), Lanes(x));
                for k in 0..2 {
                    assert_eq!(
                        a.0[k].to_bits(),
                        atan2_kernel(y[k], x[k]).to_bits(),
                        "{y:?}, {x:?}: lane {k}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_lanes_shortcut_is_the_kernel_bit_for_bit() {
        same_bits_as_the_kernel(sin_cos_kernel_lanes);
        // Two lanes: the shortcut only when both are within the limit; a group with one lane
        // beyond it takes the kernel. Lane by lane the bits are the kernel's either way.
        #[cfg(portable_lanes)]
        {
            use super::super::portable::Lanes;
            let bits = |(s, c): (f64, f64)| (s.to_bits(), c.to_bits());
            let limit = NO_REDUCTION_LIMIT;
            let beyond = f64::from_bits(limit.to_bits() + 1);
            for (a, b) in [
                (0.3, 0.5),
                (-0.0, 0.0),
                (limit, -limit),
                (0.3, beyond),
                (-beyond, 0.2),
                (0.7, 3.0),
                (-2.5, 40.0),
            ] {
                let (s, c) = sin_cos_kernel_lanes(Lanes([a, b]));
                for (k, x) in [a, b].into_iter().enumerate() {
                    assert_eq!(
                        bits((s.0[k], c.0[k])),
                        bits(sin_cos_kernel(x)),
                        "{a}, {b}: lane {k}"
                    );
                }
            }
        }
    }

    #[test]
    fn sin_cos_quadrants_are_exact_swaps() {
        // Every quadrant, both signs: the kernel's results swapped and negated, nothing else.
        for k in -8i32..8 {
            for f in [0.1, 0.3, 0.49] {
                let x = (k as f64 + f) * FRAC_PI_2;
                let (s, c) = sin_cos(x);
                let (es, ec) = x.sin_cos();
                assert!((s - es).abs() < 4e-16 && (c - ec).abs() < 4e-16, "{x}");
            }
        }
    }
}
