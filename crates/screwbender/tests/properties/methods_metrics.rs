//! The comparison metrics and the method registry: known values on known motions, the papers'
//! qualitative claims on scene A2 (`l_cycle_rotated`), and the text / JSON table.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::methods::{
    compare_methods, finite_difference, interpolation_error, preservation_inputs,
    single_step_metrics, Derivatives, Limit, Method, MetricsOptions, Side,
};
use screwbender::ErrorKind;
use screwbender::{Polyscrew, Pose};
use testkit::methods::{assert_rel, l_cycle_rotated};

#[test]
fn method_names_round_trip() {
    for m in Method::ALL {
        assert_eq!(m.name().parse::<Method>().unwrap(), m);
        assert_eq!(m.to_string(), m.name());
    }
    assert_eq!(" RB ".parse::<Method>().unwrap(), Method::Rb);
    let e = "bogus".parse::<Method>().unwrap_err();
    assert!(
        matches!(e.kind(), ErrorKind::UnknownValue { .. } if e.path() == "methods"),
        "{e}"
    );
    assert_eq!(Method::applicable(true).len(), 10);
    assert_eq!(Method::applicable(false).len(), 11);
    let e = Method::Cc1.build(&l_cycle_rotated(), true).err().unwrap();
    assert!(matches!(e.kind(), ErrorKind::Unsupported { .. }), "{e}");
}

#[test]
fn every_method_builds_open_and_closed() {
    let poses = l_cycle_rotated();
    for closed in [false, true] {
        for m in Method::applicable(closed) {
            let motion = m.build(&poses, closed).unwrap();
            assert_eq!(motion.is_closed(), closed, "{m}");
            assert_eq!(motion.knots().len(), poses.len(), "{m}");
            let (a, b) = motion.domain();
            assert_eq!(
                (a, b),
                (0.0, (poses.len() - usize::from(!closed)) as f64),
                "{m}"
            );
            for k in 0..=40 {
                assert!(
                    motion.pose_at(a + (b - a) * k as f64 / 40.0).is_finite(),
                    "{m}"
                );
            }
        }
    }
    // Errors name the pose, prefixed by nothing (the registry passes them through).
    let mut bad = poses.clone();
    bad[2].origin.x = f64::INFINITY;
    for m in Method::ALL {
        let e = m.build(&bad, false).err().unwrap();
        assert!(e.path().starts_with("poses[2]"), "{m}: {e}");
    }
}

#[test]
fn integrals_on_an_exact_circle() {
    // A polyscrew through samples of a uniform rotation is that rotation: a body point at radius
    // r from the axis turning at ω rad per unit has |a|² = r²ω⁴, |α| = 0.
    let omega = 0.5f64;
    let centre = DVec3::new(1.0, -1.0, 0.0);
    let poses: Vec<Pose> = (0..5)
        .map(|i| {
            let r = DQuat::from_rotation_z(omega * i as f64);
            Pose::new(centre + r * DVec3::new(3.0, 0.0, 0.0), r)
        })
        .collect();
    let m = Polyscrew::new(poses.clone(), false).unwrap();
    let opts = MetricsOptions::default();
    let row = single_step_metrics(&m, Derivatives::Auto, &opts);
    // Body point (0,0,0) at radius 3, (2,0,0) at radius 5, over 4 units.
    assert_rel(
        row.acceleration_energy[0],
        9.0 * omega.powi(4) * 4.0,
        1e-12,
        "∫|a|² r=3",
    );
    assert_rel(
        row.acceleration_energy[1],
        25.0 * omega.powi(4) * 4.0,
        1e-12,
        "∫|a|² r=5",
    );
    assert!(row.angular_acceleration_energy == 0.0);
    assert!(
        row.velocity_jump < 1e-9 && row.acceleration_jump < 1e-9,
        "{row:?}"
    );
    assert!(interpolation_error(&m, &poses) < 1e-14);
    assert_eq!(row.derivatives, "analytic");
    // The same through finite differences of the poses.
    let fd = single_step_metrics(&m, Derivatives::Sampled(1e-3), &opts);
    assert_rel(
        fd.acceleration_energy[1],
        row.acceleration_energy[1],
        1e-6,
        "sampled ∫|a|²",
    );
    assert!(fd.velocity_jump < 1e-5);
}

