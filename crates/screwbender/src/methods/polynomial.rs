//! Polynomial bases used by the methods: Bernstein (Bézier) evaluation with two derivatives, and
//! the cubic Hermite basis with three derivatives.
//!
//! Everything is generic over the coefficient type (`f64`, [`glam::DVec3`], and [`glam::DQuat`]
//! used as a point of R⁴), which only needs to be a vector space over `f64`.

use std::ops::{Add, Mul, Sub};

/// A vector space over `f64`: what the bases below need of their coefficients.
pub trait Vector: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self> {}

impl<T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T>> Vector for T {}

/// Value, first and second derivative (with respect to `t`) of the Bézier curve with the `K`
/// control points `c` (degree `K − 1 ≥ 1`) at `t`, by de Casteljau's algorithm.
///
/// After `K − 3` de Casteljau steps the three remaining points `r₀, r₁, r₂` give the value
/// `(1−t)²r₀ + 2t(1−t)r₁ + t²r₂`, the derivative `N((1−t)(r₁−r₀) + t(r₂−r₁))` and the second
/// derivative `N(N−1)(r₂ − 2r₁ + r₀)` with `N = K − 1`.
///
/// `K = 1` is the constant curve; `K = 0` does not compile.
pub fn bezier_d2<T: Vector, const K: usize>(c: &[T; K], t: f64) -> (T, T, T) {
    const { assert!(K >= 1, "a Bézier curve needs at least one control point") };
    if K == 1 {
        let zero = c[0] * 0.0;
        return (c[0], zero, zero);
    }
    if K == 2 {
        let d = c[1] - c[0];
        return (c[0] + d * t, d, d * 0.0);
    }
    let mut b = *c;
    let s = 1.0 - t;
    for level in 0..K - 3 {
        for k in 0..K - 1 - level {
            b[k] = b[k] * s + b[k + 1] * t;
        }
    }
    let (r0, r1, r2) = (b[0], b[1], b[2]);
    let n = (K - 1) as f64;
    let value = r0 * (s * s) + r1 * (2.0 * s * t) + r2 * (t * t);
    let d1 = ((r1 - r0) * s + (r2 - r1) * t) * n;
    let d2 = (r2 - r1 - (r1 - r0)) * (n * (n - 1.0));
    (value, d1, d2)
}

/// The value of the Bézier curve with control points `c` at `t` (de Casteljau).
pub fn bezier<T: Vector, const K: usize>(c: &[T; K], t: f64) -> T {
    bezier_d2(c, t).0
}

/// The cubic Hermite basis in power form: `HERMITE_POWER[k] = [c₀, c₁, c₂, c₃]` with
/// `H_k(s) = c₀ + c₁ s + c₂ s² + c₃ s³` (the polynomials of [`hermite_basis`]).
pub(crate) const HERMITE_POWER: [[f64; 4]; 4] = [
    [1.0, 0.0, -3.0, 2.0],
    [0.0, 1.0, -2.0, 1.0],
    [0.0, 0.0, 3.0, -2.0],
    [0.0, 0.0, -1.0, 1.0],
];

/// The cubic Hermite basis `[H0, H1, H2, H3]` at `s ∈ [0, 1]` and its first three derivatives
/// (docs/math/quaternion-splines.md §3):
///
/// ```text
/// H0 = 2s³ − 3s² + 1   H1 = s³ − 2s² + s   H2 = −2s³ + 3s²   H3 = s³ − s²
/// ```
///
/// `q(s) = H0 p₀ + H1 Δm₀ + H2 p₁ + H3 Δm₁` interpolates positions `p` and velocities `m` over a
/// piece of duration `Δ`.
pub fn hermite_basis(s: f64) -> [[f64; 4]; 4] {
    let s2 = s * s;
    let s3 = s2 * s;
    [
        [
            2.0 * s3 - 3.0 * s2 + 1.0,
            s3 - 2.0 * s2 + s,
            -2.0 * s3 + 3.0 * s2,
            s3 - s2,
        ],
        [
            6.0 * s2 - 6.0 * s,
            3.0 * s2 - 4.0 * s + 1.0,
            -6.0 * s2 + 6.0 * s,
            3.0 * s2 - 2.0 * s,
        ],
        [
            12.0 * s - 6.0,
            6.0 * s - 4.0,
            -12.0 * s + 6.0,
            6.0 * s - 2.0,
        ],
        [12.0, 6.0, -12.0, 6.0],
    ]
}

