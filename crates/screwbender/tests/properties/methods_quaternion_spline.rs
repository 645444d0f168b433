//! Ramamoorthi–Barr quaternion splines: the worked example of docs/math/quaternion-splines.md §8 (scene C1
//! `rb_sphere7`), the analytic gradient and Euler–Lagrange error against finite differences, the
//! great circle, refinement monotonicity, end-velocity constraints, closed splines and bad input.
//!
//! Expected numbers are copied from docs/math/quaternion-splines.md §8 (computed by a reference implementation outside the crate).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::methods::{
    euler_lagrange, fit_quaternion_spline, initial_spline, integrand, optimise_spline,
    HermiteQuatSpline, Insertion, RamamoorthiBarr, RbOptions,
};
use screwbender::ErrorKind;
use screwbender::{Motion, Pose};
use testkit::methods::{assert_quat_near, assert_rel, sphere7, sphere7_options, wxyz, SplitMix};

/// Initial-path quantities are polynomial and exact: the values of docs/math/quaternion-splines.md §8 have six decimals.
const SPEC_TOL: f64 = 1.5e-6;
/// Optimised quantities: docs/math/quaternion-splines.md §8 says 1e-4 relative.
const OPT_TOL: f64 = 1e-4;

#[test]
fn initial_path_numbers() {
    let (t, k) = sphere7();
    let s = initial_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    let m = |i: usize| s.frames()[i].m;
    assert_quat_near(m(1), [-0.2, 0.24, 0.32, 0.0], 1e-15, "m2");
    assert_quat_near(m(3), [-0.6, -0.24, 0.08, 0.0], 1e-15, "m4");
    assert_quat_near(m(0), [0.0; 4], 0.0, "m1 = ½ω Q with ω = 0");
    assert_rel(s.objective(), 19.370029, 1e-7, "initial OBJ");
    assert_rel(
        s.covariant_acceleration(),
        8.303738,
        1e-7,
        "initial cov-acc",
    );
    let [q, q1, q2, q3] = s.eval(0.5);
    assert_quat_near(q, [0.925, 0.27, -0.04, 0.0], 1e-15, "q(0.5)");
    assert_quat_near(q1, [-0.25, 0.84, -0.08, 0.0], 1e-14, "q'(0.5)");
    assert_quat_near(q2, [-0.2, 0.24, 0.32, 0.0], 1e-14, "q''(0.5)");
    assert_quat_near(q3, [1.2, -5.76, 1.92, 0.0], 1e-13, "q'''(0.5)");
    let (f, _, _) = integrand(q, q2, 1000.0);
    assert!((f - 5.063498).abs() < SPEC_TOL, "F = {f}");
    let el = s.euler_lagrange_at(0.5);
    assert!((el.t + 0.142992).abs() < SPEC_TOL, "T = {}", el.t);
    assert!((el.t1 + 0.318621).abs() < SPEC_TOL, "T' = {}", el.t1);
    assert!((el.t2 + 10.968563).abs() < SPEC_TOL, "T'' = {}", el.t2);
    assert_quat_near(el.el, [-238.640846, -68.323096, 10.381950, 0.0], 1e-5, "EL");
    assert!((el.norm() - 248.445736).abs() < 1e-5);
    // Largest DEV segments of the initial path (S = 5).
    let mut devs = s.segment_deviations(&t, 5);
    devs.sort_by(|a, b| b.1.total_cmp(&a.1));
    let expect = [
        (3.4, 349.77),
        (3.6, 282.60),
        (5.4, 271.76),
        (3.2, 261.62),
        (0.4, 241.31),
        (5.2, 220.59),
    ];
    for ((ts, d), (te, de)) in devs.iter().zip(expect) {
        assert!(
            (ts - te).abs() < 1e-12 && (d - de).abs() < 0.006,
            "{ts} {d} vs {te} {de}"
        );
    }
}

#[test]
fn optimised_keyframe_velocities() {
    let (t, k) = sphere7();
    let fit = fit_quaternion_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    assert_eq!(fit.stages.len(), 2);
    assert_rel(
        fit.stages[1].objective,
        9.750686,
        1e-6,
        "OBJ after keyframe velocities",
    );
    let expect = [
        [-0.413265, 0.461426, 0.461029, 0.0],
        [-0.429803, -0.179014, 0.460991, 0.0],
        [-0.832135, -0.154522, 0.131588, 0.0],
        [-0.308109, -0.584450, -0.290735, 0.0],
        [-0.113874, -0.645768, -0.502743, 0.0],
    ];
    for (i, e) in expect.iter().enumerate() {
        assert_quat_near(
            fit.spline.frames()[i + 1].m,
            *e,
            1e-5,
            &format!("m{}", i + 2),
        );
    }
    let (max, mean) = fit.spline.unit_deviation(1500);
    assert!((max - 0.016415542890906853).abs() < 1e-5 && (mean - 0.004610).abs() < 1e-5);
}

