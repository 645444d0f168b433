//! Ramamoorthi & Barr, *Fast Construction of Accurate Quaternion Splines*
//! (docs/math/quaternion-splines.md §4): optimise the keyframe velocities of the Hermite quaternion spline, then insert
//! variable frames where the Euler–Lagrange error is largest and re-optimise; and the resulting
//! rigid motion (rotation from the spline, translation interpolated separately).

use glam::{DQuat, DVec3};
use serde::Serialize;

use super::spline::{Frame, HermiteQuatSpline, FRAME_TIME_TOLERANCE};
use crate::error::{check_finite, Error, ErrorKind};
use crate::methods::algebra::{angular_rates, canonical_signs, normalised, velocity_from_omega};
use crate::methods::gauss::MAX_GAUSS_NODES;
use crate::methods::lbfgs::{minimize, LbfgsOptions, LbfgsReport};
use crate::methods::positions::CatmullRom;
use crate::motion::{Kinematics, Motion};
use crate::pose::{Pose, UNIT_QUATERNION_TOLERANCE};
use crate::timing::check_increasing_times;

/// Default penalty weight `α` for keyframe spacing 1 (docs/math/quaternion-splines.md §6: `α ≈ 1000`).
pub const DEFAULT_ALPHA: f64 = 1000.0;
/// Default number of refinement segments per keyframe interval `S` (docs/math/quaternion-splines.md §6: 4–5).
pub const DEFAULT_SEGMENTS_PER_INTERVAL: usize = 5;
/// Default number of variable frames `M` (docs/math/quaternion-splines.md §6: about 5 give nearly optimal results).
pub const DEFAULT_VARIABLE_FRAMES: usize = 5;
/// Default Gauss–Legendre nodes per piece (docs/math/quaternion-splines.md §4.1: 10 and 40 agree to `2e-9`).
pub const DEFAULT_GAUSS_NODES: usize = 10;
/// Incremental refinement stops early when one round lowers `OBJ` by less than this fraction
/// (docs/math/quaternion-splines.md §4).
pub const DEFAULT_MIN_RELATIVE_DECREASE: f64 = 1e-4;
/// Largest accepted number of variable frames or segments per interval (a size guard: the
/// optimiser's cost grows with the square of the frame count).
pub const MAX_RB_FRAMES: usize = 10_000;

/// How variable frames are inserted (docs/math/quaternion-splines.md §4 \[choice\]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize)]
pub enum Insertion {
    /// One frame per round at the segment with the largest `DEV`, re-optimising after each
    /// (how the paper's convergence plot was produced). Default.
    #[default]
    Incremental,
    /// The `M` segments with the largest `DEV` at once, one optimisation (the paper's algorithm
    /// box).
    Batch,
}

/// Options of the Ramamoorthi–Barr construction (docs/math/quaternion-splines.md §4, §6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RbOptions {
    /// Penalty weight `α` for a mean keyframe spacing of 1; internally scaled by
    /// `(mean spacing)⁻⁴` so that results do not depend on the time unit (docs/math/quaternion-splines.md §2 \[choice\]).
    pub alpha: f64,
    /// Refinement segments per keyframe interval `S`.
    pub segments_per_interval: usize,
    /// Number of variable frames `M` to insert.
    pub variable_frames: usize,
    /// World-frame angular velocity at the first keyframe (open splines only); fixes that
    /// velocity to `½ ω Q¹`.
    pub omega_start: Option<DVec3>,
    /// World-frame angular velocity at the last keyframe (open splines only).
    pub omega_end: Option<DVec3>,
    /// Whether end velocities without a given `ω` are optimised (default) or kept at the
    /// one-sided initial guess.
    pub free_unspecified_end_velocities: bool,
    /// Incremental (default) or batch insertion.
    pub insertion: Insertion,
    /// Gauss–Legendre nodes per piece (1 ..= 64).
    pub gauss_nodes: usize,
    /// Early stop of incremental refinement (see [`DEFAULT_MIN_RELATIVE_DECREASE`]).
    pub min_relative_decrease: f64,
    /// Whether to optimise at all (`false` gives the initial spline of docs/math/quaternion-splines.md §4 step 2).
    pub optimise: bool,
    /// Settings of the L-BFGS minimiser.
    pub lbfgs: LbfgsOptions,
}

