//! `screwbender rational`: the Chaudhry–Cameron motion's rational Bézier control points, end
//! condition (18) or (19), from poses or a raw triangle sequence — the same numbers as the
//! library's `RationalMotion::bezier`.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use screwbender::methods::{
    Continuity, EndCondition, RationalMotion, ReferenceTriangle, TriangleSample,
};
use screwbender::presets;
use support::run;

/// The triangle samples of the scene `triangle7` (the paper's example) at `t = 0, 1, 2, …`.
fn triangle7() -> Vec<TriangleSample> {
    let s = presets::preset("triangle7").unwrap();
    s.poses
        .iter()
        .enumerate()
        .map(|(i, p)| TriangleSample::from_pose(i as f64, p, &ReferenceTriangle::SCENE_B1))
        .collect()
}

/// The samples as the command reads them: one line per key, `t` then `a`, `x`, `y`.
fn rows(samples: &[TriangleSample]) -> String {
    let mut text = String::from("# t, a, x, y\n");
    for s in samples {
        let v: Vec<String> = [s.t]
            .into_iter()
            .chain(s.a.to_array())
            .chain(s.x.to_array())
            .chain(s.y.to_array())
            .map(|x| format!("{x:?}"))
            .collect();
        text += &v.join(",");
        text += "\n";
    }
    text
}

/// Whether two JSON values are the same up to `tol` in every number (serde_json's default
/// number parsing may miss the closest double by an ulp).
fn near(a: &serde_json::Value, b: &serde_json::Value, tol: f64) -> bool {
    use serde_json::Value::*;
    match (a, b) {
        (Number(x), Number(y)) => (x.as_f64().unwrap() - y.as_f64().unwrap()).abs() <= tol,
        (Array(x), Array(y)) => x.len() == y.len() && x.iter().zip(y).all(|(p, q)| near(p, q, tol)),
        (Object(x), Object(y)) => {
            x.len() == y.len()
                && x.iter()
                    .all(|(k, v)| y.get(k).is_some_and(|w| near(v, w, tol)))
        }
        _ => a == b,
    }
}

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

#[test]
fn triangles_give_the_librarys_bezier_form_for_every_continuity() {
    let samples = triangle7();
    for (args, continuity) in [
        (&["--continuity", "c0"][..], Continuity::C0),
        (
            &["--end", "18"],
            Continuity::C1(EndCondition::ZeroCurvatureStart),
        ),
        (
            &["--end", "19"],
            Continuity::C1(EndCondition::ZeroCurvatureEnd),
        ),
    ] {
        let mut all = vec!["rational", "--triangles"];
        all.extend_from_slice(args);
        let out = run(&all, &rows(&samples));
        assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
        let lib = RationalMotion::fit(&samples, continuity).unwrap().bezier();
        let want = serde_json::to_value(&lib).unwrap();
        assert!(
            near(&json(&out.stdout), &want, 1e-14),
            "{args:?}: {}",
            out.stdout
        );
    }
}

