//! Numerical stress and hostile input for the core, natively and in the browser: scales from 1e-6
//! to 1e6, rotations near 0 and near π, long cycles, deep levels, and mangled documents. Outputs
//! stay finite with unit rotations, invariances hold with tolerances scaled to the input, and
//! nothing panics.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use std::f64::consts::PI;

use glam::DQuat;
use screwbender::{MotionDocument, Pose, Rules, Scheme, Subdivision};
use testkit::{max_pose_error, Rng};

fn all_rules() -> Vec<Subdivision> {
    let mut v = Vec::new();
    for scheme in [
        Scheme::BSpline,
        Scheme::FourPoint,
        Scheme::Jarek,
        Scheme::J(0.7),
    ] {
        for rules in [Rules::Direct, Rules::SplitThenTweak] {
            if matches!(scheme, Scheme::J(_)) && rules == Rules::SplitThenTweak {
                continue;
            }
            v.push(Subdivision::new(scheme, rules, 3));
        }
    }
    v
}

fn healthy(q: &[Pose]) -> bool {
    q.iter()
        .all(|p| p.is_finite() && (p.rotation.length() - 1.0).abs() < 1e-12)
}

/// Scale covariance: scaling every origin by `k` scales every refined origin by `k` and keeps
/// the rotations, for `k` from 1e-6 to 1e6 (relative error ~1e-12).
#[test]
fn scales_from_micro_to_mega() {
    let mut rng = Rng::new(31);
    let base = rng.cycle(7, 1.0);
    for sub in all_rules() {
        assert_scale_covariant(&sub, &base, true, &format!("{sub:?}"));
    }
}

/// Scaling every origin of `base` by `k` (1e-6 to 1e6) scales every refined origin by `k` and
/// keeps the rotations: outputs healthy, and scaled back within 1e-11 of the unscaled result.
fn assert_scale_covariant(sub: &Subdivision, base: &[Pose], closed: bool, what: &str) {
    let reference = sub.apply(base, closed).unwrap();
    for k in [1e-6, 1e-3, 1e3, 1e6] {
        let scaled: Vec<Pose> = base
            .iter()
            .map(|p| Pose::new(p.origin * k, p.rotation))
            .collect();
        let q = sub.apply(&scaled, closed).unwrap();
        assert!(healthy(&q), "{what} k={k}");
        let back: Vec<Pose> = q
            .iter()
            .map(|p| Pose::new(p.origin / k, p.rotation))
            .collect();
        let err = max_pose_error(&back, &reference);
        assert!(err < 1e-11, "{what} k={k}: {err:e}");
    }
}

/// Adjacent rotations from 1e-12 rad up to π − 1e-6 (and exactly π): finite, unit outputs;
/// tiny rotations behave like the translation-only point rules.
#[test]
fn rotations_near_zero_and_near_pi() {
    let mut rng = Rng::new(32);
    for angle in [1e-12, 1e-9, 1e-6, 0.5, PI - 1e-3, PI - 1e-6, PI] {
        for _ in 0..5 {
            let axis = rng.direction();
            let step = DQuat::from_axis_angle(axis, angle);
            let mut poses = vec![rng.pose(3.0)];
            for _ in 1..6 {
                let last = *poses.last().unwrap();
                poses.push(Pose::new(
                    last.origin + rng.direction() * 2.0,
                    (step * last.rotation).normalize(),
                ));
            }
            for sub in all_rules() {
                for closed in [true, false] {
                    let q = sub.apply(&poses, closed).unwrap();
                    assert!(healthy(&q), "angle {angle} {sub:?} closed={closed}");
                }
            }
        }
    }
}