impl Default for RbOptions {
    fn default() -> Self {
        RbOptions {
            alpha: DEFAULT_ALPHA,
            segments_per_interval: DEFAULT_SEGMENTS_PER_INTERVAL,
            variable_frames: DEFAULT_VARIABLE_FRAMES,
            omega_start: None,
            omega_end: None,
            free_unspecified_end_velocities: true,
            insertion: Insertion::Incremental,
            gauss_nodes: DEFAULT_GAUSS_NODES,
            min_relative_decrease: DEFAULT_MIN_RELATIVE_DECREASE,
            optimise: true,
            lbfgs: LbfgsOptions::default(),
        }
    }
}

/// One stage of the construction (for convergence plots, docs/math/quaternion-splines.md §7).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RbStage {
    /// Variable frames present after this stage.
    pub variable_frames: usize,
    /// Time of the frame inserted in this stage (incremental insertion), if any.
    pub inserted_at: Option<f64>,
    /// `OBJ` after this stage (spline time units).
    pub objective: f64,
    /// L-BFGS iterations spent in this stage (0 for the initial spline).
    pub iterations: usize,
}

/// The result of [`fit_quaternion_spline`]: the optimised spline and the history of stages
/// (`stages[0]` is the initial spline, `stages[1]` after optimising keyframe velocities, then one
/// per insertion round).
#[derive(Clone, Debug, PartialEq)]
pub struct RbFit {
    /// The spline.
    pub spline: HermiteQuatSpline,
    /// The stages.
    pub stages: Vec<RbStage>,
    /// Keyframe times (for a closed spline including the period end).
    pub key_times: Vec<f64>,
}

fn validate_options(o: &RbOptions, closed: bool) -> Result<(), Error> {
    let range = |at: &str, value: String, expected: &str| {
        Error::new(
            at,
            ErrorKind::OutOfRange {
                value,
                expected: expected.into(),
            },
        )
    };
    if !(o.alpha.is_finite() && o.alpha > 0.0) {
        return Err(range(
            "alpha",
            o.alpha.to_string(),
            "a positive finite number",
        ));
    }
    if o.segments_per_interval == 0 || o.segments_per_interval > MAX_RB_FRAMES {
        return Err(range(
            "segments_per_interval",
            o.segments_per_interval.to_string(),
            "1 to 10000",
        ));
    }
    if o.variable_frames > MAX_RB_FRAMES {
        return Err(range(
            "variable_frames",
            o.variable_frames.to_string(),
            "0 to 10000",
        ));
    }
    if o.gauss_nodes == 0 || o.gauss_nodes > MAX_GAUSS_NODES {
        return Err(range("gauss_nodes", o.gauss_nodes.to_string(), "1 to 64"));
    }
    if !(o.min_relative_decrease.is_finite() && o.min_relative_decrease >= 0.0) {
        return Err(range(
            "min_relative_decrease",
            o.min_relative_decrease.to_string(),
            "a non-negative finite number",
        ));
    }
    for (name, w) in [("omega_start", o.omega_start), ("omega_end", o.omega_end)] {
        if let Some(w) = w {
            check_finite(&w.to_array(), name)?;
            if closed {
                return Err(Error::new(
                    name,
                    ErrorKind::Unsupported {
                        reason: "a closed spline has no end velocities".into(),
                    },
                ));
            }
        }
    }
    Ok(())
}

