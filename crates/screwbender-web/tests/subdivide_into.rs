//! `Motion.subdivideInto(out)`: the refined poses written into a caller's `Float64Array`, the
//! same numbers as `subdivide()` bit for bit; anything but a `Float64Array` of the right length
//! throws naming `out` and writes nothing; no user code runs (the array's length, buffer and
//! offset are read through internal slots).
//!
//! `cargo test --target wasm32-unknown-unknown -p screwbender-web --test subdivide_into` (in
//! Node; scripts/test.sh runs it with the other wasm tests).
#![cfg(target_arch = "wasm32")]

// The shared helpers; this file uses two of them.
#[allow(dead_code)]
mod support;

use js_sys::{ArrayBuffer, Float32Array, Float64Array, Function};
use screwbender_web::MotionHandle;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::*;

use support::{js, message};

/// A cycle of 5 poses with rotations about different axes (so every span is a real screw).
fn motion(scheme: &str) -> MotionHandle {
    let poses: Vec<f64> = (0..5)
        .flat_map(|k| {
            let a = 0.9 * k as f64 + 0.3;
            let (s, c) = (0.5 * a).sin_cos();
            let axis = [a.cos(), a.sin(), 0.5];
            let n = axis.iter().map(|v| v * v).sum::<f64>().sqrt();
            [
                2.0 * a.cos(),
                k as f64 - 2.0,
                a.sin(),
                c,
                s * axis[0] / n,
                s * axis[1] / n,
                s * axis[2] / n,
            ]
        })
        .collect();
    let options = js(&format!(
        r#"{{"scheme": "{scheme}", "rules": "direct", "levels": 4}}"#
    ));
    MotionHandle::from_poses(
        Float64Array::from(&poses[..]).into(),
        JsValue::TRUE,
        options,
    )
    .unwrap()
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[wasm_bindgen_test]
fn fills_the_callers_array_with_the_numbers_of_subdivide() {
    for scheme in ["bspline", "fourpoint", "jarek"] {
        let m = motion(scheme);
        let len = 7 * m.refined_count().unwrap();
        let out = Float64Array::new_with_length(len as u32);
        out.fill(f64::NAN, 0, len as u32);
        let returned = m.subdivide_into(out.clone().into()).unwrap();
        assert!(
            JsValue::from(out.clone()) == returned,
            "returns `out` itself"
        );
        assert_eq!(
            bits(&out.to_vec()),
            bits(&m.subdivide().unwrap()),
            "{scheme}"
        );
        // Again after a change, into the same array.
        m.set_levels(JsValue::from(3)).unwrap();
        let short = Float64Array::new_with_length((7 * m.refined_count().unwrap()) as u32);
        m.subdivide_into(short.clone().into()).unwrap();
        assert_eq!(
            bits(&short.to_vec()),
            bits(&m.subdivide().unwrap()),
            "{scheme}"
        );
    }
}

#[wasm_bindgen_test]
fn writes_only_the_views_own_elements() {
    let m = motion("fourpoint");
    let len = 7 * m.refined_count().unwrap();
    // A view in the middle of a larger buffer: the elements around it stay as they were.
    let buffer = ArrayBuffer::new(((len + 10) * 8) as u32);
    let whole = Float64Array::new(&buffer);
    whole.fill(-7.0, 0, (len + 10) as u32);
    let view = Float64Array::new_with_byte_offset_and_length(&buffer, 3 * 8, len as u32);
    m.subdivide_into(view.into()).unwrap();
    let all = whole.to_vec();
    assert_eq!(&all[..3], &[-7.0; 3]);
    assert_eq!(&all[3 + len..], &[-7.0; 7]);
    assert_eq!(bits(&all[3..3 + len]), bits(&m.subdivide().unwrap()));
}

#[wasm_bindgen_test]
fn bad_targets_throw_naming_out_and_write_nothing() {
    let m = motion("jarek");
    let len = 7 * m.refined_count().unwrap();
    let filled = |n: usize| {
        let a = Float64Array::new_with_length(n as u32);
        a.fill(0.25, 0, n as u32);
        a
    };
    let detached = filled(len);
    // structuredClone with a transfer list detaches the original buffer.
    let detach =
        Function::new_with_args("a", "structuredClone(a.buffer, { transfer: [a.buffer] })");
    detach.call1(&JsValue::NULL, &detached).unwrap();
    let targets: Vec<(JsValue, &str)> = vec![
        (filled(len - 1).into(), "one number short"),
        (filled(len + 7).into(), "one pose too many"),
        (filled(0).into(), "empty"),
        (detached.into(), "detached buffer"),
        (
            Float32Array::new_with_length(len as u32).into(),
            "Float32Array",
        ),
        (
            js_sys::Array::new_with_length(len as u32).into(),
            "plain array",
        ),
        (JsValue::UNDEFINED, "undefined"),
        (JsValue::from(3), "number"),
    ];
    for (target, what) in targets {
        let e = m.subdivide_into(target.clone()).unwrap_err();
        let text = message(e);
        assert!(
            text.contains("out") && text.contains(&format!("length {len}")),
            "{what}: {text}"
        );
        // (A detached array has no elements to look at.)
        if let Some(a) = target.dyn_ref::<Float64Array>().filter(|a| a.length() > 0) {
            assert!(a.to_vec().iter().all(|&v| v == 0.25), "{what}: written to");
        }
    }
    // The motion still works.
    assert_eq!(m.subdivide().unwrap().len(), len);
}

#[wasm_bindgen_test]
fn runs_no_user_code() {
    let m = motion("bspline");
    let len = 7 * m.refined_count().unwrap();
    // Own `length`, `buffer`, `byteOffset` and `set` that throw: none of them is used.
    let buffer = ArrayBuffer::new((len * 8) as u32);
    let hostile = Function::new_with_args(
        "buffer",
        "const a = new Float64Array(buffer); \
         for (const k of ['length', 'buffer', 'byteOffset', 'set']) \
           Object.defineProperty(a, k, { get() { throw new Error('user code ran: ' + k); } }); \
         return a;",
    )
    .call1(&JsValue::NULL, &buffer)
    .unwrap();
    m.subdivide_into(hostile).unwrap();
    let view = Float64Array::new(&buffer);
    assert_eq!(bits(&view.to_vec()), bits(&m.subdivide().unwrap()));
}