/// Value and first three time derivatives of the cubic Hermite piece from `(p0, m0)` to
/// `(p1, m1)` of duration `dt` at local fraction `s` (derivatives with respect to time, i.e.
/// divided by `dt`, `dt²`, `dt³`).
pub fn hermite_d3<T: Vector>(p0: T, m0: T, p1: T, m1: T, dt: f64, s: f64) -> [T; 4] {
    let h = hermite_basis(s);
    let c = [p0, m0 * dt, p1, m1 * dt];
    let mut out = [p0; 4];
    let mut scale = 1.0;
    for (k, hk) in h.iter().enumerate() {
        out[k] = (c[0] * hk[0] + c[1] * hk[1] + c[2] * hk[2] + c[3] * hk[3]) * scale;
        scale /= dt;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bezier_matches_power_form() {
        // (1−t)⁴·1 + 4t(1−t)³·2 + 6t²(1−t)²·0 + 4t³(1−t)·(−1) + t⁴·3
        let c = [1.0, 2.0, 0.0, -1.0, 3.0];
        let f = |t: f64| {
            let s = 1.0 - t;
            s.powi(4) + 8.0 * t * s.powi(3) - 4.0 * t.powi(3) * s + 3.0 * t.powi(4)
        };
        for t in [0.0, 0.3, 0.77, 1.0] {
            let (v, d1, d2) = bezier_d2(&c, t);
            let h = 1e-5;
            assert!((v - f(t)).abs() < 1e-14);
            assert!((d1 - (f(t + h) - f(t - h)) / (2.0 * h)).abs() < 1e-8);
            assert!((d2 - (f(t + h) - 2.0 * f(t) + f(t - h)) / (h * h)).abs() < 1e-4);
        }
        let (v, d1, d2) = bezier_d2(&[2.0, 5.0], 0.25);
        assert_eq!((v, d1, d2), (2.75, 3.0, 0.0));
        let (v, d1, d2) = bezier_d2(&[1.0, 0.0, 1.0], 0.5);
        assert_eq!((v, d1, d2), (0.5, 0.0, 4.0));
    }

    #[test]
    fn hermite_power_form_is_the_basis() {
        // Dyadic fractions: every product and sum below is exact, so the two forms agree bit
        // for bit, and so do their second derivatives (2c₂ + 6c₃ s).
        for s in [0.0, 0.125, 0.25, 0.5, 0.625, 0.875, 1.0] {
            let h = hermite_basis(s);
            for (k, c) in HERMITE_POWER.iter().enumerate() {
                assert_eq!(
                    c[0] + s * (c[1] + s * (c[2] + s * c[3])),
                    h[0][k],
                    "H{k}({s})"
                );
                assert_eq!(2.0 * c[2] + 6.0 * c[3] * s, h[2][k], "H{k}''({s})");
            }
        }
    }

    #[test]
    fn hermite_interpolates_ends() {
        let [q, q1, _, _] = hermite_d3(1.0, 2.0, 5.0, -1.0, 0.5, 0.0);
        assert!((q - 1.0).abs() < 1e-15 && (q1 - 2.0).abs() < 1e-15);
        let [q, q1, _, q3] = hermite_d3(1.0, 2.0, 5.0, -1.0, 0.5, 1.0);
        assert!((q - 5.0).abs() < 1e-15 && (q1 + 1.0).abs() < 1e-14);
        // third derivative of the cubic: (12 p0 + 6 Δm0 − 12 p1 + 6 Δm1)/Δ³
        assert!((q3 - (12.0 + 6.0 * 1.0 - 60.0 - 3.0) / 0.125).abs() < 1e-12);
    }
}
