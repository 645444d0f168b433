//! Local re-subdivision with caller-owned buffers (`Subdivision::update_local_with`,
//! `ScrewBender::set_control_pose_with`, as a drag uses them): bit for bit the motion built
//! afresh from the moved control poses, whatever the buffers held before, and nothing changes
//! on error.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::{Pose, Rules, Scheme, ScrewBender, Subdivision, SubdivisionBuffers};
use testkit::Rng;

fn bits(p: &[Pose]) -> Vec<[u64; 7]> {
    p.iter()
        .map(|p| {
            let (o, q) = (p.origin, p.rotation);
            [o.x, o.y, o.z, q.x, q.y, q.z, q.w].map(f64::to_bits)
        })
        .collect()
}

/// Every scheme and rule set the options allow, at a few levels.
fn options() -> Vec<Subdivision> {
    let mut out = Vec::new();
    for levels in [0, 2, 4] {
        for scheme in [
            Scheme::BSpline,
            Scheme::FourPoint,
            Scheme::Jarek,
            Scheme::J(0.3),
        ] {
            for rules in [Rules::Direct, Rules::SplitThenTweak] {
                let s = Subdivision::new(scheme, rules, levels);
                if s.validate().is_ok() {
                    out.push(s);
                }
            }
        }
    }
    out
}

/// `a` and `b` hold the same numbers bit for bit: refined poses and every span screw (the
/// `Debug` text of an `f64` names its bits apart from NaN payloads).
fn assert_same_motion(a: &ScrewBender, b: &ScrewBender, what: &str) {
    assert_eq!(
        bits(a.refined().poses()),
        bits(b.refined().poses()),
        "{what}"
    );
    assert_eq!(
        format!("{:?}", a.refined().spans()),
        format!("{:?}", b.refined().spans()),
        "{what}"
    );
    assert_eq!(a.control(), b.control(), "{what}");
}

#[test]
fn set_control_pose_with_reused_buffers_matches_a_fresh_motion_bit_for_bit() {
    let mut rng = Rng::new(4711);
    // One set of buffers for every drag below, across options, lengths and closedness: what a
    // previous drag left in them must not leak into the next.
    let mut buffers = SubdivisionBuffers::new();
    // Short sequences re-subdivide whole, long ones only the moved pose's window.
    for n in [4, 9, 17] {
        let control = rng.cycle(n, 1.1);
        for s in options() {
            for closed in [false, true] {
                let mut dragged = ScrewBender::new(control.clone(), closed, s).unwrap();
                let mut plain = dragged.clone();
                let mut poses = control.clone();
                for i in [0, 1, n / 2, n - 2, n - 1] {
                    let moved = Pose::new(
                        poses[i].origin + DVec3::new(0.3, -0.2, 0.1),
                        DQuat::from_rotation_y(0.4) * poses[i].rotation,
                    );
                    poses[i] = moved;
                    let what = format!("n {n}, {s:?}, closed {closed}, pose {i}");
                    let range = dragged
                        .set_control_pose_with(i, moved, &mut buffers)
                        .unwrap();
                    // The same rewritten range as the route with kept buffers.
                    assert_eq!(plain.set_control_pose(i, moved).unwrap(), range, "{what}");
                    let fresh = ScrewBender::new(poses.clone(), closed, s).unwrap();
                    assert_same_motion(&dragged, &fresh, &what);
                    assert_same_motion(&plain, &fresh, &what);
                }
            }
        }
    }
}

#[test]
fn update_local_with_matches_update_local_and_errors_change_nothing() {
    let mut rng = Rng::new(99);
    let mut buffers = SubdivisionBuffers::new();
    let control = rng.cycle(15, 1.0);
    let s = Subdivision::new(Scheme::Jarek, Rules::Direct, 3);
    let refined = s.apply(&control, true).unwrap();
    let mut moved = control.clone();
    moved[7] = Pose::new(moved[7].origin + DVec3::Z, moved[7].rotation);
    let (mut a, mut b) = (refined.clone(), refined.clone());
    let ra = s
        .update_local_with(&moved, true, 7, &mut a, &mut buffers)
        .unwrap();
    let rb = s.update_local(&moved, true, 7, &mut b).unwrap();
    assert_eq!(ra, rb);
    // A window, not the whole motion, and the result of a full subdivision.
    assert!(
        ra.1 < refined.len(),
        "rewrote {} of {}",
        ra.1,
        refined.len()
    );
    assert_eq!(bits(&a), bits(&s.apply(&moved, true).unwrap()));

    // Bad index, wrong refined length: an error, and the refined poses stay as they were.
    let before = bits(&a);
    assert!(s
        .update_local_with(&moved, true, 15, &mut a, &mut buffers)
        .is_err());
    assert!(s
        .update_local_with(&moved, true, 3, &mut a[1..], &mut buffers)
        .is_err());
    assert_eq!(bits(&a), before);

    // A bad pose through the motion: an error, and the motion is unchanged.
    let mut motion = ScrewBender::new(control.clone(), true, s).unwrap();
    let kept = motion.clone();
    let bad = Pose::new(DVec3::new(f64::NAN, 0.0, 0.0), DQuat::IDENTITY);
    assert!(motion.set_control_pose_with(2, bad, &mut buffers).is_err());
    assert!(motion
        .set_control_pose_with(15, control[0], &mut buffers)
        .is_err());
    assert_same_motion(&motion, &kept, "after errors");
}
