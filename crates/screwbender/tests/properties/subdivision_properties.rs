//! Properties of the pose subdivision rules (docs/math/subdivision.md, docs/math/open-sequences.md and docs/math/properties.md) for every scheme and both rule sets,
//! over random cycles, natively and in the browser.

// The math notes print values like 0.707107 (docs/math/README.md §3): comparing with them is the point.
#![allow(clippy::approx_constant)]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use std::f64::consts::PI;

use glam::{DQuat, DVec3};
use screwbender::ErrorKind;
use screwbender::{
    presets, Motion, Polyscrew, Pose, Rules, Scheme, ScrewBender, Subdivision, MAX_REFINED_POSES,
};
use testkit::{assert_pose_near, max_pose_error, Rng};

/// Every named rule set, plus two members of the J_s family off the named points.
fn all_rule_sets() -> Vec<(Scheme, Rules)> {
    let mut v = Vec::new();
    for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
        v.push((scheme, Rules::Direct));
        v.push((scheme, Rules::SplitThenTweak));
    }
    v.push((Scheme::J(0.3), Rules::Direct));
    v.push((Scheme::J(-0.5), Rules::Direct));
    v
}

fn refine(p: &[Pose], scheme: Scheme, rules: Rules, levels: u32, closed: bool) -> Vec<Pose> {
    Subdivision::new(scheme, rules, levels)
        .apply(p, closed)
        .unwrap()
}

/// docs/math/properties.md §1: `P_i → G∘P_i∘C` maps every refined pose `Q_j → G∘Q_j∘C` (world covariance and
/// local-frame independence), closed and open.
#[test]
fn invariance_under_world_and_local_frame_changes() {
    let mut rng = Rng::new(11);
    for case in 0..20 {
        // Adjacent rotations ≤ 1.2 rad keep two-span screws below π for the split rules.
        let p = rng.cycle(4 + case % 4, 1.2);
        let (g, c) = (rng.pose(4.0), rng.pose(4.0));
        let moved: Vec<Pose> = p.iter().map(|q| g.compose(q).compose(&c)).collect();
        for (scheme, rules) in all_rule_sets() {
            for closed in [true, false] {
                let a = refine(&p, scheme, rules, 3, closed);
                let b = refine(&moved, scheme, rules, 3, closed);
                let expect: Vec<Pose> = a.iter().map(|q| g.compose(q).compose(&c)).collect();
                let err = max_pose_error(&b, &expect);
                assert!(
                    err < 1e-11,
                    "case {case} {scheme} {rules} closed={closed}: {err:e}"
                );
            }
        }
    }
}

/// docs/math/properties.md §2: samples of one screw motion are reproduced exactly — circles with 3 to 6 poses
/// (direct rules; split rules from 5 poses, see `v1_breaks_down_on_the_four_pose_circle`).
#[test]
fn circles_are_preserved() {
    let mut rng = Rng::new(12);
    for n in 3..=6usize {
        let base = rng.pose(1.0);
        let axis = rng.direction();
        let center = DVec3::new(1.0, -2.0, 0.5);
        let step = |k: f64| {
            let r = DQuat::from_axis_angle(axis, 2.0 * PI * k / n as f64);
            Pose::new(center - r * center, r).compose(&base)
        };
        let p: Vec<Pose> = (0..n).map(|i| step(i as f64)).collect();
        for (scheme, rules) in all_rule_sets() {
            if rules == Rules::SplitThenTweak && n < 5 {
                continue;
            }
            let q = refine(&p, scheme, rules, 4, true);
            let want: Vec<Pose> = (0..q.len()).map(|j| step(j as f64 / 16.0)).collect();
            let err = max_pose_error(&q, &want);
            assert!(err < 1e-12, "n={n} {scheme} {rules}: {err:e}");
        }
    }
}

/// docs/math/open-sequences.md §5, scene A11: an open helix is reproduced exactly from the first to the last pose.
#[test]
fn open_helix_and_line_are_preserved() {
    let helix = presets::preset("helix_open").unwrap().poses;
    let at = |u: f64| {
        let r = DQuat::from_rotation_z((45.0 * u).to_radians());
        Pose::new(
            r * DVec3::new(3.0, 0.0, 0.0) + DVec3::new(0.0, 0.0, 0.6 * u),
            r,
        )
    };
    let line_dir = DVec3::new(1.0, 2.0, -0.5);
    let rot = DQuat::from_rotation_x(0.4);
    let line: Vec<Pose> = (0..5)
        .map(|i| Pose::new(i as f64 * line_dir, rot))
        .collect();
    for (scheme, rules) in all_rule_sets() {
        let q = refine(&helix, scheme, rules, 4, false);
        assert_eq!(q.len(), 81);
        let want: Vec<Pose> = (0..81).map(|j| at(j as f64 / 16.0)).collect();
        let err = max_pose_error(&q, &want);
        assert!(err < 1e-12, "helix {scheme} {rules}: {err:e}");
        let q = refine(&line, scheme, rules, 3, false);
        let want: Vec<Pose> = (0..q.len())
            .map(|j| Pose::new(j as f64 / 8.0 * line_dir, rot))
            .collect();
        assert!(max_pose_error(&q, &want) < 1e-13, "line {scheme} {rules}");
    }
}

