//! The split/tweak step-through (`split_tweak_step`, `split_tweak_levels`): the tweaked output is
//! exactly one `Subdivision` step for every scheme and rule set, the split poses are the screw
//! midpoints, and the point version reproduces the L-polygon vectors (docs/math/point-rules.md §5, docs/math/subdivision.md §3).

// The input of docs/math/subdivision.md §7 is printed with 0.707107: using it as printed is the point.
#![allow(clippy::approx_constant)]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec2;
use screwbender::{
    presets, screw, split_tweak_levels, split_tweak_step, Pose, Rules, Scheme, Screw, Subdivision,
};
use testkit::{assert_pose_near, max_pose_error, pose};

/// Round-off bound for comparing two computations of the same rule (a few screw evaluations on
/// scenes of size ~10).
const SAME: f64 = 1e-12;

const SCHEMES: [Scheme; 4] = [
    Scheme::BSpline,
    Scheme::FourPoint,
    Scheme::Jarek,
    Scheme::J(0.3),
];

/// docs/math/subdivision.md §7 input and the L cycle with rotations (docs/math/presets.md §2.2) and the bunny cycle (A10).
fn inputs() -> Vec<(&'static str, Vec<Pose>)> {
    vec![
        (
            "subdivision.md §7",
            vec![
                pose([0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]),
                pose([4.0, 0.0, 0.0], [0.707107, 0.0, 0.0, 0.707107]),
                pose([4.0, 4.0, 0.0], [0.707107, 0.707107, 0.0, 0.0]),
                pose([0.0, 4.0, 1.0], [1.0, 0.0, 0.0, 0.0]),
            ],
        ),
        (
            "l_cycle_rotated",
            presets::preset("l_cycle_rotated").unwrap().poses,
        ),
        ("bunny6", presets::preset("bunny6").unwrap().poses),
    ]
}

fn combos() -> impl Iterator<Item = (Scheme, Rules)> {
    SCHEMES.into_iter().flat_map(|s| {
        [Rules::Direct, Rules::SplitThenTweak]
            .into_iter()
            .filter(move |r| !(matches!(s, Scheme::J(_)) && *r == Rules::SplitThenTweak))
            .map(move |r| (s, r))
    })
}

#[test]
fn tweak_output_is_one_subdivision_step() {
    for (name, poses) in inputs() {
        for (scheme, rules) in combos() {
            let step = split_tweak_step(&poses, scheme, rules).unwrap();
            let want = Subdivision::new(scheme, rules, 1)
                .apply(&poses, true)
                .unwrap();
            let err = max_pose_error(&step.output, &want);
            assert!(err <= SAME, "{name} {scheme} {rules}: error {err:.3e}");
            assert_eq!(step.input, poses);
            assert_eq!(step.tweaked.len(), 2 * poses.len());
        }
    }
}

#[test]
fn split_poses_are_screw_midpoints() {
    for (name, poses) in inputs() {
        let n = poses.len();
        for (scheme, rules) in combos() {
            let step = split_tweak_step(&poses, scheme, rules).unwrap();
            assert_eq!(step.split.len(), 2 * n);
            for i in 0..n {
                assert_eq!(step.split[2 * i], poses[i], "{name}: old slot {i}");
                let mid = screw(&poses[i], 0.5, &poses[(i + 1) % n]);
                assert_pose_near(&step.split[2 * i + 1], &mid, SAME, name);
                // The midpoint is where the screw from P_i to P_{i+1} is half done.
                let s = Screw::between(&poses[i], &step.split[2 * i + 1]);
                assert_pose_near(&s.at(2.0), &poses[(i + 1) % n], 1e-11, name);
            }
        }
    }
}

#[test]
fn untweaked_slots_stay_split_and_helpers_explain_the_tweak() {
    for (name, poses) in inputs() {
        for (scheme, rules) in combos() {
            let step = split_tweak_step(&poses, scheme, rules).unwrap();
            for (j, moved) in step.tweaked.iter().enumerate() {
                if !moved {
                    assert_pose_near(&step.output[j], &step.split[j], SAME, name);
                }
            }
            match rules {
                Rules::Direct => {
                    let count = step.tweaked.iter().filter(|t| **t).count();
                    assert_eq!(step.helpers.len(), 2 * count, "{name} {scheme}");
                    // The output of a moved slot is the screw midpoint of its two helpers.
                    for pair in step.helpers.chunks(2) {
                        let (j, h1) = pair[0];
                        assert_eq!(pair[1].0, j);
                        assert!(step.tweaked[j]);
                        let mid = screw(&h1, 0.5, &pair[1].1);
                        assert_pose_near(&mid, &step.output[j], SAME, name);
                    }
                }
                Rules::SplitThenTweak => {
                    let count = step.tweaked.iter().filter(|t| **t).count();
                    assert_eq!(step.helpers.len(), count, "{name} {scheme}");
                    for (j, h) in &step.helpers {
                        // The tweaked pose lies on the screw through the helper and Z_j.
                        let s = Screw::between(h, &step.split[*j]);
                        let t = if j % 2 == 1 {
                            if scheme == Scheme::FourPoint {
                                1.25
                            } else {
                                1.125
                            }
                        } else if scheme == Scheme::BSpline {
                            0.5
                        } else {
                            0.75
                        };
                        assert_pose_near(&s.at(t), &step.output[*j], 1e-11, name);
                    }
                }
            }
        }
    }
}

#[test]
fn levels_end_in_the_subdivision_closed_and_open() {
    let poses = presets::preset("l_cycle_rotated").unwrap().poses;
    for (scheme, rules) in combos() {
        for closed in [true, false] {
            let sub = Subdivision::new(scheme, rules, 3);
            let steps = split_tweak_levels(&poses, closed, sub).unwrap();
            assert_eq!(steps.len(), 3);
            for w in steps.windows(2) {
                assert_eq!(w[0].output, w[1].input);
            }
            let last = steps.last().unwrap();
            let (start, len) = last.kept;
            let want = sub.apply(&poses, closed).unwrap();
            assert_eq!(len, want.len());
            let err = max_pose_error(&last.output[start..start + len], &want);
            assert!(
                err <= SAME,
                "{scheme} {rules} closed={closed}: error {err:.3e}"
            );
        }
    }
}

#[test]
fn rejects_what_subdivision_rejects() {
    let one = [Pose::IDENTITY];
    assert!(split_tweak_step(&one, Scheme::FourPoint, Rules::Direct).is_err());
    let two = [Pose::IDENTITY, Pose::IDENTITY];
    assert!(split_tweak_step(&two, Scheme::J(0.2), Rules::SplitThenTweak).is_err());
    assert!(split_tweak_levels(
        &two,
        true,
        Subdivision::new(Scheme::Jarek, Rules::Direct, 40)
    )
    .is_err());
}

/// docs/math/point-rules.md §3, §5 / docs/math/presets.md §2.4 (paper Fig. 3): split and tweak of the L polygon give the printed
/// one-step vectors, for both rule sets.
#[test]
fn l_polygon_split_and_tweak() {
    let l = presets::polygon_presets().remove(0).vertices;
    let expected = testkit::l_polygon_one_step();
    for (scheme, want) in expected {
        for rules in [Rules::Direct, Rules::SplitThenTweak] {
            let step = split_tweak_step(&l, scheme, rules).unwrap();
            for (j, (g, w)) in step.output.iter().zip(&want).enumerate() {
                assert!(
                    (*g - *w).length() < 1e-14,
                    "{scheme} {rules} [{j}]: {g} vs {w}"
                );
            }
            assert_eq!(step.split[1], DVec2::new(3.0, 0.0));
        }
    }
}
