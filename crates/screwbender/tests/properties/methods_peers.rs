//! The classical peers: piecewise SLERP + linear origins, Catmull–Rom + Squad, and the
//! Kim–Kim–Shin B-spline quaternion curve: interpolation, continuity, open and closed forms,
//! exactness where the method has it, and bad input.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::methods::{kinematics_at, DecoupledSmooth, KimKimShin, Side, SlerpPolyline};
use screwbender::ErrorKind;
use screwbender::{Motion, Pose};
use testkit::methods::{l_cycle_rotated, SplitMix};

/// Interpolation and periodicity are exact up to round-off.
const EXACT: f64 = 1e-12;

fn random_poses(seed: u64, n: usize) -> Vec<Pose> {
    let mut rng = SplitMix(seed);
    (0..n).map(|_| rng.pose(4.0, 2.5)).collect()
}

fn peers(poses: &[Pose], closed: bool) -> Vec<Box<dyn Motion>> {
    vec![
        Box::new(SlerpPolyline::new(poses, closed).unwrap()),
        Box::new(DecoupledSmooth::new(poses, closed).unwrap()),
        Box::new(KimKimShin::new(poses, closed).unwrap()),
    ]
}

#[test]
fn domains_knots_and_periodicity() {
    const SEED: u64 = 0xBEE5;
    for n in [2usize, 3, 6] {
        let poses = random_poses(SEED + n as u64, n);
        for closed in [false, true] {
            for m in peers(&poses, closed) {
                let spans = if closed { n } else { n - 1 };
                assert_eq!(m.domain(), (0.0, spans as f64), "{}", m.name());
                assert_eq!(m.knots().len(), n);
                assert_eq!(m.is_closed(), closed);
                if closed {
                    for u in [0.0, 0.37, n as f64 - 0.2] {
                        let (a, b) = (m.pose_at(u), m.pose_at(u + n as f64));
                        assert!(
                            a.approx_eq(&b, EXACT),
                            "seed {SEED} n={n} {} u={u}",
                            m.name()
                        );
                    }
                    // Continuous across the wrap.
                    let (a, b) = (m.pose_at(n as f64 - 1e-9), m.pose_at(0.0));
                    assert!(a.approx_eq(&b, 1e-7), "seed {SEED} n={n} {} wrap", m.name());
                }
                for u in [-0.5, 0.5, spans as f64 + 0.5, f64::NAN] {
                    let p = m.pose_at(u);
                    assert!(u.is_nan() || p.is_finite(), "{} at {u}", m.name());
                }
            }
        }
    }
}

#[test]
fn interpolating_peers_pass_through_the_poses() {
    const SEED: u64 = 0x1A7E;
    for case in 0..10u64 {
        let poses = random_poses(SEED + case, 5);
        for closed in [false, true] {
            for m in &peers(&poses, closed)[..2] {
                for (i, p) in poses.iter().enumerate() {
                    assert!(
                        m.pose_at(i as f64).approx_eq(p, EXACT),
                        "seed {SEED} case {case} {} pose {i}",
                        m.name()
                    );
                }
            }
            // Kim–Kim–Shin approximates, but an open curve starts and ends at the end poses.
            if !closed {
                let k = KimKimShin::new(&poses, false).unwrap();
                assert!(k.pose_at(0.0).approx_eq(&poses[0], EXACT), "case {case}");
                assert!(k.pose_at(4.0).approx_eq(&poses[4], EXACT), "case {case}");
            }
        }
    }
}

/// Largest jump of velocity / angular velocity / acceleration at interior knots, by one-sided
/// differences (what the metrics do).
fn jumps(m: &dyn Motion) -> (f64, f64) {
    let knots = m.knots();
    let inner = if m.is_closed() {
        &knots[..]
    } else {
        &knots[1..knots.len() - 1]
    };
    let (mut v, mut a) = (0.0f64, 0.0f64);
    for &u in inner {
        for local in [DVec3::ZERO, DVec3::new(2.0, 0.0, 0.0)] {
            let l = kinematics_at(m, u, local, Side::Left);
            let r = kinematics_at(m, u, local, Side::Right);
            v = v.max((l.velocity - r.velocity).length());
            v = v.max((l.angular_velocity - r.angular_velocity).length());
            a = a.max((l.acceleration - r.acceleration).length());
            a = a.max((l.angular_acceleration - r.angular_acceleration).length());
        }
    }
    (v, a)
}

#[test]
fn continuity_orders() {
    let poses = l_cycle_rotated();
    for closed in [false, true] {
        let [slerp, squad, kks] = <[Box<dyn Motion>; 3]>::try_from(peers(&poses, closed))
            .ok()
            .unwrap();
        let (v, _) = jumps(slerp.as_ref());
        assert!(v > 1.0, "slerp polyline is C0: {v}");
        let (v, a) = jumps(squad.as_ref());
        assert!(
            v < 1e-5 && a > 0.1,
            "Catmull-Rom + Squad is C1, not C2: {v} {a}"
        );
        let (v, a) = jumps(kks.as_ref());
        assert!(v < 1e-5 && a < 1e-4, "Kim-Kim-Shin is C2: {v} {a}");
    }
}