/// docs/math/properties.md §3: the 4-point scheme (and J_0) interpolates, both rule sets, cyclic and open:
/// `Q_{2^ℓ i} = P_i` exactly (bit for bit: the old slots are copied).
#[test]
fn four_point_interpolates() {
    let mut rng = Rng::new(13);
    let p = rng.cycle(7, 1.0);
    for rules in [Rules::Direct, Rules::SplitThenTweak] {
        for closed in [true, false] {
            let q = refine(&p, Scheme::FourPoint, rules, 4, closed);
            for (i, pi) in p.iter().enumerate() {
                assert_eq!(q[16 * i], *pi, "{rules} closed={closed} pose {i}");
            }
        }
    }
    let q = refine(&p, Scheme::J(0.0), Rules::Direct, 4, true);
    for (i, pi) in p.iter().enumerate() {
        assert_eq!(q[16 * i], *pi);
    }
}

/// docs/math/subdivision.md §2.2: with all rotations equal (pure translations), every pose rule reduces to its
/// point rule, compared with the closed-form formulas of docs/math/point-rules.md §2 (an oracle independent of the code).
#[test]
fn every_rule_reduces_to_the_point_rule() {
    let mut rng = Rng::new(14);
    let rot = rng.rotation();
    let pts: Vec<DVec3> = (0..7)
        .map(|_| {
            DVec3::new(
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
                rng.range(-5.0, 5.0),
            )
        })
        .collect();
    let poses: Vec<Pose> = pts.iter().map(|&o| Pose::new(o, rot)).collect();
    let n = pts.len();
    let formula = |s: f64, i: usize| {
        let (a, b, c, d) = (
            pts[(i + n - 1) % n],
            pts[i],
            pts[(i + 1) % n],
            pts[(i + 2) % n],
        );
        let old = b + s * (a - 2.0 * b + c) / 8.0;
        let new = (b + c) / 2.0 - (1.0 - s) * (a - b - c + d) / 16.0;
        (old, new)
    };
    for (scheme, rules) in all_rule_sets() {
        let q = refine(&poses, scheme, rules, 1, true);
        let as_points = Subdivision::new(scheme, rules, 1)
            .apply(&pts, true)
            .unwrap();
        for i in 0..n {
            let (old, new) = formula(scheme.s(), i);
            for (j, want) in [(2 * i, old), (2 * i + 1, new)] {
                assert!(
                    (q[j].origin - want).length() < 1e-13,
                    "{scheme} {rules} slot {j}"
                );
                assert!(
                    (as_points[j] - want).length() < 1e-13,
                    "points {scheme} {rules} slot {j}"
                );
                assert!(
                    q[j].rotation.dot(rot).abs() > 1.0 - 1e-15,
                    "rotation must not change"
                );
            }
        }
    }
}

/// The J_s family equals 4-point at s = 0, Jarek at s = ½ and B-spline at s = 1.
#[test]
fn j_family_contains_the_named_schemes() {
    let mut rng = Rng::new(15);
    for case in 0..10 {
        let p = rng.cycle(6, 1.5);
        for (s, named) in [
            (0.0, Scheme::FourPoint),
            (0.5, Scheme::Jarek),
            (1.0, Scheme::BSpline),
        ] {
            let a = refine(&p, Scheme::J(s), Rules::Direct, 3, true);
            let b = refine(&p, named, Rules::Direct, 3, true);
            let err = max_pose_error(&a, &b);
            assert!(err < 1e-12, "case {case} s={s}: {err:e}");
        }
    }
}

/// docs/math/subdivision.md §4: the two rule sets differ on generic data (by a visible amount).
#[test]
fn the_two_rule_sets_differ() {
    let mut rng = Rng::new(16);
    let p = rng.cycle(6, 1.0);
    for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
        let a = refine(&p, scheme, Rules::Direct, 1, true);
        let b = refine(&p, scheme, Rules::SplitThenTweak, 1, true);
        let diff = max_pose_error(&a, &b);
        assert!(
            diff > 1e-3,
            "{scheme}: direct and split rules agree to {diff:e}"
        );
    }
}

