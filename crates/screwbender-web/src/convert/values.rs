//! Scalar arguments from JavaScript (numbers, counts, indices, strings, booleans, bytes), plain
//! copies of object arguments, and the JS intrinsics used to read them without running user code.

use js_sys::Array;
#[cfg(feature = "files")]
use js_sys::{ArrayBuffer, Uint8Array};
use screwbender::{Error, ErrorKind};
use wasm_bindgen::prelude::wasm_bindgen;
use wasm_bindgen::{JsCast, JsValue};

/// The JavaScript type of a value, for messages: `typeof`, except `null` and `array`.
pub(crate) fn type_name(value: &JsValue) -> String {
    if value.is_null() {
        "null".into()
    } else if Array::is_array(value) {
        "array".into()
    } else {
        value.js_typeof().as_string().unwrap_or_default()
    }
}

pub(crate) fn expected(at: &str, what: &str, value: &JsValue) -> Error {
    Error::new(
        at.to_string(),
        ErrorKind::Parse {
            message: format!("expected {what}, got {}", type_name(value)),
        },
    )
}

/// A JavaScript number (any `f64`, NaN included), or a `Parse` error naming `at`.
pub(crate) fn number(value: &JsValue, at: &str) -> Result<f64, Error> {
    value
        .as_f64()
        .ok_or_else(|| expected(at, "a number", value))
}

/// A finite JavaScript number.
pub(crate) fn finite(value: &JsValue, at: &str) -> Result<f64, Error> {
    let v = number(value, at)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::new(at.to_string(), ErrorKind::NonFinite))
    }
}

/// `v` as JavaScript prints it (`Infinity`, `NaN`, `1e+300`), for error messages about numbers
/// that came from JavaScript (Rust would print `inf` and 300 digits).
pub(crate) fn js_number(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v.is_infinite() {
        if v > 0.0 { "Infinity" } else { "-Infinity" }.into()
    } else if v != 0.0 && !(1e-6..1e21).contains(&v.abs()) {
        let s = format!("{v:e}");
        match s.split_once('e') {
            Some((m, e)) if !e.starts_with('-') => format!("{m}e+{e}"),
            _ => s,
        }
    } else {
        v.to_string()
    }
}

/// A whole number in `0..=max`, as `usize`.
pub(crate) fn count(value: &JsValue, at: &str, max: usize) -> Result<usize, Error> {
    let v = number(value, at)?;
    if v.fract() == 0.0 && v >= 0.0 && v <= max as f64 {
        Ok(v as usize)
    } else {
        Err(Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: js_number(v),
                expected: format!("a whole number from 0 to {max}"),
            },
        ))
    }
}

/// Checks an index `v` (a number from [`number`]) into a sequence of `len` elements: a whole
/// number in `0..len`. Pure Rust, so it may run while a motion's state is borrowed.
pub(crate) fn check_index(v: f64, at: &str, len: usize) -> Result<usize, Error> {
    if v.fract() == 0.0 && v >= 0.0 && v < len as f64 {
        Ok(v as usize)
    } else {
        Err(Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: js_number(v),
                expected: match len {
                    0 => "no index (the sequence is empty)".to_string(),
                    _ => format!("an integer from 0 to {}", len - 1),
                },
            },
        ))
    }
}

/// A JavaScript string.
pub(crate) fn string(value: &JsValue, at: &str) -> Result<String, Error> {
    value
        .as_string()
        .ok_or_else(|| expected(at, "a string", value))
}

/// A JavaScript boolean.
pub(crate) fn boolean(value: &JsValue, at: &str) -> Result<bool, Error> {
    value
        .as_bool()
        .ok_or_else(|| expected(at, "a boolean", value))
}