#[test]
fn kks_about_one_axis_is_the_angle_b_spline() {
    // Rotations about z by θ_i: the quaternion curve is the rotation by the cubic B-spline of
    // the angles, and the origin the B-spline of the origins.
    let angles = [0.3f64, -0.4, 1.2, 2.0, 1.1];
    let poses: Vec<Pose> = angles
        .iter()
        .enumerate()
        .map(|(i, &a)| {
            Pose::new(
                DVec3::new(i as f64, (i * i) as f64, 0.0),
                DQuat::from_rotation_z(a),
            )
        })
        .collect();
    let m = KimKimShin::new(&poses, true).unwrap();
    let n = angles.len();
    for k in 0..50 {
        let u = k as f64 * n as f64 / 50.0;
        let j = u.floor() as usize;
        let f = u - j as f64;
        let b = [
            (1.0 - f).powi(3) / 6.0,
            (3.0 * f.powi(3) - 6.0 * f * f + 4.0) / 6.0,
            (-3.0 * f.powi(3) + 3.0 * f * f + 3.0 * f + 1.0) / 6.0,
            f.powi(3) / 6.0,
        ];
        let idx = |d: usize| (j + n + d - 1) % n;
        let theta: f64 = (0..4).map(|d| b[d] * angles[idx(d)]).sum();
        let origin: DVec3 = (0..4).map(|d| poses[idx(d)].origin * b[d]).sum();
        let want = Pose::new(origin, DQuat::from_rotation_z(theta));
        assert!(m.pose_at(u).approx_eq(&want, 1e-13), "u={u}");
    }
}

#[test]
fn decoupled_reproduces_uniform_rotation_and_lines() {
    // A uniform rotation about a fixed axis with the origin moving on a line: Squad's inner
    // quaternions equal the keys, Catmull–Rom reproduces the line, so the motion is exact.
    let axis = DVec3::new(0.3, -0.2, 0.9).normalize();
    let exact = |u: f64| {
        Pose::new(
            DVec3::new(1.0, 2.0, -1.0) + DVec3::new(0.5, -0.25, 1.0) * u,
            DQuat::from_axis_angle(axis, 0.7 * u),
        )
    };
    let poses: Vec<Pose> = (0..6).map(|i| exact(i as f64)).collect();
    let m = DecoupledSmooth::new(&poses, false).unwrap();
    for k in 0..=50 {
        let u = k as f64 * 0.1;
        assert!(m.pose_at(u).approx_eq(&exact(u), 1e-12), "u={u}");
    }
    // The polyline does the same (piecewise exact).
    let m = SlerpPolyline::new(&poses, false).unwrap();
    assert!(m.pose_at(2.35).approx_eq(&exact(2.35), 1e-12));
}

#[test]
fn closed_cycles_with_sign_flips() {
    // Quaternions given with alternating signs and a cycle whose canonical signs return to −q0.
    let poses: Vec<Pose> = (0..5)
        .map(|i| {
            let q = DQuat::from_axis_angle(DVec3::new(0.1, 0.2, 1.0).normalize(), 1.3 * i as f64);
            Pose::new(
                DVec3::new(i as f64, 0.0, 0.0),
                if i % 2 == 1 { -q } else { q },
            )
        })
        .collect();
    for m in peers(&poses, true) {
        let mut prev = m.pose_at(0.0);
        for k in 1..=500 {
            let p = m.pose_at(k as f64 * 5.0 / 500.0);
            assert!(prev.angle_to(&p) < 0.1, "{} jumps at step {k}", m.name());
            prev = p;
        }
    }
}

#[test]
fn slerp_kinematics_match_finite_differences() {
    let poses = random_poses(0x51E5, 5);
    let m = SlerpPolyline::new(&poses, true).unwrap();
    let local = DVec3::new(0.4, 1.0, -0.7);
    for u in [0.2, 1.5, 3.7, 4.9] {
        let a = m.kinematics_at(u, local).unwrap();
        let f = screwbender::methods::finite_difference(&m, u, local, Side::Central);
        assert!((a.position - f.position).length() < 1e-14);
        assert!((a.velocity - f.velocity).length() < 1e-6, "{u}");
        assert!((a.acceleration - f.acceleration).length() < 1e-4, "{u}");
        assert!(
            (a.angular_velocity - f.angular_velocity).length() < 1e-6,
            "{u}"
        );
        assert!(f.angular_acceleration.length() < 1e-4);
    }
}

#[test]
fn bad_input_is_named() {
    let good = random_poses(7, 3);
    let mut bad = good.clone();
    bad[1].origin.y = f64::NAN;
    let single = &good[..1];
    for closed in [false, true] {
        let errs = [
            SlerpPolyline::new(&bad, closed).unwrap_err(),
            DecoupledSmooth::new(&bad, closed).unwrap_err(),
            KimKimShin::new(&bad, closed).unwrap_err(),
        ];
        for e in errs {
            assert_eq!(e.path(), "poses[1]", "{e}");
        }
        assert!(matches!(
            SlerpPolyline::new(single, closed)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::TooFewPoses { .. })
        ));
        assert!(matches!(
            DecoupledSmooth::new(single, closed)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::TooFewPoses { .. })
        ));
        assert!(matches!(
            KimKimShin::new(single, closed)
                .as_ref()
                .map_err(|e| e.kind()),
            Err(ErrorKind::TooFewPoses { .. })
        ));
    }
    let mut scaled = good;
    scaled[2].rotation *= 3.0;
    let e = KimKimShin::new(&scaled, false).unwrap_err();
    assert!(
        matches!(e.kind(), ErrorKind::NonUnitQuaternion { .. } if e.path() == "poses[2].rotation"),
        "{e}"
    );
    // Identical consecutive poses are a rest, not an error.
    let same = vec![Pose::IDENTITY; 3];
    for m in peers(&same, false) {
        assert!(
            m.pose_at(0.7).approx_eq(&Pose::IDENTITY, 1e-15),
            "{}",
            m.name()
        );
    }
}