/// docs/math/local-update.md §1: moving control pose `j` changes the refined motion only for `u ∈ (j−2, j+2)`
/// (B-spline) or `(j−3, j+3)` (4-point, Jarek), both rule sets. Outside the window the refined
/// poses are bit-identical.
#[test]
fn locality_windows() {
    let mut rng = Rng::new(17);
    let n = 10;
    let levels = 4;
    let f = 1 << levels;
    let p = rng.cycle(n, 1.0);
    let j = 5;
    let mut moved = p.clone();
    moved[j] = rng.pose_near(&p[j], 0.5, 1.0);
    for (scheme, rules) in all_rule_sets() {
        let radius = if scheme == Scheme::BSpline { 2 } else { 3 };
        let a = refine(&p, scheme, rules, levels, true);
        let b = refine(&moved, scheme, rules, levels, true);
        let mut changed_inside = false;
        for k in 0..a.len() {
            let u = k as f64 / f as f64;
            let inside = (u - j as f64).abs() < radius as f64;
            if inside {
                changed_inside |= a[k] != b[k];
            } else {
                assert_eq!(
                    a[k], b[k],
                    "{scheme} {rules}: u = {u} outside the window changed"
                );
            }
        }
        assert!(changed_inside);
    }
}

/// docs/math/open-sequences.md: open B-spline reproduces both end poses exactly; 4-point interpolates every pose;
/// the refined open motion covers `[0, m − 1]`.
#[test]
fn open_sequences() {
    let mut rng = Rng::new(18);
    let p = rng.cycle(5, 1.0);
    for rules in [Rules::Direct, Rules::SplitThenTweak] {
        let q = refine(&p, Scheme::BSpline, rules, 4, false);
        assert_eq!(q.len(), 4 * 16 + 1);
        assert_pose_near(&q[0], &p[0], 1e-12, "B-spline start");
        assert_pose_near(q.last().unwrap(), &p[4], 1e-12, "B-spline end");
    }
    let m = ScrewBender::new(
        p.clone(),
        false,
        Subdivision::new(Scheme::Jarek, Rules::Direct, 4),
    )
    .unwrap();
    assert_eq!(m.domain(), (0.0, 4.0));
    assert!(!m.is_closed());
}

/// Rotations stay unit and outputs finite through many levels and long cycles.
#[test]
fn deep_levels_stay_unit_and_finite() {
    let mut rng = Rng::new(19);
    let p = rng.cycle(1000, 1.0);
    for (scheme, rules) in all_rule_sets() {
        let q = refine(&p, scheme, rules, 3, true);
        assert!(q
            .iter()
            .all(|x| x.is_finite() && (x.rotation.length() - 1.0).abs() < 1e-12));
    }
    let small = rng.cycle(4, 2.0);
    let q = refine(&small, Scheme::Jarek, Rules::Direct, 12, true);
    assert_eq!(q.len(), 4 << 12);
    assert!(q
        .iter()
        .all(|x| x.is_finite() && (x.rotation.length() - 1.0).abs() < 1e-12));
}

/// docs/math/subdivision.md §4: the first version's 4-point rule uses screws two spans apart, which are half turns
/// on the four-pose circle. Which of the two minimal half turns is taken is decided by the
/// tie-break (positive largest axis component), so V1 stays on the counter-clockwise circle by
/// luck and leaves the clockwise one (documented behaviour); the direct rules keep both exactly.
#[test]
fn v1_breaks_down_on_the_four_pose_circle() {
    let exact = |sign: f64, u: f64| {
        let r = DQuat::from_rotation_z(sign * PI / 2.0 * u);
        Pose::new(r * DVec3::new(3.0, 0.0, 0.0), r)
    };
    for sign in [1.0, -1.0] {
        let p: Vec<Pose> = (0..4).map(|i| exact(sign, i as f64)).collect();
        let want: Vec<Pose> = (0..32).map(|j| exact(sign, j as f64 / 8.0)).collect();
        let direct = refine(&p, Scheme::FourPoint, Rules::Direct, 3, true);
        assert!(max_pose_error(&direct, &want) < 1e-13);
        let split = refine(&p, Scheme::FourPoint, Rules::SplitThenTweak, 3, true);
        assert!(split.iter().all(Pose::is_finite));
        let err = max_pose_error(&split, &want);
        if sign > 0.0 {
            assert!(err < 1e-12, "counter-clockwise: {err:e}");
        } else {
            assert!(
                err > 0.5,
                "expected V1 to leave the clockwise circle, error {err:e}"
            );
        }
    }
}

