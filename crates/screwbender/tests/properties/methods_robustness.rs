//! No public function of `screwbender::methods` panics on hostile input: empty, NaN, infinite,
//! mismatched lengths, huge sizes. Constructors return errors; evaluation returns (possibly
//! non-finite) values.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::methods::*;
use screwbender::Pose;
use testkit::methods::SplitMix;

const ZERO_Q: DQuat = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);

#[test]
fn spline_constructors_reject_bad_frames() {
    let f = |t: f64| Frame {
        t,
        p: DQuat::IDENTITY,
        m: ZERO_Q,
        pos_free: false,
        vel_free: true,
        keyframe: true,
    };
    assert!(HermiteQuatSpline::new(vec![], false, 0.0, 1.0, 1.0, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![], true, 1.0, 1.0, 1.0, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![f(0.0)], false, 0.0, 1.0, 1.0, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![f(0.0), f(0.0)], false, 0.0, 1.0, 1.0, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![f(0.0), f(f64::NAN)], false, 0.0, 1.0, 1.0, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![f(0.0), f(1.0)], false, 0.0, 1.0, f64::NAN, 10).is_err());
    assert!(HermiteQuatSpline::new(vec![f(0.0), f(1.0)], true, 1.0, 1.0, 1.0, 10).is_err());
    let mut bad = f(1.0);
    bad.m = DQuat::from_xyzw(f64::INFINITY, 0.0, 0.0, 0.0);
    let e = HermiteQuatSpline::new(vec![f(0.0), bad], false, 0.0, 1.0, 1.0, 10).unwrap_err();
    assert_eq!(e.path(), "frames[1].m");
    // A closed spline with a single frame is a loop: fine, and evaluates everywhere.
    let s = HermiteQuatSpline::new(vec![f(0.0)], true, 2.0, -1.0, 1.0, 0).unwrap();
    for t in [-3.0, 0.0, 1.0, 7.5, f64::NAN, f64::INFINITY] {
        let _ = s.eval(t);
        let _ = s.euler_lagrange_at(t);
    }
    let _ = s.objective(); // NaN here: the curve from p to −p passes through 0 at a node
                           // Hostile arguments to the analysis functions.
    let mut s = HermiteQuatSpline::new(vec![f(0.0), f(1.0)], false, 0.0, 1.0, 1.0, 10).unwrap();
    let _ = s.segment_deviations(&[], 5);
    let _ = s.segment_deviations(&[0.0, f64::NAN, 1.0], 0);
    let _ = s.segment_deviations(&[1.0, 0.0], 3);
    assert!(s.insert_frame(f64::NAN).is_none());
    assert!(s.insert_frame(f64::INFINITY).is_none());
    s.set_variables(&[1.0; 3]);
    s.set_alpha(f64::NAN);
    let mut g = vec![0.0; 1];
    assert!(s.objective_and_gradient(&mut g).is_finite());
    let _ = s.unit_deviation(0);
}

#[test]
fn catmull_rom_and_polynomials() {
    let p = [DVec3::ZERO, DVec3::X];
    assert!(CatmullRom::new(&[0.0, 1.0], &p, false).is_ok());
    assert!(CatmullRom::new(&[0.0, 1.0], &p, true).is_err());
    assert!(CatmullRom::new(&[1.0, 0.0], &p, false).is_err());
    assert!(CatmullRom::new(&[0.0, f64::NAN], &p, false).is_err());
    assert!(CatmullRom::new(&[0.0, 1.0], &[DVec3::ZERO, DVec3::NAN], false).is_err());
    let c = CatmullRom::new(&[0.0, 1.0, 2.0], &p, true).unwrap();
    for t in [f64::NAN, f64::INFINITY, -1e300] {
        let _ = c.eval(t);
    }
    assert_eq!(bezier_d2(&[3.0], 0.4), (3.0, 0.0, 0.0));
    assert_eq!(bezier(&[1.0, 3.0], 0.5), 2.0);
    let (x, w) = gauss_legendre(0);
    assert_eq!((x.len(), w.len()), (1, 1));
    let (x, _) = gauss_legendre(usize::MAX);
    assert_eq!(x.len(), MAX_GAUSS_NODES);
}

#[test]
fn bezier_export_with_inconsistent_arrays() {
    let seg = RationalBezierSegment {
        t_start: 0.0,
        t_end: 1.0,
        degree: 2,
        weights: vec![1.0, 0.5, 1.0, 7.0, 9.0],
        quaternions: vec![],
        a: vec![[0.0; 3]; 5],
        x: vec![],
        y: vec![[1.0; 3]],
    };
    assert!(seg.evaluate(&seg.a, 0.3).is_finite());
    let _ = seg.evaluate(&seg.x, 0.3);
    let _ = seg.evaluate(&seg.y, 0.3);
    assert!(seg.control_point(&seg.x, 0).is_none());
    assert!(seg.control_point(&seg.a, 9).is_none());
}

