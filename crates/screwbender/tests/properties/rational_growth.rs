//! `RationalMotion::growth` and its warning (docs/math/rational-motion.md §6.1): the C¹
//! Chaudhry–Cameron recursion is flagged where it runs away from the data, and not on the
//! paper's data or smooth sequences.
//!
//! Native only: its fits or sampling are among the heaviest of these modules, and the browser
//! test runner gives up on a page that does not answer for 30 s, which a test that long holds
//! up; the wasm stage leaves it out (tests/properties/main.rs).
#![cfg(not(target_arch = "wasm32"))]

use glam::{DQuat, DVec3};
use screwbender::methods::{
    compare_methods, Continuity, EndCondition, Method, MetricsOptions, RationalMotion,
    ReferenceTriangle, GROWTH_WARNING,
};
use screwbender::{presets, Pose};
use testkit::Rng;

const C1_18: Continuity = Continuity::C1(EndCondition::ZeroCurvatureStart);
const C1_19: Continuity = Continuity::C1(EndCondition::ZeroCurvatureEnd);

fn fit(poses: &[Pose], c: Continuity) -> RationalMotion {
    let times: Vec<f64> = (0..poses.len()).map(|i| i as f64).collect();
    RationalMotion::from_poses(poses, &times, false, c, &ReferenceTriangle::SCENE_B1).unwrap()
}

/// A smooth wobbling motion of `n` poses, with seeded noise of size `noise`.
fn wobble(n: usize, noise: f64, seed: u64) -> Vec<Pose> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.1;
            Pose {
                origin: DVec3::new(t.cos(), t.sin(), 0.1 * t) + rng.direction() * noise,
                rotation: DQuat::from_rotation_z(t)
                    * DQuat::from_rotation_x(0.3 * (2.0 * t).sin())
                    * DQuat::from_scaled_axis(rng.direction() * noise),
            }
        })
        .collect()
}

/// `n` poses zig-zagging sideways while moving forward: the recursion's error adds up by a
/// fixed amount per sample.
fn zigzag(n: usize) -> Vec<Pose> {
    (0..n)
        .map(|i| {
            let side = if i % 2 == 0 { 0.3 } else { -0.3 };
            Pose {
                origin: DVec3::new(i as f64, side, 0.0),
                rotation: DQuat::from_rotation_z(side),
            }
        })
        .collect()
}

#[test]
fn the_papers_open_scenes_and_smooth_sequences_are_not_flagged() {
    for s in presets::all().iter().filter(|s| !s.closed) {
        let times: Vec<f64> = (0..s.poses.len()).map(|i| i as f64).collect();
        for c in [C1_18, C1_19] {
            let Ok(m) = RationalMotion::from_poses(
                &s.poses,
                &times,
                false,
                c,
                &ReferenceTriangle::SCENE_B1,
            ) else {
                continue;
            };
            assert!(m.growth() < 2.0, "{} {c:?}: {}", s.id, m.growth());
            assert!(m.warning().is_none(), "{}", s.id);
        }
    }
    // 10 000 smooth samples: the recursion stays put.
    let smooth = wobble(10_000, 0.0, 1);
    for c in [C1_18, C1_19] {
        let m = fit(&smooth, c);
        assert!(m.growth() < 0.1, "{c:?}: {}", m.growth());
        assert!(m.warning().is_none());
    }
    // C⁰ has no recursion.
    let m = fit(&zigzag(60), Continuity::C0);
    assert_eq!(m.growth(), 0.0);
    assert!(m.warning().is_none());
}

#[test]
fn long_noisy_and_zigzag_sequences_are_flagged() {
    // 10 000 samples with 1% noise: each sample's misfit is carried on and added up.
    let noisy = wobble(10_000, 0.01, 7);
    for c in [C1_18, C1_19] {
        let m = fit(&noisy, c);
        assert!(m.growth() > GROWTH_WARNING, "{c:?}: {}", m.growth());
        let w = m.warning().expect("a warning");
        assert!(w.contains("10000 samples") && w.contains("C1"), "{w}");
    }
    // A zig-zag: flagged from a few dozen samples on, and the angular acceleration energy per
    // span shows why: C⁰'s stays the same, C¹'s runs away (by orders of magnitude between 8 and
    // 60 samples).
    let short = fit(&zigzag(8), C1_18);
    let long = fit(&zigzag(60), C1_18);
    assert!(short.warning().is_none(), "{}", short.growth());
    assert!(long.warning().is_some(), "{}", long.growth());
    let per_span = |n: usize, m: Method| {
        let t = compare_methods(&zigzag(n), false, &[m], &MetricsOptions::default()).unwrap();
        t.rows[0].single_step.angular_acceleration_energy / (n - 1) as f64
    };
    let (c0_short, c0_long) = (per_span(8, Method::Cc0), per_span(60, Method::Cc0));
    let (c1_short, c1_long) = (per_span(8, Method::Cc1), per_span(60, Method::Cc1));
    assert!(
        (c0_long / c0_short - 1.0).abs() < 0.1,
        "{c0_short} {c0_long}"
    );
    assert!(c1_long > 100.0 * c1_short, "{c1_short} {c1_long}");
}

#[test]
fn the_metrics_table_notes_the_warning_for_cc1_only() {
    let poses = zigzag(60);
    let options = MetricsOptions::default();
    let table = compare_methods(&poses, false, &[Method::Cc0, Method::Cc1], &options).unwrap();
    let warned = |row: usize| {
        table.rows[row]
            .notes
            .iter()
            .any(|n| n.starts_with("warning: ") && n.contains("grows without damping"))
    };
    assert!(!warned(0), "{:?}", table.rows[0].notes);
    assert!(warned(1), "{:?}", table.rows[1].notes);
    assert_eq!(Method::Cc1.warnings(&poses, false).len(), 1);
    assert!(Method::Cc1.warnings(&zigzag(8), false).is_empty());
    assert!(Method::Rb.warnings(&poses, false).is_empty());
}
