//! Key times and velocities (docs/math/timing.md §3): a timed motion reaches each key pose at its
//! key time, and the given rate `p'(T_i)` shows in the sampled motion (finite differences of the
//! samples' parameter and of a body point's position); bad timing is refused and changes
//! nothing.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::{
    presets, sample_fixed_rate, Motion, MotionDocument, Rules, Scheme, ScrewBender, Subdivision,
};

/// How closely the key times map to the key parameters.
const KEY_PARAMETER: f64 = 1e-9;

/// A timed, partly constrained document of preset `id` (4-point: the motion interpolates its
/// control poses, so pose `i` is the key pose).
fn timed(id: &str, velocities: &[Option<f64>]) -> (MotionDocument, ScrewBender) {
    let scene = presets::preset(id).unwrap();
    let mut doc = MotionDocument::new(scene.poses.clone(), scene.closed);
    let keys = scene.poses.len() + usize::from(scene.closed);
    let times: Vec<f64> = (0..keys)
        .map(|i| 0.5 + 1.5 * i as f64 + 0.4 * (i % 2) as f64)
        .collect();
    doc.set_timing(Some(times), Some(velocities.to_vec()))
        .unwrap();
    let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 5);
    let motion = ScrewBender::new(scene.poses, scene.closed, sub).unwrap();
    (doc, motion)
}

#[test]
fn key_poses_are_reached_at_key_times() {
    for (id, v) in [
        (
            "l_cycle_rotated",
            vec![None, Some(0.0), Some(1.5), None, None, Some(0.3)],
        ),
        (
            "helix_open",
            vec![Some(0.2), None, Some(0.0), None, Some(0.9)],
        ),
    ] {
        let mut v = v;
        v.resize(doc_keys(id), None);
        let (doc, motion) = timed(id, &v);
        let timing = doc.timing().unwrap();
        for (i, pose) in doc.poses.iter().enumerate() {
            let (u, _) = timing.parameter(timing.knots()[i]);
            assert!(
                (u - i as f64).abs() <= KEY_PARAMETER,
                "{id}: p(T_{i}) = {u}"
            );
            let at = motion.pose_at(u);
            assert!(
                at.approx_eq(pose, 1e-9),
                "{id}: pose {i}: {at:?} vs {pose:?}"
            );
        }
    }
}

fn doc_keys(id: &str) -> usize {
    presets::preset(id).unwrap().poses.len()
}

#[test]
fn given_rates_hold_in_the_sampled_motion() {
    let given = vec![None, Some(0.0), Some(1.5), None, None, Some(0.3)];
    let (doc, motion) = timed("l_cycle_rotated", &given);
    let timing = doc.timing().unwrap();
    // Samples at 1 kHz from T_0: the key times (T_0 plus multiples of 0.1 s) are on the grid.
    let samples = sample_fixed_rate(&motion, &timing, 1000.0).unwrap();
    let local = DVec3::new(1.0, 0.5, -0.25);
    for (i, v) in given.iter().enumerate() {
        let Some(v) = *v else { continue };
        let tk = timing.knots()[i];
        let j = samples
            .iter()
            .position(|s| (s.time - tk).abs() < 1e-9)
            .unwrap();
        let (a, b) = (&samples[j - 1], &samples[j + 1]);
        // The map is C¹ but not C² at a key: each one-sided slope, by a second-order one-sided
        // difference over 2 ms (error h² |p'''| / 3 < 1e-5 for |p'''| < 30 poses/s³), equals
        // the given rate.
        let h = samples[j + 1].time - samples[j].time;
        let right = (-3.0 * samples[j].u + 4.0 * samples[j + 1].u - samples[j + 2].u) / (2.0 * h);
        let left = (3.0 * samples[j].u - 4.0 * samples[j - 1].u + samples[j - 2].u) / (2.0 * h);
        for du in [left, right] {
            assert!((du - v).abs() < 1e-5, "key {i}: du/dt = {du}, given {v}");
        }
        // A body point's speed is |v_u| · p'(T_i): zero where the key has velocity 0.
        let speed = b
            .pose
            .transform_point(local)
            .distance(a.pose.transform_point(local))
            / (b.time - a.time);
        // |dx/du| at the key by a central difference in the parameter (the refined polyscrew's
        // velocity jumps slightly at refined knots; the difference averages both sides as the
        // time difference does).
        let du = 1e-4;
        let at = |u: f64| motion.pose_at(u).transform_point(local);
        let v_u = at(i as f64 + du).distance(at(i as f64 - du)) / (2.0 * du);
        assert!(
            (speed - v_u * v).abs() < 1e-2 * (1.0 + v_u),
            "key {i}: speed {speed}, expected {}",
            v_u * v
        );
    }
}

#[test]
fn bad_timing_is_refused_and_changes_nothing() {
    let (mut doc, _) = timed("l_cycle_rotated", &[None; 6]);
    let before = doc.clone();
    let times = doc.times.clone();
    for (t, v, path) in [
        (
            times.clone(),
            vec![Some(-0.1), None, None, None, None, None],
            "velocities[0]",
        ),
        (
            times.clone(),
            vec![None, Some(f64::NAN), None, None, None, None],
            "velocities[1]",
        ),
        // Key 1's span lasts 1.9 s: more than 4 / 1.9 poses per second cannot stay monotone.
        (
            times.clone(),
            vec![None, Some(10.0), None, None, None, None],
            "velocities[1]",
        ),
        (
            Some(vec![0.0, 1.0, 1.0, 2.0, 3.0, 4.0, 5.0]),
            vec![None; 6],
            "times[2]",
        ),
    ] {
        let e = doc.set_timing(t, Some(v)).unwrap_err();
        assert_eq!(e.path(), path, "{e}");
        assert_eq!(doc, before, "a refused timing changed the document");
    }
}

/// glTF keyframes carry the key times but not the retiming's slopes: the exporter records the
/// given velocities in the control animation's extras and import restores them, so a timed,
/// constrained motion comes back with the same timing; a malformed record is refused naming it.
#[test]
fn key_velocities_survive_a_glb_round_trip() {
    use screwbender::{export_motion, import_glb, ExportSettings, NodeSelection};
    let velocities = [None, Some(0.5), None, Some(2.0), None, None];
    let (doc, _) = timed("l_cycle_rotated", &velocities);
    let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 3);
    let glb = export_motion(&doc, sub, &ExportSettings::default())
        .unwrap()
        .data;
    let back = import_glb(&glb, &NodeSelection::Auto).unwrap();
    assert_eq!(back.velocities.as_deref(), Some(&velocities[..]));
    assert!(back.times.is_some());
    // Without velocities nothing is recorded (and nothing comes back).
    let mut free = doc.clone();
    free.set_timing(doc.times.clone(), None).unwrap();
    let glb_free = export_motion(&free, sub, &ExportSettings::default())
        .unwrap()
        .data;
    assert_eq!(
        import_glb(&glb_free, &NodeSelection::Auto)
            .unwrap()
            .velocities,
        None
    );
    // A record with a negative velocity (same length, so the GLB's chunk sizes hold): refused,
    // naming the extras.
    let (from, to) = (b"\"velocities\":[null,0.5", b"\"velocities\":[null,-99");
    let at = glb
        .windows(from.len())
        .position(|w| w == from)
        .expect("the GLB's JSON chunk records the velocities");
    let mut bad_glb = glb.clone();
    bad_glb[at..at + to.len()].copy_from_slice(to);
    let err = import_glb(&bad_glb, &NodeSelection::Auto).unwrap_err();
    assert!(
        err.to_string().contains("extras.screwbender.velocities[1]"),
        "{err}"
    );
}
