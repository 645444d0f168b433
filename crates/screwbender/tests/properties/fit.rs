//! Fitting motions to measured poses: a known motion sampled with noise and outliers is
//! recovered within a stated multiple of the noise, a fit beats `reduce_poses` at the same number
//! of control poses, a tolerance is met, and bad input is refused with the element named.

// Native only: hundreds of samples fitted several times over would hold up the browser's test
// page for longer than its runner waits (see main.rs).
#![cfg(not(target_arch = "wasm32"))]

use glam::{DQuat, DVec3};
use screwbender::methods::Se3BSpline;
use screwbender::{
    fit_poses, reduce_poses, Closure, ControlCount, FitMethod, FitOptions, Motion, MotionDocument,
    Pose, Reduction, RobustLoss, Rules, Scheme, ScrewBender, Subdivision,
};
use testkit::Rng;

/// Position noise σ (scene units) and angle noise σ (radians) of the samples.
const SIGMA: f64 = 0.01;

/// Control poses of a wandering motion (turns of about 0.5 rad between neighbours).
fn true_controls(m: usize) -> Vec<Pose> {
    (0..m)
        .map(|k| {
            let a = k as f64 * 0.5;
            Pose::new(
                DVec3::new(3.0 * a.cos(), 2.0 * a.sin() + 0.2 * a, 0.4 * a),
                DQuat::from_axis_angle(DVec3::new(0.2, 1.0, 0.4).normalize(), a)
                    * DQuat::from_rotation_x(0.3 * a.sin()),
            )
        })
        .collect()
}

/// A standard normal number (Box–Muller).
fn normal(rng: &mut Rng) -> f64 {
    let u = rng.unit().max(1e-300);
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * rng.unit()).cos()
}