/// Validates keyframe times (strictly increasing, finite; closed: one more time than keys, the
/// period end) and quaternions (finite, unit within [`UNIT_QUATERNION_TOLERANCE`], normalised),
/// and returns the keys with canonical signs.
fn validate_keys(times: &[f64], keys: &[DQuat], closed: bool) -> Result<Vec<DQuat>, Error> {
    if keys.len() < 2 {
        return Err(Error::new(
            "keys",
            ErrorKind::TooFewPoses {
                found: keys.len(),
                min: 2,
            },
        ));
    }
    let want = keys.len() + closed as usize;
    if times.len() != want {
        return Err(Error::new(
            "times",
            ErrorKind::OutOfRange {
                value: format!("{} times", times.len()),
                expected: if closed {
                    format!("{want} (one per keyframe plus the period end)")
                } else {
                    format!("{want} (one per keyframe)")
                },
            },
        ));
    }
    check_increasing_times(times, " (duplicate keyframes are not allowed)")?;
    let mut unit = Vec::with_capacity(keys.len());
    for (i, q) in keys.iter().enumerate() {
        check_finite(&q.to_array(), &format!("keys[{i}]"))?;
        let n = q.length();
        if n == 0.0 {
            return Err(Error::new(format!("keys[{i}]"), ErrorKind::ZeroQuaternion));
        }
        if (n - 1.0).abs() > UNIT_QUATERNION_TOLERANCE {
            return Err(Error::new(
                format!("keys[{i}]"),
                ErrorKind::NonUnitQuaternion {
                    norm: n,
                    tolerance: crate::pose::UNIT_QUATERNION_TOLERANCE,
                },
            ));
        }
        unit.push(*q / n);
    }
    Ok(canonical_signs(&unit))
}

/// The initial spline of docs/math/quaternion-splines.md §4 step 2: keyframes with finite-difference velocities
/// `m_i = (Q^{i+1} − Q^{i−1})/(t_{i+1} − t_{i−1})` (ends one-sided, or `½ ω Q` when given;
/// closed splines wrap), interior velocities free.
pub fn initial_spline(
    times: &[f64],
    keys: &[DQuat],
    closed: bool,
    options: &RbOptions,
) -> Result<HermiteQuatSpline, Error> {
    validate_options(options, closed)?;
    let q = validate_keys(times, keys, closed)?;
    let k = q.len();
    let wrap_sign = if closed && q[k - 1].dot(q[0]) < 0.0 {
        -1.0
    } else {
        1.0
    };
    let span = times[times.len() - 1] - times[0];
    let mean_spacing = span / (times.len() - 1) as f64;
    let alpha = options.alpha / mean_spacing.powi(4);
    let frames = (0..k)
        .map(|i| {
            let (m, free) = if closed {
                let period = times[k] - times[0];
                let (tp, qp) = if i == 0 {
                    (times[k - 1] - period, q[k - 1] * wrap_sign)
                } else {
                    (times[i - 1], q[i - 1])
                };
                let qn = if i + 1 == k {
                    q[0] * wrap_sign
                } else {
                    q[i + 1]
                };
                ((qn - qp) / (times[i + 1] - tp), true)
            } else if i == 0 {
                match options.omega_start {
                    Some(w) => (velocity_from_omega(w, q[0]), false),
                    None => (
                        (q[1] - q[0]) / (times[1] - times[0]),
                        options.free_unspecified_end_velocities,
                    ),
                }
            } else if i == k - 1 {
                match options.omega_end {
                    Some(w) => (velocity_from_omega(w, q[k - 1]), false),
                    None => (
                        (q[k - 1] - q[k - 2]) / (times[k - 1] - times[k - 2]),
                        options.free_unspecified_end_velocities,
                    ),
                }
            } else {
                ((q[i + 1] - q[i - 1]) / (times[i + 1] - times[i - 1]), true)
            };
            Frame {
                t: times[i],
                p: q[i],
                m,
                pos_free: false,
                vel_free: free,
                keyframe: true,
            }
        })
        .collect();
    HermiteQuatSpline::new(
        frames,
        closed,
        times[times.len() - 1],
        wrap_sign,
        alpha,
        options.gauss_nodes,
    )
}

