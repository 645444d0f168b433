//! `screwbender: warning: …` lines on standard error where a subdivision is silently poor
//! (`Subdivision::warnings`), with standard output unchanged.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use screwbender::{presets, MotionDocument, Rules, Scheme, Subdivision};
use support::run;

fn preset(id: &str) -> String {
    let out = run(&["preset", id], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
}

/// The warning lines of a run's standard error.
fn warnings(stderr: &str) -> Vec<&str> {
    stderr
        .lines()
        .filter(|l| l.starts_with("screwbender: warning: "))
        .collect()
}

#[test]
fn split_rules_on_the_four_pose_circle_warn_per_span_and_keep_stdout() {
    let circle = preset("circle4");
    let split = run(
        &[
            "subdivide",
            "--scheme",
            "jarek",
            "--rules",
            "split",
            "--levels",
            "2",
        ],
        &circle,
    );
    assert_eq!(split.code, 0, "{}", split.stderr);
    let lines = warnings(&split.stderr);
    assert_eq!(lines.len(), 4, "{}", split.stderr);
    for (span, line) in lines.iter().enumerate() {
        assert!(line.contains(&format!("span {span}:")), "{line}");
        assert!(line.contains("Jarek") && line.contains("180.0°"), "{line}");
    }
    // Standard output is the library's result, warnings or not.
    let doc = MotionDocument::from_json(&split.stdout).unwrap();
    let lib = Subdivision::new(Scheme::Jarek, Rules::SplitThenTweak, 2)
        .apply(&presets::preset("circle4").unwrap().poses, true)
        .unwrap();
    assert_eq!(doc.poses.len(), lib.len());
    for (a, b) in doc.poses.iter().zip(&lib) {
        assert!(a.approx_eq(b, 1e-12));
    }
    // eval and export say the same.
    let eval = run(
        &[
            "eval",
            "--scheme",
            "fourpoint",
            "--rules",
            "split",
            "--u",
            "0.5",
        ],
        &circle,
    );
    assert_eq!(eval.code, 0, "{}", eval.stderr);
    assert_eq!(warnings(&eval.stderr).len(), 4, "{}", eval.stderr);
    let export = run(
        &[
            "export",
            "--format",
            "csv",
            "--rules",
            "split",
            "--scheme",
            "fourpoint",
        ],
        &circle,
    );
    assert_eq!(export.code, 0, "{}", export.stderr);
    assert_eq!(warnings(&export.stderr).len(), 4, "{}", export.stderr);
}

#[test]
fn no_warning_where_the_result_is_good() {
    let circle = preset("circle4");
    for args in [
        // The direct rules, the B-spline with the split rules, no levels at all.
        &["subdivide", "--scheme", "jarek", "--levels", "2"][..],
        &[
            "subdivide",
            "--scheme",
            "bspline",
            "--rules",
            "split",
            "--levels",
            "2",
        ],
        &[
            "eval",
            "--scheme",
            "fourpoint",
            "--rules",
            "split",
            "--levels",
            "0",
            "--u",
            "0.5",
        ],
    ] {
        let out = run(args, &circle);
        assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
        assert!(out.stderr.is_empty(), "{args:?}: {}", out.stderr);
    }
    // Six poses: split rules are fine.
    let out = run(
        &["subdivide", "--scheme", "fourpoint", "--rules", "split"],
        &preset("l_cycle_rotated"),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stderr.is_empty(), "{}", out.stderr);
}

/// `n` poses zig-zagging sideways while moving forward, as a motion document (open).
fn zigzag(n: usize) -> String {
    let poses: Vec<String> = (0..n)
        .map(|i| {
            let side: f64 = if i % 2 == 0 { 0.3 } else { -0.3 };
            let (s, c) = (0.5 * side).sin_cos();
            format!(r#"{{"origin":[{i},{side},0],"rotation":[{c},0,0,{s}]}}"#)
        })
        .collect();
    format!(r#"{{"closed":false,"poses":[{}]}}"#, poses.join(","))
}

#[test]
fn compare_warns_where_the_c1_recursion_runs_away() {
    let out = run(&["compare", "--methods", "cc0,cc1"], &zigzag(60));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let lines = warnings(&out.stderr);
    assert_eq!(lines.len(), 1, "{}", out.stderr);
    assert!(
        lines[0].starts_with("screwbender: warning: cc1: "),
        "{}",
        lines[0]
    );
    assert!(lines[0].contains("grows without damping"), "{}", lines[0]);
    // The table notes it too, and a short zig-zag is not flagged.
    assert!(
        out.stdout.contains("grows without damping"),
        "{}",
        out.stdout
    );
    let short = run(&["compare", "--methods", "cc1"], &zigzag(8));
    assert_eq!(short.code, 0, "{}", short.stderr);
    assert!(warnings(&short.stderr).is_empty(), "{}", short.stderr);
}