/// File contents: the bytes of a `Uint8Array` (or `ArrayBuffer`), or the UTF-8 bytes of a
/// string, at most `max` bytes (checked before copying).
#[cfg(feature = "files")]
pub(crate) fn bytes(value: &JsValue, at: &str, max: usize) -> Result<Vec<u8>, Error> {
    let too_long = |len: usize| {
        Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: format!("{len} bytes"),
                expected: format!("at most {max} bytes"),
            },
        )
    };
    if let Some(text) = value.as_string() {
        if text.len() > max {
            return Err(too_long(text.len()));
        }
        return Ok(text.into_bytes());
    }
    // `ArrayBuffer.isView` / `instanceof` read internal slots: no user code runs.
    let view = if value.is_instance_of::<ArrayBuffer>() {
        Uint8Array::new(value)
    } else if ArrayBuffer::is_view(value) && value.is_instance_of::<Uint8Array>() {
        value.clone().unchecked_into::<Uint8Array>()
    } else {
        return Err(expected(at, "a Uint8Array or a string", value));
    };
    if view.length() as usize > max {
        return Err(too_long(view.length() as usize));
    }
    Ok(view.to_vec())
}

/// Whether an optional argument was left out (`undefined` or `null`).
pub(crate) fn is_absent(value: &JsValue) -> bool {
    value.is_undefined() || value.is_null()
}

/// The error of an argument whose reading threw `e`.
pub(crate) fn unreadable(at: &str, e: &JsValue) -> Error {
    Error::new(
        at.to_string(),
        ErrorKind::Parse {
            message: format!("cannot read the argument: {}", js_message(e)),
        },
    )
}

/// The message of a thrown JavaScript value (`Error.message`, or its string form).
pub(crate) fn js_message(value: &JsValue) -> String {
    match value.dyn_ref::<js_sys::Error>() {
        Some(e) => e.message().into(),
        None => value.as_string().unwrap_or_else(|| format!("{value:?}")),
    }
}

#[wasm_bindgen]
extern "C" {
    /// The global `structuredClone`, with a thrown exception returned as `Err`.
    #[wasm_bindgen(catch, js_name = structuredClone)]
    pub(crate) fn structured_clone(value: &JsValue) -> Result<JsValue, JsValue>;

    /// `Float64Array.prototype.set` called on `target` (a view of wasm memory): copies a typed
    /// array's elements through internal slots, with a thrown exception returned as `Err`.
    #[wasm_bindgen(catch, js_namespace = ["Float64Array", "prototype", "set"], js_name = call)]
    pub(crate) fn set_from_typed_array(target: &mut [f64], source: &JsValue)
        -> Result<(), JsValue>;

    /// `Float64Array.prototype.set` called on `target` with `source` (a view of wasm memory):
    /// copies wasm memory into a typed array, with a thrown exception returned as `Err`.
    #[wasm_bindgen(catch, js_namespace = ["Float64Array", "prototype", "set"], js_name = call)]
    pub(crate) fn set_typed_array_from(target: &Float64View, source: &[f64])
        -> Result<(), JsValue>;

    /// A `Float64Array` made here as a view of part of another one's buffer.
    #[wasm_bindgen(js_name = Float64Array)]
    pub(crate) type Float64View;

    /// `new Float64Array(buffer, byteOffset, length)`, with a thrown exception (a detached
    /// buffer, a range beyond its end) returned as `Err`.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    pub(crate) fn new(
        buffer: &JsValue,
        byte_offset: f64,
        length: f64,
    ) -> Result<Float64View, JsValue>;
}

/// A plain-data copy of an object argument (primitives are returned as they are).
///
/// Reading a user's object can run user code (getters, proxies) that throws, and an exception
/// crossing the wasm frames would skip Rust's cleanup. `structuredClone` runs all of that code
/// once, inside a caught call; the copy has no getters or proxies, so nothing that reads it
/// afterwards can throw. (Functions, symbols and proxies are not cloneable: they are rejected
/// here with the engine's message.)
pub(crate) fn plain(value: &JsValue, at: &str) -> Result<JsValue, Error> {
    if !value.is_object() {
        return Ok(value.clone());
    }
    structured_clone(value).map_err(|e| {
        Error::new(
            at.to_string(),
            ErrorKind::Parse {
                message: format!("cannot read the argument: {}", js_message(&e)),
            },
        )
    })
}