/// `n` samples of `motion` at uniform times over its domain, each origin and rotation disturbed
/// by normal noise of [`SIGMA`] per coordinate, and every twentieth sample (5 %) an outlier
/// moved 0.5–1 away and turned 0.5–1 rad.
fn noisy_samples(motion: &dyn Motion, n: usize, seed: u64) -> (MotionDocument, Vec<f64>) {
    let mut rng = Rng::new(seed);
    let (a, b) = motion.domain();
    let params: Vec<f64> = (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect();
    let poses = params
        .iter()
        .enumerate()
        .map(|(i, &u)| {
            let p = motion.pose_at(u);
            let (offset, turn) = if i % 20 == 7 {
                (
                    rng.direction() * rng.range(0.5, 1.0),
                    rng.direction() * rng.range(0.5, 1.0),
                )
            } else {
                let mut g = || DVec3::new(normal(&mut rng), normal(&mut rng), normal(&mut rng));
                (g() * SIGMA, g() * SIGMA)
            };
            Pose::new(
                p.origin + offset,
                (p.rotation * DQuat::from_scaled_axis(turn)).normalize(),
            )
        })
        .collect();
    let mut doc = MotionDocument::new(poses, false);
    // Times in seconds, not starting at zero, to check the mapping to the spline's parameter.
    doc.times = Some(params.iter().map(|u| 10.0 + 0.5 * u).collect());
    (doc, params)
}

/// Largest origin distance and angle between `fitted` and `truth` at the parameters `params`.
fn worst(fitted: &dyn Motion, truth: &dyn Motion, params: &[f64]) -> (f64, f64) {
    params.iter().fold((0.0f64, 0.0f64), |(d, a), &u| {
        let (p, q) = (fitted.pose_at(u), truth.pose_at(u));
        (d.max(p.origin.distance(q.origin)), a.max(p.angle_to(&q)))
    })
}

fn options(method: FitMethod, controls: ControlCount, robust: RobustLoss) -> FitOptions {
    FitOptions {
        method,
        controls,
        robust,
        ..FitOptions::default()
    }
}

#[test]
fn a_noisy_se3_spline_with_outliers_is_recovered_within_the_noise() {
    // 800 samples of an 8-control SE(3) spline: with a Huber loss the fitted motion is within
    // σ of the true one everywhere (each control pose rests on about 100 samples, so the error
    // of the estimate is a fraction of σ), while plain least squares is pulled away by the
    // outliers beyond that.
    let m = 8;
    let truth = Se3BSpline::new(&true_controls(m), false).unwrap();
    let (doc, params) = noisy_samples(&truth, 800, 0x05EE_DF17);
    let robust = fit_poses(
        &doc,
        &options(
            FitMethod::Se3BSpline,
            ControlCount::Count(m),
            RobustLoss::Huber,
        ),
    )
    .unwrap();
    let fitted = Se3BSpline::new(&robust.document.poses, false).unwrap();
    let (d, a) = worst(&fitted, &truth, &params);
    assert!(
        d < SIGMA && a < SIGMA,
        "robust fit off by {d:.2e}, {a:.2e} rad"
    );
    for (c, t) in robust.document.poses.iter().zip(true_controls(m)) {
        assert!(
            c.origin.distance(t.origin) < 3.0 * SIGMA,
            "control pose {c:?}"
        );
        assert!(c.angle_to(&t) < 3.0 * SIGMA, "control pose {c:?}");
    }
    let times = robust.document.times.as_ref().unwrap();
    assert!((times[0] - 10.0).abs() < 1e-12 && (times[m - 1] - 13.5).abs() < 1e-12);
    let r = robust.report;
    assert_eq!((r.controls, r.samples), (m, 800));
    // Inliers have |noise| ≈ √3 σ; the outliers raise the RMS and set the maximum.
    assert!(r.max_position > 0.4 && r.rms_position > SIGMA, "{r:?}");
    let plain = fit_poses(
        &doc,
        &options(
            FitMethod::Se3BSpline,
            ControlCount::Count(m),
            RobustLoss::None,
        ),
    )
    .unwrap();
    let (d_plain, _) = worst(
        &Se3BSpline::new(&plain.document.poses, false).unwrap(),
        &truth,
        &params,
    );
    assert!(d_plain > d, "least squares {d_plain:.2e} vs robust {d:.2e}");
}

#[test]
fn a_noisy_screwbender_motion_is_recovered_within_the_noise() {
    let m = 6;
    let sub = Subdivision::new(Scheme::BSpline, Rules::Direct, 6);
    let truth = ScrewBender::new(true_controls(m), Closure::Open, sub).unwrap();
    let (doc, params) = noisy_samples(&truth, 300, 0x000F_175B);
    let fit = fit_poses(
        &doc,
        &options(
            FitMethod::ScrewBender,
            ControlCount::Count(m),
            RobustLoss::Cauchy,
        ),
    )
    .unwrap();
    let fitted = ScrewBender::new(fit.document.poses.clone(), Closure::Open, sub).unwrap();
    let (d, a) = worst(&fitted, &truth, &params);
    assert!(d < SIGMA && a < SIGMA, "fit off by {d:.2e}, {a:.2e} rad");
}

#[test]
fn a_fit_beats_reduce_at_the_same_number_of_control_poses() {
    // Noise only (no outliers would favour the fit unfairly): reduce keeps every k-th measured
    // pose, whose polyscrew carries their noise; the fit averages it away.
    let truth = Se3BSpline::new(&true_controls(7), false).unwrap();
    let (mut doc, _) = noisy_samples(&truth, 481, 3);
    let clean = noisy_samples(&truth, 481, 3).0; // same noise stream, outliers replaced below
    for (i, p) in doc.poses.iter_mut().enumerate() {
        if i % 20 == 7 {
            *p = truth.pose_at(6.0 * i as f64 / 480.0);
        }
    }
    assert_eq!(clean.poses.len(), doc.poses.len());
    let reduced = reduce_poses(&doc, Reduction::Every(40)).unwrap();
    let m = reduced.poses.len();
    // The reduced motion at each sample's time: the polyscrew through the kept poses.
    let kept_times = reduced.times.clone().unwrap();
    let times = doc.times.clone().unwrap();
    let rms = |f: &dyn Fn(f64) -> Pose| {
        let s: f64 = doc
            .poses
            .iter()
            .zip(&times)
            .map(|(p, &t)| {
                let q = f(t);
                let d = q.origin.distance(p.origin) + q.angle_to(p);
                d * d
            })
            .sum();
        (s / doc.poses.len() as f64).sqrt()
    };
    let polyscrew = |t: f64| {
        let b = kept_times.partition_point(|&k| k < t).clamp(1, m - 1);
        let s = (t - kept_times[b - 1]) / (kept_times[b] - kept_times[b - 1]);
        screwbender::screw(&reduced.poses[b - 1], s, &reduced.poses[b])
    };
    let reduce_rms = rms(&polyscrew);
    for method in [FitMethod::ScrewBender, FitMethod::Se3BSpline] {
        let fit = fit_poses(
            &doc,
            &options(method, ControlCount::Count(m), RobustLoss::None),
        )
        .unwrap();
        assert!(
            fit.report.rms_deviation < 0.8 * reduce_rms,
            "{method:?}: fit {:.3e} vs reduce {reduce_rms:.3e}",
            fit.report.rms_deviation
        );
    }
}

#[test]
fn a_tolerance_is_met_with_few_control_poses() {
    let truth = Se3BSpline::new(&true_controls(9), false).unwrap();
    let poses: Vec<Pose> = (0..400)
        .map(|i| truth.pose_at(8.0 * i as f64 / 399.0))
        .collect();
    let doc = MotionDocument::new(poses, false);
    for tol in [1e-2, 1e-3] {
        let fit = fit_poses(
            &doc,
            &options(
                FitMethod::Se3BSpline,
                ControlCount::Tolerance(tol),
                RobustLoss::None,
            ),
        )
        .unwrap();
        assert!(fit.report.rms_deviation <= tol, "{:?}", fit.report);
        assert_eq!(fit.document.poses.len(), fit.report.controls);
        // The search doubles to 16 at most and bisects down: 9 control poses reproduce the data
        // exactly, but 10 to 15 do not (their knots differ), so the count found may exceed 9.
        assert!(fit.report.controls < 16, "{:?}", fit.report);
        let fewer = fit_poses(
            &doc,
            &options(
                FitMethod::Se3BSpline,
                ControlCount::Count(fit.report.controls - 1),
                RobustLoss::None,
            ),
        )
        .unwrap();
        assert!(fewer.report.rms_deviation > tol, "one fewer also fits");
    }
}

#[test]
fn bad_input_is_refused_with_the_element_named() {
    let truth = Se3BSpline::new(&true_controls(5), false).unwrap();
    let poses: Vec<Pose> = (0..20).map(|i| truth.pose_at(i as f64 * 0.2)).collect();
    let doc = MotionDocument::new(poses.clone(), false);
    let opts = options(
        FitMethod::ScrewBender,
        ControlCount::Count(4),
        RobustLoss::None,
    );
    let path =
        |doc: &MotionDocument, o: &FitOptions| fit_poses(doc, o).unwrap_err().path().to_string();
    let few = options(
        FitMethod::ScrewBender,
        ControlCount::Count(21),
        RobustLoss::None,
    );
    assert_eq!(path(&doc, &few), "poses");
    let one = options(
        FitMethod::ScrewBender,
        ControlCount::Count(1),
        RobustLoss::None,
    );
    assert_eq!(path(&doc, &one), "controls");
    let mut bad = doc.clone();
    bad.times = Some(
        (0..20)
            .map(|i| if i == 6 { 4.0 } else { i as f64 })
            .collect(),
    );
    assert_eq!(path(&bad, &opts), "times[6]");
    bad.times = Some(
        (0..20)
            .map(|i| if i == 3 { f64::NAN } else { i as f64 })
            .collect(),
    );
    assert_eq!(path(&bad, &opts), "times[3]");
    let mut bad = doc.clone();
    bad.poses[5].origin.y = f64::NAN;
    assert_eq!(path(&bad, &opts), "poses[5]");
    // A cycle's samples are fitted as an open sequence.
    let mut cycle = doc.clone();
    cycle.set_closed(true);
    let fit = fit_poses(&cycle, &opts).unwrap();
    assert!(!fit.document.closed);
    assert_eq!(fit.report.samples, 20);
    for (o, p) in [
        (
            FitOptions {
                smoothness: -1.0,
                ..opts
            },
            "smoothness",
        ),
        (
            FitOptions {
                radius: 0.0,
                ..opts
            },
            "radius",
        ),
        (
            FitOptions {
                robust_scale: Some(f64::NAN),
                ..opts
            },
            "robust_scale",
        ),
        (
            FitOptions {
                controls: ControlCount::Tolerance(0.0),
                ..opts
            },
            "tolerance",
        ),
    ] {
        assert_eq!(path(&doc, &o), p);
    }
}
