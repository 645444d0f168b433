//! The cumulative B-splines on SE(3) and on R³ × SO(3): analytic derivatives (Sommer et al.'s
//! recursion) against finite differences, C² at the knots, the interpolating variant through its
//! poses, the split spline against Kim–Kim–Shin's construction, frame independence on SE(3), and
//! the error when interpolation cannot converge.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::methods::{
    KimKimShin, LieBSpline, LieGroup, Se3, Se3BSpline, SplitBSpline, SplitSe3,
};
use screwbender::{ErrorKind, Motion, Pose};
use testkit::methods::{l_cycle_rotated, SplitMix};

fn random_poses(seed: u64, n: usize) -> Vec<Pose> {
    let mut rng = SplitMix(seed);
    (0..n).map(|_| rng.pose(4.0, 1.2)).collect()
}

/// A cycle of poses turning by well under half a turn between neighbours, with long
/// translations (the interpolating spline needs its control poses less than half a turn apart).
fn gentle_poses(seed: u64, n: usize) -> Vec<Pose> {
    let mut rng = SplitMix(seed);
    let (a, b, c) = (rng.unit() * 1.2, rng.unit() * 1.2, rng.unit() * 0.5);
    (0..n)
        .map(|i| {
            let t = i as f64 * std::f64::consts::TAU / n as f64;
            Pose::new(
                DVec3::new(5.0 * t.cos(), 3.0 * t.sin(), rng.range(-1.0, 1.0)),
                DQuat::from_scaled_axis(a * t.cos() + b * t.sin() + c),
            )
        })
        .collect()
}

/// A body point off the local origin, so that rotation and translation both show.
const LOCAL: DVec3 = DVec3::new(0.7, -0.4, 1.1);

/// Analytic velocity and acceleration of a body point and the body's angular rates against
/// central differences of poses; the jerk against central differences of the analytic
/// acceleration.
fn derivatives_match_differences<G: LieGroup>(spline: &LieBSpline<G>, what: &str) {
    let h = 1e-4;
    let (a, b) = spline.domain();
    for k in 0..23 {
        // Away from the knots so that each difference stays within one span.
        let u = a + (b - a) * (k as f64 + 0.37) / 23.0;
        if (u - u.round()).abs() < 3.0 * h {
            continue;
        }
        let k0 = spline.kinematics_at(u, LOCAL).unwrap();
        let x = |u: f64| spline.pose_at(u).transform_point(LOCAL);
        let v = (x(u + h) - x(u - h)) / (2.0 * h);
        let acc = (x(u + h) - 2.0 * x(u) + x(u - h)) / (h * h);
        assert!((k0.position - x(u)).length() < 1e-13, "{what} u={u}");
        assert!(
            (k0.velocity - v).length() < 1e-7,
            "{what} u={u}: {k0:?} {v}"
        );
        assert!(
            (k0.acceleration - acc).length() < 1e-5,
            "{what} u={u}: {k0:?} {acc}"
        );
        // ω from the rotation's difference: q(u+h) q(u−h)⁻¹ ≈ exp(2h ω).
        let q = |u: f64| spline.pose_at(u).rotation;
        let w = (q(u + h) * q(u - h).conjugate()).to_scaled_axis() / (2.0 * h);
        assert!((k0.angular_velocity - w).length() < 1e-7, "{what} u={u}");
        let wk = |u: f64| spline.kinematics_at(u, LOCAL).unwrap().angular_velocity;
        let alpha = (wk(u + h) - wk(u - h)) / (2.0 * h);
        assert!(
            (k0.angular_acceleration - alpha).length() < 1e-7,
            "{what} u={u}"
        );
        let d = |u: f64| spline.derivatives(u).acceleration;
        let jerk = (d(u + h) - d(u - h)) * (0.5 / h);
        assert!(
            (spline.derivatives(u).jerk - jerk).size() < 1e-6,
            "{what} u={u}"
        );
    }
}