/// Minimises the spline's objective over its free variables with L-BFGS (docs/math/quaternion-splines.md §4.2).
pub fn optimise_spline(spline: &mut HermiteQuatSpline, options: &LbfgsOptions) -> LbfgsReport {
    let mut x = spline.variables();
    let mut work = spline.clone();
    let report = minimize(
        |x, g| {
            work.set_variables(x);
            work.objective_and_gradient(g)
        },
        &mut x,
        options,
    );
    spline.set_variables(&x);
    report
}

/// The whole construction of docs/math/quaternion-splines.md §4: initial spline, optimisation of the keyframe velocities,
/// then variable frames inserted at the segment of largest `DEV` (recomputed on the optimised
/// path before each insertion; candidates are segment starts that are neither keyframe times nor
/// existing frames) and re-optimisation, until `variable_frames` are in, no candidate is left, or
/// a round gains less than `min_relative_decrease`.
///
/// `times` has one entry per keyframe (closed: plus the period end). Quaternions are normalised
/// (they must be unit within [`UNIT_QUATERNION_TOLERANCE`]) and their signs made consecutive
/// (`Q^{i−1}·Q^i ≥ 0`).
pub fn fit_quaternion_spline(
    times: &[f64],
    keys: &[DQuat],
    closed: bool,
    options: &RbOptions,
) -> Result<RbFit, Error> {
    let mut spline = initial_spline(times, keys, closed, options)?;
    let mut stages = vec![RbStage {
        variable_frames: 0,
        inserted_at: None,
        objective: spline.objective(),
        iterations: 0,
    }];
    if options.optimise {
        let r = optimise_spline(&mut spline, &options.lbfgs);
        stages.push(RbStage {
            variable_frames: 0,
            inserted_at: None,
            objective: spline.objective(),
            iterations: r.iterations,
        });
        let mut inserted = 0;
        while inserted < options.variable_frames {
            let want = match options.insertion {
                Insertion::Incremental => 1,
                Insertion::Batch => options.variable_frames - inserted,
            };
            let picks = best_segments(&spline, times, options.segments_per_interval, want);
            if picks.is_empty() {
                break;
            }
            for &t in &picks {
                spline.insert_frame(t);
            }
            inserted += picks.len();
            let before = stages[stages.len() - 1].objective;
            let r = optimise_spline(&mut spline, &options.lbfgs);
            let after = spline.objective();
            stages.push(RbStage {
                variable_frames: inserted,
                inserted_at: (picks.len() == 1).then(|| picks[0]),
                objective: after,
                iterations: r.iterations,
            });
            if options.insertion == Insertion::Incremental
                && before - after < options.min_relative_decrease * before.abs()
            {
                break;
            }
        }
    }
    Ok(RbFit {
        spline,
        stages,
        key_times: times.to_vec(),
    })
}

/// The `count` segment starts with the largest `DEV` that are neither keyframe times nor frames.
fn best_segments(
    spline: &HermiteQuatSpline,
    key_times: &[f64],
    per_interval: usize,
    count: usize,
) -> Vec<f64> {
    let devs = spline.segment_deviations(key_times, per_interval);
    let span = key_times[key_times.len() - 1] - key_times[0];
    let tol = FRAME_TIME_TOLERANCE * span.max(f64::MIN_POSITIVE);
    let mut cand: Vec<(f64, f64)> = devs
        .into_iter()
        .filter(|&(t, d)| {
            d.is_finite()
                && !key_times.iter().any(|&k| (k - t).abs() <= tol)
                && !spline.frames().iter().any(|f| (f.t - t).abs() <= tol)
        })
        .collect();
    // Largest DEV first; ties broken by earlier time (deterministic).
    cand.sort_by(|a, b| b.1.total_cmp(&a.1).then(a.0.total_cmp(&b.0)));
    cand.into_iter().take(count).map(|(t, _)| t).collect()
}

