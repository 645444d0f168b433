//! Helpers shared by the integration tests (native and wasm32 alike: no clocks, files or threads).

pub mod methods;
mod rng;

pub use rng::Rng;

use glam::{DQuat, DVec2, DVec3};
use screwbender::{Pose, Scheme};

/// The bits of a pose's seven numbers (origin, then quaternion `x, y, z, w`): for comparisons
/// that must be exact (`==` would pass `0.0` for `-0.0` and fail on equal NaNs).
pub fn pose_bits(p: &Pose) -> [u64; 7] {
    let (o, q) = (p.origin, p.rotation);
    [o.x, o.y, o.z, q.x, q.y, q.z, q.w].map(f64::to_bits)
}

/// A pose from an origin and a `[w, x, y, z]` quaternion that may be rounded (normalised here).
pub fn pose(o: [f64; 3], q: [f64; 4]) -> Pose {
    Pose::new(
        DVec3::from_array(o),
        DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize(),
    )
}

/// Asserts that two poses agree: origins within `tol` and rotations within `tol` radians
/// (quaternion sign ignored). Prints both poses on failure.
#[track_caller]
pub fn assert_pose_near(got: &Pose, want: &Pose, tol: f64, what: &str) {
    let dx = (got.origin - want.origin).length();
    let da = got.angle_to(want);
    assert!(
        dx <= tol && da <= tol,
        "{what}: poses differ (|Δo| = {dx:.3e}, angle = {da:.3e}, tol {tol:.1e})\n  got  {:?} {:?}\n  want {:?} {:?}",
        got.origin,
        got.rotation_wxyz(),
        want.origin,
        want.rotation_wxyz()
    );
}

/// Asserts two vectors agree to `tol`.
#[track_caller]
pub fn assert_vec_near(got: DVec3, want: DVec3, tol: f64, what: &str) {
    let d = (got - want).length();
    assert!(
        d <= tol,
        "{what}: |Δ| = {d:.3e} > {tol:.1e}\n  got  {got:?}\n  want {want:?}"
    );
}

/// The largest pose error between two equally long sequences.
pub fn max_pose_error(a: &[Pose], b: &[Pose]) -> f64 {
    assert_eq!(a.len(), b.len(), "sequence lengths differ");
    a.iter()
        .zip(b)
        .map(|(p, q)| (p.origin - q.origin).length() + p.angle_to(q))
        .fold(0.0, f64::max)
}

/// docs/math/point-rules.md §5: one subdivision step of the L polygon (scene A4 `polygon_l`) by
/// each point scheme, the same for both rule sets.
pub fn l_polygon_one_step() -> Vec<(Scheme, Vec<DVec2>)> {
    let points =
        |pts: &[[f64; 2]]| -> Vec<DVec2> { pts.iter().map(|p| DVec2::from_array(*p)).collect() };
    vec![
        (
            Scheme::BSpline,
            points(&[
                [0.75, 0.75],
                [3.0, 0.0],
                [5.25, 0.25],
                [6.0, 1.0],
                [5.5, 1.75],
                [4.0, 2.0],
                [2.5, 2.5],
                [2.0, 4.0],
                [1.75, 5.5],
                [1.0, 6.0],
                [0.25, 5.25],
                [0.0, 3.0],
            ]),
        ),
        (
            Scheme::FourPoint,
            points(&[
                [0.0, 0.0],
                [3.0, -0.5],
                [6.0, 0.0],
                [6.625, 1.0],
                [6.0, 2.0],
                [4.0, 1.875],
                [2.0, 2.0],
                [1.875, 4.0],
                [2.0, 6.0],
                [1.0, 6.625],
                [0.0, 6.0],
                [-0.5, 3.0],
            ]),
        ),
        (
            Scheme::Jarek,
            points(&[
                [0.375, 0.375],
                [3.0, -0.25],
                [5.625, 0.125],
                [6.3125, 1.0],
                [5.75, 1.875],
                [4.0, 1.9375],
                [2.25, 2.25],
                [1.9375, 4.0],
                [1.875, 5.75],
                [1.0, 6.3125],
                [0.125, 5.625],
                [-0.25, 3.0],
            ]),
        ),
    ]
}
