//! `screwbender export --times … --velocities …` and `screwbender import --reduce …` driven as
//! a user would: key poses reached at key times, a given key velocity in the exported samples,
//! documents carrying their timing, and dense CSV imports reported and reduced.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use screwbender::{MotionDocument, MANY_POSES};
use support::run;

fn preset(id: &str) -> String {
    let out = run(&["preset", id], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    out.stdout
}

/// The `t,u,…` columns of an exported CSV.
fn rows(csv: &str) -> Vec<Vec<f64>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect()
}

#[test]
fn timed_export_reaches_key_poses_at_key_times_with_the_given_velocity() {
    let doc = preset("l_cycle_rotated");
    let times = [0.0, 1.0, 3.0, 4.0, 6.0, 7.0, 9.0];
    let out = run(
        &[
            "export",
            "--format",
            "csv",
            "--fps",
            "1000",
            "--times",
            "0,1,3,4,6,7,9",
            "--velocities",
            "-,0.25,-,-,-,-",
        ],
        &doc,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let rows = rows(&out.stdout);
    for (i, &t) in times.iter().enumerate() {
        let row = rows.iter().find(|r| (r[0] - t).abs() < 1e-9).unwrap();
        let want = if i == 6 { 6.0 } else { i as f64 };
        assert!((row[1] - want).abs() < 1e-9, "u({t}) = {}", row[1]);
    }
    // At key 1 (t = 1 s) both one-sided slopes of u are 0.25 poses/s (second-order differences
    // over 1 ms: error below 1e-5).
    let j = rows.iter().position(|r| (r[0] - 1.0).abs() < 1e-9).unwrap();
    let h = rows[j + 1][0] - rows[j][0];
    let right = (-3.0 * rows[j][1] + 4.0 * rows[j + 1][1] - rows[j + 2][1]) / (2.0 * h);
    let left = (3.0 * rows[j][1] - 4.0 * rows[j - 1][1] + rows[j - 2][1]) / (2.0 * h);
    assert!(
        (right - 0.25).abs() < 1e-5 && (left - 0.25).abs() < 1e-5,
        "{left} {right}"
    );
}

#[test]
fn a_document_carries_its_timing_into_the_export() {
    let mut doc = MotionDocument::from_json(&preset("circle4")).unwrap();
    doc.set_timing(
        Some(vec![0.0, 1.0, 3.0, 4.0, 8.0]),
        Some(vec![None, Some(0.0), None, None]),
    )
    .unwrap();
    let text = doc.to_json();
    let out = run(&["export", "--format", "csv", "--fps", "2"], &text);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let rows = rows(&out.stdout);
    assert_eq!(rows.len(), 17, "8 s at 2 fps, both ends");
    assert_eq!(rows.last().unwrap()[0], 8.0);
    // Options override the document's times.
    let out = run(
        &[
            "export",
            "--format",
            "csv",
            "--fps",
            "2",
            "--times",
            "0,1,2,3,4",
        ],
        &text,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(out.stdout.lines().count() - 1, 9);
}

#[test]
fn a_dense_csv_import_is_reported_and_reduced() {
    let dir = std::env::temp_dir().join(format!("screwbender-cli-timing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("cylinder5-poses.csv");
    let out = run(&["export", "--format", "csv"], &preset("cylinder5"));
    assert_eq!(out.code, 0, "{}", out.stderr);
    std::fs::write(&csv, &out.stdout).unwrap();
    let dense = out.stdout.lines().count() - 1;
    assert!(dense > MANY_POSES);
    let path = csv.to_str().unwrap();

    let out = run(&["import", path], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    let all = MotionDocument::from_json(&out.stdout).unwrap();
    // The repeated last sample closes the cycle.
    assert_eq!(all.poses.len(), dense - 1);
    assert!(
        out.stderr.contains(&format!("has {} poses", dense - 1)) && out.stderr.contains("--reduce"),
        "{}",
        out.stderr
    );

    let out = run(&["import", path, "--reduce", "every:8"], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    let every = MotionDocument::from_json(&out.stdout).unwrap();
    assert_eq!(every.poses.len(), (dense - 1).div_ceil(8));
    assert!(out
        .stderr
        .contains(&format!("kept {} of {}", every.poses.len(), dense - 1)));

    let out = run(&["import", path, "--reduce", "fit:1e-3:1"], "");
    assert_eq!(out.code, 0, "{}", out.stderr);
    let fit = MotionDocument::from_json(&out.stdout).unwrap();
    assert!(
        fit.poses.len() >= 5 && fit.poses.len() < all.poses.len() / 2,
        "{}",
        fit.poses.len()
    );
    // A looser tolerance keeps fewer poses.
    let out = run(&["import", path, "--reduce", "fit:1e-2:1"], "");
    let loose = MotionDocument::from_json(&out.stdout).unwrap();
    assert!(
        loose.poses.len() < fit.poses.len(),
        "{} vs {}",
        loose.poses.len(),
        fit.poses.len()
    );

    for bad in ["every:0", "fit:0", "fit:1e-3:-1", "half"] {
        let out = run(&["import", path, "--reduce", bad], "");
        assert_eq!(out.code, 2, "{bad}: {}", out.stderr);
        assert!(
            out.stdout.is_empty() && out.stderr.contains("--reduce"),
            "{bad}: {}",
            out.stderr
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