#[test]
fn rational_and_rb_reject_garbage() {
    let s = TriangleSample {
        t: 0.0,
        a: DVec3::ZERO,
        x: DVec3::X,
        y: DVec3::Y,
    };
    for c in [
        Continuity::C0,
        Continuity::C1(EndCondition::ZeroCurvatureEnd),
    ] {
        assert!(RationalMotion::fit(&[], c).is_err());
        assert!(RationalMotion::fit(&[s], c).is_err());
        assert!(RationalMotion::fit_closed(&[s], f64::NAN, c).is_err());
        assert!(RationalMotion::fit_closed(&[], 1.0, c).is_err());
        assert!(RationalMotion::from_poses(&[], &[], false, c, &Default::default()).is_err());
        assert!(RationalMotion::from_poses(&[], &[0.0], true, c, &Default::default()).is_err());
        let degenerate = ReferenceTriangle {
            a: DVec3::ZERO,
            x: DVec3::ZERO,
            y: DVec3::ZERO,
        };
        let poses = [Pose::IDENTITY, Pose::from_translation(DVec3::X)];
        let e = RationalMotion::from_poses(&poses, &[0.0, 1.0], false, c, &degenerate).unwrap_err();
        assert_eq!(e.path(), "samples[0]");
    }
    let q = [DQuat::IDENTITY; 2];
    let o = RbOptions::default();
    assert!(fit_quaternion_spline(&[], &[], false, &o).is_err());
    assert!(fit_quaternion_spline(&[0.0, f64::INFINITY], &q, false, &o).is_err());
    assert!(fit_quaternion_spline(&[0.0, 1.0], &[DQuat::NAN; 2], false, &o).is_err());
    let huge = RbOptions {
        variable_frames: usize::MAX,
        ..o
    };
    assert!(fit_quaternion_spline(&[0.0, 1.0], &q, false, &huge).is_err());
    let huge = RbOptions {
        segments_per_interval: usize::MAX,
        ..o
    };
    assert!(fit_quaternion_spline(&[0.0, 1.0], &q, false, &huge).is_err());
    assert!(RamamoorthiBarr::from_poses(&[Pose::IDENTITY; 2], &[0.0], false, &o).is_err());
}

#[test]
fn random_poses_never_break_any_method() {
    const SEED: u64 = 0x0DD_BA11;
    let mut rng = SplitMix(SEED);
    for case in 0..6 {
        let n = 2 + (rng.uniform() * 4.0) as usize;
        // Large rotations, including exact half turns and repeated poses.
        let mut poses: Vec<Pose> = (0..n)
            .map(|_| rng.pose(5.0, std::f64::consts::PI))
            .collect();
        if case % 3 == 1 {
            poses[1] = poses[0];
        }
        if case % 3 == 2 {
            poses[1].rotation =
                DQuat::from_axis_angle(DVec3::Z, std::f64::consts::PI) * poses[0].rotation;
        }
        for closed in [false, true] {
            for m in Method::applicable(closed) {
                let motion = match m.build(&poses, closed) {
                    Ok(x) => x,
                    Err(e) => {
                        // Only documented rejections (a vanishing C¹ denominator).
                        assert!(m == Method::Cc1, "seed {SEED:#x} case {case} {m}: {e}");
                        continue;
                    }
                };
                let (a, b) = motion.domain();
                for k in 0..=20 {
                    let p = motion.pose_at(a + (b - a) * k as f64 / 20.0);
                    assert!(
                        p.is_finite(),
                        "seed {SEED:#x} case {case} {m} closed={closed}"
                    );
                }
                if matches!(
                    m,
                    Method::FourPoint
                        | Method::Polyscrew
                        | Method::Slerp
                        | Method::Decoupled
                        | Method::Rb
                        | Method::Cc0
                        | Method::Cc1
                ) {
                    for (i, p) in poses.iter().enumerate() {
                        assert!(
                            motion.pose_at(i as f64).approx_eq(p, 1e-9),
                            "seed {SEED:#x} case {case} {m} closed={closed}: pose {i}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn metrics_with_odd_options() {
    let poses = vec![Pose::IDENTITY, Pose::from_translation(DVec3::X)];
    let o = MetricsOptions {
        body_points: vec![],
        quadrature_subintervals: 0,
        samples_per_span: 0,
        ..MetricsOptions::default()
    };
    let t = compare_methods(&poses, false, &[Method::Slerp, Method::Kks], &o).unwrap();
    assert_eq!(t.rows.len(), 2);
    assert!(t.to_text().contains("slerp"));
    assert!(compare_methods(&poses[..1], false, &[Method::Slerp], &o).is_err());
    let e = compare_methods(&poses, true, &[Method::Cc1], &o).unwrap_err();
    assert!(e.path().starts_with("cc1"), "{e}");
}