#[test]
fn derivatives_are_those_of_the_poses() {
    let poses = random_poses(11, 6);
    let gentle = gentle_poses(11, 7);
    for closed in [true, false] {
        derivatives_match_differences(&Se3BSpline::new(&poses, closed).unwrap(), "se3");
        derivatives_match_differences(&SplitBSpline::new(&poses, closed).unwrap(), "split");
        derivatives_match_differences(
            &Se3BSpline::interpolating(&gentle, closed).unwrap(),
            "se3 interpolating",
        );
    }
}

/// The largest jump of velocity and acceleration at the knots, between the analytic values
/// just before a knot (the previous span) and at it (the next span).
fn knot_jumps(m: &dyn Motion) -> (f64, f64) {
    let eps = 1e-9;
    let (a, b) = m.domain();
    let mut worst = (0.0f64, 0.0f64);
    for knot in m.knots() {
        if knot <= a || knot >= b {
            continue;
        }
        let l = m.kinematics_at(knot - eps, LOCAL).unwrap();
        let r = m.kinematics_at(knot, LOCAL).unwrap();
        let dv =
            (l.velocity - r.velocity).length() + (l.angular_velocity - r.angular_velocity).length();
        let da = (l.acceleration - r.acceleration).length()
            + (l.angular_acceleration - r.angular_acceleration).length();
        worst = (worst.0.max(dv), worst.1.max(da));
    }
    worst
}

#[test]
fn twice_continuous_at_the_knots() {
    let poses = random_poses(5, 7);
    for closed in [true, false] {
        let splines: [Box<dyn Motion>; 3] = [
            Box::new(Se3BSpline::new(&poses, closed).unwrap()),
            Box::new(SplitBSpline::new(&poses, closed).unwrap()),
            Box::new(Se3BSpline::interpolating(&gentle_poses(5, 7), closed).unwrap()),
        ];
        for s in &splines {
            let (dv, da) = knot_jumps(s.as_ref());
            // Over 1e-9 the acceleration changes by the jerk times 1e-9.
            assert!(
                dv < 1e-7 && da < 1e-6,
                "{} closed={closed}: {dv:e} {da:e}",
                s.name()
            );
        }
        // A closed spline also joins at its seam.
        if closed {
            let s = &splines[0];
            let end = s.domain().1;
            let l = s.kinematics_at(end - 1e-9, LOCAL).unwrap();
            let r = s.kinematics_at(0.0, LOCAL).unwrap();
            assert!((l.acceleration - r.acceleration).length() < 1e-6);
        }
    }
}

fn passes_through<G: LieGroup>(poses: &[Pose], closed: bool) {
    let s = LieBSpline::<G>::interpolating(poses, closed).unwrap();
    for (i, p) in poses.iter().enumerate() {
        let d = s.pose_at(i as f64).distance(p);
        assert!(d < 1e-10, "{} closed={closed} pose {i}: {d:e}", G::NAME);
    }
    // It is not the approximating spline: its control poses moved.
    let moved = s
        .control_poses()
        .iter()
        .zip(poses)
        .map(|(c, p)| c.distance(p))
        .fold(0.0, f64::max);
    assert!(moved > 1e-3, "{}", G::NAME);
}

#[test]
fn interpolating_variant_passes_through_its_poses() {
    for closed in [true, false] {
        let poses = gentle_poses(3, 9);
        passes_through::<Se3>(&poses, closed);
        passes_through::<SplitSe3>(&poses, closed);
    }
    // The preset's cycle closes with a turn of 105°, its interpolating control poses would be
    // 181° apart there: only its open sequence has an interpolating spline.
    passes_through::<Se3>(&l_cycle_rotated(), false);
    passes_through::<SplitSe3>(&l_cycle_rotated(), false);
    let e = Se3BSpline::interpolating(&l_cycle_rotated(), true).unwrap_err();
    assert_eq!(e.path(), "poses");
}

