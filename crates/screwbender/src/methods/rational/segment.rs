//! The pieces every Chaudhry–Cameron motion is made of: one rational segment, and the end
//! condition that closes the C¹ recursion. Shared by the C⁰ (`c0.rs`) and C¹ (`c1.rs`) fits and
//! the motion (`mod.rs`), below all three.

use glam::{DMat3, DQuat, DVec3};
use serde::Serialize;

use crate::methods::algebra::{polar_matrix, unnormalised_matrix};
use crate::methods::polynomial::bezier_d2;

/// Smallest accepted value of the C¹ motion's denominator `w(t) = |Q(t)|²` on `[t_0, t_n]`.
///
/// The end-condition recursions never damp irregularities (docs/math/rational-motion.md §6.1), so with very uneven data the
/// middle quaternions can zig-zag and `Q(t)` pass near zero, where the rotation spins arbitrarily
/// fast. Below `1e-4` (`|Q| < 0.01` while the data have `|Q_i| = 1`) the fit is rejected.
pub const MIN_DENOMINATOR: f64 = 1e-4;

/// Which end condition closes the C¹ consistency equations (docs/math/rational-motion.md §6.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize)]
pub enum EndCondition {
    /// Eq. (18): zero second derivative at `t_0` (the first quaternion segment is straight).
    #[default]
    ZeroCurvatureStart,
    /// Eq. (19): zero second derivative at `t_n` (the last quaternion segment is straight).
    ZeroCurvatureEnd,
}

/// One segment `[t0, t1]` of a rational motion: quaternion Bézier control points, the weights of
/// the common denominator and the homogeneous translation control points `ω_k c_k`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Segment {
    pub t0: f64,
    pub t1: f64,
    /// C⁰: `[Q_i, Q_{i+1}, _]` (linear); C¹: `[Q_i, M_i, Q_{i+1}]` (quadratic).
    pub quats: [DQuat; 3],
    /// Bernstein coefficients of `w`, degree `degree` (the first `degree + 1` are used).
    pub weights: [f64; 5],
    /// Homogeneous control points `ω_k c_k` of the translation curve `a(t)`.
    pub numer: [DVec3; 5],
    /// 2 (C⁰) or 4 (C¹).
    pub degree: usize,
}

impl Segment {
    /// `Q, dQ/dτ, d²Q/dτ²`.
    pub(super) fn quat(&self, tau: f64) -> (DQuat, DQuat, DQuat) {
        if self.degree == 2 {
            bezier_d2(&[self.quats[0], self.quats[1]], tau)
        } else {
            bezier_d2(&self.quats, tau)
        }
    }

    /// `(N, N', N'')` and `(w, w', w'')` in `τ`.
    pub(super) fn homogeneous(&self, tau: f64) -> ((DVec3, DVec3, DVec3), (f64, f64, f64)) {
        if self.degree == 2 {
            let n = [self.numer[0], self.numer[1], self.numer[2]];
            let w = [self.weights[0], self.weights[1], self.weights[2]];
            (bezier_d2(&n, tau), bezier_d2(&w, tau))
        } else {
            (bezier_d2(&self.numer, tau), bezier_d2(&self.weights, tau))
        }
    }

    /// Bernstein coefficients (3×3 matrices) of `M(Q(τ))`, degree `degree`.
    pub(super) fn matrix_coefficients(&self) -> Vec<DMat3> {
        let [q0, m, q1] = self.quats;
        if self.degree == 2 {
            let q1 = m; // C⁰ stores Q_{i+1} in slot 1
            vec![
                unnormalised_matrix(q0),
                polar_matrix(q0, q1),
                unnormalised_matrix(q1),
            ]
        } else {
            vec![
                unnormalised_matrix(q0),
                polar_matrix(q0, m),
                polar_matrix(q0, q1) * (1.0 / 3.0) + unnormalised_matrix(m) * (2.0 / 3.0),
                polar_matrix(m, q1),
                unnormalised_matrix(q1),
            ]
        }
    }

    /// The minimum of `w(τ) = |Q(τ)|²` over `τ ∈ [0, 1]`: the smallest Bernstein coefficient is a
    /// lower bound; when it is not conclusive, a dense sample refined by golden-section search.
    pub(super) fn min_denominator(&self) -> f64 {
        let w = &self.weights[..=self.degree];
        let lower = w.iter().fold(f64::INFINITY, |m, &v| m.min(v));
        if lower >= MIN_DENOMINATOR {
            return lower;
        }
        let f = |tau: f64| self.quat(tau).0.length_squared();
        /// Dense samples of the quartic `w(τ)` before refining its minimum.
        const SAMPLES: usize = 256;
        /// Golden-section steps: the bracket shrinks by 0.618⁶⁰ ≈ 3e-13.
        const GOLDEN_STEPS: usize = 60;
        let (mut best, mut best_v) = (0.0, f(0.0));
        for k in 1..=SAMPLES {
            let tau = k as f64 / SAMPLES as f64;
            let v = f(tau);
            if v < best_v {
                best = tau;
                best_v = v;
            }
        }
        let step = 1.0 / SAMPLES as f64;
        let (mut lo, mut hi) = ((best - step).max(0.0), (best + step).min(1.0));
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..GOLDEN_STEPS {
            let (c, d) = (hi - g * (hi - lo), lo + g * (hi - lo));
            if f(c) < f(d) {
                hi = d;
            } else {
                lo = c;
            }
        }
        best_v.min(f(0.5 * (lo + hi)))
    }
}
