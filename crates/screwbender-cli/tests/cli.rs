//! The `screwbender` binary, driven as a user would: good input, bad input, exit codes.
#![cfg(not(target_arch = "wasm32"))]
// The math notes print values like 0.707107 (docs/math/README.md §3): comparing with them is the point.
#![allow(clippy::approx_constant)]

mod support;

use std::io::Write;
use std::process::{Command, Stdio};

use screwbender::{MotionDocument, Pose, Rules, Scheme, Subdivision};

use support::run;

fn preset(id: &str) -> String {
    let out = run(&["preset", id], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
}

const TWO_POSES: &str = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},
                                    {"origin":[2,0,1],"rotation":[0.7071067811865476,0,0,0.7071067811865476]}]}"#;

#[test]
fn subdivide_reads_stdin_and_writes_a_document() {
    let out = run(
        &["subdivide", "--scheme", "bspline", "--levels", "2"],
        &preset("l_cycle_rotated"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let doc = MotionDocument::from_json(&out.stdout).unwrap();
    assert_eq!(doc.poses.len(), 24);
    assert!(doc.closed);
    // The same as the library.
    let lib =
        screwbender::Subdivision::new(screwbender::Scheme::BSpline, screwbender::Rules::Direct, 2)
            .apply(
                &screwbender::presets::preset("l_cycle_rotated")
                    .unwrap()
                    .poses,
                true,
            )
            .unwrap();
    for (a, b) in doc.poses.iter().zip(&lib) {
        assert!(a.approx_eq(b, 1e-12));
    }
}

#[test]
fn subdivide_options_and_file_argument() {
    let dir = std::env::temp_dir().join(format!("screwbender-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("helix.json");
    std::fs::write(&file, preset("helix_open")).unwrap();
    let f = file.to_str().unwrap();
    let out = run(
        &[
            "subdivide",
            "--s",
            "0.5",
            "--rules",
            "direct",
            "--levels",
            "3",
            f,
        ],
        "",
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let doc = MotionDocument::from_json(&out.stdout).unwrap();
    assert_eq!(doc.poses.len(), 5 * 8 + 1, "open document stays open");
    assert!(!doc.closed);
    let out = run(
        &["subdivide", "--open", "--levels", "1", "-"],
        &preset("circle4"),
    );
    let doc = MotionDocument::from_json(&out.stdout).unwrap();
    assert_eq!(
        (doc.poses.len(), doc.closed),
        (7, false),
        "--open overrides closed"
    );
    let out = run(
        &[
            "subdivide",
            "--rules",
            "split",
            "--scheme",
            "jarek",
            "--levels",
            "1",
        ],
        &preset("circle4"),
    );
    assert_eq!(out.code, 0);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn eval_and_screw() {
    let out = run(
        &["eval", "--u", "1", "--u", "2.5", "--levels", "4"],
        &preset("l_cycle_rotated"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let p = &v["poses"][0];
    // 4-point interpolates control pose 1 at u = 1.
    let o: Vec<f64> = serde_json::from_value(p["origin"].clone()).unwrap();
    assert!((o[0] - 6.0).abs() < 1e-12 && o[1].abs() < 1e-12);
    assert_eq!(v["poses"][1]["u"], 2.5);
    let out = run(
        &["eval", "--u", "0.5", "--levels", "0"],
        &preset("l_cycle_parallel"),
    );
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(v["motion"], "polyscrew");
    let o: Vec<f64> = serde_json::from_value(v["poses"][0]["origin"].clone()).unwrap();
    assert!((o[0] - 3.0).abs() < 1e-12);

    let out = run(&["screw", "--t", "0.5", "--t", "-0.5"], TWO_POSES);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(v["screw"]["kind"], "screw");
    assert!((v["screw"]["angle"].as_f64().unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    let o: Vec<f64> = serde_json::from_value(v["poses"][0]["origin"].clone()).unwrap();
    assert!(
        (o[1] + (2f64.sqrt() - 1.0)).abs() < 1e-12,
        "docs/math/screw.md §7 example A"
    );
    let q: Vec<f64> = serde_json::from_value(v["poses"][1]["rotation"].clone()).unwrap();
    let p = Pose::from_wxyz([0.0; 3], [q[0], q[1], q[2], q[3]]).unwrap();
    assert!((p.rotation.to_axis_angle().1 - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
}

/// Every command and every `--flag` it accepts (as its own `--help` lists them, which clap
/// generates from the parser) is described in the overview of `--help`: a command or flag added
/// without its line there fails here.
#[test]
fn help_names_every_flag() {
    let help = run(&["--help"], "").stdout;
    let commands = [
        "subdivide",
        "eval",
        "screw",
        "preset",
        "compare",
        "rational",
        "export",
        "import",
        "completions",
        "man",
    ];
    let mut flags = Vec::new();
    for command in commands {
        assert!(
            help.contains(&format!("screwbender {command}")),
            "{command} is not in --help"
        );
        let own = run(&[command, "--help"], "");
        assert_eq!(own.code, 0, "{command}: {}", own.stderr);
        for word in own
            .stdout
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        {
            let is_flag = word.len() > 2
                && word.starts_with("--")
                && word[2..]
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c == '-');
            if is_flag && !flags.iter().any(|f| f == word) {
                flags.push(word.to_string());
            }
        }
    }
    assert!(flags.len() >= 20, "found only {flags:?}");
    for flag in &flags {
        assert!(
            help.contains(flag.as_str()),
            "{flag} is accepted but not in --help"
        );
    }
}

#[test]
fn help_version_and_presets() {
    let out = run(&["--help"], "");
    assert_eq!(out.code, 0);
    assert!(out.stdout.contains("screwbender subdivide") && out.stdout.contains("[w, x, y, z]"));
    assert!(run(&["--version"], "").stdout.starts_with("screwbender "));
    let list = run(&["preset"], "").stdout;
    for id in [
        "l_cycle_rotated",
        "pendulum",
        "circle4",
        "helix_open",
        "bunny6",
    ] {
        assert!(list.contains(id), "{id} missing from the preset list");
    }
    // Each preset by its name in words, the core's (as the page's chooser shows it).
    for p in screwbender::presets::all() {
        let line = list
            .lines()
            .find(|l| l.split_whitespace().next() == Some(p.id));
        let name = screwbender::presets::display(p.id).name;
        assert!(
            line.is_some_and(|l| l.contains(&format!(" {name}: "))),
            "{}: {line:?} does not name it '{name}'",
            p.id
        );
    }
}

/// Bad usage and bad input: exit status 2, one line on stderr naming the problem, nothing on
/// stdout.
#[test]
fn bad_input_exits_2_with_one_line() {
    let zero_q = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"rotation":[0,0,0,0]}]}"#;
    let far = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"rotation":[3,0,0,0]}]}"#;
    let left = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"basis":[[1,0,0],[0,1,0],[0,0,-1]]}]}"#;
    let skew = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1,0,0],"basis":[[1,0,0],[0.5,1,0],[0,0,1]]}]}"#;
    let one = r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]}]}"#;
    let huge = r#"{"poses":[{"origin":[1e999,0,0],"rotation":[1,0,0,0]},{"origin":[0,0,0],"rotation":[1,0,0,0]}]}"#;
    let wrong_type = r#"{"poses":[{"origin":"here","rotation":[1,0,0,0]},{"origin":[0,0,0],"rotation":[1,0,0,0]}]}"#;
    let cases: &[(&[&str], &str, &str)] = &[
        (&["subdivide"], zero_q, "poses[1].rotation: zero quaternion"),
        (&["subdivide"], far, "poses[1].rotation: quaternion norm 3"),
        (&["subdivide"], left, "poses[1].basis: basis is left-handed"),
        (
            &["subdivide"],
            skew,
            "poses[1].basis: basis is not orthonormal",
        ),
        (
            &["subdivide"],
            one,
            "poses: 1 pose(s) given, at least 2 needed",
        ),
        (&["subdivide"], huge, "invalid motion document"),
        (&["subdivide"], wrong_type, "invalid motion document"),
        (&["subdivide"], "{not json", "invalid motion document"),
        (&["subdivide"], "", "invalid motion document"),
        (
            &["subdivide", "--scheme", "cubic"],
            TWO_POSES,
            "scheme: unknown value 'cubic'",
        ),
        (
            &["subdivide", "--rules", "v3"],
            TWO_POSES,
            "rules: unknown value 'v3'",
        ),
        (
            &["subdivide", "--levels", "-1"],
            TWO_POSES,
            "levels: -1 is out of range (expected a whole number from 0 to 19",
        ),
        (
            &["subdivide", "--levels", "99"],
            TWO_POSES,
            "levels: 99 is out of range (expected a whole number from 0 to 19",
        ),
        (
            &["subdivide", "--levels"],
            TWO_POSES,
            "--levels needs a value",
        ),
        (
            &["subdivide", "--s", "nan"],
            TWO_POSES,
            "--s: 'nan' is not a finite number",
        ),
        (
            &["subdivide", "--s", "0.3", "--scheme", "jarek"],
            TWO_POSES,
            "s: s = 0.3 contradicts scheme 'jarek'",
        ),
        (
            &["subdivide", "--s", "0.5", "--rules", "split"],
            TWO_POSES,
            "J_s family is defined with the direct rules only",
        ),
        (
            &["subdivide", "--frobnicate"],
            TWO_POSES,
            "unknown option '--frobnicate'",
        ),
        (
            &["subdivide", "/nonexistent/motion.json"],
            "",
            "/nonexistent/motion.json:",
        ),
        (&["eval"], TWO_POSES, "eval needs at least one --u"),
        (
            &["eval", "--u", "inf"],
            TWO_POSES,
            "--u: 'inf' is not a finite number",
        ),
        (&["screw"], TWO_POSES, "screw needs at least one --t"),
        (
            &["screw", "--t", "0.5", "--levels", "2"],
            TWO_POSES,
            "unknown option '--levels'",
        ),
        (
            &["screw", "--t", "0.5"],
            &preset("circle4"),
            "screw needs exactly 2 poses, 4 given",
        ),
        (&["preset", "nope"], "", "unknown preset 'nope'"),
        (&["frobnicate"], "", "unknown command 'frobnicate'"),
        (&[], "", "no command given"),
    ];
    for (args, stdin, want) in cases {
        let out = run(args, stdin);
        assert_eq!(
            out.code, 2,
            "{args:?}: exit {} stderr {}",
            out.code, out.stderr
        );
        assert!(out.stdout.is_empty(), "{args:?}: printed {}", out.stdout);
        assert_eq!(out.stderr.lines().count(), 1, "{args:?}: {}", out.stderr);
        assert!(
            out.stderr.contains(want),
            "{args:?}: '{}' lacks '{want}'",
            out.stderr.trim()
        );
    }
}

