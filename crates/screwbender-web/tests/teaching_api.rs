//! The teaching exports of the wasm API (`src/web/teaching.rs`) called from Rust inside
//! headless Chromium: layouts, the L-polygon vectors of docs/math/point-rules.md §5, the split/tweak step of a known
//! motion, frame (in)dependence, and bad input that must throw an error naming the element.
//!
//! `cargo test --target wasm32-unknown-unknown -p screwbender-web --features teaching --test teaching_api`.
#![cfg(all(target_arch = "wasm32", feature = "teaching"))]

mod support;

use js_sys::{Array, Float64Array, Uint32Array, Uint8Array};
use screwbender_web::{
    compare_frames_js, polygon_presets, span_screws_of, split_tweak_step_js,
    subdivide_decoupled_js, subdivide_polygon,
};
use wasm_bindgen::{JsError, JsValue};
use wasm_bindgen_test::*;

use support::{get, js, message, numbers};

wasm_bindgen_test_configure!(run_in_browser);

/// The L cycle of scene A2 as 7 numbers per pose (rotations about z).
fn l_cycle() -> JsValue {
    let scene = screwbender::presets::preset("l_cycle_rotated").expect("scene A2");
    let mut data = Vec::new();
    for p in &scene.poses {
        data.extend_from_slice(&p.origin.to_array());
        let q = p.rotation;
        data.extend_from_slice(&[q.w, q.x, q.y, q.z]);
    }
    Float64Array::from(&data[..]).into()
}

const L: [f64; 12] = [0.0, 0.0, 6.0, 0.0, 6.0, 2.0, 2.0, 2.0, 2.0, 6.0, 0.0, 6.0];

#[wasm_bindgen_test]
fn polygon_presets_and_the_l_polygon_vectors() {
    let list = Array::from(&polygon_presets().unwrap());
    assert_eq!(list.length(), 3);
    assert_eq!(get(&list.get(0), "id").as_string().unwrap(), "polygon_l");
    let points: JsValue = Float64Array::from(&L[..]).into();
    let four = subdivide_polygon(
        points.clone(),
        JsValue::TRUE,
        js(r#"{"scheme": "fourpoint", "levels": 1}"#),
    )
    .unwrap();
    let want = [
        0.0, 0.0, 3.0, -0.5, 6.0, 0.0, 6.625, 1.0, 6.0, 2.0, 4.0, 1.875, 2.0, 2.0, 1.875, 4.0, 2.0,
        6.0, 1.0, 6.625, 0.0, 6.0, -0.5, 3.0,
    ];
    assert_eq!(four.len(), want.len());
    for (g, w) in four.iter().zip(want) {
        assert!((g - w).abs() < 1e-14, "{four:?}");
    }
    // Defaults: closed, 4-point, 5 levels.
    let five = subdivide_polygon(points, JsValue::UNDEFINED, JsValue::UNDEFINED).unwrap();
    assert_eq!(five.len(), 12 << 5);
}

#[wasm_bindgen_test]
fn split_tweak_step_layout() {
    let step = split_tweak_step_js(
        l_cycle(),
        JsValue::TRUE,
        js(r#"{"scheme": "jarek", "rules": "split"}"#),
        JsValue::from(1),
    )
    .unwrap();
    assert_eq!(numbers(&get(&step, "input")).len(), 12 * 7);
    assert_eq!(numbers(&get(&step, "split")).len(), 24 * 7);
    assert_eq!(numbers(&get(&step, "output")).len(), 24 * 7);
    let tweaked = Uint8Array::from(get(&step, "tweaked")).to_vec();
    assert_eq!(tweaked, vec![1; 24]);
    let slots = Uint32Array::from(get(&step, "helperSlots")).to_vec();
    assert_eq!(slots.len(), 24);
    assert_eq!(numbers(&get(&step, "helpers")).len(), 24 * 7);
    let kept: Vec<f64> = Array::from(&get(&step, "kept"))
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(kept, vec![0.0, 24.0]);
    // The split's old slots are the input.
    let input = numbers(&get(&step, "input"));
    let split = numbers(&get(&step, "split"));
    assert_eq!(&split[..7], &input[..7]);
}

#[wasm_bindgen_test]
fn frames_screw_independent_decoupled_not() {
    let cmp = compare_frames_js(
        l_cycle(),
        JsValue::TRUE,
        js(r#"{"levels": 3}"#),
        js("[1.5, 0, 0]"),
        js("[0, 0, 0, 2, 0, 0]"),
    )
    .unwrap();
    assert_eq!(get(&cmp, "length").as_f64().unwrap(), 48.0);
    assert_eq!(numbers(&get(&cmp, "screw")).len(), 2 * 48 * 3);
    assert!(get(&cmp, "screwDeviation").as_f64().unwrap() < 1e-9);
    assert!(get(&cmp, "decoupledDeviation").as_f64().unwrap() > 1e-2);
    let dec = subdivide_decoupled_js(l_cycle(), JsValue::TRUE, js(r#"{"levels": 2}"#)).unwrap();
    assert_eq!(dec.len(), 24 * 7);
    let screws = Array::from(&span_screws_of(l_cycle(), JsValue::TRUE).unwrap());
    assert_eq!(screws.length(), 6);
    assert_eq!(
        get(&screws.get(1), "kind").as_string().unwrap(),
        "translation"
    );
}

#[wasm_bindgen_test]
fn bad_input_names_the_element() {
    let e = |r: Result<Vec<f64>, JsError>| message(r.unwrap_err());
    let ej = |r: Result<JsValue, JsError>| message(r.unwrap_err());
    assert!(e(subdivide_polygon(
        js("[0, 0, 1]"),
        JsValue::TRUE,
        JsValue::UNDEFINED
    ))
    .starts_with("points: "));
    assert!(e(subdivide_polygon(
        js("[0, 0, 1, \"x\"]"),
        JsValue::TRUE,
        JsValue::UNDEFINED
    ))
    .starts_with("points[1]"));
    assert!(e(subdivide_polygon(
        js("[0, 0, 1, 1]"),
        js("\"yes\""),
        JsValue::UNDEFINED
    ))
    .starts_with("closed"));
    assert!(ej(split_tweak_step_js(
        l_cycle(),
        JsValue::TRUE,
        JsValue::UNDEFINED,
        JsValue::from(-1)
    ))
    .starts_with("level"));
    assert!(ej(split_tweak_step_js(
        l_cycle(),
        JsValue::TRUE,
        js(r#"{"scheme": "j", "j": 0.3, "rules": "split"}"#),
        JsValue::from(0)
    ))
    .starts_with("rules"));
    assert!(ej(compare_frames_js(
        l_cycle(),
        JsValue::TRUE,
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
        js("[0, 0, 0]")
    ))
    .starts_with("offset"));
    assert!(ej(compare_frames_js(
        l_cycle(),
        JsValue::TRUE,
        JsValue::UNDEFINED,
        js("[0, 0, 0]"),
        js("[0, 0]")
    ))
    .starts_with("points"));
    assert!(
        ej(span_screws_of(js("[0, 0, 0, 0, 0, 0, 0]"), JsValue::TRUE))
            .starts_with("poses[0].rotation")
    );
}
