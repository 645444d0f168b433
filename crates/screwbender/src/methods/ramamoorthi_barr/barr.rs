//! The baseline of Ramamoorthi–Barr's paper: the discrete method of Barr, Currin, Gabriel and
//! Hughes (docs/math/quaternion-splines.md §9). The curve is a dense sequence of frames `q_k`
//! in R⁴, the objective (3) becomes a sum over finite differences, and the frames between the
//! keyframes are optimised all at once. Meant for small inputs: the cost grows with the number
//! of frames, which is why the paper's spline method was 2000 times faster.

use glam::{DQuat, DVec3, DVec4};

use super::optimizer::DEFAULT_ALPHA;
use crate::error::{Error, ErrorKind};
use crate::methods::algebra::{canonical_signs, normalised};
use crate::methods::positions::CatmullRom;
use crate::motion::Motion;
use crate::pose::Pose;

/// Frames per keyframe interval by default (the paper's run: 600 frames for seven keyframes).
pub const DEFAULT_BARR_FRAMES_PER_INTERVAL: usize = 100;

/// The most frames the discrete method takes (about 40 keyframes at the default density): the
/// baseline is for small inputs.
pub const MAX_BARR_FRAMES: usize = 4_000;

/// Stop when an accepted step lowers the objective by less than this fraction of it.
pub const BARR_RELATIVE_DECREASE: f64 = 1e-13;

/// Options of the discrete method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BarrOptions {
    /// Penalty weight `α` for a mean keyframe spacing of 1, scaled by `(mean spacing)⁻⁴` as in
    /// the spline method (docs/math/quaternion-splines.md §2).
    pub alpha: f64,
    /// Frames per keyframe interval (uniform within an interval).
    pub frames_per_interval: usize,
    /// The most Gauss–Newton steps.
    pub max_iterations: usize,
}

impl Default for BarrOptions {
    fn default() -> Self {
        BarrOptions {
            alpha: DEFAULT_ALPHA,
            frames_per_interval: DEFAULT_BARR_FRAMES_PER_INTERVAL,
            max_iterations: 200,
        }
    }
}

/// The optimised frames of the discrete method.
#[derive(Clone, Debug, PartialEq)]
pub struct BarrFit {
    /// The frame times (the keyframe times among them).
    pub times: Vec<f64>,
    /// The frames `q_k` (not unit: the unit length is a penalty, as in the spline method).
    pub frames: Vec<DQuat>,
    /// The discrete objective (3) at the frames: covariant acceleration plus penalty.
    pub objective: f64,
    /// Its covariant-acceleration part alone.
    pub covariant_acceleration: f64,
    /// The objective of the starting frames (the SLERP polyline through the keyframes).
    pub initial_objective: f64,
    /// Gauss–Newton steps taken.
    pub iterations: usize,
}

impl BarrOptions {
    /// The default options with as many frames per interval as fit [`MAX_BARR_FRAMES`] for
    /// `key_count` keyframes (at most [`DEFAULT_BARR_FRAMES_PER_INTERVAL`], at least 2): what
    /// the comparison uses.
    pub fn for_keys(key_count: usize) -> BarrOptions {
        let spans = key_count.saturating_sub(1).max(1);
        BarrOptions {
            frames_per_interval: DEFAULT_BARR_FRAMES_PER_INTERVAL
                .min((MAX_BARR_FRAMES - 1) / spans)
                .max(2),
            ..BarrOptions::default()
        }
    }
}

/// One interior frame's second difference `a_k = c₋ q_{k−1} + c₀ q_k + c₊ q_{k+1}` and its
/// quadrature weight `w_k` (non-uniform spacing `h₋`, `h₊`).
#[derive(Clone, Copy)]
struct Stencil {
    c: [f64; 3],
    w: f64,
}

fn stencil(h0: f64, h1: f64) -> Stencil {
    let s = h0 + h1;
    Stencil {
        c: [2.0 / (h0 * s), -2.0 / (h0 * h1), 2.0 / (h1 * s)],
        w: 0.5 * s,
    }
}

/// `F = |a|² − (q·a)²/|q|² + α(1 − |q|²)²` (docs/math/quaternion-splines.md §2, eq. 3), its two
/// parts.
fn integrand(q: DVec4, a: DVec4, alpha: f64) -> (f64, f64) {
    let qq = q.length_squared();
    let qa = q.dot(a);
    let cov = a.length_squared() - qa * qa / qq;
    (cov, alpha * (1.0 - qq) * (1.0 - qq))
}