#[test]
fn compare_prints_the_metrics_table() {
    let out = run(
        &[
            "compare",
            "--methods",
            "polyscrew,fourpoint",
            "--methods",
            "slerp",
        ],
        &preset("l_cycle_rotated"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let rows: Vec<&str> = out.stdout.lines().collect();
    assert!(rows[1].starts_with("method"), "{}", out.stdout);
    for (row, name) in rows[2..].iter().zip(["polyscrew", "fourpoint", "slerp"]) {
        assert!(row.starts_with(name), "{row}");
    }
    // The smoothness columns are the converged values: the C⁰ polyscrew's accelerations are
    // impulses with infinite integrals, the C¹ 4-point's velocity jumps are zero (not the
    // differences of its refined poses).
    let cells = |row: &str| row.split_whitespace().map(String::from).collect::<Vec<_>>();
    let (poly, four) = (cells(rows[2]), cells(rows[3]));
    assert!(
        poly[3].starts_with("impulse(") && poly[5] == "∞",
        "{poly:?}"
    );
    assert_eq!((four[1].as_str(), four[2].as_str()), ("0", "0"), "{four:?}");
    let out = run(
        &["compare", "--json", "--methods", "jarek,decoupled"],
        &preset("circle4"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(v["rows"].as_array().unwrap().len(), 2);
    // The paper's Fig. 9 claim: screws keep the circle frame-independently, decoupled does not.
    let frame = |i: usize| v["rows"][i]["frame_dependence"].as_f64().unwrap();
    assert!(frame(0) < 1e-12 && frame(1) > 1e-3, "{}", out.stdout);
    // The headline fields are converged metrics, each with its limit; the one-step numbers are
    // under `single_step`, named by their derivative route.
    for i in 0..2 {
        assert_eq!(
            v["rows"][i]["velocity_jump"]["limit"], "zero",
            "{}",
            out.stdout
        );
        assert!(
            v["rows"][i]["acceleration_energy"][0]["value"]
                .as_f64()
                .unwrap()
                > 0.0
        );
        assert!(v["rows"][i]["single_step"]["derivatives"].is_string());
    }
    for (args, want) in [
        (
            &["compare", "--methods", "nope"][..],
            "methods[0]: unknown value 'nope'",
        ),
        (&["compare", "--methods", "cc1"][..], "cc1"),
        (
            &["compare", "--levels", "3"][..],
            "unknown option '--levels'",
        ),
    ] {
        let out = run(args, &preset("circle4"));
        assert_eq!(out.code, 2, "{args:?}");
        assert!(out.stderr.contains(want), "{args:?}: {}", out.stderr);
    }
}

/// A large output is written as it is produced: a reader that takes its first lines and then
/// stops (`| head`) gets exactly the start of the full output, and the binary ends quietly
/// with exit 0; read in full, the output is the core's document of the same subdivision.
#[test]
fn large_output_streams_and_a_reader_may_stop_partway() {
    let input = preset("cylinder5");
    let args = [
        "subdivide",
        "--scheme",
        "fourpoint",
        "--rules",
        "direct",
        "--levels",
        "12",
    ];
    let full = run(&args, &input);
    assert_eq!(full.code, 0, "{}", full.stderr);
    let doc = MotionDocument::from_json(&input).unwrap();
    let poses = Subdivision::new(Scheme::FourPoint, Rules::Direct, 12)
        .apply(&doc.poses, doc.closed)
        .unwrap();
    assert_eq!(poses.len(), 5 << 12);
    let mut want = MotionDocument::new(poses, doc.closed);
    want.name = doc.name;
    assert_eq!(
        full.stdout,
        want.to_json(),
        "the CLI writes the core's document"
    );

    let mut child = Command::new(env!("CARGO_BIN_EXE_screwbender"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let mut head = vec![0; 10_000];
    std::io::Read::read_exact(child.stdout.as_mut().unwrap(), &mut head).unwrap();
    drop(child.stdout.take()); // stop reading, with most of the output still to come
    let out = child.wait_with_output().unwrap();
    assert!(
        full.stdout.len() > 100 * head.len(),
        "{}",
        full.stdout.len()
    );
    assert_eq!(head, full.stdout.as_bytes()[..head.len()]);
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A reader that closes the pipe early is not an error (no panic message, exit 0).
#[test]
fn closed_stdout_is_quiet() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_screwbender"))
        .args(["subdivide", "--levels", "8"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(preset("cylinder5").as_bytes())
        .unwrap();
    drop(child.stdout.take()); // close our end before the binary writes
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