#[test]
fn end_condition_19_straightens_the_last_quaternion_segment() {
    let samples = triangle7();
    let out = run(&["rational", "--triangles", "--end", "19"], &rows(&samples));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v = json(&out.stdout);
    assert_eq!(v["continuity"], "C1 (19)");
    let segments = v["segments"].as_array().unwrap();
    assert_eq!(segments.len(), samples.len() - 1);
    let straight = |seg: &serde_json::Value| {
        let q = |k: usize| -> Vec<f64> {
            seg["quaternions"][k]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        let (q0, m, q1) = (q(0), q(1), q(2));
        (0..4).all(|k| (m[k] - 0.5 * (q0[k] + q1[k])).abs() < 1e-12)
    };
    // (19): zero curvature at t_n, so the middle of the last segment is its chord's midpoint;
    // (18) would straighten the first one instead.
    assert!(straight(segments.last().unwrap()));
    assert!(!straight(&segments[0]));
    // The vertex curves pass through the samples at the segment ends.
    for (i, seg) in segments.iter().enumerate() {
        let w: Vec<f64> = seg["weights"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        let end = |curve: &str, k: usize| -> [f64; 3] {
            let p = &seg[curve][k];
            [0, 1, 2].map(|j| p[j].as_f64().unwrap() / w[k])
        };
        for (curve, at0, at1) in [
            ("a", samples[i].a, samples[i + 1].a),
            ("x", samples[i].x, samples[i + 1].x),
            ("y", samples[i].y, samples[i + 1].y),
        ] {
            let (s, e) = (end(curve, 0), end(curve, 4));
            for j in 0..3 {
                assert!((s[j] - at0[j]).abs() < 1e-12, "segment {i} {curve} start");
                assert!((e[j] - at1[j]).abs() < 1e-12, "segment {i} {curve} end");
            }
        }
    }
}

#[test]
fn poses_at_the_documents_times_match_the_library() {
    let doc = run(&["preset", "helix_open"], "").stdout;
    let out = run(&["rational", "--end", "19"], &doc);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let s = presets::preset("helix_open").unwrap();
    let times: Vec<f64> = (0..s.poses.len()).map(|i| i as f64).collect();
    let lib = RationalMotion::from_poses(
        &s.poses,
        &times,
        false,
        Continuity::C1(EndCondition::ZeroCurvatureEnd),
        &ReferenceTriangle::SCENE_B1,
    )
    .unwrap()
    .bezier();
    let want = serde_json::to_value(&lib).unwrap();
    assert!(near(&json(&out.stdout), &want, 1e-12), "{}", out.stdout);
}

#[test]
fn bad_input_is_named_and_prints_nothing() {
    let samples = triangle7();
    let mut text = rows(&samples);
    text += "9,1,2,3\n";
    for (args, input, needle) in [
        (
            &["rational", "--triangles"][..],
            text.as_str(),
            "10: t, then a, x, y",
        ),
        (
            &["rational", "--triangles"],
            "0,0,0,0,1,0,0,0,1,0\n0,0,0,0,1,0,0,0,1,0\n",
            "samples[1].t",
        ),
        (
            &["rational", "--triangles"],
            "0,0,0,0,1,0,0,0,1,zero\n",
            "'zero' is not a number",
        ),
        (&["rational", "--end", "20"], "", "expected 18"),
        (&["rational", "--continuity", "c2"], "", "expected c0 or c1"),
        (
            &["rational", "--closing-time", "3"],
            "{}",
            "--closing-time is for --triangles",
        ),
    ] {
        let out = run(args, input);
        assert_eq!(out.code, 2, "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert!(out.stderr.contains(needle), "{args:?}: {}", out.stderr);
    }
    // A cycle of C¹ (the default) is refused by the library with its reason; C⁰ closes.
    let out = run(
        &["rational", "--triangles", "--closing-time", "10"],
        &rows(&samples),
    );
    assert_eq!(out.code, 2);
    assert!(
        out.stderr.contains("closed motions are C0 only"),
        "{}",
        out.stderr
    );
    let out = run(
        &[
            "rational",
            "--triangles",
            "--continuity",
            "c0",
            "--closing-time",
            "10",
        ],
        &rows(&samples),
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(
        json(&out.stdout)["segments"].as_array().unwrap().len(),
        samples.len()
    );
}

#[test]
fn compare_puts_the_barr_baseline_beside_ramamoorthi_barr() {
    let doc = run(&["preset", "rb_sphere7"], "").stdout;
    let out = run(
        &["compare", "--methods", "rb,barr", "--open", "--json"],
        &doc,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let v = json(&out.stdout);
    let rb = v["objectives"]["rb"]["objective"].as_f64().unwrap();
    let barr = v["objectives"]["barr"]["objective"].as_f64().unwrap();
    // docs/math/quaternion-splines.md §9: the baseline at or below, R–B within a few tenths of a
    // percent.
    assert!(barr <= rb && (rb - barr) / barr < 0.005, "{rb} {barr}");
    assert!(v["objectives"]["barr"]["seconds"].as_f64().unwrap() > 0.0);
    assert_eq!(v["rows"].as_array().unwrap().len(), 2);
    // Without `barr` named, the output is the table alone.
    let plain = run(&["compare", "--methods", "rb", "--open"], &doc);
    assert!(!plain.stdout.contains("Objective (3)"));
    // A cycle is refused with the reason.
    let closed = run(
        &["compare", "--methods", "barr"],
        &run(&["preset", "l_cycle_rotated"], "").stdout,
    );
    assert_eq!(closed.code, 2);
    assert!(
        closed.stderr.contains("open sequences only"),
        "{}",
        closed.stderr
    );
}
