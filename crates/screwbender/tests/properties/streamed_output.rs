//! The streaming writers (`MotionDocument::write_json`, `write_poses_csv`,
//! `write_trajectory_csv`) write byte for byte the text the String route built before them —
//! the reference writers below are that route, kept here — through a writer that takes a few
//! bytes per call, and hand back the writer's error instead of panicking.

#![cfg(feature = "json")]

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use std::io::{self, Write};

use glam::DVec3;
use screwbender::{
    poses_csv, trajectory_csv, write_poses_csv, write_trajectory_csv, MotionDocument, Pose, Rules,
    Sample, Scheme, Subdivision,
};
use testkit::Rng;

/// The String route of `MotionDocument::to_json` before streaming (the file form, then one
/// `format!` per line).
fn reference_json(doc: &MotionDocument) -> String {
    let raw = doc.to_raw();
    let mut s = String::from("{\n");
    if let Some(name) = &raw.name {
        s += &format!("  \"name\": {},\n", serde_json::to_string(name).unwrap());
    }
    s += &format!("  \"closed\": {},\n", raw.closed);
    if let Some(times) = &raw.times {
        s += &format!("  \"times\": {},\n", serde_json::to_string(times).unwrap());
    }
    if let Some(v) = &raw.velocities {
        s += &format!("  \"velocities\": {},\n", serde_json::to_string(v).unwrap());
    }
    s += "  \"poses\": [\n";
    for (i, p) in raw.poses.iter().enumerate() {
        s += "    ";
        s += &serde_json::to_string(p).unwrap();
        s += if i + 1 < raw.poses.len() { ",\n" } else { "\n" };
    }
    s += "  ]\n}\n";
    s
}

/// A writer that takes at most `chunk` bytes per call (as a pipe may), keeping them.
struct Trickle {
    chunk: usize,
    data: Vec<u8>,
    calls: usize,
}

impl Write for Trickle {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let n = buf.len().min(self.chunk);
        self.data.extend_from_slice(&buf[..n]);
        self.calls += 1;
        Ok(n)
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// A writer that fails once `room` bytes are taken.
struct Full {
    room: usize,
}

impl Write for Full {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.room == 0 {
            return Err(io::Error::new(io::ErrorKind::StorageFull, "full"));
        }
        let n = buf.len().min(self.room);
        self.room -= n;
        Ok(n)
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

fn trickled(chunk: usize, write: impl FnOnce(&mut Trickle) -> io::Result<()>) -> Vec<u8> {
    let mut w = Trickle {
        chunk,
        data: Vec::new(),
        calls: 0,
    };
    write(&mut w).unwrap();
    assert!(
        w.calls >= w.data.len() / chunk,
        "{} calls for {} bytes",
        w.calls,
        w.data.len()
    );
    w.data
}

/// A refined motion of `8 · 2^levels` poses of a random cycle (4-point, direct rules).
fn refined(levels: u32, seed: u64) -> Vec<Pose> {
    let control = Rng::new(seed).cycle(8, 1.0);
    Subdivision::new(Scheme::FourPoint, Rules::Direct, levels)
        .apply(&control, true)
        .unwrap()
}

#[test]
fn streamed_document_is_the_string_route_byte_for_byte() {
    // 2^17 poses: the size of a large CLI `subdivide`, every pose's numbers in full precision.
    let poses = refined(14, 7);
    assert_eq!(poses.len(), 1 << 17);
    let mut doc = MotionDocument::new(poses, true);
    doc.name = Some("a \"quoted\" name\twith ünïcode".into());
    let want = reference_json(&doc);
    assert_eq!(doc.to_json(), want);
    assert_eq!(trickled(7, |w| doc.write_json(w)), want.as_bytes());

    // Small documents with and without each optional field, open and closed.
    let mut rng = Rng::new(3);
    for (k, closed) in [(0, true), (1, false), (2, true), (3, false)] {
        let n = 2 + k;
        let mut doc = MotionDocument::new(rng.cycle(n, 2.0), closed);
        if k % 2 == 1 {
            doc.name = Some(format!("doc {k}"));
        }
        if k >= 2 {
            let keys = n + usize::from(closed);
            let times: Vec<f64> = (0..keys).map(|i| 0.1 + i as f64 * 0.7).collect();
            let v: Vec<Option<f64>> = (0..n).map(|i| (i % 2 == 0).then_some(0.25)).collect();
            doc.set_timing(Some(times), Some(v)).unwrap();
        }
        let want = reference_json(&doc);
        assert_eq!(
            trickled(1, |w| doc.write_json(w)),
            want.as_bytes(),
            "doc {k}"
        );
        assert_eq!(doc.to_json(), want, "doc {k}");
        let again = MotionDocument::from_json(&want).unwrap();
        assert_eq!(
            (&again.name, again.closed, &again.times, &again.velocities),
            (&doc.name, doc.closed, &doc.times, &doc.velocities),
            "doc {k}"
        );
    }
}

#[test]
fn streamed_csv_is_the_string_route_byte_for_byte() {
    let poses = refined(6, 11);
    let n = poses.len() as f64;
    let samples: Vec<Sample> = poses
        .into_iter()
        .enumerate()
        .map(|(i, pose)| Sample {
            time: i as f64 / 3.0,
            u: 8.0 * i as f64 / n,
            pose,
        })
        .collect();
    let point = DVec3::new(0.3, -1.0 / 7.0, 2.5);
    let mut want_poses = String::from("t,u,x,y,z,qw,qx,qy,qz\n");
    let mut want_path = String::from("t,u,x,y,z\n");
    for s in &samples {
        let [x, y, z] = s.pose.origin.to_array();
        let [qw, qx, qy, qz] = s.pose.rotation_wxyz();
        want_poses += &format!("{},{},{x},{y},{z},{qw},{qx},{qy},{qz}\n", s.time, s.u);
        let q = s.pose.transform_point(point);
        want_path += &format!("{},{},{},{},{}\n", s.time, s.u, q.x, q.y, q.z);
    }
    assert_eq!(poses_csv(&samples), want_poses);
    assert_eq!(trajectory_csv(&samples, point), want_path);
    assert_eq!(
        trickled(5, |w| write_poses_csv(w, &samples)),
        want_poses.as_bytes()
    );
    assert_eq!(
        trickled(3, |w| write_trajectory_csv(w, &samples, point)),
        want_path.as_bytes()
    );
}

#[test]
fn a_failing_writer_is_an_error_not_a_panic() {
    let doc = MotionDocument::new(refined(2, 5), true);
    let samples = vec![
        Sample {
            time: 0.0,
            u: 0.0,
            pose: Pose::IDENTITY,
        };
        50
    ];
    let full = doc.to_json().len();
    for room in [0, 1, 40, full / 2, full - 1] {
        let e = doc.write_json(&mut Full { room }).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::StorageFull, "room {room}");
        let e = write_poses_csv(
            &mut Full {
                room: room.min(500),
            },
            &samples,
        )
        .unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::StorageFull, "room {room}");
        let e = write_trajectory_csv(
            &mut Full {
                room: room.min(300),
            },
            &samples,
            DVec3::X,
        )
        .unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::StorageFull, "room {room}");
    }
    // With room for all of it, nothing fails.
    doc.write_json(&mut Full { room: full }).unwrap();
}

