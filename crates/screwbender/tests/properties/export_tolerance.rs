//! Exports meet their stated tolerance in scene units at the object's points
//! (docs/math/sampling.md §3): every preset, uniform and timed, exported as GLB and CSV through
//! [`export_motion`] (the path of the CLI and the JS API), read back and replayed with glTF
//! `LINEAR` semantics (lerp the translation, slerp the rotation) at many times; the replayed
//! mesh vertices are compared with the same vertices carried by the true motion.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use crate::support;

use glam::{DMat3, DQuat, DVec3};
use screwbender::mesh::Mesh;
use screwbender::{
    export_motion, mesh_radius, presets, ExportFormat, ExportSettings, Motion, MotionDocument,
    Pose, Rules, SamplingMode, ScrewBender, Subdivision, Timing, DEFAULT_TOLERANCE,
};

/// Allowance on top of the tolerance for the `f32` storage of glTF keyframes: value rounding
/// (`6e-8 |x|` for coordinates up to ~20, so about 1.2e-6) plus time rounding (`6e-8 t` for `t`
/// up to ~20 s) times the fastest point's speed (up to ~5 units/s): together below 1e-5. CSV
/// stores `f64` and gets none.
const F32_SLACK: f64 = 1e-5;

/// Probes per keyframe interval (the ends included).
const PROBES: usize = 6;

/// The CSV's `(t, pose)` rows (header `t,u,x,y,z,qw,qx,qy,qz`).
fn csv_keyframes(text: &str) -> (Vec<f64>, Vec<Pose>) {
    let mut times = Vec::new();
    let mut poses = Vec::new();
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|f| f.parse().unwrap()).collect();
        times.push(v[0]);
        poses.push(Pose::new(
            DVec3::new(v[2], v[3], v[4]),
            DQuat::from_xyzw(v[6], v[7], v[8], v[5]),
        ));
    }
    (times, poses)
}

/// glTF `LINEAR`: lerp of the translation, slerp of the stored quaternions, normalised as a
/// player does. A glTF player slerps the stored values as they are (the exporter must store
/// consistent signs: `short_arc` false checks that); a CSV reader takes the short arc.
fn linear(a: &Pose, b: &Pose, s: f64, short_arc: bool) -> (DVec3, DMat3) {
    let mut qb = b.rotation;
    if a.rotation.dot(qb) < 0.0 {
        assert!(short_arc, "glTF keyframe signs flip");
        qb = -qb;
    }
    let q = a.rotation.normalize().slerp(qb.normalize(), s);
    (a.origin.lerp(b.origin, s), DMat3::from_quat(q.normalize()))
}

/// The worst distance between replayed and true vertices over every probe of every interval.
/// `t0` is the first key time (glTF times start at 0).
fn worst_vertex_error(
    times: &[f64],
    poses: &[Pose],
    t0: f64,
    motion: &dyn Motion,
    timing: &Timing,
    vertices: &[DVec3],
    short_arc: bool,
) -> f64 {
    let mut worst = 0.0f64;
    for k in 0..times.len() - 1 {
        for j in 0..=PROBES {
            let s = j as f64 / PROBES as f64;
            let t = times[k] + s * (times[k + 1] - times[k]);
            let (o, r) = linear(&poses[k], &poses[k + 1], s, short_arc);
            let truth = motion.pose_at(timing.parameter(t + t0).0);
            let (to, tr) = (truth.origin, DMat3::from_quat(truth.rotation));
            let (d_o, d_r) = (o - to, r - tr);
            for &x in vertices {
                worst = worst.max((d_o + d_r * x).length());
            }
        }
    }
    worst
}

/// Key times with alternating gaps of 1 s and 2 s (as `--times 0,1,3,4,6,7,9`).
fn uneven_times(keys: usize) -> Vec<f64> {
    let mut t = vec![0.0];
    for i in 1..keys {
        t.push(t[i - 1] + if i % 2 == 1 { 1.0 } else { 2.0 });
    }
    t
}

/// The vertex positions of `mesh`, each once.
fn vertices(mesh: &Mesh) -> Vec<DVec3> {
    let mut v: Vec<DVec3> = Vec::new();
    for p in &mesh.positions {
        if !v.iter().any(|q| q.distance(*p) < 1e-12) {
            v.push(*p);
        }
    }
    v
}