/// Local-frame and world invariance with tolerances scaled to the scene size (1e-6 to 1e6).
#[test]
fn invariances_at_large_scale() {
    let mut rng = Rng::new(33);
    for scale in [1e-6, 1e-4, 1e4, 1e6] {
        let poses: Vec<Pose> = rng
            .cycle(6, 1.0)
            .iter()
            .map(|p| Pose::new(p.origin * scale, p.rotation))
            .collect();
        let c = Pose::new(rng.direction() * scale, rng.rotation());
        let g = Pose::new(rng.direction() * scale, rng.rotation());
        for sub in all_rules() {
            let a = sub.apply(&poses, true).unwrap();
            let moved: Vec<Pose> = poses.iter().map(|p| g.compose(p).compose(&c)).collect();
            let b = sub.apply(&moved, true).unwrap();
            let expect: Vec<Pose> = a.iter().map(|p| g.compose(p).compose(&c)).collect();
            let err = max_pose_error(&b, &expect);
            assert!(
                err < 1e-11 * scale.max(1.0),
                "scale {scale} {sub:?}: {err:e}"
            );
        }
    }
}

/// Long cycles stay healthy; a request past the memory guard (1000 poses × 2¹¹ > 2²⁰) is an
/// error before any work, not an abort.
#[test]
fn long_cycles_and_the_level_cap() {
    let mut rng = Rng::new(34);
    let poses = rng.cycle(1000, 1.0);
    let q = Subdivision::new(Scheme::Jarek, Rules::Direct, 6)
        .apply(&poses, true)
        .unwrap();
    assert_eq!(q.len(), 1000 << 6);
    assert!(healthy(&q));
    let e = Subdivision::new(Scheme::Jarek, Rules::Direct, 11)
        .apply(&poses, true)
        .unwrap_err();
    assert_eq!(e.path(), "levels");
}

/// Every scale from 1e-6 to 1e6 combined with adjacent rotations near 0 and near π, open and
/// closed, every scheme and rule set: outputs finite, unit to 1e-12, and scale covariant
/// (refined origins scale by `k`, rotations do not change) to 1e-11 relative.
#[test]
fn scales_and_extreme_rotations_open_and_closed() {
    let mut rng = Rng::new(36);
    for angle in [1e-12, 1e-7, PI - 1e-7, PI] {
        let step = DQuat::from_axis_angle(rng.direction(), angle);
        let mut base = vec![rng.pose(1.0)];
        for _ in 1..5 {
            let last = *base.last().unwrap();
            base.push(Pose::new(
                last.origin + rng.direction(),
                (step * last.rotation).normalize(),
            ));
        }
        for sub in all_rules() {
            for closed in [true, false] {
                let what = format!("angle {angle} {sub:?} closed={closed}");
                assert_scale_covariant(&sub, &base, closed, &what);
            }
        }
    }
}

/// Deep levels up to the memory guard: a 4-pose cycle (one span near a half turn) at level 18
/// gives exactly `MAX_REFINED_POSES` healthy poses; one more level is refused. (Native only:
/// a million screws are too slow for the browser test run.)
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn deep_levels_up_to_the_cap() {
    let mut rng = Rng::new(37);
    let mut poses = rng.cycle(4, 3.0);
    // One span near a half turn.
    poses[1] = Pose::new(
        poses[1].origin,
        (DQuat::from_axis_angle(rng.direction(), PI - 1e-9) * poses[0].rotation).normalize(),
    );
    let sub = Subdivision::new(Scheme::Jarek, Rules::Direct, 18);
    let q = sub.apply(&poses, true).unwrap();
    assert_eq!(q.len(), screwbender::MAX_REFINED_POSES);
    assert!(healthy(&q));
    let deeper = Subdivision::new(Scheme::Jarek, Rules::Direct, 19);
    assert_eq!(deeper.apply(&poses, true).unwrap_err().path(), "levels");
}

