//! The wasm-bindgen API (`screwbender::web`) called from Rust inside headless Chromium:
//! construction from JS objects, typed-array layouts, known poses, and bad input that must throw
//! a clear error and leave the motion unchanged.
//!
//! `cargo test --target wasm32-unknown-unknown --test web_api` (scripts/test.sh runs it).
#![cfg(target_arch = "wasm32")]

mod support;

use js_sys::{Array, Float64Array, Reflect};
use screwbender_web::{screw_info, screw_poses, MotionHandle};
use wasm_bindgen::{JsError, JsValue};
use wasm_bindgen_test::*;

use support::{get, js, message, numbers};

wasm_bindgen_test_configure!(run_in_browser);

const H: f64 = std::f64::consts::FRAC_1_SQRT_2;

fn assert_near(a: &[f64], b: &[f64], tol: f64) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tol, "{a:?} vs {b:?}");
    }
}

/// Compares quaternions up to sign.
fn assert_quat_near(q: &[f64], e: &[f64], tol: f64) {
    let dot: f64 = q.iter().zip(e).map(|(a, b)| a * b).sum();
    let s = if dot < 0.0 { -1.0 } else { 1.0 };
    let q: Vec<f64> = q.iter().map(|v| s * v).collect();
    assert_near(&q, e, tol);
}

const TRIANGLE: &str = r#"{"closed": true, "poses": [
    {"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]},
    {"origin": [4, 0, 0], "rotation": [0.7071067811865476, 0, 0, 0.7071067811865476]},
    {"origin": [4, 4, 1], "basis": [[-1, 0, 0], [0, -1, 0], [0, 0, 1]]}]}"#;