#[test]
fn every_preset_uniform_and_timed_meets_the_tolerance_at_its_vertices() {
    let mut report = Vec::new();
    for scene in presets::all() {
        let mesh = Mesh::from_shape(&scene.shape);
        let verts = vertices(&mesh);
        let sub = Subdivision::new(scene.scheme, Rules::Direct, scene.levels);
        let motion = ScrewBender::new(scene.poses.clone(), scene.closed, sub).unwrap();
        let keys = scene.poses.len() + usize::from(scene.closed);
        for timed in [false, true] {
            let mut doc = MotionDocument::new(scene.poses.clone(), scene.closed);
            doc.name = Some(scene.id.into());
            if timed {
                doc.times = Some(uneven_times(keys));
            }
            let timing = doc.timing().unwrap();
            let t0 = timing.knots()[0];
            for format in [ExportFormat::Glb, ExportFormat::Csv] {
                let out = export_motion(
                    &doc,
                    sub,
                    &ExportSettings {
                        format,
                        sampling: SamplingMode::Adaptive(DEFAULT_TOLERANCE),
                        mesh: Some(&mesh),
                        ..ExportSettings::default()
                    },
                )
                .unwrap();
                assert_eq!(out.radius, Some(mesh_radius(&mesh)));
                let (times, poses, slack, shift) = match format {
                    ExportFormat::Csv => {
                        let (t, p) = csv_keyframes(std::str::from_utf8(&out.data).unwrap());
                        (t, p, 0.0, 0.0)
                    }
                    _ => {
                        let (t, p) = support::glb_keyframes(&out.data, 0);
                        (t, p, F32_SLACK, t0)
                    }
                };
                assert_eq!(times.len(), out.sample_count);
                let csv = format == ExportFormat::Csv;
                let worst =
                    worst_vertex_error(&times, &poses, shift, &motion, &timing, &verts, csv);
                report.push(format!(
                    "{:<18} {:<7} {format:?}: {:>6} keyframes, radius {:.3}, worst vertex {worst:.3e}",
                    scene.id,
                    if timed { "timed" } else { "uniform" },
                    out.sample_count,
                    mesh_radius(&mesh),
                ));
                assert!(
                    worst <= DEFAULT_TOLERANCE + slack,
                    "{} {} {format:?}: a vertex is {worst:e} from the motion",
                    scene.id,
                    if timed { "timed" } else { "uniform" },
                );
            }
        }
    }
    eprintln!("{}", report.join("\n"));
}

#[test]
fn a_csv_trajectory_meets_the_tolerance_at_its_point() {
    let scene = presets::preset("l_cycle_rotated").unwrap();
    let sub = Subdivision::new(scene.scheme, Rules::Direct, scene.levels);
    let motion = ScrewBender::new(scene.poses.clone(), scene.closed, sub).unwrap();
    let mut doc = MotionDocument::new(scene.poses.clone(), scene.closed);
    doc.times = Some(uneven_times(scene.poses.len() + 1));
    let timing = doc.timing().unwrap();
    let point = DVec3::new(1.5, -0.5, 0.75);
    let out = export_motion(
        &doc,
        sub,
        &ExportSettings {
            format: ExportFormat::Csv,
            point: Some(point),
            ..ExportSettings::default()
        },
    )
    .unwrap();
    let rows: Vec<Vec<f64>> = std::str::from_utf8(&out.data)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    let mut worst = 0.0f64;
    for w in rows.windows(2) {
        let (a, b) = (
            DVec3::new(w[0][2], w[0][3], w[0][4]),
            DVec3::new(w[1][2], w[1][3], w[1][4]),
        );
        for j in 0..=PROBES {
            let s = j as f64 / PROBES as f64;
            let t = w[0][0] + s * (w[1][0] - w[0][0]);
            let truth = motion.pose_at(timing.parameter(t).0).transform_point(point);
            worst = worst.max(a.lerp(b, s).distance(truth));
        }
    }
    eprintln!(
        "trajectory of {point}: {} rows, worst {worst:.3e}",
        rows.len()
    );
    assert!(
        worst <= DEFAULT_TOLERANCE,
        "trajectory deviates by {worst:e}"
    );
}

#[test]
fn key_times_survive_a_glb_round_trip_and_uniform_files_stay_untimed() {
    let scene = presets::preset("l_cycle_rotated").unwrap();
    let sub = Subdivision::new(scene.scheme, Rules::Direct, 3);
    let mut doc = MotionDocument::new(scene.poses.clone(), scene.closed);
    for times in [None, Some(vec![0.5, 1.5, 3.25, 4.0, 6.5, 7.0, 9.5])] {
        doc.times = times.clone();
        let glb = export_motion(&doc, sub, &ExportSettings::default())
            .unwrap()
            .data;
        let back = screwbender::import_glb(&glb, &screwbender::NodeSelection::Auto).unwrap();
        match (&times, &back.times) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                assert_eq!(a.len(), b.len());
                for (x, y) in a.iter().zip(b) {
                    // Stored as f32 after subtracting the first time.
                    assert!((x - y).abs() < 1e-6, "{x} vs {y}");
                }
            }
            other => panic!("times {other:?}"),
        }
    }
}
