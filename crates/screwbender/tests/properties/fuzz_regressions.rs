//! Regression tests for the fuzz targets (fuzz/, docs/fuzzing.md): each function below replays
//! one target's checks on given input bytes, and every input a fuzzer ever crashed on becomes a
//! named `#[test]` here, its bytes inline, next to the fix.
//!
//! The inputs below are the ones the randomized JS calls found (huge finite values that
//! overflowed inside the math), replayed through the fuzz targets' checks, plus edge inputs of
//! each target kept as a floor (docs/fuzzing.md has the fuzzers' runs).
#![cfg(not(target_arch = "wasm32"))]

use screwbender::{
    import_glb, import_gltf, parse_csv_poses, Error, Motion, MotionDocument, NodeSelection, Pose,
    Rules, Scheme, Screw, ScrewBender, Subdivision,
};

/// A finite pose with a unit rotation (to 1e-12).
#[track_caller]
fn assert_sane(p: &Pose, what: &str) {
    assert!(p.is_finite(), "{what}: non-finite pose {p:?}");
    let n = p.rotation.length();
    assert!((n - 1.0).abs() <= 1e-12, "{what}: rotation norm {n}");
}

/// The `document_json` target's checks.
fn replay_document_json(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(doc) = MotionDocument::from_json(text) else {
        return;
    };
    assert!(doc.poses.len() >= 2);
    doc.poses.iter().for_each(|p| assert_sane(p, "pose"));
    let again = MotionDocument::from_json(&doc.to_json()).expect("to_json output reads back");
    assert_eq!(again.poses.len(), doc.poses.len());
}

/// The `csv_import` target's checks.
fn replay_csv_import(data: &[u8]) {
    if let Ok(doc) = std::str::from_utf8(data)
        .map_err(|_| ())
        .and_then(|t| parse_csv_poses(t).map_err(|_| ()))
    {
        assert!(doc.poses.len() >= 2);
        doc.poses.iter().for_each(|p| assert_sane(p, "pose"));
    }
}

/// The `gltf_import` target's checks (pose import only).
fn replay_gltf_import(data: &[u8]) {
    for selection in [
        NodeSelection::Auto,
        NodeSelection::Animated("control poses".into()),
    ] {
        let result = if screwbender::is_glb(data) {
            import_glb(data, &selection)
        } else {
            let mut resolve = |_: &str| -> Result<Vec<u8>, Error> { Ok(data.to_vec()) };
            import_gltf(data, &mut resolve, &selection)
        };
        if let Ok(doc) = result {
            doc.poses.iter().for_each(|p| assert_sane(p, "pose"));
        }
    }
}

/// The `subdivide` target's main check: a validated request gives finite, unit poses everywhere.
fn replay_subdivide(poses: &[([f64; 3], [f64; 4])], closed: bool, sub: Subdivision) {
    let poses: Vec<Pose> = poses
        .iter()
        .filter_map(|(o, q)| Pose::from_wxyz(*o, *q).ok())
        .collect();
    if sub.validate().is_err() || sub.output_len(poses.len(), closed).is_err() {
        assert!(ScrewBender::new(poses, closed, sub).is_err());
        return;
    }
    let motion = ScrewBender::new(poses, closed, sub).expect("a validated request subdivides");
    motion
        .refined()
        .poses()
        .iter()
        .for_each(|p| assert_sane(p, "refined"));
    let (a, b) = motion.domain();
    assert_sane(&motion.pose_at(0.5 * (a + b)), "pose_at");
}

/// Found by tests/js/random-calls.test.mjs: an origin of 1e300 was accepted and the refined
/// motion overflowed to NaN. Now refused (`MAX_COORDINATE`), so nothing non-finite comes out.
#[test]
fn huge_origin_overflowed_the_subdivision() {
    let id = [1.0, 0.0, 0.0, 0.0];
    let h = 0.5f64.sqrt();
    replay_subdivide(
        &[
            ([0.0, 0.0, 0.0], id),
            ([1e300, 0.0, 0.0], [h, 0.0, 0.0, h]),
            ([0.0, -1e300, 1.0], [0.0, 0.0, 0.0, 1.0]),
        ],
        true,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 3),
    );
    replay_document_json(
        br#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[1e300,0,0],"rotation":[1,0,0,0]},{"origin":[0,1e300,0],"rotation":[1,0,0,0]}]}"#,
    );
    replay_csv_import(b"0,0,0,1,0,0,0\n1e300,0,0,1,0,0,0\n0,1e300,0,1,0,0,0\n");
}

/// Found by tests/js/random-calls.test.mjs: `setJ(1e300)` was accepted and every refined pose
/// became non-finite. Now refused (`MAX_J_PARAMETER`).
#[test]
fn huge_j_parameter_overflowed_the_subdivision() {
    let id = [1.0, 0.0, 0.0, 0.0];
    let poses = [
        ([0.0, 0.0, 0.0], id),
        ([1.0, 0.0, 0.0], id),
        ([1.0, 1.0, 0.0], id),
    ];
    for s in [1e300, -1e300, 4.0, -4.0, 1e3] {
        replay_subdivide(
            &poses,
            true,
            Subdivision::new(Scheme::J(s), Rules::Direct, 6),
        );
    }
}

/// Edge inputs of each target: empty, truncated, near-half-turn screws at the coordinate limit.
#[test]
fn edge_inputs_of_every_target() {
    for data in [
        &b""[..],
        b"{",
        b"\xff\xfe",
        b"{\"poses\":[]}",
        b"glTF",
        b"glTF\x02\0\0\0\x0c\0\0\0",
    ] {
        replay_document_json(data);
        replay_csv_import(data);
        replay_gltf_import(data);
    }
    // Screws at the coordinate limit and near a half turn stay finite and hit both ends.
    let far = screwbender::MAX_COORDINATE;
    let a = Pose::from_wxyz([far, -far, far], [1.0, 0.0, 0.0, 0.0]).unwrap();
    let eps = 1e-9f64;
    let (s, c) = ((std::f64::consts::PI - eps) / 2.0).sin_cos();
    let b = Pose::from_wxyz([-far, far, far], [c, 0.0, s, 0.0]).unwrap();
    let screw = Screw::between(&a, &b);
    for t in [0.0, 0.5, 1.0, -3.0, 4.0] {
        assert_sane(&screw.at(t), "screw");
    }
    assert!((screw.at(1.0).origin - b.origin).length() <= 1e-9 * far);
}
