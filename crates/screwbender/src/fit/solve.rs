//! Levenberg–Marquardt over the control poses (Nocedal & Wright, *Numerical Optimization*, §10.3):
//! each control pose moves by a body increment `δ = [ω, v]` ([`retract`]), the normal equations
//! `(JᵀWJ + λ diag) δ = −JᵀWr` are block-banded (a sample on span `j` touches control poses
//! `j − 1 … j + 2`, so blocks at most 3 apart meet: half-bandwidth 23) and solved banded.
//!
//! The Jacobian is taken by forward differences through the real motion ([`Model`]): one control
//! pose perturbed at a time, only the samples of the spans it reaches re-evaluated. For the
//! ScrewBender motion this is the only way to differentiate what the subdivision produces; for
//! the SE(3) spline it keeps both motions on one code path, at 24 evaluations per sample.
//!
//! Objective, for `N` samples with residuals `r_i` ([`residual`]) and `m` control poses:
//!
//! ```text
//! F = (1/N) Σ_i ρ(|r_i|²)  +  (W / (m − 2)) Σ_{k=1}^{m−2} |σ_k|²,
//! σ_k = log(C_k⁻¹ C_{k+1}) − log(C_{k−1}⁻¹ C_k)     (angular part times the radius)
//! ```
//!
//! The smoothness term is the second difference of the control poses in the group: zero when
//! consecutive control poses step by the same screw, so it pulls towards a helix, not towards
//! standing still.

use super::banded::BandMatrix;
use super::loss::RobustLoss;
use super::model::{FitMethod, Model};
use super::residual::{residual, retract};
use crate::error::Error;
use crate::methods::{LieGroup, Se3};
use crate::pose::Pose;

/// Half-bandwidth of the normal equations: 4 control poses × 6 coordinates, minus 1.
const BANDWIDTH: usize = 23;
/// Forward-difference step of the rotation coordinates (radians) and, times the scene's size,
/// of the translation ones: near the square root of the machine epsilon.
const DIFF_STEP: f64 = 1e-7;
/// Stop when an accepted step lowers the objective by less than this fraction of it.
const RELATIVE_DECREASE: f64 = 1e-10;
/// The damping gives up beyond this (no step lowers the objective: a minimum to round-off).
const MAX_DAMPING: f64 = 1e10;

/// The fixed data of a fit: measured poses, their parameters, and the weights.
pub(crate) struct Problem<'a> {
    pub(crate) method: FitMethod,
    pub(crate) samples: &'a [Pose],
    /// `u_i`, nondecreasing, in `[0, m − 1]`.
    pub(crate) params: Vec<f64>,
    /// `span_start[j]..span_start[j + 1]` are the samples on span `j`.
    pub(crate) span_start: Vec<usize>,
    pub(crate) radius: f64,
    pub(crate) smoothness: f64,
    /// Largest origin coordinate (at least 1): scales the translation steps.
    pub(crate) size: f64,
}

