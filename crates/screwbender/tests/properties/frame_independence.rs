//! Local-frame independence (docs/math/properties.md §1, paper Fig. 9 V1 / Fig. 8 V2): moving the object's local
//! origin to another body point leaves the screw subdivision's point trajectories unchanged and
//! changes the decoupled ones (`compare_frames`, `DecoupledPose`).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::{
    compare_frames, move_local_origin, presets, subdivide_decoupled, Pose, Rules, Scheme,
    Subdivision,
};

/// Bound on the screw trajectories' change (round-off on scenes of size ~10).
const INDEPENDENT: f64 = 1e-9;
/// The decoupled trajectories must move at least this much for the offsets used here.
const DEPENDENT: f64 = 1e-2;

fn body_points() -> Vec<DVec3> {
    vec![
        DVec3::ZERO,
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::new(0.3, -0.5, 0.4),
    ]
}

#[test]
fn screw_trajectories_ignore_the_local_origin_decoupled_do_not() {
    // A2 (the rotated L cycle) and A9.
    for id in ["l_cycle_rotated", "circle4"] {
        let scene = presets::preset(id).unwrap();
        for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
            let sub = Subdivision::new(scheme, Rules::Direct, 4);
            for c in [
                DVec3::new(3.0, 0.0, 0.0),
                DVec3::new(-2.0, 0.0, 0.0),
                DVec3::new(1.0, -1.5, 0.7),
            ] {
                let cmp = compare_frames(&scene.poses, true, &sub, c, &body_points()).unwrap();
                assert_eq!(cmp.len, scene.poses.len() << 4);
                assert_eq!(cmp.screw.len(), 3 * cmp.len);
                assert!(
                    cmp.screw_deviation <= INDEPENDENT,
                    "{id} {scheme} c={c}: screw deviation {:.3e}",
                    cmp.screw_deviation
                );
                assert!(
                    cmp.decoupled_deviation >= DEPENDENT,
                    "{id} {scheme} c={c}: decoupled deviation only {:.3e}",
                    cmp.decoupled_deviation
                );
            }
        }
    }
}

#[test]
fn zero_offset_changes_nothing() {
    let poses = presets::preset("circle4").unwrap().poses;
    let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 3);
    let cmp = compare_frames(&poses, true, &sub, DVec3::ZERO, &body_points()).unwrap();
    assert_eq!(cmp.screw_deviation, 0.0);
    assert_eq!(cmp.decoupled_deviation, 0.0);
}

#[test]
fn moving_the_origin_keeps_the_object_in_place() {
    let poses = presets::preset("bunny6").unwrap().poses;
    let c = DVec3::new(0.5, -1.0, 2.0);
    for (p, q) in poses.iter().zip(move_local_origin(&poses, c)) {
        assert!(
            (q.transform_point(DVec3::new(1.0, 2.0, 3.0) - c)
                - p.transform_point(DVec3::new(1.0, 2.0, 3.0)))
            .length()
                < 1e-14
        );
    }
}

/// docs/math/presets.md §2.9: the screw scheme keeps circle4 on the circle of radius 3; the decoupled 4-point
/// origins dip to 10/16·√2·3 = 2.651650 at 45°.
#[test]
fn circle4_screw_keeps_the_circle_decoupled_cuts_corners() {
    let poses = presets::preset("circle4").unwrap().poses;
    let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 5);
    let screw = sub.apply(&poses, true).unwrap();
    let dev = screw
        .iter()
        .map(|p: &Pose| (p.origin.length() - 3.0).abs())
        .fold(0.0, f64::max);
    assert!(dev < 1e-12, "screw radial deviation {dev:.3e}");
    let one = Subdivision::new(Scheme::FourPoint, Rules::Direct, 1);
    let dec = subdivide_decoupled(&poses, true, &one).unwrap();
    let r45 = dec[1].origin.length();
    assert!(
        (r45 - 2.651650).abs() < 1e-6,
        "decoupled radius at 45°: {r45}"
    );
    // The decoupled rotations are the screw rotations (rotation-only poses): same angle at 45°.
    assert!(dec[1].rotation.dot(screw[16].rotation).abs() > 1.0 - 1e-12);
}
