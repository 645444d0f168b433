//! Properties of `screw(a, t, b)` (docs/math/screw.md §4–§6) over random and degenerate inputs, natively and
//! in the browser. Exact expectations come from constructing `b` by a known screw motion.

// The math notes print values like 0.707107 (docs/math/README.md §3): comparing with them is the point.
#![allow(clippy::approx_constant)]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use std::f64::consts::PI;

use glam::{DQuat, DVec3};
use screwbender::{screw, screw_paper, Pose, Screw, ScrewKind};
use testkit::{assert_pose_near, Rng};

/// Random pose pairs per property.
const CASES: usize = 500;
/// Tolerance for identities between screws of well-conditioned random pairs (scene scale ~5).
const TOL: f64 = 1e-12;

/// The exact screw motion: rotation by `t·angle` about the axis through `point` with direction
/// `axis`, plus slide `t·slide` along it, applied to `a`.
fn exact(a: &Pose, axis: DVec3, point: DVec3, angle: f64, slide: f64, t: f64) -> Pose {
    let r = DQuat::from_axis_angle(axis, t * angle);
    let g = Pose::new(point - r * point + t * slide * axis, r);
    g.compose(a)
}

#[test]
fn paper_route_agrees_with_closed_form() {
    let mut rng = Rng::new(1);
    for case in 0..2000 {
        let (a, b) = (rng.pose(5.0), rng.pose(5.0));
        // The paper's route needs the angle away from 0 (its accuracy is ε/θ) and from π
        // (where the two routes may pick different minimal screws).
        let angle = a.angle_to(&b);
        if !(1e-3..PI - 1e-3).contains(&angle) {
            continue;
        }
        for t in [0.0, 0.25, 0.5, 1.0, 1.7, -0.6] {
            let tol = 1e-12 / (PI - angle).min(1.0);
            assert_pose_near(
                &screw(&a, t, &b),
                &screw_paper(&a, t, &b),
                tol,
                &format!("case {case} t={t}"),
            );
        }
    }
}

#[test]
fn endpoints_and_reversal() {
    let mut rng = Rng::new(2);
    for case in 0..CASES {
        let (a, b) = (rng.pose(5.0), rng.pose(5.0));
        assert_pose_near(&screw(&a, 0.0, &b), &a, TOL, &format!("case {case} t=0"));
        assert_pose_near(&screw(&a, 1.0, &b), &b, TOL, &format!("case {case} t=1"));
        if a.angle_to(&b) < PI - 1e-6 {
            for t in [0.1, 0.5, 0.8, 1.3, -0.4] {
                assert_pose_near(
                    &screw(&a, t, &b),
                    &screw(&b, 1.0 - t, &a),
                    TOL,
                    &format!("reversal case {case} t={t}"),
                );
            }
        }
    }
}

#[test]
fn one_parameter_subgroup() {
    let mut rng = Rng::new(3);
    for case in 0..CASES {
        let (a, b) = (rng.pose(5.0), rng.pose(5.0));
        let theta = a.angle_to(&b);
        let (t1, t2) = (rng.range(-1.0, 2.0), rng.range(-1.0, 2.0));
        if (t2 - t1).abs() * theta >= PI - 1e-3 {
            continue;
        }
        let lambda = rng.range(-1.0, 2.0);
        let lhs = screw(&screw(&a, t1, &b), lambda, &screw(&a, t2, &b));
        let rhs = screw(&a, t1 + lambda * (t2 - t1), &b);
        assert_pose_near(&lhs, &rhs, 1e-11, &format!("case {case}"));
    }
}

#[test]
fn local_frame_independence_and_world_covariance() {
    let mut rng = Rng::new(4);
    for case in 0..CASES {
        let (a, b) = (rng.pose(5.0), rng.pose(5.0));
        if a.angle_to(&b) > PI - 1e-6 {
            continue;
        }
        let (c, g) = (rng.pose(3.0), rng.pose(3.0));
        let t = rng.range(-1.0, 2.0);
        let base = screw(&a, t, &b);
        assert_pose_near(
            &screw(&a.compose(&c), t, &b.compose(&c)),
            &base.compose(&c),
            1e-11,
            &format!("local case {case}"),
        );
        assert_pose_near(
            &screw(&g.compose(&a), t, &g.compose(&b)),
            &g.compose(&base),
            1e-11,
            &format!("world case {case}"),
        );
    }
}

