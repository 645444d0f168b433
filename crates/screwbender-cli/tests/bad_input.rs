//! The bad-input matrix (docs/bad-input.md), core and CLI columns: one test per row. Each bad
//! input is refused with a one-line error that names the offending element, through every
//! entry point that accepts it (JSON documents, CSV, glTF, option parsing; the CLI's
//! `subdivide`, `eval`, `export` and `import`), and nothing is written to standard output.
//! The JS API and page-import columns are tests/js/bad-input.test.mjs and
//! tests/e2e/bad-input.test.mjs.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use screwbender::{
    import_glb, parse_csv_poses, MotionDocument, NodeSelection, Pose, Rules, Scheme, ScrewBender,
    Subdivision, MAX_COORDINATE, MAX_DOCUMENT_BYTES, MAX_GLTF_BYTES, MAX_J_PARAMETER,
    MAX_REFINED_POSES,
};
use support::run;

const GOOD: &str = r#"{"origin":[0,0,0],"rotation":[1,0,0,0]}"#;

/// A document of a good pose followed by `pose` (the bad one is `poses[1]`).
fn doc_with(pose: &str) -> String {
    format!(r#"{{"closed":true,"poses":[{GOOD},{pose},{GOOD}]}}"#)
}

/// CSV of a good line followed by `line` (the bad one is line 3, after the header).
fn csv_with(line: &str) -> String {
    format!("x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n{line}\n1,1,1,1,0,0,0\n")
}

/// A scratch file `name` in a directory unique to this call (tests run in parallel).
fn scratch(name: &str, contents: &[u8]) -> PathBuf {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "screwbender-bad-input-{}-{}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// Removes a file made by [`scratch`] and its directory.
fn remove(path: &std::path::Path) {
    let _ = std::fs::remove_dir_all(path.parent().unwrap());
}

/// Asserts that the CLI refuses: exit status 2, nothing on stdout, one stderr line containing
/// every string of `want`.
#[track_caller]
fn cli_refuses(args: &[&str], stdin: &str, want: &[&str]) {
    let out = run(args, stdin);
    assert_eq!(out.code, 2, "{args:?}: exit {} ({})", out.code, out.stderr);
    assert!(out.stdout.is_empty(), "{args:?}: printed {}", out.stdout);
    assert_eq!(out.stderr.lines().count(), 1, "{args:?}: {}", out.stderr);
    for w in want {
        assert!(
            out.stderr.contains(w),
            "{args:?}: '{}' lacks '{w}'",
            out.stderr.trim()
        );
    }
}

/// The document refused by the core with exactly `message`, and by the CLI's document readers.
#[track_caller]
fn document_refused(text: &str, message: &str) {
    let e = MotionDocument::from_json(text).unwrap_err();
    assert_eq!(e.to_string(), message);
    for args in [
        &["subdivide"][..],
        &["eval", "--u", "0.5"],
        &["export", "--format", "csv"],
    ] {
        cli_refuses(args, text, &[message]);
    }
    let path = scratch("doc.json", text.as_bytes());
    cli_refuses(&["import", path.to_str().unwrap()], "", &[message]);
    remove(&path);
}

/// The CSV refused by the core with exactly `message`, and by `screwbender import`.
#[track_caller]
fn csv_refused(text: &str, message: &str) {
    let e = parse_csv_poses(text).unwrap_err();
    assert_eq!(e.to_string(), message);
    let path = scratch("poses.csv", text.as_bytes());
    cli_refuses(&["import", path.to_str().unwrap()], "", &[message]);
    remove(&path);
}

#[test]
fn nan_is_refused_and_named() {
    // Constructors (JS API and CSV go through them) name the component.
    let e = Pose::from_wxyz([0.0, f64::NAN, 0.0], [1.0, 0.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "origin: not a finite number (NaN or infinity)"
    );
    let e = Pose::from_wxyz([0.0; 3], [f64::NAN, 0.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "rotation: not a finite number (NaN or infinity)"
    );
    // JSON has no NaN: a syntax error at the element's line and column.
    let text = doc_with(r#"{"origin":[0,NaN,0],"rotation":[1,0,0,0]}"#);
    let e = MotionDocument::from_json(&text).unwrap_err().to_string();
    assert!(
        e.starts_with("invalid motion document: expected value at line 1 column"),
        "{e}"
    );
    cli_refuses(
        &["subdivide"],
        &text,
        &["invalid motion document", "column"],
    );
    csv_refused(
        &csv_with("1,NaN,0,1,0,0,0"),
        "line 3, column y: not a finite number (NaN or infinity)",
    );
    // Options.
    let e = Subdivision::new(Scheme::J(f64::NAN), Rules::Direct, 2)
        .validate()
        .unwrap_err();
    assert_eq!(e.to_string(), "s: not a finite number (NaN or infinity)");
    cli_refuses(
        &["subdivide", "--s", "NaN"],
        &doc_with(GOOD),
        &["--s: 'NaN' is not a finite number"],
    );
    cli_refuses(
        &["eval", "--u", "nan"],
        &doc_with(GOOD),
        &["--u: 'nan' is not a finite number"],
    );
}

#[test]
fn infinity_is_refused_and_named() {
    let e = Pose::from_wxyz([f64::INFINITY, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "origin: not a finite number (NaN or infinity)"
    );
    let e = Pose::from_basis(
        [0.0; 3],
        [[1.0, 0.0, 0.0], [0.0, f64::INFINITY, 0.0], [0.0; 3]],
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "basis[1]: not a finite number (NaN or infinity)"
    );
    // A JSON number beyond f64 is refused at its position, not read as infinity.
    let text = doc_with(r#"{"origin":[0,1e999,0],"rotation":[1,0,0,0]}"#);
    let e = MotionDocument::from_json(&text).unwrap_err().to_string();
    assert!(
        e.starts_with("invalid motion document: number out of range at line 1 column"),
        "{e}"
    );
    cli_refuses(&["subdivide"], &text, &["number out of range", "column"]);
    csv_refused(
        &csv_with("1,0,0,inf,0,0,0"),
        "line 3, column qw: not a finite number (NaN or infinity)",
    );
    csv_refused(
        &csv_with("1,0,-1e999,1,0,0,0"),
        "line 3, column z: not a finite number (NaN or infinity)",
    );
    cli_refuses(
        &["export", "--format", "csv", "--fps", "inf"],
        &doc_with(GOOD),
        &["--fps: 'inf' is not a finite number"],
    );
}

/// Finite but absurd magnitudes would overflow inside the math (squared lengths, the J_s rule):
/// refused up front, so every accepted input gives finite results.
#[test]
fn huge_finite_values_are_refused_and_named() {
    let e = Pose::from_wxyz([0.0, 1e300, 0.0], [1.0, 0.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "origin: 1e300 is out of range (expected coordinates within ±1e100)"
    );
    assert!(Pose::from_wxyz([0.0, MAX_COORDINATE, 0.0], [1.0, 0.0, 0.0, 0.0]).is_ok());
    document_refused(
        &doc_with(r#"{"origin":[0,-1e200,0],"rotation":[1,0,0,0]}"#),
        "poses[1].origin: -1e200 is out of range (expected coordinates within ±1e100)",
    );
    document_refused(
        &doc_with(r#"{"origin":[0,0,1e101],"basis":[[1,0,0],[0,1,0],[0,0,1]]}"#),
        "poses[1].origin: 1e101 is out of range (expected coordinates within ±1e100)",
    );
    csv_refused(
        &csv_with("1e150,0,0,1,0,0,0"),
        "line 3.origin: 1e150 is out of range (expected coordinates within ±1e100)",
    );
    let e = Subdivision::new(Scheme::J(1e300), Rules::Direct, 2)
        .validate()
        .unwrap_err();
    assert_eq!(e.to_string(), "s: 1e300 is out of range (expected -4 to 4)");
    let e = Subdivision::new(Scheme::J(-4.5), Rules::Direct, 2)
        .validate()
        .unwrap_err();
    assert_eq!(e.to_string(), "s: -4.5 is out of range (expected -4 to 4)");
    assert!(
        Subdivision::new(Scheme::J(-MAX_J_PARAMETER), Rules::Direct, 2)
            .validate()
            .is_ok()
    );
    cli_refuses(
        &["subdivide", "--s", "1e300"],
        &doc_with(GOOD),
        &["s: 1e300 is out of range (expected -4 to 4)"],
    );
    // At the limits, the deepest allowed subdivision stays finite.
    let far: Vec<Pose> = [[1.0, 1.0, 1.0], [-1.0, 1.0, -1.0], [1.0, -1.0, -1.0]]
        .iter()
        .enumerate()
        .map(|(k, o)| {
            let o = [
                o[0] * MAX_COORDINATE,
                o[1] * MAX_COORDINATE,
                o[2] * MAX_COORDINATE,
            ];
            let a = k as f64 * 2.0;
            Pose::from_wxyz(o, [a.cos(), 0.0, a.sin(), 0.0]).unwrap()
        })
        .collect();
    for s in [-MAX_J_PARAMETER, MAX_J_PARAMETER] {
        let motion = ScrewBender::new(
            far.clone(),
            true,
            Subdivision::new(Scheme::J(s), Rules::Direct, 12),
        )
        .unwrap();
        assert!(
            motion.refined().poses().iter().all(Pose::is_finite),
            "s = {s}"
        );
    }
}

#[test]
fn zero_quaternion_is_refused_and_named() {
    document_refused(
        &doc_with(r#"{"origin":[1,0,0],"rotation":[0,0,0,0]}"#),
        "poses[1].rotation: zero quaternion",
    );
    csv_refused(
        &csv_with("1,0,0,0,0,0,0"),
        "line 3.rotation: zero quaternion",
    );
}

#[test]
fn non_unit_quaternion_is_refused_and_named() {
    document_refused(
        &doc_with(r#"{"origin":[1,0,0],"rotation":[2,0,0,0]}"#),
        "poses[1].rotation: quaternion norm 2 is not 1 (accepted: within 0.001 of 1, then normalised)",
    );
    csv_refused(
        &csv_with("1,0,0,0.5,0,0,0"),
        "line 3.rotation: quaternion norm 0.5 is not 1 (accepted: within 0.001 of 1, then normalised)",
    );
    // Within the tolerance it is accepted and normalised exactly.
    let doc =
        MotionDocument::from_json(&doc_with(r#"{"origin":[1,0,0],"rotation":[1.0005,0,0,0]}"#))
            .unwrap();
    assert_eq!(doc.poses[1].rotation_wxyz(), [1.0, 0.0, 0.0, 0.0]);
}

#[test]
fn non_orthonormal_basis_is_refused_and_named() {
    document_refused(
        &doc_with(r#"{"origin":[1,0,0],"basis":[[1,0,0],[0.5,1,0],[0,0,1]]}"#),
        "poses[1].basis: basis is not orthonormal (largest |RᵀR − I| entry 5.000e-1, accepted up to 1e-4)",
    );
    document_refused(
        &doc_with(r#"{"origin":[1,0,0],"basis":[[2,0,0],[0,2,0],[0,0,2]]}"#),
        "poses[1].basis: basis is not orthonormal (largest |RᵀR − I| entry 3.000e0, accepted up to 1e-4)",
    );
}

#[test]
fn left_handed_basis_is_refused_and_named() {
    document_refused(
        &doc_with(r#"{"origin":[1,0,0],"basis":[[1,0,0],[0,1,0],[0,0,-1]]}"#),
        "poses[1].basis: basis is left-handed (det = −1); a pose needs a right-handed frame",
    );
    let e = Pose::from_basis_orthonormalized(
        [0.0; 3],
        [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
    )
    .unwrap_err();
    assert_eq!(e.path(), "basis");
}

#[test]
fn too_few_poses_are_refused() {
    document_refused(
        r#"{"poses":[]}"#,
        "poses: 0 pose(s) given, at least 2 needed",
    );
    document_refused(
        &format!(r#"{{"poses":[{GOOD}]}}"#),
        "poses: 1 pose(s) given, at least 2 needed",
    );
    csv_refused("0,0,0,1,0,0,0\n", "csv: 1 pose(s) given, at least 2 needed");
    csv_refused("# nothing\n\n", "csv: 0 pose(s) given, at least 2 needed");
    let e = ScrewBender::new(vec![Pose::IDENTITY], true, Subdivision::default()).unwrap_err();
    assert_eq!(e.to_string(), "poses: 1 pose(s) given, at least 2 needed");
    let e = Subdivision::default()
        .apply::<Pose>(&[], false)
        .unwrap_err();
    assert_eq!(e.path(), "poses");
}

#[test]
fn unknown_option_values_are_refused_and_named() {
    let e = "cubic".parse::<Scheme>().unwrap_err();
    assert_eq!(
        e.to_string(),
        "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek)"
    );
    let e = "v3".parse::<Rules>().unwrap_err();
    assert_eq!(
        e.to_string(),
        "rules: unknown value 'v3' (expected direct, split (also split-then-tweak))"
    );
    let e = Subdivision::new(Scheme::J(0.3), Rules::SplitThenTweak, 2)
        .validate()
        .unwrap_err();
    assert_eq!(e.path(), "rules");
    let doc = doc_with(GOOD);
    for args in [
        &["subdivide", "--scheme", "cubic"][..],
        &["eval", "--u", "1", "--scheme", "cubic"],
        &["export", "--format", "csv", "--scheme", "cubic"],
    ] {
        cli_refuses(args, &doc, &["scheme: unknown value 'cubic'"]);
    }
    cli_refuses(
        &["subdivide", "--rules", "v3"],
        &doc,
        &["rules: unknown value 'v3'"],
    );
    cli_refuses(
        &["export", "--format", "obj"],
        &doc,
        &["--format: unknown value 'obj'"],
    );
    cli_refuses(
        &["subdivide", "--levels", "two"],
        &doc,
        &["levels: 'two' is not a level count"],
    );
    cli_refuses(
        &["subdivide", "--levels", "-3"],
        &doc,
        &["levels: -3 is out of range (expected a whole number from 0 to 19"],
    );
}

#[test]
fn levels_beyond_the_cap_are_refused_before_any_work() {
    // 3 poses · 2^19 > 2^20: the memory guard, named `levels`, before allocating.
    let poses = MotionDocument::from_json(&doc_with(GOOD)).unwrap().poses;
    for levels in [19, 20, 31, 32, 63, 64, 1000, u32::MAX] {
        let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, levels);
        let e = sub.output_len(poses.len(), true).unwrap_err();
        assert_eq!(e.path(), "levels", "{levels}");
        assert!(
            e.to_string()
                .ends_with(&format!("more than the limit of {MAX_REFINED_POSES}")),
            "{e}"
        );
        assert!(sub.apply(&poses, false).is_err());
        assert!(ScrewBender::new(poses.clone(), true, sub).is_err());
    }
    // 3 · 2^18 < 2^20 is allowed: the cap is on the result, not on the level number.
    assert!(Subdivision::new(Scheme::BSpline, Rules::Direct, 18)
        .output_len(3, true)
        .is_ok());
    let doc = doc_with(GOOD);
    // Beyond MAX_LEVELS no input fits: refused as out of range, whatever the poses.
    for args in [
        &["subdivide", "--levels", "30"][..],
        &["eval", "--u", "1", "--levels", "30"],
        &["export", "--format", "csv", "--levels", "30"],
    ] {
        cli_refuses(args, &doc, &["levels: 30 is out of range", "from 0 to 19"]);
    }
    // Within it, the memory guard on these 3 poses.
    for args in [
        &["subdivide", "--levels", "19"][..],
        &["eval", "--u", "1", "--levels", "19"],
        &["export", "--format", "csv", "--levels", "19"],
    ] {
        cli_refuses(
            args,
            &doc,
            &["levels: the result would have", "more than the limit"],
        );
    }
    cli_refuses(
        &["subdivide", "--levels", "99999999999"],
        &doc,
        &["levels: 99999999999 is out of range"],
    );
}

#[test]
fn malformed_files_are_refused_with_their_position() {
    let cases = [
        // Truncated.
        (
            r#"{"poses":[{"origin":[0,0"#.to_string(),
            "EOF while parsing",
        ),
        // Wrong type.
        (
            doc_with(r#"{"origin":"here","rotation":[1,0,0,0]}"#),
            "invalid type: string \"here\"",
        ),
        // Wrong length.
        (
            doc_with(r#"{"origin":[0,0],"rotation":[1,0,0,0]}"#),
            "invalid length 2",
        ),
        // Misspelt field.
        (
            r#"{"poses":[], "clossed": true}"#.to_string(),
            "unknown field `clossed`",
        ),
        (
            doc_with(r#"{"origin":[0,0,0],"rotaton":[1,0,0,0]}"#),
            "unknown field `rotaton`",
        ),
        // Not an object at all.
        ("[1, 2, 3]".to_string(), "invalid type: integer `1`"),
        (String::new(), "EOF while parsing"),
    ];
    for (text, want) in &cases {
        let e = MotionDocument::from_json(text).unwrap_err().to_string();
        assert!(
            e.starts_with("invalid motion document: ") && e.contains(want) && e.contains("line"),
            "{text}: {e}"
        );
        cli_refuses(&["subdivide"], text, &[want]);
    }
    // Both forms of a rotation, and neither.
    document_refused(
        &doc_with(r#"{"origin":[0,0,0],"rotation":[1,0,0,0],"basis":[[1,0,0],[0,1,0],[0,0,1]]}"#),
        "poses[1]: give either 'rotation' or 'basis', not both",
    );
    // Not UTF-8: the file is named.
    let path = scratch("latin1.json", b"{\"name\":\"caf\xe9\",\"poses\":[]}");
    cli_refuses(&["subdivide", path.to_str().unwrap()], "", &["latin1.json"]);
    cli_refuses(&["import", path.to_str().unwrap()], "", &["not UTF-8 text"]);
    remove(&path);
    // CSV: missing fields, text in a number field, a header without a pose column.
    csv_refused(
        &csv_with("1,2,3"),
        "line 3: 3 field(s), expected 7 (x,y,z,qw,qx,qy,qz)",
    );
    csv_refused(
        &csv_with("1,2,three,1,0,0,0"),
        "line 3, column z: 'three' is not a number",
    );
    csv_refused(
        "x,y,z,w,qx,qy,qz\n0,0,0,1,0,0,0\n",
        "line 1: header has no column 'qw' (expected x,y,z,qw,qx,qy,qz)",
    );
    // glTF: not GLB, truncated GLB, JSON that is not glTF.
    let mut glb = b"glTF".to_vec();
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&1000u32.to_le_bytes());
    let e = import_glb(&glb, &NodeSelection::Auto).unwrap_err();
    assert_eq!(e.path(), "glb", "{e}");
    let path = scratch("truncated.glb", &glb);
    cli_refuses(
        &["import", path.to_str().unwrap()],
        "",
        &["truncated.glb: glb: "],
    );
    remove(&path);
    let path = scratch("notgltf.gltf", br#"{"poses": []}"#);
    cli_refuses(
        &["import", path.to_str().unwrap()],
        "",
        &["notgltf.gltf: gltf: invalid glTF JSON"],
    );
    remove(&path);
}

#[test]
fn oversized_files_are_refused_before_parsing() {
    // The core refuses by length alone (the text is not looked at).
    let big = " ".repeat(MAX_DOCUMENT_BYTES + 1);
    let e = MotionDocument::from_json(&big).unwrap_err();
    assert_eq!(e.path(), "document");
    assert!(e.to_string().contains("out of range"), "{e}");
    // The CLI checks the size of a file before reading it: a sparse file costs nothing.
    let path = scratch("huge.json", b"");
    let f = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    f.set_len(MAX_DOCUMENT_BYTES as u64 + 1).unwrap();
    cli_refuses(
        &["subdivide", path.to_str().unwrap()],
        "",
        &["huge.json", "is larger than the limit of 16777216 bytes"],
    );
    remove(&path);
    for name in ["huge.glb", "huge.csv"] {
        let path = scratch(name, b"");
        let f = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
        f.set_len(MAX_GLTF_BYTES as u64 + 1).unwrap();
        cli_refuses(
            &["import", path.to_str().unwrap()],
            "",
            &[
                name,
                &format!("is larger than the limit of {MAX_GLTF_BYTES} bytes"),
            ],
        );
        remove(&path);
    }
    // Standard input has no size to check first: the document limit applies after reading.
    cli_refuses(&["subdivide"], &big, &["document: ", "out of range"]);
}

#[test]
fn bad_key_timing_is_refused_and_named() {
    // In a document (times not increasing, wrong count; velocities negative, not finite as a
    // huge literal, or making time run backwards) and as export options.
    let poses = format!("{GOOD},{GOOD},{GOOD}");
    for (extra, message) in [
        (r#""times":[0,2,1,3]"#, "times[2]"),
        (r#""times":[0,1]"#, "times: 2 times given, expected 4"),
        (r#""velocities":[null,-1,null]"#, "velocities[1]"),
        (
            r#""velocities":[1e999,null,null]"#,
            "invalid motion document",
        ),
        (r#""velocities":[null,40,null]"#, "velocities[1]"),
    ] {
        let text = format!(r#"{{"closed":true,{extra},"poses":[{poses}]}}"#);
        let e = MotionDocument::from_json(&text).unwrap_err().to_string();
        assert!(e.contains(message), "{e}");
        for args in [&["subdivide"][..], &["export", "--format", "csv"]] {
            cli_refuses(args, &text, &[message]);
        }
    }
    let doc = format!(r#"{{"closed":true,"poses":[{poses}]}}"#);
    for (args, message) in [
        (&["--times", "0,1,1,3"][..], "times[2]"),
        (&["--velocities", "-,-1,-"][..], "velocities[1]"),
        (
            &["--velocities", "-,nan,-"][..],
            "--velocities: 'nan' is not a finite number",
        ),
        (
            &["--velocities", "-,-"][..],
            "velocities: 2 velocities given, expected 3",
        ),
        (&["--velocities", "9,-,-"][..], "velocities[0]"),
    ] {
        let mut all = vec!["export", "--format", "csv"];
        all.extend_from_slice(args);
        cli_refuses(&all, &doc, &[message]);
    }
}