/// Reference optimum of docs/math/quaternion-splines.md §8 (54 variable frames, `α = 1000`).
const OBJ_REF: f64 = 8.524169;

#[test]
fn incremental_refinement_matches_the_spec() {
    let (t, k) = sphere7();
    let fit = fit_quaternion_spline(&t, &k, false, &sphere7_options(6)).unwrap();
    let expect = [
        (0.4, 9.011019),
        (5.4, 8.735138),
        (3.4, 8.627186),
        (1.4, 8.550429),
        (4.8, 8.536225),
        (5.8, 8.534958),
    ];
    assert_eq!(fit.stages.len(), 2 + expect.len());
    for (stage, (te, oe)) in fit.stages[2..].iter().zip(expect) {
        let at = stage.inserted_at.unwrap();
        assert!((at - te).abs() < 1e-12, "inserted at {at}, expected {te}");
        assert_rel(
            stage.objective,
            oe,
            OPT_TOL,
            &format!("OBJ +{}", stage.variable_frames),
        );
    }
    // Never increases across rounds.
    for w in fit.stages.windows(2) {
        assert!(
            w[1].objective <= w[0].objective * (1.0 + 1e-12),
            "{:?}",
            fit.stages
        );
    }
    // With 5 variable frames within 0.3 % of the optimum (docs/math/quaternion-splines.md §8: 0.14 %).
    let gap5 = (fit.stages[6].objective - OBJ_REF) / OBJ_REF;
    assert!(gap5 < 0.003 && gap5 > 0.0, "gap with 5 frames {gap5}");
    let gap4 = (fit.stages[5].objective - OBJ_REF) / OBJ_REF;
    assert!((gap4 - 0.0031).abs() < 0.0002, "gap with 4 frames {gap4}");
    // Fig. 5: |EL| after optimisation is much smaller than before (largest segment DEV).
    let max_dev = |s: &HermiteQuatSpline| {
        s.segment_deviations(&t, 5)
            .iter()
            .fold(0.0f64, |m, d| m.max(d.1))
    };
    let initial = initial_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    let (before, after) = (max_dev(&initial), max_dev(&fit.spline));
    assert!(after < 0.25 * before, "max DEV {before} → {after}");
    // Unit deviation with 4 frames ≈ 0.29 % (max), below 0.3 %.
    let (max, _) = fit.spline.unit_deviation(3000);
    assert!(max < 0.003, "max unit deviation {max}");
}

#[test]
fn batch_insertion_also_descends() {
    let (t, k) = sphere7();
    let o = RbOptions {
        insertion: Insertion::Batch,
        ..sphere7_options(4)
    };
    let fit = fit_quaternion_spline(&t, &k, false, &o).unwrap();
    assert_eq!(fit.stages.len(), 3);
    assert_eq!(fit.stages[2].variable_frames, 4);
    assert!(fit.stages[2].objective < fit.stages[1].objective);
    assert_eq!(
        fit.spline.frames().iter().filter(|f| !f.keyframe).count(),
        4
    );
}

fn gradient_check(s: &HermiteQuatSpline, what: &str) {
    let x = s.variables();
    let mut g = vec![0.0; x.len()];
    let f0 = s.objective_and_gradient(&mut g);
    assert!((f0 - s.objective()).abs() <= 1e-14 * f0.abs());
    let mut work = s.clone();
    let gmax = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for i in 0..x.len() {
        let h = 1e-6;
        let mut xp = x.clone();
        xp[i] += h;
        work.set_variables(&xp);
        let fp = work.objective();
        xp[i] -= 2.0 * h;
        work.set_variables(&xp);
        let fm = work.objective();
        let fd = (fp - fm) / (2.0 * h);
        assert!(
            (fd - g[i]).abs() <= 1e-6 * gmax.max(1.0),
            "{what}: variable {i}: analytic {} vs central difference {fd}",
            g[i]
        );
    }
}

