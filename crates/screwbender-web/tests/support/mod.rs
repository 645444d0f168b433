//! Helpers of the wasm-only tests that call the JS API from Rust (`tests/web_api.rs`,
//! `tests/teaching_api.rs`).

use js_sys::{Float64Array, Reflect, JSON};
use wasm_bindgen::{JsCast, JsError, JsValue};

/// A JS value from JSON text.
pub fn js(text: &str) -> JsValue {
    JSON::parse(text).expect("test JSON is valid")
}

/// The message a JS caller would see.
pub fn message(e: JsError) -> String {
    let v = JsValue::from(e);
    v.dyn_ref::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .unwrap_or_default()
}

/// A property of a JS object.
pub fn get(v: &JsValue, key: &str) -> JsValue {
    Reflect::get(v, &key.into()).unwrap()
}

/// The numbers of a `Float64Array` value.
pub fn numbers(v: &JsValue) -> Vec<f64> {
    Float64Array::from(v.clone()).to_vec()
}
