//! The converged comparison metrics (methods::convergence): every method measured the same way
//! and extrapolated to a vanishing step, on scene A2 (`l_cycle_rotated`, a cycle).
//!
//! Native only: its fits or sampling are among the heaviest of these modules, and the browser
//! test runner gives up on a page that does not answer for 30 s, which a test that long holds
//! up; the wasm stage leaves it out (tests/properties/main.rs).
#![cfg(not(target_arch = "wasm32"))]

use glam::DVec3;
use screwbender::methods::{converged_metrics, Limit, Method};
use screwbender::Pose;
use testkit::methods::l_cycle_rotated;

const POINTS: [DVec3; 2] = [DVec3::ZERO, DVec3::new(2.0, 0.0, 0.0)];

/// The velocity jumps of SLERP + linear origins in closed form: on span i the body point moves
/// with (o_{i+1} − o_i) + ω_i × R_i p, ω_i the rotation vector of R_{i+1} R_iᵀ.
fn slerp_jumps(poses: &[Pose]) -> (f64, f64) {
    let n = poses.len();
    let span = |i: usize| {
        let (a, b) = (poses[i % n], poses[(i + 1) % n]);
        let (axis, angle) = (b.rotation * a.rotation.conjugate()).to_axis_angle();
        let w = if angle > std::f64::consts::PI {
            axis * (angle - 2.0 * std::f64::consts::PI)
        } else {
            axis * angle
        };
        (b.origin - a.origin, w)
    };
    let (mut v, mut w) = (0.0f64, 0.0f64);
    for (i, pose) in poses.iter().enumerate() {
        let (dl, wl) = span(i + n - 1);
        let (dr, wr) = span(i);
        w = w.max((wr - wl).length());
        for p in POINTS {
            let rp = pose.rotation * p;
            v = v.max(((dr + wr.cross(rp)) - (dl + wl.cross(rp))).length());
        }
    }
    (v, w)
}

#[test]
fn slerp_jumps_are_exact_and_its_accelerations_impulses() {
    let poses = l_cycle_rotated();
    let c = converged_metrics(Method::Slerp, &poses, true, &POINTS).unwrap();
    let (v, w) = slerp_jumps(&poses);
    assert_eq!(c.velocity_jump.limit, Limit::Value);
    assert!(
        (c.velocity_jump.value - v).abs() <= 1e-7 * v,
        "{:?} vs {v}",
        c.velocity_jump
    );
    assert!(
        (c.angular_velocity_jump.value - w).abs() <= 1e-7 * w,
        "{:?} vs {w}",
        c.angular_velocity_jump
    );
    for m in [
        &c.acceleration_jump,
        &c.angular_acceleration_jump,
        &c.angular_acceleration_energy,
        &c.acceleration_energy[0],
    ] {
        assert_eq!(m.limit, Limit::Impulse, "{m:?}");
    }
}

#[test]
fn four_point_and_decoupled_are_c1_at_convergence() {
    let poses = l_cycle_rotated();
    for m in [Method::FourPoint, Method::Decoupled, Method::BSpline] {
        let c = converged_metrics(m, &poses, true, &POINTS).unwrap();
        eprintln!("{m}: {c:#?}");
        assert_eq!(
            c.velocity_jump.limit,
            Limit::Zero,
            "{m}: {:?}",
            c.velocity_jump
        );
        assert_eq!(
            c.angular_velocity_jump.limit,
            Limit::Zero,
            "{m}: {:?}",
            c.angular_velocity_jump
        );
        // The coarse estimates shrink at least linearly with the step.
        let e = c.velocity_jump.estimates;
        assert!(
            e[2] <= 0.6 * e[1] + 1e-9 && e[1] <= 0.6 * e[0] + 1e-9,
            "{m}: {e:?}"
        );
    }
}

#[test]
fn finite_values_are_converged() {
    let poses = l_cycle_rotated();
    for m in [
        Method::FourPoint,
        Method::Decoupled,
        Method::BSpline,
        Method::Jarek,
    ] {
        let c = converged_metrics(m, &poses, true, &POINTS).unwrap();
        for x in [&c.angular_acceleration_energy, &c.acceleration_energy[1]] {
            if x.limit == Limit::Value {
                // Two significant digits hold at least (the page shows as many as the error
                // allows): the extrapolation's correction is below 1 %.
                assert!(x.error <= 1e-2 * x.value.max(1e-9), "{m}: {x:?}");
            }
        }
    }
}