#[test]
fn finite_differences_match_analytic_kinematics() {
    let poses = l_cycle_rotated();
    for method in [Method::Polyscrew, Method::Rb, Method::Cc0, Method::Slerp] {
        let m = method.build(&poses, true).unwrap();
        for u in [0.3, 2.5, 4.71] {
            for local in [DVec3::ZERO, DVec3::new(2.0, 0.0, 0.0)] {
                let a = m.kinematics_at(u, local).unwrap();
                for side in [Side::Left, Side::Right, Side::Central] {
                    let f = finite_difference(m.as_ref(), u, local, side);
                    let scale = 1.0 + a.velocity.length();
                    assert!(
                        (a.velocity - f.velocity).length() < 1e-6 * scale,
                        "{method} {u} {side:?}"
                    );
                    assert!(
                        (a.angular_velocity - f.angular_velocity).length() < 1e-6,
                        "{method} {u}"
                    );
                    let scale = 1.0 + a.acceleration.length();
                    assert!(
                        (a.acceleration - f.acceleration).length() < 1e-4 * scale,
                        "{method} {u} {side:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn table_reproduces_the_papers_claims_on_scene_a2() {
    let poses = l_cycle_rotated();
    let t = compare_methods(
        &poses,
        true,
        &Method::applicable(true),
        &MetricsOptions::default(),
    )
    .unwrap();
    let row = |name: &str| t.rows.iter().find(|r| r.method == name).unwrap();
    // ScrewBender and the polyscrew: independent of the local frame and exact on screw motions.
    // So is the cumulative B-spline on SE(3) (each piece a screw; the poses of a screw motion
    // have equal twists, which the cumulative basis sums back to the screw).
    for name in ["polyscrew", "bspline", "fourpoint", "jarek", "se3bspline"] {
        let r = row(name);
        assert!(r.frame_dependence.unwrap() < 1e-12, "{name}: {r:?}");
        for e in [r.line_error, r.circle_error, r.helix_error] {
            assert!(e.unwrap() < 1e-12, "{name}: {r:?}");
        }
    }
    // The decoupled methods depend on the frame and cut circles and helices, but keep lines.
    for name in ["slerp", "decoupled", "kks", "rb", "cc0"] {
        let r = row(name);
        assert!(r.frame_dependence.unwrap() > 1e-2, "{name}: {r:?}");
        assert!(
            r.circle_error.unwrap() > 1e-2 && r.helix_error.unwrap() > 1e-2,
            "{name}: {r:?}"
        );
        assert!(r.line_error.unwrap() < 1e-12, "{name}: {r:?}");
    }
    // Interpolating methods pass through the poses; B-spline, Jarek and Kim–Kim–Shin do not.
    for name in ["polyscrew", "fourpoint", "slerp", "decoupled", "rb", "cc0"] {
        assert!(row(name).interpolation_error < 1e-12, "{name}");
    }
    for name in ["bspline", "jarek", "kks", "se3bspline"] {
        assert!(row(name).interpolation_error > 0.1, "{name}");
    }
    // Continuity classes: tests/properties/methods_continuity.rs. Smoothness ordering of the
    // subdivision schemes on the converged values: B-spline smoothest, then Jarek, then
    // 4-point.
    let (b, j, f) = (
        &row("bspline").smoothness,
        &row("jarek").smoothness,
        &row("fourpoint").smoothness,
    );
    assert_eq!(b.acceleration_jump.limit, Limit::Zero);
    let e = |c: &screwbender::methods::ConvergedMetrics| c.acceleration_energy[1].value;
    assert!(e(b) < e(j) && e(j) < e(f), "{} {} {}", e(b), e(j), e(f));
    let alpha = |name: &str| row(name).smoothness.angular_acceleration_energy.value;
    // Ramamoorthi–Barr minimises covariant acceleration among the interpolating C1 methods here
    // (rotation part; Squad is the other interpolating C1 rotation curve).
    assert!(alpha("rb") < alpha("decoupled"));
    // About one axis, KKS and the ScrewBender B-spline have the same rotation (the angle
    // B-spline), so the same ∫|α|².
    assert_rel(alpha("kks"), alpha("bspline"), 1e-3, "∫|α|²");

    let text = t.to_text();
    assert_eq!(
        text.lines().filter(|l| l.starts_with("rb ")).count(),
        1,
        "{text}"
    );
    let header = text.lines().nth(1).unwrap();
    assert!(
        header.starts_with("method") && header.contains("helix"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&t.to_json()).unwrap();
    assert_eq!(json["rows"].as_array().unwrap().len(), 10);
    assert_eq!(json["closed"], true);
}

#[test]
fn preservation_inputs_are_screws() {
    let [line, circle, helix] = preservation_inputs();
    assert_eq!((line.0, circle.0, helix.0), ("line", "circle", "helix"));
    assert!(line.1.angle() == 0.0);
    assert!((circle.1.angle() - 50f64.to_radians()).abs() < 1e-14);
    assert!((helix.1.angle() - 45f64.to_radians()).abs() < 1e-14);
}

#[test]
fn applicable_table_skips_unsupported_methods() {
    // Large alternating turns about z: the C¹ Chaudhry–Cameron recursion zig-zags and its
    // quaternion curve passes within 1e-3 of zero on segment 3 (found by a seeded search).
    let poses: Vec<Pose> = [3.0f64, -2.0, 1.2, -0.4, 2.6]
        .iter()
        .enumerate()
        .map(|(i, &a)| Pose::new(DVec3::new(i as f64, 0.0, 0.0), DQuat::from_rotation_z(a)))
        .collect();
    let e = Method::Cc1.build(&poses, false).err().unwrap();
    assert!(matches!(e.kind(), ErrorKind::Unsupported { .. }), "{e}");
    assert!(e.to_string().contains("segment 3"), "{e}");
    let t = screwbender::methods::compare_applicable(&poses, false, &MetricsOptions::default())
        .unwrap();
    assert_eq!(t.rows.len(), 10);
    assert!(t.skipped[0].starts_with("cc1"), "{:?}", t.skipped);
    assert!(t.to_text().contains("skipped cc1"));
    let e = compare_methods(&poses, false, &[Method::Cc1], &MetricsOptions::default()).unwrap_err();
    assert!(e.path().starts_with("cc1"), "{e}");
    let closed =
        screwbender::methods::compare_applicable(&poses, true, &MetricsOptions::default()).unwrap();
    assert_eq!((closed.rows.len(), closed.skipped.len()), (10, 0));
}
