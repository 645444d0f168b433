//! Every comparison method's row against its continuity class ([`Method::smoothness`]): the
//! converged metrics of a C⁰ method show velocity jumps at the knots, a C¹ one none in velocity
//! (and, when made of pieces, jumps in acceleration), a C² one neither. On a cycle (scene A2) and on an open sequence,
//! so that every method of [`Method::ALL`] is measured at least once.
//!
//! Native only: its fits or sampling are among the heaviest of these modules, and the browser
//! test runner gives up on a page that does not answer for 30 s, which a test that long holds
//! up; the wasm stage leaves it out (tests/properties/main.rs).
#![cfg(not(target_arch = "wasm32"))]

use screwbender::methods::{
    compare_methods, Limit, Method, MetricsOptions, MetricsRow, Smoothness,
};
use testkit::methods::l_cycle_rotated;

/// The C¹ methods made of polynomial or rational pieces joined at the knots: their acceleration
/// jumps there. (The C¹ subdivision limits have no such jump at the control knots: their second
/// derivative is rough everywhere rather than broken at the knots.)
const PIECEWISE_C1: [&str; 3] = ["decoupled", "rb", "cc1"];

fn check(row: &MetricsRow, class: Smoothness) {
    let c = &row.smoothness;
    let name = &row.method;
    let jumps =
        |limit: Limit| [c.velocity_jump.limit, c.angular_velocity_jump.limit].contains(&limit);
    match class {
        Smoothness::C0 => {
            assert_eq!(c.velocity_jump.limit, Limit::Value, "{name}: {c:?}");
            assert!(c.velocity_jump.value > 1e-3, "{name}: {c:?}");
            // The acceleration at a velocity jump is an impulse, its integral infinite.
            assert_eq!(c.acceleration_jump.limit, Limit::Impulse, "{name}: {c:?}");
            assert_eq!(c.acceleration_jump.value, c.velocity_jump.value, "{name}");
            assert!(
                c.acceleration_energy
                    .iter()
                    .all(|e| e.limit == Limit::Impulse),
                "{name}"
            );
        }
        Smoothness::C1 | Smoothness::C2 => {
            assert!(
                !jumps(Limit::Value) && !jumps(Limit::Impulse),
                "{name}: {c:?}"
            );
            assert_eq!(c.velocity_jump.limit, Limit::Zero, "{name}: {c:?}");
            assert_eq!(c.angular_velocity_jump.limit, Limit::Zero, "{name}: {c:?}");
            assert!(
                c.acceleration_energy
                    .iter()
                    .all(|e| e.limit == Limit::Value),
                "{name}"
            );
            if PIECEWISE_C1.contains(&name.as_str()) {
                assert_eq!(c.acceleration_jump.limit, Limit::Value, "{name}: {c:?}");
                assert!(c.acceleration_jump.value > 1e-2, "{name}: {c:?}");
            }
            if class == Smoothness::C2 {
                assert_eq!(c.acceleration_jump.limit, Limit::Zero, "{name}: {c:?}");
                assert_eq!(
                    c.angular_acceleration_jump.limit,
                    Limit::Zero,
                    "{name}: {c:?}"
                );
            }
        }
    }
}

#[test]
fn every_method_shows_its_continuity_class() {
    let poses = l_cycle_rotated();
    let options = MetricsOptions::default();
    let cycle = compare_methods(&poses, true, &Method::applicable(true), &options).unwrap();
    // Open: the methods without a cyclic form (the C¹ Chaudhry–Cameron motion, the discrete
    // baseline of Barr et al.) and the interpolating Lie-group B-splines, which this cycle's
    // closing turn of 105° defeats (methods_lie_spline.rs), on the same poses as a sequence.
    let open = compare_methods(
        &poses,
        false,
        &[
            Method::Cc1,
            Method::Barr,
            Method::Se3Interp,
            Method::SplitInterp,
        ],
        &options,
    )
    .unwrap();
    let mut seen = Vec::new();
    for row in cycle.rows.iter().chain(&open.rows) {
        let m: Method = row.method.parse().unwrap();
        check(row, m.smoothness());
        seen.push(m);
    }
    for m in Method::ALL {
        assert!(seen.contains(&m), "{m} not measured");
    }
}