#[test]
fn bad_requests_are_errors() {
    let p = presets::preset("circle4").unwrap().poses;
    let e = Subdivision::new(Scheme::Jarek, Rules::Direct, 30)
        .apply(&p, true)
        .unwrap_err();
    assert!(
        matches!(
            e.kind(),
            ErrorKind::TooManyPoses {
                max: MAX_REFINED_POSES,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(e.path(), "levels");
    let e = ScrewBender::new(p[..1].to_vec(), true, Subdivision::default()).unwrap_err();
    assert_eq!(e.to_string(), "poses: 1 pose(s) given, at least 2 needed");
    let mut bad = p.clone();
    bad[2].origin.x = f64::NAN;
    let e = Polyscrew::new(bad, true).unwrap_err();
    assert_eq!(e.path(), "poses[2]");
    let mut bad = p;
    bad[1].rotation = DQuat::from_xyzw(0.0, 0.0, 0.0, 2.0);
    let e = ScrewBender::new(bad, true, Subdivision::default()).unwrap_err();
    assert_eq!(e.path(), "poses[1].rotation");
}

/// `update_local` after moving one pose equals a full re-subdivision bit for bit, for every rule
/// set, closed and open, at every position (including the open ends and short cycles).
#[test]
fn local_update_equals_full_recompute() {
    let mut rng = Rng::new(20);
    for (scheme, rules) in all_rule_sets() {
        for closed in [true, false] {
            for n in [3, 9, 16, 20] {
                let mut p = rng.cycle(n, 0.8);
                let sub = Subdivision::new(scheme, rules, 3);
                let mut refined = sub.apply(&p, closed).unwrap();
                for _ in 0..4 {
                    let j = (rng.unit() * n as f64) as usize % n;
                    p[j] = rng.pose_near(&p[j], 0.4, 1.0);
                    let (start, count) = sub.update_local(&p, closed, j, &mut refined).unwrap();
                    let full = sub.apply(&p, closed).unwrap();
                    assert!(count > 0 && start < refined.len());
                    assert!(
                        refined == full,
                        "{scheme} {rules} closed={closed} n={n} moved {j}: local update differs"
                    );
                }
            }
        }
    }
    let p = rng.cycle(5, 0.8);
    let sub = Subdivision::new(Scheme::Jarek, Rules::Direct, 2);
    let mut wrong = vec![p[0]; 7];
    assert!(sub.update_local(&p, true, 1, &mut wrong).is_err());
    let mut refined = sub.apply(&p, true).unwrap();
    assert!(sub.update_local(&p, true, 5, &mut refined).is_err());
}

/// Dragging a control pose through `ScrewBender::set_control_pose` gives the same motion
/// (refined poses and span screws) as building it anew; bad poses change nothing.
#[test]
fn set_control_pose_matches_a_rebuild() {
    let mut rng = Rng::new(23);
    for closed in [true, false] {
        let p = rng.cycle(24, 0.8);
        let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 4);
        let mut m = ScrewBender::new(p.clone(), closed, sub).unwrap();
        for step in 0..10 {
            let j = (step * 7) % 24;
            let moved = rng.pose_near(&m.control()[j], 0.3, 0.5);
            m.set_control_pose(j, moved).unwrap();
            let fresh = ScrewBender::new(m.control().to_vec(), closed, sub).unwrap();
            let (a, b) = (m.refined(), fresh.refined());
            let bad_pose = a.poses().iter().zip(b.poses()).position(|(x, y)| x != y);
            assert_eq!(
                bad_pose, None,
                "closed={closed} step {step}: first differing pose"
            );
            let bad_span = a.spans().iter().zip(b.spans()).position(|(x, y)| x != y);
            assert_eq!(
                bad_span, None,
                "closed={closed} step {step}: first differing span"
            );
        }
        let before = m.clone();
        let mut nan = m.control()[3];
        nan.origin.y = f64::NAN;
        assert_eq!(m.set_control_pose(3, nan).unwrap_err().path(), "pose");
        let mut far = m.control()[3];
        far.rotation *= 3.0;
        assert_eq!(
            m.set_control_pose(3, far).unwrap_err().path(),
            "pose.rotation"
        );
        assert!(m.set_control_pose(24, m.control()[0]).is_err());
        assert_eq!(m, before, "a rejected edit changes nothing");
    }
}
