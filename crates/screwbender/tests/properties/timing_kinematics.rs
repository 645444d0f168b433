//! Kinematics in real time (what the Plots view draws): the analytic kinematics of the refined
//! polyscrew, retimed through the C¹ timing map, equal finite differences of the sampled poses
//! in time — natively and in the browser.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::{Rules, Scheme, ScrewBender, Subdivision, Timing};
use testkit::{assert_vec_near, Rng};

/// Time step of the differences and their accuracy (central differences: O(h²) truncation,
/// O(ε/h²) rounding for accelerations).
const H: f64 = 1e-4;

#[test]
fn retimed_kinematics_equal_differences_of_timed_poses() {
    let mut rng = Rng::new(0x7133);
    let poses = rng.cycle(6, 1.2);
    let sub = Subdivision::new(Scheme::Jarek, Rules::Direct, 3);
    let motion = ScrewBender::new(poses, true, sub).unwrap();
    let timing = Timing::new(vec![0.0, 0.7, 2.0, 2.5, 4.0, 4.3, 6.0], true).unwrap();
    let local = DVec3::new(1.5, -0.4, 0.8);
    let position = |t: f64| {
        let (u, _) = timing.parameter(t);
        motion.refined().point_kinematics(u, local).position
    };
    let mut checked = 0;
    for k in 0..300 {
        let t = 0.013 + 0.0199 * k as f64;
        let (u, du, ddu) = timing.parameter_derivatives(t);
        // Stay inside one refined span and one timing interval (the derivatives jump at their
        // knots: the refined polyscrew is C⁰, the timing map C¹).
        let span = u * 8.0;
        let near_knot = (span - span.round()).abs() < 0.02
            || timing.knots().iter().any(|&x| (x - t).abs() < 3.0 * H);
        if near_knot {
            continue;
        }
        let k = motion.refined().point_kinematics(u, local).retimed(du, ddu);
        let (p, m, c) = (position(t + H), position(t - H), position(t));
        let v = (p - m) / (2.0 * H);
        let a = (p - c * 2.0 + m) / (H * H);
        assert_vec_near(
            k.velocity,
            v,
            1e-6 * (1.0 + v.length()),
            &format!("velocity at t = {t}"),
        );
        assert_vec_near(
            k.acceleration,
            a,
            2e-3 * (1.0 + a.length()),
            &format!("acceleration at t = {t}"),
        );
        checked += 1;
    }
    assert!(checked > 150, "only {checked} samples away from knots");
}

#[test]
fn uniform_timing_leaves_kinematics_unchanged() {
    let mut rng = Rng::new(9);
    let motion = ScrewBender::new(
        rng.cycle(5, 1.0),
        true,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 4),
    )
    .unwrap();
    let timing = Timing::uniform(5, true);
    for k in 0..50 {
        let t = 0.1 * k as f64 + 0.005;
        let (u, du, ddu) = timing.parameter_derivatives(t);
        assert!((du - 1.0).abs() < 1e-15 && ddu.abs() < 1e-12);
        let a = motion.refined().point_kinematics(u, DVec3::X);
        let b = a.retimed(du, ddu);
        assert_vec_near(b.velocity, a.velocity, 1e-14, "velocity");
        assert_vec_near(b.acceleration, a.acceleration, 1e-12, "acceleration");
    }
}