#[test]
fn open_ends_are_the_end_poses() {
    let poses = random_poses(8, 5);
    let se3 = Se3BSpline::new(&poses, false).unwrap();
    assert!(se3.pose_at(0.0).approx_eq(&poses[0], 1e-12));
    assert!(se3.pose_at(4.0).approx_eq(&poses[4], 1e-12));
    assert_eq!(se3.domain(), (0.0, 4.0));
    let closed = Se3BSpline::new(&poses, true).unwrap();
    assert_eq!(closed.domain(), (0.0, 5.0));
    assert!(closed.pose_at(5.0).approx_eq(&closed.pose_at(0.0), 1e-12));
    assert!(closed.pose_at(-0.5).approx_eq(&closed.pose_at(4.5), 1e-12));
}

#[test]
fn split_spline_is_kim_kim_shin() {
    let poses = random_poses(21, 6);
    for closed in [true, false] {
        let split = SplitBSpline::new(&poses, closed).unwrap();
        let kks = KimKimShin::new(&poses, closed).unwrap();
        for k in 0..=50 {
            let u = split.domain().1 * k as f64 / 50.0;
            let (a, b) = (split.pose_at(u), kks.pose_at(u));
            assert!(a.approx_eq(&b, 1e-12), "closed={closed} u={u}");
        }
    }
}

/// SE(3)'s spline commutes with changes of the local frame (`P_i ∘ C`) and of the world frame
/// (`W ∘ P_i`); the split spline does not.
#[test]
fn se3_spline_is_frame_independent() {
    let poses = gentle_poses(13, 6);
    let c = Pose::new(
        DVec3::new(0.3, -2.0, 1.0),
        DQuat::from_axis_angle(DVec3::new(1.0, 1.0, 0.0).normalize(), 0.9),
    );
    let local: Vec<Pose> = poses.iter().map(|p| p.compose(&c)).collect();
    let world: Vec<Pose> = poses.iter().map(|p| c.compose(p)).collect();
    let worst = |build: &dyn Fn(&[Pose]) -> Box<dyn Motion>| {
        let (m, ml, mw) = (build(&poses), build(&local), build(&world));
        (0..=60)
            .map(|k| {
                let u = k as f64 / 10.0;
                let p = m.pose_at(u);
                p.compose(&c).distance(&ml.pose_at(u)) + c.compose(&p).distance(&mw.pose_at(u))
            })
            .fold(0.0, f64::max)
    };
    let se3 = worst(&|p| Box::new(Se3BSpline::new(p, true).unwrap()));
    let interp = worst(&|p| Box::new(Se3BSpline::interpolating(p, true).unwrap()));
    let split = worst(&|p| Box::new(SplitBSpline::new(p, true).unwrap()));
    assert!(se3 < 1e-12 && interp < 1e-11, "{se3:e} {interp:e}");
    assert!(split > 1e-2, "{split:e}");
}

#[test]
fn interpolation_that_cannot_converge_is_an_error() {
    // Half turns back and forth about alternating axes: every neighbour is π away, so the
    // knots' corrections do not contract.
    let poses: Vec<Pose> = (0..6)
        .map(|i| {
            let axis = if i % 2 == 0 { DVec3::X } else { DVec3::Y };
            Pose::new(
                DVec3::new(i as f64, 0.0, 0.0),
                DQuat::from_axis_angle(axis, 3.1 * (i % 3) as f64),
            )
        })
        .collect();
    let e = Se3BSpline::interpolating(&poses, true).unwrap_err();
    assert_eq!(e.path(), "poses");
    assert!(matches!(e.kind(), ErrorKind::Unsupported { .. }), "{e}");
    assert!(
        e.to_string().contains("interpolating SE(3) B-spline"),
        "{e}"
    );
    // Bad poses are named as for every method.
    let mut bad = random_poses(1, 4);
    bad[2].origin.x = f64::NAN;
    assert!(Se3BSpline::new(&bad, false)
        .unwrap_err()
        .path()
        .contains("poses[2]"));
}