/// `ExportSamples::write_csv`, the CLI's row-by-row export, writes the bytes of the
/// whole-file export (`export_motion`) and of the String writers on the same samples, for poses
/// and for a body-point trajectory, adaptive and fixed-rate.
#[cfg(feature = "gltf")]
#[test]
fn row_by_row_export_is_the_whole_file_export() {
    use screwbender::{export_motion, ExportFormat, ExportSamples, ExportSettings, SamplingMode};
    let mut doc = MotionDocument::new(Rng::new(19).cycle(6, 1.5), true);
    doc.set_timing(Some(vec![0.0, 0.5, 1.5, 2.0, 3.5, 4.0, 5.0]), None)
        .unwrap();
    let sub = Subdivision::new(Scheme::Jarek, Rules::Direct, 3);
    let point = DVec3::new(0.2, 0.7, -0.4);
    for sampling in [SamplingMode::Adaptive(1e-3), SamplingMode::FixedRate(24.0)] {
        for point in [None, Some(point)] {
            let settings = ExportSettings {
                format: ExportFormat::Csv,
                sampling,
                point,
                ..ExportSettings::default()
            };
            let export = ExportSamples::new(&doc, sub, &settings).unwrap();
            let samples = &export.sampled.samples;
            assert!(samples.len() > 100, "{} samples", samples.len());
            let whole = export_motion(&doc, sub, &settings).unwrap();
            assert_eq!(whole.sample_count, samples.len());
            assert_eq!(whole.radius, export.radius);
            let text = match point {
                Some(p) => trajectory_csv(samples, p),
                None => poses_csv(samples),
            };
            assert_eq!(whole.data, text.as_bytes(), "{sampling:?} {point:?}");
            assert_eq!(trickled(11, |w| export.write_csv(w)), text.as_bytes());
        }
    }
    // A trajectory asked of a glTF export is refused before any sampling.
    let refused = ExportSamples::new(
        &doc,
        sub,
        &ExportSettings {
            point: Some(point),
            ..ExportSettings::default()
        },
    );
    assert!(refused
        .unwrap_err()
        .to_string()
        .contains("needs --format csv"));
}
