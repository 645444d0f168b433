//! The control-pose CSV (formats::csv::control_poses_csv): a design's poses, key times and
//! velocities written and read back to the same document, open and closed.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::{DQuat, DVec3};
use screwbender::{control_poses_csv, parse_csv_poses, MotionDocument, Pose};

fn poses(n: usize) -> Vec<Pose> {
    (0..n)
        .map(|i| {
            let a = 0.7 * i as f64;
            Pose::new(
                DVec3::new(a.cos() * 3.0, a.sin() * 2.0, 0.1 * i as f64),
                DQuat::from_axis_angle(DVec3::new(0.2, 1.0, 0.4).normalize(), a),
            )
        })
        .collect()
}

fn same(a: &MotionDocument, b: &MotionDocument) {
    assert_eq!(a.closed, b.closed);
    assert_eq!(a.poses.len(), b.poses.len());
    for (p, q) in a.poses.iter().zip(&b.poses) {
        assert!(p.origin.distance(q.origin) <= 1e-12, "{p:?} vs {q:?}");
        assert!(
            p.rotation.angle_between(q.rotation) <= 1e-7,
            "{p:?} vs {q:?}"
        );
    }
    assert_eq!(a.times, b.times);
    assert_eq!(a.velocities, b.velocities);
}

#[test]
fn an_open_design_reads_back_with_its_times_and_velocities() {
    let mut doc = MotionDocument::new(poses(5), false);
    doc.times = Some(vec![0.0, 0.5, 2.0, 2.25, 4.0]);
    doc.velocities = Some(vec![Some(0.0), None, Some(1.5), None, Some(0.0)]);
    let text = control_poses_csv(&doc);
    assert_eq!(text.lines().count(), 1 + 5, "{text}");
    assert!(text.starts_with("x,y,z,qw,qx,qy,qz,time,velocity\n"));
    same(&parse_csv_poses(&text).unwrap(), &doc);
}

#[test]
fn a_cycle_repeats_pose_0_at_its_end_time_and_reads_back_closed() {
    let mut doc = MotionDocument::new(poses(4), true);
    doc.times = Some(vec![0.0, 1.0, 3.0, 3.5, 5.0]);
    let text = control_poses_csv(&doc);
    assert_eq!(text.lines().count(), 1 + 5, "{text}");
    same(&parse_csv_poses(&text).unwrap(), &doc);
    // Uniform timing is written as the times in use (one per span) and reads back as those.
    let plain = MotionDocument::new(poses(3), false);
    let back = parse_csv_poses(&control_poses_csv(&plain)).unwrap();
    assert_eq!(back.times, Some(vec![0.0, 1.0, 2.0]));
    assert_eq!(back.velocities, None);
}

#[test]
fn a_bad_time_names_its_line_and_column() {
    let e = parse_csv_poses("x,y,z,qw,qx,qy,qz,time\n0,0,0,1,0,0,0,0\n1,0,0,1,0,0,0,abc\n")
        .unwrap_err();
    assert!(e.to_string().contains("line 3, column time"), "{e}");
    let e =
        parse_csv_poses("x,y,z,qw,qx,qy,qz,time\n0,0,0,1,0,0,0,0\n1,0,0,1,0,0,0,\n").unwrap_err();
    assert!(e.to_string().contains("line 3, column time"), "{e}");
}