/// The discrete objective and its covariant part.
fn objective(q: &[DVec4], st: &[Stencil], alpha: f64) -> (f64, f64) {
    let (mut total, mut cov) = (0.0, 0.0);
    for k in 1..q.len() - 1 {
        let s = st[k];
        let a = q[k - 1] * s.c[0] + q[k] * s.c[1] + q[k + 1] * s.c[2];
        let (c, p) = integrand(q[k], a, alpha);
        total += s.w * (c + p);
        cov += s.w * c;
    }
    (total, cov)
}

/// Half bandwidth (in scalars) of `JᵀJ`: a residual at frame `k` reads frames `k − 1 … k + 1`,
/// so frames up to two apart are coupled.
const BAND: usize = 11;

/// A symmetric positive definite band matrix (lower band, `BAND` below the diagonal).
struct Band {
    n: usize,
    a: Vec<[f64; BAND + 1]>,
}

impl Band {
    fn new(n: usize) -> Band {
        Band {
            n,
            a: vec![[0.0; BAND + 1]; n],
        }
    }
    /// Adds `v` at `(i, j)` with `i ≥ j`, `i − j ≤ BAND`.
    fn add(&mut self, i: usize, j: usize, v: f64) {
        self.a[i][i - j] += v;
    }
    /// Solves `A x = b` in place by a band Cholesky factorisation; `false` if `A` is not
    /// positive definite.
    // Band indices (row, row − column) read as in the textbook algorithm.
    #[allow(clippy::needless_range_loop)]
    fn solve(mut self, b: &mut [f64]) -> bool {
        let n = self.n;
        for i in 0..n {
            for d in (0..=BAND.min(i)).rev() {
                let j = i - d;
                let mut s = self.a[i][d];
                for k in j.saturating_sub(BAND).max(i.saturating_sub(BAND))..j {
                    s -= self.a[i][i - k] * self.a[j][j - k];
                }
                if d == 0 {
                    if s <= 0.0 || !s.is_finite() {
                        return false;
                    }
                    self.a[i][0] = s.sqrt();
                } else {
                    self.a[i][d] = s / self.a[j][0];
                }
            }
        }
        for i in 0..n {
            let mut s = b[i];
            for k in i.saturating_sub(BAND)..i {
                s -= self.a[i][i - k] * b[k];
            }
            b[i] = s / self.a[i][0];
        }
        for i in (0..n).rev() {
            let mut s = b[i];
            for k in i + 1..(i + BAND + 1).min(n) {
                s -= self.a[k][k - i] * b[k];
            }
            b[i] = s / self.a[i][0];
        }
        true
    }
}

#[allow(clippy::needless_range_loop)]
fn outer(u: DVec4, v: DVec4) -> [[f64; 4]; 4] {
    let (u, v) = (u.to_array(), v.to_array());
    let mut m = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            m[i][j] = u[i] * v[j];
        }
    }
    m
}