/// Random edits of a valid document (deleted, duplicated, swapped characters; spliced-in
/// numbers and tokens) never panic: each is a valid motion or a clear error, and valid ones
/// subdivide to healthy poses.
#[test]
fn mangled_documents_never_panic() {
    let mut rng = Rng::new(35);
    let text = MotionDocument::new(rng.cycle(4, 1.0), true).to_json();
    let splices = [
        "NaN",
        "1e999",
        "-0",
        "null",
        "[]",
        "{}",
        "\"x\"",
        "0.0",
        "1e-320",
        "true",
        ",",
        "]",
        "}",
        "\"basis\":[[1,0,0],[0,1,0],[0,0,1]]",
        "\"rotation\":[0,0,0,0]",
    ];
    let bytes: Vec<char> = text.chars().collect();
    let (mut ok, mut err) = (0, 0);
    for _ in 0..3000 {
        let mut s = bytes.clone();
        for _ in 0..1 + (rng.unit() * 3.0) as usize {
            let at = (rng.unit() * s.len() as f64) as usize % s.len().max(1);
            match (rng.unit() * 4.0) as usize {
                0 => {
                    s.remove(at);
                }
                1 => s.insert(at, s[at]),
                2 => {
                    let other = (rng.unit() * s.len() as f64) as usize % s.len();
                    s.swap(at, other);
                }
                _ => {
                    let piece =
                        splices[(rng.unit() * splices.len() as f64) as usize % splices.len()];
                    for (k, ch) in piece.chars().enumerate() {
                        s.insert((at + k).min(s.len()), ch);
                    }
                }
            }
            if s.is_empty() {
                break;
            }
        }
        let mangled: String = s.into_iter().collect();
        match MotionDocument::from_json(&mangled) {
            Ok(doc) => {
                ok += 1;
                let q = Subdivision::new(Scheme::FourPoint, Rules::Direct, 2)
                    .apply(&doc.poses, doc.closed)
                    .unwrap();
                assert!(healthy(&q), "{mangled}");
            }
            Err(e) => {
                err += 1;
                assert!(!e.to_string().is_empty());
            }
        }
    }
    assert!(
        ok > 0 && err > 0,
        "the mutations should produce both ({ok} ok, {err} errors)"
    );
}

/// Validation is idempotent: a unit quaternion (to rounding) passes `Pose::from_wxyz` bit for
/// bit, and any accepted quaternion is stable after one normalisation, so saving and reloading a
/// motion (the page's autosave, share links) reproduces it exactly. Found by the page's share-link
/// test: reloading a session changed the last bits of rotations.
#[test]
fn validation_keeps_unit_quaternions_bit_for_bit() {
    let mut rng = Rng::new(38);
    for _ in 0..10_000 {
        let q = rng.rotation();
        let wxyz = [q.w, q.x, q.y, q.z];
        let p = Pose::from_wxyz([1.0, 2.0, 3.0], wxyz).unwrap();
        assert_eq!(p.rotation_wxyz(), wxyz);
        let off = wxyz.map(|c| c * (1.0 + 1e-4 * (rng.unit() - 0.5)));
        let once = Pose::from_wxyz([0.0; 3], off).unwrap().rotation_wxyz();
        let twice = Pose::from_wxyz([0.0; 3], once).unwrap().rotation_wxyz();
        assert_eq!(once, twice, "{off:?}");
    }
}

/// Pose constructors reject every non-finite component, naming where it is.
#[test]
fn non_finite_components_are_named() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for i in 0..3 {
            let mut o = [0.0; 3];
            o[i] = bad;
            assert_eq!(
                Pose::from_wxyz(o, [1.0, 0.0, 0.0, 0.0]).unwrap_err().path(),
                "origin"
            );
        }
        for i in 0..4 {
            let mut q = [1.0, 0.0, 0.0, 0.0];
            q[i] = bad;
            assert_eq!(Pose::from_wxyz([0.0; 3], q).unwrap_err().path(), "rotation");
        }
        let mut basis = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        basis[1][2] = bad;
        assert_eq!(
            Pose::from_basis([0.0; 3], basis).unwrap_err().path(),
            "basis[1]"
        );
    }
}