/// Tiny angles down to 1e-12 rad, near-half turns up to π − 1e-6, axes along basis vectors:
/// the pose at any t (interpolation and extrapolation) matches the exact screw to ~1e-12 of the
/// scene scale.
#[test]
fn exact_for_tiny_large_and_axis_aligned_angles() {
    let mut rng = Rng::new(5);
    let angles = [
        1e-12,
        1e-10,
        1e-8,
        1e-6,
        1e-3,
        0.5,
        2.0,
        3.0,
        PI - 1e-3,
        PI - 1e-6,
    ];
    let axes = [
        DVec3::X,
        DVec3::Y,
        DVec3::Z,
        -DVec3::X,
        -DVec3::Y,
        -DVec3::Z,
    ];
    for case in 0..100 {
        let a = rng.pose(5.0);
        let point = DVec3::new(
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
        );
        let slide = rng.range(-3.0, 3.0);
        for (k, &angle) in angles.iter().enumerate() {
            let axis = if case % 2 == 0 {
                axes[(case / 2 + k) % 6]
            } else {
                rng.direction()
            };
            let b = exact(&a, axis, point, angle, slide, 1.0);
            let s = Screw::between(&a, &b);
            for t in [0.0, 0.3, 0.5, 1.0, -1.0, 2.5] {
                let want = exact(&a, axis, point, angle, slide, t);
                let scale = 1.0 + point.length() + a.origin.length() + slide.abs();
                assert_pose_near(
                    &s.at(t),
                    &want,
                    2e-13 * scale,
                    &format!("case {case} angle {angle:e} axis {axis} t={t}"),
                );
            }
            if angle >= 1e-3 {
                if let ScrewKind::General(p) = s.parameters() {
                    let (ax, sl) = if p.axis.dot(axis) > 0.0 {
                        (p.axis, p.slide)
                    } else {
                        (-p.axis, -p.slide)
                    };
                    assert!((ax - axis).length() < 1e-9, "axis {ax} vs {axis}");
                    assert!((sl - slide).abs() < 1e-9, "slide {sl} vs {slide}");
                    assert!((p.angle - angle).abs() < 1e-12);
                    // The foot point lies on the true axis.
                    let off = (p.foot - point) - axis * axis.dot(p.foot - point);
                    assert!(
                        off.length() < 1e-9 / angle.min(1.0),
                        "foot off the axis by {}",
                        off.length()
                    );
                } else {
                    panic!("angle {angle} must be a general screw");
                }
            }
        }
    }
}

#[test]
fn identical_poses_and_pure_translation() {
    let mut rng = Rng::new(6);
    for _ in 0..100 {
        let a = rng.pose(5.0);
        assert_eq!(Screw::between(&a, &a).parameters(), ScrewKind::Identity);
        for t in [-2.0, 0.5, 3.0] {
            assert_pose_near(&screw(&a, t, &a), &a, 1e-14, "identity");
        }
        let d = rng.direction() * rng.range(0.1, 5.0);
        let b = Pose::new(a.origin + d, a.rotation);
        match Screw::between(&a, &b).parameters() {
            ScrewKind::Translation {
                direction,
                distance,
            } => {
                assert!((direction * distance - d).length() < 1e-14);
            }
            other => panic!("expected translation, got {other:?}"),
        }
        for t in [-2.0, 0.5, 3.0] {
            let want = Pose::new(a.origin + t * d, a.rotation);
            assert_pose_near(&screw(&a, t, &b), &want, 1e-13, "translation");
        }
    }
}

/// At exactly π the tie-break is deterministic: the sign of either quaternion does not matter,
/// the slide is positive (or, without slide, the axis' largest component is positive), and the
/// result is one of the two minimal screws.
#[test]
fn half_turn_tie_break_is_deterministic() {
    let mut rng = Rng::new(7);
    for case in 0..200 {
        let a = rng.pose(5.0);
        let axis = rng.direction();
        let point = DVec3::new(
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
            rng.range(-5.0, 5.0),
        );
        let slide = if case % 3 == 0 {
            0.0
        } else {
            rng.range(-3.0, 3.0)
        };
        let b = exact(&a, axis, point, PI, slide, 1.0);
        let mid = screw(&a, 0.5, &b);
        for (sa, sb) in [(1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
            let a2 = Pose::new(a.origin, a.rotation * sa);
            let b2 = Pose::new(b.origin, b.rotation * sb);
            assert_pose_near(
                &screw(&a2, 0.5, &b2),
                &mid,
                1e-12,
                &format!("case {case} signs"),
            );
        }
        assert_pose_near(&screw(&a, 1.0, &b), &b, 1e-12, "end pose");
        let plus = exact(&a, axis, point, PI, slide, 0.5);
        let minus = exact(&a, -axis, point, PI, -slide, 0.5);
        let p = match Screw::between(&a, &b).parameters() {
            ScrewKind::General(p) => p,
            other => panic!("{other:?}"),
        };
        if slide != 0.0 {
            assert!(p.slide > 0.0, "tie-break prefers a positive slide");
            let want = if slide > 0.0 { plus } else { minus };
            assert_pose_near(&mid, &want, 1e-12, &format!("case {case} half-way"));
        } else {
            let c = p.axis.to_array();
            let k = (0..3).fold(0, |k, i| if c[i].abs() > c[k].abs() { i } else { k });
            assert!(c[k] > 0.0, "largest component positive: {:?}", p.axis);
            assert!(mid.approx_eq(&plus, 1e-12) || mid.approx_eq(&minus, 1e-12));
        }
    }
}

#[test]
fn results_are_finite_and_unit_for_extreme_inputs() {
    let mut rng = Rng::new(8);
    for scale in [1e-6, 1e-3, 1.0, 1e3, 1e6] {
        for _ in 0..100 {
            let (a, b) = (rng.pose(scale), rng.pose(scale));
            for t in [-3.0, 0.5, 4.0] {
                let p = screw(&a, t, &b);
                assert!(p.is_finite());
                assert!((p.rotation.length() - 1.0).abs() < 1e-14);
            }
            // Relative accuracy at the end point.
            assert_pose_near(
                &screw(&a, 1.0, &b),
                &b,
                1e-12 * scale.max(1.0),
                &format!("scale {scale}"),
            );
        }
    }
}