#[test]
fn gradient_matches_finite_differences() {
    let (t, k) = sphere7();
    let mut s = initial_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    gradient_check(&s, "initial");
    // With variable frames (free positions) and off-sphere values.
    s.insert_frame(0.4);
    s.insert_frame(3.7);
    let mut x = s.variables();
    let mut rng = SplitMix(0x6A_D1E7);
    for v in &mut x {
        *v += rng.range(-0.05, 0.05);
    }
    s.set_variables(&x);
    gradient_check(&s, "perturbed with frames");
    // A closed spline whose cycle returns to −Q₀ (wrap sign −1: four steps of 100° about a
    // tilted axis add up to 400°, i.e. half-angle 200°), all four components active.
    let keys: Vec<DQuat> = (0..4)
        .map(|i| {
            DQuat::from_rotation_z(100f64.to_radians() * i as f64)
                * DQuat::from_rotation_x(0.3 * (i as f64).sin())
        })
        .collect();
    let times = [0.0, 0.7, 1.5, 2.0, 3.1];
    let mut s = initial_spline(&times, &keys, true, &RbOptions::default()).unwrap();
    let p0 = s.frames()[0].p;
    assert!(
        (s.eval(3.1 - 1e-12)[0] + p0).length() < 1e-9,
        "the cycle ends at −Q₀"
    );
    s.insert_frame(2.5);
    gradient_check(&s, "closed");
}

#[test]
fn euler_lagrange_checks() {
    // Great circle q = (cos t, sin t, 0, 0): EL = 0 (with the q'''' term).
    for t in [0.0, 0.4, 2.0] {
        let (s, c) = f64::sin_cos(t);
        let q = wxyz([c, s, 0.0, 0.0]);
        let q1 = wxyz([-s, c, 0.0, 0.0]);
        let el = euler_lagrange(q, q1, -q, -q1, q, 1000.0);
        assert!(el.norm() < 1e-12, "great circle EL {}", el.norm());
        assert!((el.t + 1.0).abs() < 1e-15 && el.t1.abs() < 1e-15 && el.t2.abs() < 1e-14);
    }
    // EL = ∂F/∂q + d²/dt² ∂F/∂q'', and T', T'' against central differences, inside a piece.
    let (t, k) = sphere7();
    let s = initial_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    let alpha = s.alpha();
    for t0 in [0.37, 2.5, 4.81] {
        let h = 1e-4;
        let parts = |t: f64| {
            let [q, _, q2, _] = s.eval(t);
            integrand(q, q2, alpha)
        };
        let (_, fq, _) = parts(t0);
        let fq2 = |t: f64| parts(t).2;
        let d2 = (fq2(t0 + h) - fq2(t0) * 2.0 + fq2(t0 - h)) * (1.0 / (h * h));
        let el = s.euler_lagrange_at(t0);
        let fd = fq + d2;
        assert!(
            (fd - el.el).length() < 1e-5 * el.norm().max(1.0),
            "t={t0}: {fd} vs {}",
            el.el
        );
        let tt = |t: f64| s.euler_lagrange_at(t).t;
        let t1 = (tt(t0 + h) - tt(t0 - h)) / (2.0 * h);
        let t2 = (tt(t0 + h) - 2.0 * tt(t0) + tt(t0 - h)) / (h * h);
        assert!(
            (t1 - el.t1).abs() < 1e-6 && (t2 - el.t2).abs() < 1e-4,
            "t={t0}"
        );
    }
}

#[test]
fn inserting_a_frame_keeps_the_curve() {
    let (t, k) = sphere7();
    let fit = fit_quaternion_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    let mut s = fit.spline.clone();
    let before: Vec<[DQuat; 4]> = (0..=60).map(|i| s.eval(0.1 * i as f64)).collect();
    let o0 = s.objective();
    assert!(s.insert_frame(2.6).is_some());
    assert!(
        s.insert_frame(2.6).is_none(),
        "an existing frame time is refused"
    );
    assert!(s.insert_frame(3.0).is_none(), "a keyframe time is refused");
    assert!(s.insert_frame(7.0).is_none(), "outside the domain");
    for (i, b) in before.iter().enumerate() {
        let a = s.eval(0.1 * i as f64);
        for d in 0..3 {
            assert!(
                (a[d] - b[d]).length() < 1e-12,
                "derivative {d} at {}",
                0.1 * i as f64
            );
        }
    }
    assert!((s.objective() - o0).abs() < 1e-12 * o0);
}