impl<'a> Problem<'a> {
    /// The problem of fitting `m` control poses to `samples` at normalised times `s_i ∈ [0, 1]`.
    pub(crate) fn new(
        method: FitMethod,
        samples: &'a [Pose],
        fractions: &[f64],
        m: usize,
        radius: f64,
        smoothness: f64,
    ) -> Problem<'a> {
        let spans = m - 1;
        let params: Vec<f64> = fractions.iter().map(|s| s * spans as f64).collect();
        // Span j holds the samples with j ≤ u < j + 1; the last span also the end, u = m − 1.
        let mut span_start = Vec::with_capacity(spans + 1);
        span_start.push(0);
        for j in 1..spans {
            span_start.push(params.partition_point(|&u| u < j as f64));
        }
        span_start.push(params.len());
        let size = samples
            .iter()
            .fold(1.0f64, |s, p| s.max(p.origin.abs().max_element()));
        Problem {
            method,
            samples,
            params,
            span_start,
            radius,
            smoothness,
            size,
        }
    }

    fn controls(&self) -> usize {
        self.span_start.len()
    }

    /// Residuals of every sample against `model`.
    pub(crate) fn residuals(&self, model: &Model) -> Vec<[f64; 6]> {
        self.params
            .iter()
            .zip(self.samples)
            .map(|(&u, p)| residual(&model.pose_at(u), p, self.radius))
            .collect()
    }

    /// The smoothness residuals `σ_k` (unweighted), `k = 1 … m − 2`.
    fn smoothness_residuals(&self, controls: &[Pose]) -> Vec<[f64; 6]> {
        (1..controls.len().saturating_sub(1))
            .map(|k| self.second_difference(&controls[k - 1], &controls[k], &controls[k + 1]))
            .collect()
    }

    fn second_difference(&self, a: &Pose, b: &Pose, c: &Pose) -> [f64; 6] {
        let t1 = Se3::twist(&Se3::segment(a, b));
        let t2 = Se3::twist(&Se3::segment(b, c));
        let (w, v) = (
            (t2.angular - t1.angular) * self.radius,
            t2.linear - t1.linear,
        );
        [v.x, v.y, v.z, w.x, w.y, w.z]
    }

    fn smoothness_weight(&self, m: usize) -> f64 {
        if m > 2 {
            self.smoothness / (m - 2) as f64
        } else {
            0.0
        }
    }

    /// The objective `F` (see the module documentation).
    pub(crate) fn objective(
        &self,
        residuals: &[[f64; 6]],
        controls: &[Pose],
        loss: RobustLoss,
        delta: f64,
    ) -> f64 {
        let data: f64 = residuals.iter().map(|r| loss.rho(norm2(r), delta)).sum();
        let ws = self.smoothness_weight(controls.len());
        let smooth: f64 = if ws > 0.0 {
            self.smoothness_residuals(controls).iter().map(norm2).sum()
        } else {
            0.0
        };
        data / self.samples.len() as f64 + ws * smooth
    }

    fn step(&self, d: usize) -> f64 {
        if d < 3 {
            DIFF_STEP
        } else {
            DIFF_STEP * self.size
        }
    }

    /// The normal equations `JᵀWJ` and `JᵀWr` at `controls` (`model` built from them).
    fn normal_equations(
        &self,
        model: &mut Model,
        controls: &[Pose],
        residuals: &[[f64; 6]],
        loss: RobustLoss,
        delta: f64,
    ) -> (BandMatrix, Vec<f64>) {
        let m = controls.len();
        let mut h = BandMatrix::zeros(6 * m, BANDWIDTH);
        let mut g = vec![0.0; 6 * m];
        let data_weight = 1.0 / self.samples.len() as f64;
        let mut jac: Vec<[[f64; 24]; 6]> = Vec::new();
        let mut unit = [0.0; 6];
        for j in 0..m - 1 {
            let range = self.span_start[j]..self.span_start[j + 1];
            if range.is_empty() {
                continue;
            }
            jac.clear();
            jac.resize(range.len(), [[0.0; 24]; 6]);
            let first = j as isize - 1;
            let slots: Vec<(usize, usize)> = (0..4)
                .filter_map(|a| {
                    let k = first + a as isize;
                    (k >= 0 && (k as usize) < m).then_some((a, k as usize))
                })
                .collect();
            for &(a, k) in &slots {
                for d in 0..6 {
                    let step = self.step(d);
                    unit[d] = step;
                    model.set_control_pose(k, retract(&controls[k], &unit));
                    unit[d] = 0.0;
                    for (s, i) in range.clone().enumerate() {
                        let r = residual(
                            &model.pose_at(self.params[i]),
                            &self.samples[i],
                            self.radius,
                        );
                        for row in 0..6 {
                            jac[s][row][a * 6 + d] = (r[row] - residuals[i][row]) / step;
                        }
                    }
                }
                model.set_control_pose(k, controls[k]);
            }
            for (s, i) in range.enumerate() {
                let w = data_weight * loss.weight(norm2(&residuals[i]), delta);
                let jb = &jac[s];
                for &(a1, k1) in &slots {
                    for d1 in 0..6 {
                        let c1 = a1 * 6 + d1;
                        let g1 = 6 * k1 + d1;
                        let mut gr = 0.0;
                        for row in 0..6 {
                            gr += jb[row][c1] * residuals[i][row];
                        }
                        g[g1] += w * gr;
                        for &(a2, k2) in slots.iter().filter(|s| s.0 <= a1) {
                            let dmax = if a2 == a1 { d1 + 1 } else { 6 };
                            for d2 in 0..dmax {
                                let c2 = a2 * 6 + d2;
                                let sum: f64 = jb.iter().map(|row| row[c1] * row[c2]).sum();
                                h.add(g1, 6 * k2 + d2, w * sum);
                            }
                        }
                    }
                }
            }
        }
        self.add_smoothness(controls, &mut h, &mut g);
        (h, g)
    }

    /// Adds the smoothness term's Gauss–Newton blocks (each `σ_k` touches three control poses).
    fn add_smoothness(&self, controls: &[Pose], h: &mut BandMatrix, g: &mut [f64]) {
        let m = controls.len();
        let ws = self.smoothness_weight(m);
        if ws <= 0.0 {
            return;
        }
        let mut unit = [0.0; 6];
        for k in 1..m - 1 {
            let base = self.second_difference(&controls[k - 1], &controls[k], &controls[k + 1]);
            let mut jb = [[0.0; 18]; 6];
            for a in 0..3 {
                for d in 0..6 {
                    let step = self.step(d);
                    unit[d] = step;
                    let mut c = [controls[k - 1], controls[k], controls[k + 1]];
                    c[a] = retract(&c[a], &unit);
                    unit[d] = 0.0;
                    let r = self.second_difference(&c[0], &c[1], &c[2]);
                    for row in 0..6 {
                        jb[row][a * 6 + d] = (r[row] - base[row]) / step;
                    }
                }
            }
            let offset = 6 * (k - 1);
            for c1 in 0..18 {
                let mut gr = 0.0;
                for row in 0..6 {
                    gr += jb[row][c1] * base[row];
                }
                g[offset + c1] += ws * gr;
                for c2 in 0..=c1 {
                    let sum: f64 = jb.iter().map(|row| row[c1] * row[c2]).sum();
                    h.add(offset + c1, offset + c2, ws * sum);
                }
            }
        }
    }

    /// Levenberg–Marquardt from `controls` with `loss` at scale `delta`, at most `max_iterations`
    /// Jacobians. Returns the control poses, the motion built from them and the iterations taken.
    pub(crate) fn solve(
        &self,
        mut controls: Vec<Pose>,
        loss: RobustLoss,
        delta: f64,
        max_iterations: usize,
    ) -> Result<(Vec<Pose>, Model, usize), Error> {
        debug_assert_eq!(controls.len(), self.controls());
        let mut model = Model::build(self.method, &controls)?;
        let mut residuals = self.residuals(&model);
        let mut cost = self.objective(&residuals, &controls, loss, delta);
        let mut lambda = 1e-4;
        let mut iterations = 0;
        while iterations < max_iterations && cost > 0.0 {
            iterations += 1;
            let (h, g) = self.normal_equations(&mut model, &controls, &residuals, loss, delta);
            let n = h.len();
            let mean_diagonal = (0..n).map(|i| h.diagonal(i)).sum::<f64>() / n as f64;
            let floor = 1e-9 * mean_diagonal.max(f64::MIN_POSITIVE);
            let mut accepted = None;
            while lambda <= MAX_DAMPING {
                let mut damped = h.clone();
                for i in 0..n {
                    damped.add(i, i, lambda * h.diagonal(i).max(floor) + floor);
                }
                let Some(step) = damped.solve(&g) else {
                    lambda *= 10.0;
                    continue;
                };
                let trial: Vec<Pose> = controls
                    .iter()
                    .enumerate()
                    .map(|(k, c)| {
                        let d: Vec<f64> = step[6 * k..6 * k + 6].iter().map(|x| -x).collect();
                        retract(c, &d)
                    })
                    .collect();
                if let Ok(trial_model) = Model::build(self.method, &trial) {
                    let trial_residuals = self.residuals(&trial_model);
                    let trial_cost = self.objective(&trial_residuals, &trial, loss, delta);
                    if trial_cost < cost {
                        accepted = Some((trial, trial_model, trial_residuals, trial_cost));
                        lambda = (lambda * 0.3).max(1e-12);
                        break;
                    }
                }
                lambda *= 4.0;
            }
            let Some((c, mo, r, new_cost)) = accepted else {
                break;
            };
            let decrease = cost - new_cost;
            (controls, model, residuals) = (c, mo, r);
            let old = cost;
            cost = new_cost;
            if decrease <= RELATIVE_DECREASE * old {
                break;
            }
        }
        Ok((controls, model, iterations))
    }
}

fn norm2(r: &[f64; 6]) -> f64 {
    r.iter().map(|x| x * x).sum()
}