fn triangle() -> MotionHandle {
    MotionHandle::new(js(TRIANGLE), js(r#"{"levels": 3}"#)).unwrap()
}

#[wasm_bindgen_test]
fn builds_from_objects_and_round_trips() {
    let m = triangle();
    assert_eq!(m.pose_count().unwrap(), 3);
    assert!(m.closed().unwrap());
    assert_eq!(m.levels().unwrap(), 3);
    assert_eq!(m.scheme().unwrap(), "fourpoint");
    assert_eq!(m.refined_count().unwrap(), 24);
    let text = m.to_json().unwrap();
    let again = MotionHandle::from_json(text.clone().into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(again.to_json().unwrap(), text);
    let doc = m.to_document().unwrap();
    assert_eq!(Array::from(&get(&doc, "poses")).length(), 3);
}

#[wasm_bindgen_test]
fn typed_array_layouts() {
    let m = triangle();
    let poses = m.subdivide().unwrap();
    assert_eq!(poses.len(), 24 * 7);
    // 4-point interpolates: refined pose 8 is control pose 1 (origin, then quaternion w x y z).
    assert_near(&poses[56..63], &[4.0, 0.0, 0.0, H, 0.0, 0.0, H], 1e-12);
    let mats = m.refined_matrices().unwrap();
    assert_eq!(mats.len(), 24 * 16);
    let m8: Vec<f64> = mats[8 * 16..9 * 16].iter().map(|v| *v as f64).collect();
    // Column-major: x axis → (0, 1, 0), y axis → (−1, 0, 0), origin in the last column.
    let expect = [
        0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 4.0, 0.0, 0.0, 1.0,
    ];
    assert_near(&m8, &expect, 1e-6);
    let ks = m.sample_kinematics(5.into(), JsValue::UNDEFINED).unwrap();
    assert_eq!(ks.len(), 5 * 16);
    assert_eq!(ks[16], 3.0 / 5.0);
}

#[wasm_bindgen_test]
fn circle_is_kept_exactly() {
    let m = MotionHandle::from_preset("circle4".into()).unwrap();
    for u in [0.3, 1.5, 3.9] {
        let p = m.pose_at(u.into()).unwrap();
        let a = std::f64::consts::FRAC_PI_2 * u;
        assert_near(
            &numbers(&get(&p, "origin")),
            &[3.0 * a.cos(), 3.0 * a.sin(), 0.0],
            1e-12,
        );
        let q = numbers(&get(&p, "rotation"));
        assert_quat_near(&q, &[(a / 2.0).cos(), 0.0, 0.0, (a / 2.0).sin()], 1e-12);
    }
    let k = m.kinematics_at(0.0.into(), JsValue::UNDEFINED).unwrap();
    let w = std::f64::consts::FRAC_PI_2;
    assert_near(&numbers(&get(&k, "velocity")), &[0.0, 3.0 * w, 0.0], 1e-12);
}

#[wasm_bindgen_test]
fn screw_functions() {
    let a = js(r#"{"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]}"#);
    let b =
        js(r#"{"origin": [2, 0, 1], "rotation": [0.7071067811865476, 0, 0, 0.7071067811865476]}"#);
    let ts = Float64Array::from(&[0.0, 0.5, 1.0][..]);
    let out = screw_poses(a.clone(), b.clone(), ts.into()).unwrap();
    assert_eq!(out.len(), 21);
    let c = (std::f64::consts::PI / 8.0).cos();
    let s = (std::f64::consts::PI / 8.0).sin();
    assert_near(
        &out[7..14],
        &[1.0, 1.0 - 2f64.sqrt(), 0.5, c, 0.0, 0.0, s],
        1e-15,
    );
    let info = screw_info(a, b).unwrap();
    assert_eq!(get(&info, "kind").as_string().unwrap(), "general");
    assert_eq!(get(&info, "slide").as_f64().unwrap(), 1.0);
}

/// Asserts the error message and that the motion is unchanged and still usable.
fn rejects(m: &MotionHandle, result: Result<impl Sized, JsError>, expected: &str) {
    let before = (
        m.to_json().unwrap(),
        m.levels().unwrap(),
        m.scheme().unwrap(),
    );
    let err = result.err().map(message);
    assert_eq!(err.as_deref(), Some(expected));
    let after = (
        m.to_json().unwrap(),
        m.levels().unwrap(),
        m.scheme().unwrap(),
    );
    assert_eq!(before, after);
    assert_eq!(m.subdivide().unwrap().len(), m.refined_count().unwrap() * 7);
}

#[wasm_bindgen_test]
fn bad_input_is_rejected_and_changes_nothing() {
    let m = triangle();
    let nan_pose = js(r#"{"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]}"#);
    Reflect::set(&get(&nan_pose, "origin"), &1.into(), &f64::NAN.into()).unwrap();
    rejects(
        &m,
        m.set_pose(1.into(), nan_pose),
        "pose.origin: not a finite number (NaN or infinity)",
    );
    let zero = js(r#"{"origin": [0, 0, 0], "rotation": [0, 0, 0, 0]}"#);
    rejects(
        &m,
        m.set_pose(0.into(), zero),
        "pose.rotation: zero quaternion",
    );
    let short = js(r#"{"origin": [0, 0, 0], "rotation": [1, 0, 0]}"#);
    rejects(
        &m,
        m.insert_pose(0.into(), short),
        "pose.rotation: invalid pose: invalid length 3, expected an array of length 4",
    );
    let ok = js(r#"{"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]}"#);
    rejects(
        &m,
        m.set_pose("1".into(), ok.clone()),
        "index: expected a number, got string",
    );
    rejects(
        &m,
        m.set_pose(3.into(), ok),
        "index: 3 is out of range (expected an integer from 0 to 2)",
    );
    rejects(
        &m,
        m.set_levels(19.into()),
        "levels: the result would have 1572864 poses, more than the limit of 1048576",
    );
    rejects(
        &m,
        m.set_scheme("cubic".into()),
        "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)",
    );
    rejects(
        &m,
        m.set_rules("v3".into()),
        "rules: unknown value 'v3' (expected direct, split (also split-then-tweak))",
    );
    rejects(
        &m,
        m.load_json("{\"poses\": [".into()),
        "invalid motion document: EOF while parsing a list at line 1 column 11",
    );
    m.remove_pose(0.into()).unwrap();
    rejects(
        &m,
        m.remove_pose(0.into()),
        "poses: 1 pose(s) given, at least 2 needed",
    );
    let missing = js(
        r#"{"poses": [{"rotation": [1, 0, 0, 0]}, {"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]}]}"#,
    );
    assert_eq!(
        MotionHandle::new(missing, JsValue::UNDEFINED)
            .err()
            .map(message)
            .as_deref(),
        Some("poses[0]: invalid motion document: missing field `origin`")
    );
}

#[wasm_bindgen_test]
fn scenes_are_listed_and_loadable() {
    let list = Array::from(&screwbender_web::presets().unwrap());
    assert_eq!(list.length() as usize, screwbender::presets::all().len());
    for s in list.iter() {
        let id = get(&s, "id");
        let m = MotionHandle::from_preset(id).unwrap();
        assert_eq!(
            m.pose_count().unwrap(),
            get(&s, "poseCount").as_f64().unwrap() as usize
        );
    }
}