#[test]
fn end_angular_velocities_are_exact() {
    let (t, k) = sphere7();
    let w0 = DVec3::new(0.3, -0.2, 0.5);
    let w1 = DVec3::new(-0.1, 0.4, 0.2);
    let o = RbOptions {
        omega_start: Some(w0),
        omega_end: Some(w1),
        variable_frames: 2,
        ..RbOptions::default()
    };
    let fit = fit_quaternion_spline(&t, &k, false, &o).unwrap();
    for (time, w) in [(0.0, w0), (6.0, w1)] {
        let [q, q1, _, _] = fit.spline.eval(time);
        let got = (q1 * q.inverse()).xyz() * 2.0;
        assert!((got - w).length() < 1e-14, "ω at {time}: {got} vs {w}");
    }
    // Free end velocities (default) optimise lower than fixed zero ones.
    let free = fit_quaternion_spline(
        &t,
        &k,
        false,
        &RbOptions {
            variable_frames: 0,
            ..RbOptions::default()
        },
    )
    .unwrap();
    let fixed = fit_quaternion_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    assert!(free.stages[1].objective < fixed.stages[1].objective);
}

#[test]
fn time_unit_does_not_matter() {
    let (t, k) = sphere7();
    let o = sphere7_options(2);
    let a = fit_quaternion_spline(&t, &k, false, &o).unwrap();
    let t2: Vec<f64> = t.iter().map(|t| 3.0 * t + 1.0).collect();
    let b = fit_quaternion_spline(&t2, &k, false, &o).unwrap();
    for i in 0..=24 {
        let u = 0.25 * i as f64;
        let qa = a.spline.eval(u)[0];
        let qb = b.spline.eval(3.0 * u + 1.0)[0];
        assert!((qa - qb).length() < 1e-6, "u={u}: {qa} vs {qb}");
    }
    // OBJ scales like (time unit)⁻³.
    let ra = a.stages.last().unwrap().objective;
    let rb = b.stages.last().unwrap().objective;
    assert_rel(rb * 27.0, ra, 1e-6, "scaled objective");
}

#[test]
fn closed_spline_is_periodic_and_smooth() {
    let keys: Vec<DQuat> = (0..5)
        .map(|i| {
            DQuat::from_axis_angle(
                DVec3::new(0.2, 1.0, 0.4 * i as f64).normalize(),
                1.1 * i as f64,
            )
        })
        .collect();
    let poses: Vec<Pose> = keys
        .iter()
        .enumerate()
        .map(|(i, q)| Pose::new(DVec3::new(i as f64, (i * i) as f64 * 0.3, 0.0), *q))
        .collect();
    let times = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
    let m = RamamoorthiBarr::from_poses(&poses, &times, true, &RbOptions::default()).unwrap();
    assert!(m.is_closed());
    assert_eq!(m.knots(), vec![0.0, 1.0, 2.0, 3.0, 4.0]);
    for (i, p) in poses.iter().enumerate() {
        assert!(m.pose_at(i as f64).approx_eq(p, 1e-12), "pose {i}");
    }
    for u in [0.0, 0.3, 4.7] {
        assert!(m.pose_at(u).approx_eq(&m.pose_at(u + 5.0), 1e-12));
    }
    // Angular velocity continuous at the wrap and at keyframes.
    let local = DVec3::new(1.0, 0.5, -0.3);
    for knot in [0.0, 2.0, 5.0] {
        let right = m.kinematics_at(knot, local).unwrap();
        let l1 = m.kinematics_at(knot - 1e-6, local).unwrap();
        let l2 = m.kinematics_at(knot - 2e-6, local).unwrap();
        let wl = l1.angular_velocity * 2.0 - l2.angular_velocity;
        let vl = l1.velocity * 2.0 - l2.velocity;
        assert!(
            (right.angular_velocity - wl).length() < 1e-8,
            "ω jump at {knot}"
        );
        assert!((right.velocity - vl).length() < 1e-8, "v jump at {knot}");
    }
    let stages = &m.fit().stages;
    assert!(stages.last().unwrap().objective < stages[0].objective);
}

#[test]
fn motion_kinematics_match_finite_differences() {
    let (t, k) = sphere7();
    let poses: Vec<Pose> = k
        .iter()
        .enumerate()
        .map(|(i, q)| {
            Pose::new(
                DVec3::new(i as f64, 0.5 * (i as f64).sin(), 0.0),
                q.normalize(),
            )
        })
        .collect();
    let m = RamamoorthiBarr::from_poses(&poses, &t, false, &sphere7_options(3)).unwrap();
    assert!(m.max_unit_deviation(3000) < 0.01);
    let local = DVec3::new(2.0, 0.0, 0.0);
    let h = 1e-4;
    for u in [0.33, 1.9, 4.45] {
        let x = |u: f64| m.pose_at(u).transform_point(local);
        let kin = m.kinematics_at(u, local).unwrap();
        let v = (x(u + h) - x(u - h)) / (2.0 * h);
        let a = (x(u + h) - x(u) * 2.0 + x(u - h)) / (h * h);
        assert!((kin.position - x(u)).length() < 1e-14);
        assert!((kin.velocity - v).length() < 1e-7, "{u}");
        assert!((kin.acceleration - a).length() < 1e-4, "{u}");
    }
}

