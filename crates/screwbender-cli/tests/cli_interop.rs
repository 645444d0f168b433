//! `screwbender export` / `screwbender import` driven as a user would: files written and read
//! back, exit codes 0/2, one line on standard error for bad input.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use std::path::{Path, PathBuf};

use screwbender::{MotionDocument, MAX_GLTF_BYTES};

/// Control poses must survive export → import to this (the `f32` storage of glTF).
const ROUND_TRIP: f64 = 1e-6;

use support::{run, Output};

/// A fresh directory under the target's temp dir, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> TempDir {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("cli_interop-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }

    fn path(&self, file: &str) -> String {
        self.0.join(file).to_str().unwrap().to_string()
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn preset(id: &str) -> String {
    let out = run(&["preset", id], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
}

fn assert_fails(out: &Output, needle: &str) {
    assert_eq!(
        out.code, 2,
        "stdout: {}\nstderr: {}",
        out.stdout, out.stderr
    );
    assert!(out.stdout.is_empty(), "stdout on failure: {}", out.stdout);
    assert_eq!(out.stderr.lines().count(), 1, "one line: {}", out.stderr);
    assert!(
        out.stderr.starts_with("screwbender: ") && out.stderr.contains(needle),
        "expected '{needle}' in: {}",
        out.stderr
    );
}

fn assert_same_poses(a: &MotionDocument, b: &MotionDocument) {
    assert_eq!(a.closed, b.closed);
    assert_eq!(a.poses.len(), b.poses.len());
    for (p, q) in a.poses.iter().zip(&b.poses) {
        assert!(p.approx_eq(q, ROUND_TRIP), "{p:?} vs {q:?}");
    }
}

#[test]
fn glb_and_gltf_round_trip_through_import() {
    let dir = TempDir::new("roundtrip");
    for id in ["l_cycle_rotated", "helix_open", "pendulum"] {
        let doc_text = preset(id);
        let doc = MotionDocument::from_json(&doc_text).unwrap();
        let glb = dir.path(&format!("{id}.glb"));
        let out = run(&["export", "--format", "glb", "-o", &glb], &doc_text);
        assert_eq!(out.code, 0, "{}", out.stderr);
        assert!(out.stdout.is_empty() && out.stderr.is_empty());
        let back = run(&["import", &glb], "");
        assert_eq!(back.code, 0, "{}", back.stderr);
        let imported = MotionDocument::from_json(&back.stdout).unwrap();
        assert_same_poses(&doc, &imported);

        // .gltf + .bin next to it, then export the imported document again.
        let stem = dir.path(&format!("{id}-b"));
        let json = dir.path(&format!("{id}-back.json"));
        let out = run(&["import", &glb, "-o", &json], "");
        assert_eq!(out.code, 0, "{}", out.stderr);
        let out = run(&["export", "--format", "gltf", &json, "-o", &stem], "");
        assert_eq!(out.code, 0, "{}", out.stderr);
        assert!(Path::new(&format!("{stem}.bin")).exists());
        let again = run(&["import", &format!("{stem}.gltf")], "");
        assert_eq!(again.code, 0, "{}", again.stderr);
        assert_same_poses(&doc, &MotionDocument::from_json(&again.stdout).unwrap());
    }
}

#[test]
fn verbose_reports_the_sample_count_on_stderr_only() {
    let dir = TempDir::new("verbose");
    let glb = dir.path("c.glb");
    let out = run(
        &[
            "export",
            "--format",
            "glb",
            "--tolerance",
            "1e-3",
            "--verbose",
            "-o",
            &glb,
        ],
        &preset("circle4"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.is_empty());
    assert_eq!(out.stderr.lines().count(), 1);
    assert!(
        out.stderr.contains(" samples (tolerance 1e-3"),
        "{}",
        out.stderr
    );
    // A tighter tolerance needs more samples (here the span count, 128, is not the limit).
    let count = |s: &str| -> usize {
        s.split("export: ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    let fine = run(
        &[
            "export",
            "--format",
            "glb",
            "--tolerance",
            "1e-6",
            "--verbose",
            "-o",
            &glb,
        ],
        &preset("circle4"),
    );
    assert!(
        count(&fine.stderr) > count(&out.stderr),
        "{} / {}",
        fine.stderr,
        out.stderr
    );
}

#[test]
fn csv_export_poses_trajectory_fps_and_times() {
    let doc = preset("pendulum");
    let out = run(&["export", "--format", "csv", "--fps", "10"], &doc);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let lines: Vec<&str> = out.stdout.lines().collect();
    assert_eq!(lines[0], "t,u,x,y,z,qw,qx,qy,qz");
    // Two poses, a cycle: 2 s at 10 fps, both ends included.
    assert_eq!(lines.len(), 1 + 21);
    assert!(lines[1].starts_with("0,0,"));

    let out = run(
        &[
            "export", "--format", "csv", "--point", "0,0,0", "--times", "0,1,3",
        ],
        &doc,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let last = out.stdout.lines().last().unwrap();
    assert!(last.starts_with("3,2,"), "{last}");
    assert_eq!(out.stdout.lines().next(), Some("t,u,x,y,z"));

    // CSV samples read back as control poses (header columns by name).
    let dir = TempDir::new("csv");
    let csv = dir.path("p.csv");
    let out = run(
        &[
            "export",
            "--format",
            "csv",
            "--tolerance",
            "1e-2",
            "-o",
            &csv,
        ],
        &doc,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    // The file is written row by row, the standard output too: the same bytes either way.
    let streamed = run(&["export", "--format", "csv", "--tolerance", "1e-2"], &doc);
    assert_eq!(streamed.code, 0, "{}", streamed.stderr);
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), streamed.stdout);
    let back = run(&["import", &csv], "");
    assert_eq!(back.code, 0, "{}", back.stderr);
    let imported = MotionDocument::from_json(&back.stdout).unwrap();
    assert!(imported.closed && imported.poses.len() > 2);
}

#[test]
fn import_selects_nodes() {
    let dir = TempDir::new("nodes");
    let glb = dir.path("n.glb");
    let out = run(
        &[
            "export",
            "--format",
            "glb",
            "--control-nodes",
            "--levels",
            "1",
            "-o",
            &glb,
        ],
        &preset("circle4"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let nodes = run(
        &[
            "import",
            &glb,
            "--nodes",
            "control pose 0,control pose 1,control pose 2",
        ],
        "",
    );
    assert_eq!(nodes.code, 0, "{}", nodes.stderr);
    let d = MotionDocument::from_json(&nodes.stdout).unwrap();
    assert_eq!(d.poses.len(), 3);
    let object = run(&["import", &glb, "--node", "circle4"], "");
    assert_eq!(object.code, 0, "{}", object.stderr);
    assert!(
        MotionDocument::from_json(&object.stdout)
            .unwrap()
            .poses
            .len()
            > 4
    );
    assert_fails(
        &run(&["import", &glb, "--node", "nope"], ""),
        "no node named 'nope'",
    );
}

#[test]
fn bad_export_options_fail_with_one_line() {
    let doc = preset("circle4");
    assert_fails(&run(&["export", "-o", "x.glb"], &doc), "needs --format");
    assert_fails(
        &run(&["export", "--format", "obj"], &doc),
        "unknown value 'obj'",
    );
    assert_fails(&run(&["export", "--format", "glb"], &doc), "needs -o OUT");
    assert_fails(
        &run(&["export", "--format", "csv", "--tolerance", "0"], &doc),
        "tolerance: 0 is out of range",
    );
    assert_fails(
        &run(&["export", "--format", "csv", "--tolerance", "nan"], &doc),
        "not a finite number",
    );
    assert_fails(
        &run(&["export", "--format", "csv", "--fps", "-1"], &doc),
        "fps: -1 is out of range",
    );
    assert_fails(
        &run(&["export", "--format", "csv", "--times", "0,1,2"], &doc),
        "times: 3 times given, expected 5",
    );
    assert_fails(
        &run(&["export", "--format", "csv", "--times", "0,1,1,2,3"], &doc),
        "times[2]",
    );
    assert_fails(
        &run(&["export", "--format", "csv", "--point", "1,2"], &doc),
        "expected x,y,z",
    );
    assert_fails(
        &run(
            &[
                "export", "--format", "glb", "--point", "1,2,3", "-o", "x.glb",
            ],
            &doc,
        ),
        "needs --format csv",
    );
    assert_fails(
        &run(
            &[
                "export",
                "--format",
                "csv",
                "--fps",
                "30",
                "--tolerance",
                "1e-3",
            ],
            &doc,
        ),
        "not both",
    );
}

#[test]
fn bad_import_files_fail_with_one_line() {
    let dir = TempDir::new("bad");
    let write = |name: &str, data: &[u8]| {
        let p = dir.path(name);
        std::fs::write(&p, data).unwrap();
        p
    };
    // Truncated GLB.
    let glb = dir.path("ok.glb");
    let out = run(
        &["export", "--format", "glb", "-o", &glb],
        &preset("pendulum"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let bytes = std::fs::read(&glb).unwrap();
    let cut = write("cut.glb", &bytes[..bytes.len() - 100]);
    assert_fails(&run(&["import", &cut], ""), "cut.glb: glb: header says");
    // Not JSON at all.
    let junk = write("junk.gltf", b"{\"asset\": ");
    assert_fails(
        &run(&["import", &junk], ""),
        "junk.gltf: gltf: invalid glTF JSON",
    );
    // No animations.
    let still = write(
        "still.gltf",
        br#"{"asset":{"version":"2.0"},"nodes":[{"name":"a"}]}"#,
    );
    assert_fails(
        &run(&["import", &still], ""),
        "animations: the file has no animations",
    );
    // A .gltf whose .bin is missing.
    let gltf_stem = dir.path("lost");
    let out = run(
        &["export", "--format", "gltf", "-o", &gltf_stem],
        &preset("pendulum"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    std::fs::remove_file(format!("{gltf_stem}.bin")).unwrap();
    assert_fails(
        &run(&["import", &format!("{gltf_stem}.gltf")], ""),
        "buffers[0]",
    );
    // CSV problems, each named by line and column.
    let short = write("short.csv", b"0,0,0,1,0,0,0\n1,0,0,1,0,0\n");
    assert_fails(
        &run(&["import", &short], ""),
        "short.csv: line 2: 6 field(s)",
    );
    let text = write(
        "text.csv",
        b"x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n1,zero,0,1,0,0,0\n",
    );
    assert_fails(
        &run(&["import", &text], ""),
        "text.csv: line 3, column y: 'zero' is not a number",
    );
    let nan = write("nan.csv", b"0,0,0,1,0,0,0\n# ok\n1,0,0,1,NaN,0,0\n");
    assert_fails(
        &run(&["import", &nan], ""),
        "nan.csv: line 3, column qx: not a finite",
    );
    // Unknown type, missing file, huge file (sparse: no disk space used).
    let odd = write("poses.txt", b"");
    assert_fails(&run(&["import", &odd], ""), "unknown file type");
    assert_fails(
        &run(&["import", &dir.path("missing.glb")], ""),
        "missing.glb",
    );
    let huge = dir.path("huge.glb");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(MAX_GLTF_BYTES as u64 + 1)
        .unwrap();
    assert_fails(&run(&["import", &huge], ""), "larger than the limit");
    let json = write(
        "bad.json",
        br#"{"poses":[{"origin":[0,0,0],"rotation":[0,0,0,0]}]}"#,
    );
    assert_fails(
        &run(&["import", &json], ""),
        "bad.json: poses[0].rotation: zero quaternion",
    );
    assert_fails(&run(&["import"], ""), "import needs a FILE");
    assert_fails(
        &run(&["import", &short, "--bogus"], ""),
        "unknown option '--bogus'",
    );
}

#[test]
fn gltf_output_names_and_json_import() {
    let dir = TempDir::new("names");
    let doc = preset("spinning_block");
    for (out, gltf, bin) in [
        ("a.gltf", "a.gltf", "a.bin"),
        ("b.glb", "b.gltf", "b.bin"),
        ("c.v2", "c.v2.gltf", "c.v2.bin"),
    ] {
        let r = run(&["export", "--format", "gltf", "-o", &dir.path(out)], &doc);
        assert_eq!(r.code, 0, "{}", r.stderr);
        assert!(Path::new(&dir.path(gltf)).exists(), "{gltf}");
        assert!(Path::new(&dir.path(bin)).exists(), "{bin}");
        let text = std::fs::read_to_string(dir.path(gltf)).unwrap();
        assert!(text.contains(&format!("\"uri\": \"{bin}\"")), "{text}");
    }
    // A motion document imports as itself.
    let json = dir.path("m.json");
    std::fs::write(&json, &doc).unwrap();
    let r = run(&["import", &json], "");
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert_same_poses(
        &MotionDocument::from_json(&doc).unwrap(),
        &MotionDocument::from_json(&r.stdout).unwrap(),
    );
}

#[test]
fn fit_writes_the_document_and_reports_the_core_residuals() {
    use screwbender::methods::Se3BSpline;
    use screwbender::{fit_poses, ControlCount, FitMethod, FitOptions, Motion, Pose, RobustLoss};
    // Samples of a known SE(3) spline with a deterministic wobble, one every 0.1 s.
    let controls: Vec<Pose> = (0..6)
        .map(|k| {
            let a = k as f64 * 0.6;
            Pose::new(
                glam::DVec3::new(2.0 * a.cos(), 2.0 * a.sin(), 0.3 * a),
                glam::DQuat::from_rotation_z(a),
            )
        })
        .collect();
    let truth = Se3BSpline::new(&controls, false).unwrap();
    let mut doc = MotionDocument::new(
        (0..120)
            .map(|i| {
                let mut p = truth.pose_at(5.0 * i as f64 / 119.0);
                p.origin.z += 0.01 * (i as f64 * 1.7).sin();
                p
            })
            .collect(),
        false,
    );
    doc.times = Some((0..120).map(|i| 0.1 * i as f64).collect());
    let dir = TempDir::new("fit");
    let (input, output) = (dir.path("samples.json"), dir.path("fitted.json"));
    std::fs::write(&input, doc.to_json()).unwrap();
    let args = ["fit", &input, "--method", "se3bspline", "--controls", "6"];
    let out = run(
        &[&args[..], &["--robust", "huber", "--json", "-o", &output]].concat(),
        "",
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let report: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let written = MotionDocument::from_json(&std::fs::read_to_string(&output).unwrap()).unwrap();
    // The same numbers as the core's fit of the same document (read back from its file).
    let read = MotionDocument::from_json(&std::fs::read_to_string(&input).unwrap()).unwrap();
    let core = fit_poses(
        &read,
        &FitOptions {
            method: FitMethod::Se3BSpline,
            controls: ControlCount::Count(6),
            robust: RobustLoss::Huber,
            ..FitOptions::default()
        },
    )
    .unwrap();
    assert_same_poses(&written, &core.document);
    assert_eq!(report["controls"], 6);
    assert_eq!(report["samples"], 120);
    assert_eq!(report["method"], "se3bspline");
    for (key, value) in [
        ("rms_position", core.report.rms_position),
        ("max_angle", core.report.max_angle),
        ("rms_deviation", core.report.rms_deviation),
    ] {
        assert_eq!(report[key].as_f64().unwrap(), value, "{key}");
    }
    // The wobble (amplitude 0.01) is what remains.
    assert!(core.report.max_position < 0.012, "{:?}", core.report);
    // Without -o: the document on standard output, the report as text on standard error.
    let out = run(&args, "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out
        .stderr
        .starts_with("fit: 6 control poses (se3bspline) to 120 samples"));
    assert_eq!(
        MotionDocument::from_json(&out.stdout).unwrap().poses.len(),
        6
    );
    // Bad input: one line, nothing on standard output.
    assert_fails(
        &run(&["fit", &input, "--controls", "121"], ""),
        "at least 121 needed",
    );
    assert_fails(
        &run(&["fit", &input], ""),
        "exactly one of --controls N and --tolerance T",
    );
    assert_fails(
        &run(&["fit", &input, "--controls", "4", "--robust", "l1"], ""),
        "--robust",
    );
    // --measure: the fitted document measured against its samples gives the fit's report (no
    // iterations); a motion that covers half the path is far; bad input is named.
    let measured = run(
        &[
            "fit",
            &input,
            "--method",
            "se3bspline",
            "--measure",
            &output,
            "--json",
        ],
        "",
    );
    assert_eq!(measured.code, 0, "{}", measured.stderr);
    let again: serde_json::Value = serde_json::from_str(&measured.stdout).unwrap();
    assert_eq!(again["iterations"], 0);
    assert_eq!(again["controls"], 6);
    for key in ["rms_position", "max_position", "rms_angle", "max_deviation"] {
        let (a, b) = (again[key].as_f64().unwrap(), report[key].as_f64().unwrap());
        assert!((a - b).abs() <= 1e-12, "{key}: {a} against {b}");
    }
    let ends = dir.path("ends.json");
    // Half of the path stretched over the whole time span.
    let mut two = MotionDocument::new(vec![doc.poses[0], doc.poses[60]], false);
    two.times = Some(vec![0.0, 11.9]);
    std::fs::write(&ends, two.to_json()).unwrap();
    let coarse = run(&["fit", &input, "--measure", &ends, "--json"], "");
    assert_eq!(coarse.code, 0, "{}", coarse.stderr);
    let coarse: serde_json::Value = serde_json::from_str(&coarse.stdout).unwrap();
    let (c, f) = (
        coarse["rms_position"].as_f64().unwrap(),
        report["rms_position"].as_f64().unwrap(),
    );
    assert!(c > 10.0 * f, "half the path: {c}, the fit: {f}");
    assert_fails(
        &run(&["fit", &input, "--measure", &input, "--radius", "0"], ""),
        "radius",
    );
    assert_fails(
        &run(
            &["fit", &input, "--measure", &output, "--controls", "4"],
            "",
        ),
        "--controls",
    );
}