/// The Gauss–Newton normal equations `JᵀJ`, `Jᵀr` of the residuals `r_k = √w_k P(q_k) a_k`
/// (`P` the projection off `q`) and `p_k = √(w_k α)(1 − |q_k|²)`; rows of fixed frames left out.
// 4×4 blocks indexed as matrices.
#[allow(clippy::needless_range_loop)]
fn normal_equations(q: &[DVec4], st: &[Stencil], alpha: f64, fixed: &[bool]) -> (Band, Vec<f64>) {
    let n = q.len();
    let mut h = Band::new(4 * n);
    let mut g = vec![0.0; 4 * n];
    for k in 1..n - 1 {
        let s = st[k];
        let a = q[k - 1] * s.c[0] + q[k] * s.c[1] + q[k + 1] * s.c[2];
        let (qk, sw) = (q[k], s.w.sqrt());
        let qq = qk.length_squared();
        let qa = qk.dot(a);
        // P = I − q qᵀ/|q|²; D = ∂(P a)/∂q = −((q·a) I + q aᵀ)/|q|² + 2 (q·a) q qᵀ/|q|⁴.
        let qq_outer = outer(qk, qk);
        let qa_outer = outer(qk, a);
        let mut p = [[0.0; 4]; 4];
        let mut d = [[0.0; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                let id = if i == j { 1.0 } else { 0.0 };
                p[i][j] = id - qq_outer[i][j] / qq;
                d[i][j] = -(qa * id + qa_outer[i][j]) / qq + 2.0 * qa * qq_outer[i][j] / (qq * qq);
            }
        }
        let r = (a - qk * (qa / qq)) * sw;
        // Blocks of the residual's Jacobian for frames k − 1, k, k + 1.
        let mut blocks = [[[0.0; 4]; 4]; 3];
        for (b, block) in blocks.iter_mut().enumerate() {
            for i in 0..4 {
                for j in 0..4 {
                    block[i][j] = sw * (p[i][j] * s.c[b] + if b == 1 { d[i][j] } else { 0.0 });
                }
            }
        }
        let r = r.to_array();
        for bi in 0..3 {
            let fi = k + bi - 1;
            if fixed[fi] {
                continue;
            }
            for col in 0..4 {
                let gi: f64 = (0..4).map(|row| blocks[bi][row][col] * r[row]).sum();
                g[4 * fi + col] += gi;
            }
            for bj in 0..=bi {
                let fj = k + bj - 1;
                if fixed[fj] {
                    continue;
                }
                for ci in 0..4 {
                    for cj in 0..4 {
                        let (ri, rj) = (4 * fi + ci, 4 * fj + cj);
                        if rj > ri {
                            continue;
                        }
                        let v: f64 = (0..4)
                            .map(|row| blocks[bi][row][ci] * blocks[bj][row][cj])
                            .sum();
                        h.add(ri, rj, v);
                    }
                }
            }
        }
        // The penalty residual: ∂p/∂q_k = −2 √(wα) qᵀ.
        if !fixed[k] {
            let sa = (s.w * alpha).sqrt();
            let pk = sa * (1.0 - qq);
            let jp = (qk * (-2.0 * sa)).to_array();
            for ci in 0..4 {
                g[4 * k + ci] += jp[ci] * pk;
                for cj in 0..=ci {
                    h.add(4 * k + ci, 4 * k + cj, jp[ci] * jp[cj]);
                }
            }
        }
    }
    (h, g)
}

/// Minimises the discrete objective (3) over frames at `frames_per_interval` uniform steps in
/// every keyframe interval, the keyframes fixed and the end velocities free
/// (docs/math/quaternion-splines.md §9): Levenberg–Marquardt-damped Gauss–Newton steps on the
/// residuals of the covariant acceleration and the unit penalty, each a band solve.
///
/// Keyframe signs are fixed first (consecutive dot products ≥ 0). Open sequences only; needs at
/// least 2 keyframes at strictly increasing finite times and at most [`MAX_BARR_FRAMES`] frames.
pub fn fit_barr(times: &[f64], keys: &[DQuat], options: &BarrOptions) -> Result<BarrFit, Error> {
    if keys.len() < 2 {
        return Err(Error::new(
            "keys",
            ErrorKind::TooFewPoses {
                found: keys.len(),
                min: 2,
            },
        ));
    }
    if times.len() != keys.len() {
        return Err(Error::new(
            "times",
            ErrorKind::OutOfRange {
                value: format!("{} times", times.len()),
                expected: format!("{} (one per keyframe)", keys.len()),
            },
        ));
    }
    for (i, w) in times.windows(2).enumerate() {
        if !(w[0].is_finite() && w[1].is_finite() && w[1] > w[0]) {
            return Err(Error::new(
                format!("times[{}]", i + 1),
                ErrorKind::OutOfRange {
                    value: w[1].to_string(),
                    expected: "a finite time after the one before".into(),
                },
            ));
        }
    }
    let s = options.frames_per_interval.max(2);
    let count = (keys.len() - 1) * s + 1;
    if count > MAX_BARR_FRAMES {
        return Err(Error::new(
            "keys",
            ErrorKind::Unsupported {
                reason: format!(
                    "the discrete baseline of Barr et al. takes at most {MAX_BARR_FRAMES} frames \
                     ({count} asked for: {} keyframes × {s} frames per interval): it is meant for \
                     small inputs",
                    keys.len()
                ),
            },
        ));
    }
    let keys = canonical_signs(keys);
    let spacing = (times[times.len() - 1] - times[0]) / (times.len() - 1) as f64;
    let alpha = options.alpha / spacing.powi(4);
    // Frames: the SLERP polyline through the keyframes, sampled uniformly per interval.
    let mut t = Vec::with_capacity(count);
    let mut q = Vec::with_capacity(count);
    let mut fixed = Vec::with_capacity(count);
    for i in 0..keys.len() - 1 {
        for j in 0..s {
            let u = j as f64 / s as f64;
            t.push(times[i] + (times[i + 1] - times[i]) * u);
            q.push(DVec4::from(keys[i].slerp(keys[i + 1], u)));
            fixed.push(j == 0);
        }
    }
    t.push(times[times.len() - 1]);
    q.push(DVec4::from(keys[keys.len() - 1]));
    fixed.push(true);
    let mut st = vec![stencil(1.0, 1.0); count];
    for k in 1..count - 1 {
        st[k] = stencil(t[k] - t[k - 1], t[k + 1] - t[k]);
    }
    let (initial, _) = objective(&q, &st, alpha);
    let mut value = initial;
    let mut lambda = 1e-6;
    let mut iterations = 0;
    for _ in 0..options.max_iterations {
        iterations += 1;
        let (h, g) = normal_equations(&q, &st, alpha, &fixed);
        let mut accepted = false;
        // Damping: raise λ until a step lowers the objective (at most a few times).
        for _ in 0..30 {
            let mut m = Band {
                n: h.n,
                a: h.a.clone(),
            };
            for (i, row) in m.a.iter_mut().enumerate() {
                if fixed[i / 4] {
                    *row = [0.0; BAND + 1];
                    row[0] = 1.0;
                } else {
                    row[0] += lambda * row[0].max(1e-12);
                }
            }
            let mut step: Vec<f64> = g.iter().map(|v| -v).collect();
            if !m.solve(&mut step) {
                lambda *= 10.0;
                continue;
            }
            let trial: Vec<DVec4> = q
                .iter()
                .enumerate()
                .map(|(k, &v)| {
                    v + DVec4::new(
                        step[4 * k],
                        step[4 * k + 1],
                        step[4 * k + 2],
                        step[4 * k + 3],
                    )
                })
                .collect();
            let (tv, _) = objective(&trial, &st, alpha);
            if tv.is_finite() && tv <= value {
                let decrease = value - tv;
                q = trial;
                value = tv;
                lambda = (lambda * 0.3).max(1e-12);
                accepted = decrease > BARR_RELATIVE_DECREASE * value;
                break;
            }
            lambda *= 10.0;
        }
        if !accepted {
            break;
        }
    }
    let (objective, covariant_acceleration) = objective(&q, &st, alpha);
    Ok(BarrFit {
        times: t,
        frames: q.into_iter().map(DQuat::from_vec4).collect(),
        objective,
        covariant_acceleration,
        initial_objective: initial,
        iterations,
    })
}