#[test]
fn bad_input_is_named() {
    let (t, k) = sphere7();
    let o = RbOptions::default();
    let e = fit_quaternion_spline(&t[..1], &k[..1], false, &o).unwrap_err();
    assert!(matches!(e.kind(), ErrorKind::TooFewPoses { .. }), "{e}");
    let mut tt = t.clone();
    tt[3] = tt[2];
    assert_eq!(
        fit_quaternion_spline(&tt, &k, false, &o)
            .unwrap_err()
            .path(),
        "times[3]"
    );
    assert_eq!(
        fit_quaternion_spline(&t, &k, true, &o).unwrap_err().path(),
        "times"
    );
    let mut kk = k.clone();
    kk[2] *= 2.0;
    let e = fit_quaternion_spline(&t, &kk, false, &o).unwrap_err();
    assert!(
        matches!(e.kind(), ErrorKind::NonUnitQuaternion { .. } if e.path() == "keys[2]"),
        "{e}"
    );
    kk[2] = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert_eq!(
        fit_quaternion_spline(&t, &kk, false, &o)
            .unwrap_err()
            .path(),
        "keys[2]"
    );
    for bad in [
        RbOptions { alpha: -1.0, ..o },
        RbOptions {
            alpha: f64::NAN,
            ..o
        },
        RbOptions {
            segments_per_interval: 0,
            ..o
        },
        RbOptions {
            gauss_nodes: 0,
            ..o
        },
        RbOptions {
            gauss_nodes: 1000,
            ..o
        },
        RbOptions {
            omega_start: Some(DVec3::new(f64::NAN, 0.0, 0.0)),
            ..o
        },
    ] {
        assert!(
            fit_quaternion_spline(&t, &k, false, &bad).is_err(),
            "{bad:?}"
        );
    }
    let closed_times: Vec<f64> = (0..8).map(|i| i as f64).collect();
    let e = fit_quaternion_spline(
        &closed_times,
        &k,
        true,
        &RbOptions {
            omega_end: Some(DVec3::X),
            ..o
        },
    )
    .unwrap_err();
    assert!(matches!(e.kind(), ErrorKind::Unsupported { .. }));
    let poses = vec![
        Pose::IDENTITY,
        Pose {
            rotation: DQuat::from_xyzw(0.0, 0.0, 0.0, 3.0),
            ..Pose::IDENTITY
        },
    ];
    let e = RamamoorthiBarr::from_poses(&poses, &[0.0, 1.0], false, &o).unwrap_err();
    assert_eq!(e.path(), "poses[1].rotation");
    // More variable frames than candidate segments: stops when none is left, no panic.
    let fit = fit_quaternion_spline(
        &t[..3],
        &k[..3],
        false,
        &RbOptions {
            variable_frames: 50,
            segments_per_interval: 2,
            min_relative_decrease: 0.0,
            ..o
        },
    )
    .unwrap();
    assert_eq!(fit.spline.frames().len(), 5);
    // Optimiser on the identity path: nothing to do.
    let same = vec![DQuat::IDENTITY; 3];
    let fit = fit_quaternion_spline(&[0.0, 1.0, 2.0], &same, false, &o).unwrap();
    assert!(fit.stages.last().unwrap().objective < 1e-20);
    let mut s = fit.spline;
    let r = optimise_spline(&mut s, &o.lbfgs);
    assert!(r.value.is_finite());
}

#[test]
fn reference_optimum_with_a_frame_at_every_segment() {
    // docs/math/quaternion-splines.md §7.1: a variable frame at every segment start (24 frames for 7 keyframes, S = 5)
    // gives OBJ 8.525252; the 54-frame reference is 8.524169.
    let (t, k) = sphere7();
    let fit = fit_quaternion_spline(&t, &k, false, &sphere7_options(0)).unwrap();
    let mut s = fit.spline;
    for i in 0..6 {
        for j in 1..5 {
            assert!(s.insert_frame(i as f64 + j as f64 / 5.0).is_some());
        }
    }
    optimise_spline(&mut s, &RbOptions::default().lbfgs);
    assert_rel(s.objective(), 8.525252, OPT_TOL, "24-frame reference");
    assert!((s.objective() - OBJ_REF) / OBJ_REF < 2e-4);
}
