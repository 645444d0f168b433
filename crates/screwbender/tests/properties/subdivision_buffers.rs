//! Subdivision into caller-owned buffers (`Subdivision::apply_into`), motions rebuilt in place
//! (`ScrewBender::rebuild`) and span screws built in batches: all bit for bit the one-at-a-time
//! routes, whatever the buffers held before.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::{
    ErrorKind, Polyscrew, Pose, Rules, Scheme, Screw, ScrewBender, Subdivision, SubdivisionBuffers,
};
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
    for levels in [0, 1, 3, 5] {
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

/// Pose sequences of several lengths, with the rare cases of the screw kernel among regular
/// spans: identical and sign-flipped rotations, a pure translation, a half turn.
fn sequences() -> Vec<Vec<Pose>> {
    let mut rng = Rng::new(2020);
    let mut out: Vec<Vec<Pose>> = [2, 3, 7, 13].map(|n| rng.cycle(n, 1.2)).into();
    let mut rare = rng.cycle(9, 1.0);
    rare[3] = Pose::new(rare[2].origin + DVec3::X, rare[2].rotation);
    rare[5] = Pose::new(rare[4].origin, -rare[4].rotation);
    rare[7] = Pose::new(
        rare[6].origin + DVec3::Y,
        DQuat::from_rotation_z(std::f64::consts::PI) * rare[6].rotation,
    );
    out.push(rare);
    out
}

#[test]
fn apply_into_reused_buffers_matches_apply_bit_for_bit() {
    // One pair of buffers for every call, large and small, poses and points: what they held
    // before must never show in a result.
    let mut out = Vec::new();
    let mut buffers = SubdivisionBuffers::new();
    let mut points = Vec::new();
    let mut point_buffers = SubdivisionBuffers::new();
    for poses in sequences() {
        for s in options() {
            for closed in [true, false] {
                let want = s.apply(&poses, closed).unwrap();
                s.apply_into(&poses, closed, &mut out, &mut buffers)
                    .unwrap();
                assert_eq!(out.len(), s.output_len(poses.len(), closed).unwrap());
                assert_eq!(bits(&out), bits(&want), "{s:?} closed {closed}");
                let origins: Vec<DVec3> = poses.iter().map(|p| p.origin).collect();
                s.apply_into(&origins, closed, &mut points, &mut point_buffers)
                    .unwrap();
                assert_eq!(points, s.apply(&origins, closed).unwrap(), "{s:?} points");
            }
        }
    }
}

#[test]
fn apply_into_errors_leave_the_output_as_it_was() {
    let poses = Rng::new(5).cycle(4, 1.0);
    let mut out = vec![Pose::IDENTITY; 3];
    let mut buffers = SubdivisionBuffers::new();
    let too_many = Subdivision::new(Scheme::FourPoint, Rules::Direct, 30);
    let err = too_many
        .apply_into(&poses, true, &mut out, &mut buffers)
        .unwrap_err();
    assert!(
        matches!(err.kind(), ErrorKind::TooManyPoses { .. }),
        "{err}"
    );
    let bad_option = Subdivision::new(Scheme::J(f64::NAN), Rules::Direct, 2);
    assert!(bad_option
        .apply_into(&poses, true, &mut out, &mut buffers)
        .is_err());
    let s = Subdivision::new(Scheme::FourPoint, Rules::Direct, 2);
    assert!(s
        .apply_into(&poses[..1], true, &mut out, &mut buffers)
        .is_err());
    assert_eq!(out, vec![Pose::IDENTITY; 3]);
}

/// `a` and `b` hold the same numbers bit for bit (refined poses and every span screw; the
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
    assert_eq!(a.subdivision(), b.subdivision(), "{what}");
}

#[test]
fn span_screws_are_those_of_one_at_a_time_bit_for_bit() {
    for poses in sequences() {
        for closed in [true, false] {
            let p = Polyscrew::new(poses.clone(), closed).unwrap();
            let n = poses.len();
            let one: Vec<Screw> = (0..p.spans().len())
                .map(|i| Screw::between(&poses[i], &poses[(i + 1) % n]))
                .collect();
            assert_eq!(format!("{:?}", p.spans()), format!("{one:?}"), "n {n}");
            let s = Subdivision::new(Scheme::Jarek, Rules::Direct, 4);
            let m = ScrewBender::new(poses.clone(), closed, s).unwrap();
            let r = m.refined().poses();
            let one: Vec<Screw> = (0..m.refined().spans().len())
                .map(|i| Screw::between(&r[i], &r[(i + 1) % r.len()]))
                .collect();
            assert_eq!(format!("{:?}", m.refined().spans()), format!("{one:?}"));
        }
    }
}

#[test]
fn rebuild_matches_new_bit_for_bit_and_errors_change_nothing() {
    let mut buffers = SubdivisionBuffers::new();
    let all = sequences();
    let first = Subdivision::new(Scheme::FourPoint, Rules::Direct, 5);
    let mut motion = ScrewBender::new(all[3].clone(), true, first).unwrap();
    for poses in &all {
        for s in options() {
            for closed in [false, true] {
                motion.rebuild(poses, closed, s, &mut buffers).unwrap();
                let want = ScrewBender::new(poses.clone(), closed, s).unwrap();
                assert_same_motion(&motion, &want, &format!("{s:?} closed {closed}"));
            }
        }
    }
    let before = motion.clone();
    let mut bad = all[2].clone();
    bad[1].rotation = DQuat::from_xyzw(0.0, 0.0, 0.0, 2.0);
    let s = Subdivision::new(Scheme::BSpline, Rules::Direct, 3);
    let err = motion.rebuild(&bad, true, s, &mut buffers).unwrap_err();
    assert_eq!(
        err.to_string(),
        ScrewBender::new(bad.clone(), true, s)
            .unwrap_err()
            .to_string()
    );
    let too_many = Subdivision::new(Scheme::BSpline, Rules::Direct, 40);
    assert!(motion
        .rebuild(&all[2], true, too_many, &mut buffers)
        .is_err());
    assert!(motion.rebuild(&all[2][..1], true, s, &mut buffers).is_err());
    assert_same_motion(&motion, &before, "after errors");
}

#[test]
fn refined_poses_are_the_subdivision_of_the_checked_control_poses() {
    // What the CLI's `subdivide` writes without building the motion: for every preset, scheme
    // and rule set, the refined poses of `ScrewBender::new` are the subdivision of the control
    // poses as `Polyscrew::new` checks them, bit for bit (the motion's own check of its refined
    // poses changes none of them).
    for scene in screwbender::presets::all() {
        let control = Polyscrew::new(scene.poses.clone(), scene.closed).unwrap();
        for s in options().into_iter().filter(|s| s.levels == 3) {
            let motion = ScrewBender::new(scene.poses.clone(), scene.closed, s).unwrap();
            let refined = s.apply(control.poses(), scene.closed).unwrap();
            assert_eq!(
                bits(motion.refined().poses()),
                bits(&refined),
                "{} {s:?}",
                scene.id
            );
        }
    }
}