/// The Ramamoorthi–Barr motion of a rigid body: rotation `q(t)/|q(t)|` from the optimised
/// quaternion spline, translation the [`CatmullRom`] interpolant of the origins at the same
/// times (the method concerns orientations only; like the paper's I-beam animation, the
/// translation is simply interpolated — scene C2).
#[derive(Clone, Debug, PartialEq)]
pub struct RamamoorthiBarr {
    fit: RbFit,
    positions: CatmullRom,
    closed: bool,
}

impl RamamoorthiBarr {
    /// The motion through `poses` at `times` (closed: one more time, the period end).
    pub fn from_poses(
        poses: &[Pose],
        times: &[f64],
        closed: bool,
        options: &RbOptions,
    ) -> Result<RamamoorthiBarr, Error> {
        for (i, p) in poses.iter().enumerate() {
            if !p.is_finite() {
                return Err(Error::new(format!("poses[{i}]"), ErrorKind::NonFinite));
            }
        }
        let keys: Vec<DQuat> = poses.iter().map(|p| p.rotation).collect();
        let fit = fit_quaternion_spline(times, &keys, closed, options).map_err(rename_keys)?;
        let origins: Vec<DVec3> = poses.iter().map(|p| p.origin).collect();
        let positions = CatmullRom::new(times, &origins, closed)?;
        Ok(RamamoorthiBarr {
            fit,
            positions,
            closed,
        })
    }

    /// The optimised spline and its stages.
    pub fn fit(&self) -> &RbFit {
        &self.fit
    }

    /// `max_t | |q(t)| − 1 |` over `samples` uniform samples (docs/math/quaternion-splines.md §7.1 reports it at 3000).
    pub fn max_unit_deviation(&self, samples: usize) -> f64 {
        self.fit.spline.unit_deviation(samples).0
    }
}

fn rename_keys(e: Error) -> Error {
    // Errors about `keys[i]` concern the poses' rotations.
    let path = e.path().to_string();
    match path.strip_prefix("keys") {
        Some(rest) if rest.starts_with('[') => {
            let idx = rest.trim_start_matches('[').split(']').next().unwrap_or("");
            relabel(e, format!("poses[{idx}].rotation"))
        }
        _ => e,
    }
}

fn relabel(e: Error, at: String) -> Error {
    match e.kind() {
        ErrorKind::NonFinite | ErrorKind::ZeroQuaternion | ErrorKind::NonUnitQuaternion { .. } => {
            Error::new(at, e.kind().clone())
        }
        _ => e,
    }
}

impl Motion for RamamoorthiBarr {
    fn name(&self) -> String {
        let v = self.fit.stages.last().map_or(0, |s| s.variable_frames);
        format!("ramamoorthi-barr ({v} variable frames)")
    }

    fn domain(&self) -> (f64, f64) {
        self.fit.spline.domain()
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn pose_at(&self, t: f64) -> Pose {
        let q = self.fit.spline.eval(t)[0];
        Pose::new(self.positions.eval(t).0, normalised(q))
    }

    fn knots(&self) -> Vec<f64> {
        let k = self.fit.key_times.len() - self.closed as usize;
        self.fit.key_times[..k].to_vec()
    }

    /// Closed form: rotation rates from `q, q', q''` of the Hermite piece (see
    /// [`crate::methods::algebra::angular_rates`]), translation from the Catmull–Rom piece.
    fn kinematics_at(&self, t: f64, local: DVec3) -> Option<Kinematics> {
        let [q, q1, q2, _] = self.fit.spline.eval(t);
        let (omega, alpha) = angular_rates(q, q1, q2);
        let (o, v, a) = self.positions.eval(t);
        let r = normalised(q) * local;
        Some(Kinematics {
            position: o + r,
            velocity: v + omega.cross(r),
            acceleration: a + alpha.cross(r) + omega.cross(omega.cross(r)),
            angular_velocity: omega,
            angular_acceleration: alpha,
        })
    }
}