/// The discrete method of Barr et al. as a motion: the rotation between two frames by SLERP of
/// the normalised frames, the translation the [`CatmullRom`] interpolant of the origins (as for
/// [`super::optimizer::RamamoorthiBarr`]). Open motions only.
#[derive(Clone, Debug, PartialEq)]
pub struct BarrBaseline {
    fit: BarrFit,
    positions: CatmullRom,
    key_times: Vec<f64>,
}

impl BarrBaseline {
    /// The motion through `poses` at `times` (open).
    pub fn from_poses(
        poses: &[Pose],
        times: &[f64],
        options: &BarrOptions,
    ) -> Result<BarrBaseline, Error> {
        for (i, p) in poses.iter().enumerate() {
            if !p.is_finite() {
                return Err(Error::new(format!("poses[{i}]"), ErrorKind::NonFinite));
            }
        }
        let keys: Vec<DQuat> = poses.iter().map(|p| p.rotation).collect();
        let fit = fit_barr(times, &keys, options)?;
        let origins: Vec<DVec3> = poses.iter().map(|p| p.origin).collect();
        let positions = CatmullRom::new(times, &origins, false)?;
        Ok(BarrBaseline {
            fit,
            positions,
            key_times: times.to_vec(),
        })
    }

    /// The optimised frames and objective.
    pub fn fit(&self) -> &BarrFit {
        &self.fit
    }
}

impl Motion for BarrBaseline {
    fn name(&self) -> String {
        format!("barr et al. discrete ({} frames)", self.fit.frames.len())
    }

    fn domain(&self) -> (f64, f64) {
        (self.fit.times[0], self.fit.times[self.fit.times.len() - 1])
    }

    fn is_closed(&self) -> bool {
        false
    }

    fn pose_at(&self, t: f64) -> Pose {
        let ts = &self.fit.times;
        let k = ts.partition_point(|&x| x <= t).clamp(1, ts.len() - 1) - 1;
        let u = ((t - ts[k]) / (ts[k + 1] - ts[k])).clamp(0.0, 1.0);
        let (a, b) = (
            normalised(self.fit.frames[k]),
            normalised(self.fit.frames[k + 1]),
        );
        Pose::new(self.positions.eval(t).0, a.slerp(b, u))
    }

    fn knots(&self) -> Vec<f64> {
        self.key_times.clone()
    }
}
