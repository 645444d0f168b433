//! `Subdivision::warnings` (docs/math/subdivision.md §4): the split-then-tweak 4-point and Jarek
//! rules are warned about exactly where a tweak screw spans half a turn or more, and those are
//! the cases whose results leave the data's path.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use std::f64::consts::{PI, TAU};

use glam::{DQuat, DVec3};
use screwbender::{presets, Pose, Rules, Scheme, Subdivision, Warning};

/// The radius of the test circles, in scene units.
const RADIUS: f64 = 5.0;

/// `n` poses on a circle of [`RADIUS`] about the z axis, each turned with its place.
fn circle(n: usize, arc: f64) -> Vec<Pose> {
    (0..n)
        .map(|i| {
            let a = arc * i as f64 / n as f64;
            Pose {
                origin: DVec3::new(RADIUS * a.cos(), RADIUS * a.sin(), 0.0),
                rotation: DQuat::from_rotation_z(a),
            }
        })
        .collect()
}

/// The farthest a refined closed circle's origin lies from where the circle puts it (the
/// direct rules' interpolating schemes reproduce the circle exactly, docs/math/subdivision.md §4).
fn off_circle(poses: &[Pose]) -> f64 {
    let exact = circle(poses.len(), TAU);
    poses
        .iter()
        .zip(&exact)
        .map(|(p, e)| (p.origin - e.origin).length())
        .fold(0.0, f64::max)
}

fn spans(warnings: &[Warning]) -> Vec<usize> {
    warnings
        .iter()
        .map(|w| match w {
            Warning::WideTweak { span, .. } => *span,
            _ => unreachable!("only wide tweaks exist"),
        })
        .collect()
}

#[test]
fn split_rules_on_three_and_four_pose_circles_warn_for_every_span() {
    for scheme in [Scheme::FourPoint, Scheme::Jarek] {
        for n in [3, 4] {
            let poses = circle(n, TAU);
            let warnings =
                Subdivision::new(scheme, Rules::SplitThenTweak, 3).warnings(&poses, true);
            assert_eq!(
                spans(&warnings),
                (0..n).collect::<Vec<_>>(),
                "{scheme} n={n}"
            );
            for w in &warnings {
                let Warning::WideTweak { turn, .. } = w else {
                    unreachable!()
                };
                // Two spans of 360°/n each.
                assert!(
                    (turn - 2.0 * TAU / n as f64).abs() < 1e-12,
                    "{scheme} n={n}: {turn}"
                );
                let text = w.to_string();
                assert!(text.contains("span ") && text.contains("°"), "{text}");
            }
            // And the result is indeed poor.
            let refined = Subdivision::new(scheme, Rules::SplitThenTweak, 3)
                .apply(&poses, true)
                .unwrap();
            // Three poses: the tweak screws turn 240°, the short way is 120° the other way, and
            // the result leaves the circle (by 3.8 and 1.6 units here). Four: exactly a half
            // turn, whose direction rounding decides (the scene `circle4` below).
            if n == 3 {
                assert!(off_circle(&refined) > 0.2 * RADIUS, "{scheme} n={n}");
            }
        }
    }
}

#[test]
fn four_poses_around_a_circle_warn_where_the_turn_passes_a_half_turn() {
    // The scene `circle4`, 90° steps: every tweak screw is exactly a half turn, an ambiguous
    // screw whose direction rounding decides, so every span is named.
    let scene = presets::preset("circle4").unwrap();
    for scheme in [Scheme::FourPoint, Scheme::Jarek] {
        let s = Subdivision::new(scheme, Rules::SplitThenTweak, scene.levels);
        assert_eq!(
            spans(&s.warnings(&scene.poses, scene.closed)),
            vec![0, 1, 2, 3]
        );
    }
    // Steps of 100°, 90°, 80°, 90°: the tweak screws turn 190°, 180°, 170°, 180°; span 2 is
    // clear, and span 0 (past the half turn) comes out wrong.
    let angles = [0.0f64, 100.0, 190.0, 270.0];
    let at = |deg: f64| {
        let a = deg.to_radians();
        Pose {
            origin: DVec3::new(RADIUS * a.cos(), RADIUS * a.sin(), 0.0),
            rotation: DQuat::from_rotation_z(a),
        }
    };
    let poses: Vec<Pose> = angles.iter().map(|&d| at(d)).collect();
    for scheme in [Scheme::FourPoint, Scheme::Jarek] {
        let s = Subdivision::new(scheme, Rules::SplitThenTweak, 1);
        assert_eq!(spans(&s.warnings(&poses, true)), vec![0, 1, 3], "{scheme}");
        let split = s.apply(&poses, true).unwrap();
        let direct = Subdivision::new(scheme, Rules::Direct, 1)
            .apply(&poses, true)
            .unwrap();
        // The new pose of span 0 is far from the direct rules' (which stay near the circle);
        // that of span 2, whose tweak screw turns 170°, is close.
        let new0 = (split[1].origin - direct[1].origin).length();
        let new2 = (split[5].origin - direct[5].origin).length();
        assert!(new0 > 0.2 * RADIUS, "{scheme}: {new0}");
        assert!(new2 < 0.05 * RADIUS, "{scheme}: {new2}");
    }
}

