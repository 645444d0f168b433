//! The screw between arbitrary poses, including near-degenerate pairs (relative rotations at and
//! near 0 and π, tiny and huge translations): no panic; finite, unit results; the screw starts at
//! `a`, ends at `b` and its midpoint agrees with `at(½)`, to tolerances scaled to the input.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use screwbender::{screw_paper, Pose, Screw};

#[path = "common.rs"]
mod common;
use common::PoseIn;

#[derive(Arbitrary, Debug)]
struct Input {
    a: PoseIn,
    b: PoseIn,
    /// When set, `b` is `a` moved by `b` (a relative motion, often tiny or a half turn).
    relative: bool,
    t: f64,
}

fuzz_target!(|input: Input| {
    let (Some(a), Some(m)) = (input.a.pose(), input.b.pose()) else {
        return;
    };
    let b = if input.relative { m.compose(&a) } else { m };
    let scale = common::scale_of(&[a, b]);
    let checked = scale <= common::FINITE_CHECK_SCALE && b.is_finite();
    if !b.is_finite() {
        return;
    }
    let s = Screw::between(&a, &b);
    let _ = s.parameters();
    let (omega, v0) = s.twist();
    let t = if input.t.is_finite() {
        input.t.fract() * 4.0
    } else {
        0.5
    };
    let at = [
        s.at(0.0),
        s.at(1.0),
        s.at(0.5),
        s.at(t),
        Screw::midpoint(&a, &b),
    ];
    let _ = screw_paper(&a, t, &b);
    if !checked {
        return;
    }
    assert!(
        omega.is_finite() && v0.is_finite(),
        "twist {omega:?} {v0:?}"
    );
    for (k, p) in at.iter().enumerate() {
        common::assert_sane(p, &format!("screw point {k}"));
    }
    // Position tolerance scaled to the input; rotations are compared by angle.
    let tol = 1e-9 * (1.0 + scale);
    let near = |p: &Pose, q: &Pose, what: &str| {
        let d = (p.origin - q.origin).length();
        let ang = p.angle_to(q);
        assert!(
            d <= tol && ang <= 1e-9,
            "{what}: {p:?} vs {q:?} (d = {d:e}, angle = {ang:e})"
        );
    };
    near(&at[0], &a, "at(0) = a");
    near(&at[1], &b, "at(1) = b");
    near(&at[4], &at[2], "midpoint = at(½)");
});
