//! Polyscrew evaluation and its closed-form kinematics (docs/math/polyscrew.md), natively and in the browser.

// The math notes print values like 0.707107 (docs/math/README.md §3): comparing with them is the point.
#![allow(clippy::approx_constant)]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::{Motion, Polyscrew, Rules, Scheme, ScrewBender, Subdivision};
use testkit::{assert_pose_near, assert_vec_near, Rng};

/// Finite-difference step (coarse units) and the accuracy it allows: central differences have
/// error O(h²)·|x'''| plus rounding O(ε|x|/h) for velocity, O(ε|x|/h²) for acceleration.
const H: f64 = 1e-4;

#[test]
fn passes_through_poses_and_wraps() {
    let mut rng = Rng::new(21);
    let p = rng.cycle(5, 1.5);
    let closed = Polyscrew::new(p.clone(), true).unwrap();
    for (i, pi) in p.iter().enumerate() {
        assert_pose_near(&closed.pose_at(i as f64), pi, 1e-12, "closed knot");
    }
    assert_pose_near(&closed.pose_at(5.0), &p[0], 1e-12, "wrap at n");
    assert_pose_near(
        &closed.pose_at(-0.25),
        &closed.pose_at(4.75),
        1e-12,
        "negative u wraps",
    );
    assert_eq!(closed.domain(), (0.0, 5.0));
    let open = Polyscrew::new(p.clone(), false).unwrap();
    assert_eq!(open.domain(), (0.0, 4.0));
    assert_pose_near(&open.pose_at(4.0), &p[4], 1e-12, "open end");
    // Outside the domain an open polyscrew extrapolates its end screws.
    let s = screwbender::Screw::between(&p[3], &p[4]);
    assert_pose_near(&open.pose_at(4.5), &s.at(1.5), 1e-12, "extrapolation");
    assert_eq!(closed.sample(10).len(), 10);
    assert_pose_near(
        &open.sample(9)[8],
        &p[4],
        1e-12,
        "open sample includes the end",
    );
}

/// The analytic velocity, acceleration and angular velocity equal central finite differences of
/// sampled poses, on a plain and on a refined polyscrew (span length 2^−ℓ).
#[test]
fn analytic_kinematics_match_finite_differences() {
    let mut rng = Rng::new(22);
    for case in 0..20 {
        let p = rng.cycle(5, 1.5);
        let plain = Polyscrew::new(p.clone(), true).unwrap();
        let smooth =
            ScrewBender::new(p, true, Subdivision::new(Scheme::Jarek, Rules::Direct, 3)).unwrap();
        let motions: [&dyn Motion; 2] = [&plain, &smooth];
        for m in motions {
            for _ in 0..10 {
                let local = DVec3::new(
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                    rng.range(-2.0, 2.0),
                );
                // Stay inside a span of the refined motion so the finite differences don't cross a knot.
                let span = 1.0 / 8.0;
                let u = (rng.range(0.0, 5.0) / span).floor() * span + rng.range(0.2, 0.8) * span;
                let x = |v: f64| m.pose_at(v).transform_point(local);
                let k = m.kinematics_at(u, local).unwrap();
                let vel = (x(u + H) - x(u - H)) / (2.0 * H);
                let acc = (x(u + H) - 2.0 * x(u) + x(u - H)) / (H * H);
                let scale = 1.0 + k.velocity.length();
                assert_vec_near(
                    k.position,
                    x(u),
                    1e-12,
                    &format!("{} case {case} position", m.name()),
                );
                assert_vec_near(
                    k.velocity,
                    vel,
                    1e-6 * scale,
                    &format!("{} case {case} velocity", m.name()),
                );
                assert_vec_near(
                    k.acceleration,
                    acc,
                    1e-3 * (1.0 + k.acceleration.length()),
                    &format!("{} case {case} acceleration", m.name()),
                );
                // Angular velocity: the rotation difference over 2H.
                let (r0, r1) = (m.pose_at(u - H).rotation, m.pose_at(u + H).rotation);
                let d = r1 * r0.conjugate();
                let d = if d.w < 0.0 { -d } else { d };
                let omega = 2.0 * DVec3::new(d.x, d.y, d.z) / (2.0 * H);
                assert_vec_near(
                    k.angular_velocity,
                    omega,
                    1e-6 * (1.0 + omega.length()),
                    "angular velocity",
                );
                assert_eq!(k.angular_acceleration, DVec3::ZERO);
            }
        }
    }
}

/// docs/math/properties.md §7: the plain polyscrew's velocity jumps at the control poses; a B-spline refinement's
/// jumps at its refined knots shrink as levels grow (towards a C¹/C² limit).
#[test]
fn velocity_jumps_shrink_with_levels() {
    let p = screwbender::presets::preset("l_cycle_rotated")
        .unwrap()
        .poses;
    let plain = Polyscrew::new(p.clone(), true).unwrap();
    let local = DVec3::new(2.0, 0.0, 0.0);
    let jump = |m: &Polyscrew, i: usize| {
        let n = m.spans().len();
        let left = m.span_kinematics((i + n - 1) % n, 1.0, local).velocity;
        let right = m.span_kinematics(i, 0.0, local).velocity;
        (left - right).length()
    };
    let max_jump = |m: &Polyscrew| (0..m.spans().len()).map(|i| jump(m, i)).fold(0.0, f64::max);
    assert!(max_jump(&plain) > 1.0, "the polyscrew has corners");
    let mut last = f64::INFINITY;
    for levels in [2, 4, 6] {
        let m = ScrewBender::new(
            p.clone(),
            true,
            Subdivision::new(Scheme::BSpline, Rules::Direct, levels),
        )
        .unwrap();
        let j = max_jump(m.refined());
        assert!(
            j < last / 2.0,
            "levels {levels}: max velocity jump {j} did not shrink from {last}"
        );
        last = j;
    }
}