#[test]
fn no_warning_where_the_result_is_good() {
    for n in [3, 4, 5, 6, 8, 12] {
        let poses = circle(n, TAU);
        for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
            for rules in [Rules::Direct, Rules::SplitThenTweak] {
                let s = Subdivision::new(scheme, rules, 3);
                let bad = rules == Rules::SplitThenTweak && scheme != Scheme::BSpline && n <= 4;
                if bad {
                    continue;
                }
                assert!(
                    s.warnings(&poses, true).is_empty(),
                    "{scheme} {rules} n={n}"
                );
                // Interpolating schemes stay on the circle (the B-spline cuts inside it).
                if scheme != Scheme::BSpline {
                    let refined = s.apply(&poses, true).unwrap();
                    assert!(off_circle(&refined) < 1e-9, "{scheme} {rules} n={n}");
                }
            }
        }
    }
    // The J_s family is direct-only: never a warning.
    let poses = circle(3, TAU);
    assert!(Subdivision::new(Scheme::J(0.3), Rules::Direct, 2)
        .warnings(&poses, true)
        .is_empty());
}

#[test]
fn only_the_spans_next_to_a_wide_turn_are_named() {
    // Eight poses, turns of 20° except one span of 170°: the tweak screws over that span and
    // its neighbours span 10 + 170 + 10 = 190° (the span itself) and 10 + 20 + 85 = 115° (the
    // neighbours), so only the span itself is named.
    let turns_deg = [20.0, 20.0, 20.0, 170.0, 20.0, 20.0, 20.0];
    let mut poses = vec![Pose::IDENTITY];
    for (i, t) in turns_deg.iter().enumerate() {
        let last = poses[i];
        poses.push(Pose {
            origin: last.origin + DVec3::X,
            rotation: last.rotation * DQuat::from_rotation_z(f64::to_radians(*t)),
        });
    }
    let s = Subdivision::new(Scheme::FourPoint, Rules::SplitThenTweak, 2);
    let warnings = s.warnings(&poses, false);
    assert_eq!(spans(&warnings), vec![3]);
    let Warning::WideTweak { turn, .. } = &warnings[0] else {
        unreachable!()
    };
    assert!(
        (turn.to_degrees() - 190.0).abs() < 1e-9,
        "{}",
        turn.to_degrees()
    );
    // Direct rules and the B-spline read no such screw.
    assert!(Subdivision::new(Scheme::FourPoint, Rules::Direct, 2)
        .warnings(&poses, false)
        .is_empty());
    assert!(Subdivision::new(Scheme::BSpline, Rules::SplitThenTweak, 2)
        .warnings(&poses, false)
        .is_empty());
}

#[test]
fn open_half_circle_of_three_poses_warns() {
    // Three poses 90° apart, open: the extension continues the end spans, so every tweak screw
    // turns 180°.
    let poses = circle(3, 1.5 * PI);
    let warnings =
        Subdivision::new(Scheme::Jarek, Rules::SplitThenTweak, 2).warnings(&poses, false);
    assert_eq!(spans(&warnings), vec![0, 1]);
    // Fine steps on an open arc: no warning.
    let poses = circle(9, PI);
    assert!(Subdivision::new(Scheme::Jarek, Rules::SplitThenTweak, 2)
        .warnings(&poses, false)
        .is_empty());
}

#[test]
fn degenerate_input_gives_no_warning() {
    let s = Subdivision::new(Scheme::FourPoint, Rules::SplitThenTweak, 2);
    assert!(s.warnings(&[], true).is_empty());
    assert!(s.warnings(&[Pose::IDENTITY], false).is_empty());
    // No levels: nothing is subdivided.
    let none = Subdivision::new(Scheme::FourPoint, Rules::SplitThenTweak, 0);
    assert!(none.warnings(&circle(3, TAU), true).is_empty());
    // Invalid options: the subdivision reports the error, the warnings stay quiet.
    let bad = Subdivision::new(Scheme::J(0.3), Rules::SplitThenTweak, 2);
    assert!(bad.warnings(&circle(3, TAU), true).is_empty());
}
