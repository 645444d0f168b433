//! The one place where JavaScript values meet glam types: pose objects, typed-array layouts,
//! scalar arguments, and the serde bridge with element paths in its errors.
//!
//! Every function here returns the core [`Error`] (with the path of the bad element), so the
//! callers can validate everything before they mutate anything.
//!
//! ## Typed-array layouts
//!
//! * **Poses** ([`POSE_STRIDE`] = 7 `f64` per pose, `Float64Array`):
//!   `[ox, oy, oz, qw, qx, qy, qz]` — the origin, then the unit quaternion scalar first.
//! * **Matrices** ([`MATRIX_STRIDE`] = 16 `f32` per pose, `Float32Array`): the 4×4 homogeneous
//!   local-to-world matrix in column-major order (`m[12..15]` is the origin), ready for WebGL /
//!   WebGPU instance buffers and `DOMMatrix.fromFloat32Array`.
//! * **Kinematics samples** ([`KINEMATICS_STRIDE`] = 16 `f64` per sample, `Float64Array`):
//!   `[u, px, py, pz, vx, vy, vz, ax, ay, az, wx, wy, wz, αx, αy, αz]` — the parameter, the body
//!   point's position, velocity and acceleration, the body's angular velocity and angular
//!   acceleration (all world frame, per coarse parameter unit).

use std::ops::Range;

use glam::DVec3;
#[cfg(feature = "files")]
use js_sys::Uint8Array;
use js_sys::{Array, ArrayBuffer, Float64Array, Object, Reflect};
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::wasm_bindgen;
use wasm_bindgen::{JsCast, JsError, JsValue};

use crate::{Error, Kinematics, MotionDocument, Pose, RawDocument, RawPose};

/// Numbers per pose in a pose `Float64Array`: origin `x, y, z`, then quaternion `w, x, y, z`.
pub const POSE_STRIDE: usize = 7;

/// Numbers per pose in a matrix `Float32Array`: a column-major 4×4 matrix.
pub const MATRIX_STRIDE: usize = 16;

/// Numbers per sample in a kinematics `Float64Array` (see the module docs for the order).
pub const KINEMATICS_STRIDE: usize = 16;

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

fn expected(at: &str, what: &str, value: &JsValue) -> Error {
    Error::Parse {
        at: at.to_string(),
        message: format!("expected {what}, got {}", type_name(value)),
    }
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
        Err(Error::NonFinite { at: at.to_string() })
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
        Err(Error::OutOfRange {
            at: at.to_string(),
            value: js_number(v),
            expected: format!("a whole number from 0 to {max}"),
        })
    }
}

/// Checks an index `v` (a number from [`number`]) into a sequence of `len` elements: a whole
/// number in `0..len`. Pure Rust, so it may run while a motion's state is borrowed.
pub(crate) fn check_index(v: f64, at: &str, len: usize) -> Result<usize, Error> {
    if v.fract() == 0.0 && v >= 0.0 && v < len as f64 {
        Ok(v as usize)
    } else {
        Err(Error::OutOfRange {
            at: at.to_string(),
            value: js_number(v),
            expected: match len {
                0 => "no index (the sequence is empty)".to_string(),
                _ => format!("an integer from 0 to {}", len - 1),
            },
        })
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
    let too_long = |len: usize| Error::OutOfRange {
        at: at.to_string(),
        value: format!("{len} bytes"),
        expected: format!("at most {max} bytes"),
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

/// A list of at most `max` numbers from a `Float64Array` or a plain array (non-numbers become
/// NaN and are caught by the caller's finiteness checks). The length is checked before copying.
pub(crate) fn f64_array(value: &JsValue, at: &str, max: usize) -> Result<Vec<f64>, Error> {
    let mut out = Vec::new();
    read_f64_array(value, at, max, &mut out)?;
    Ok(out)
}

thread_local! {
    /// The numbers of pose batches, kept from call to call: refilling it costs only the copy,
    /// where a fresh buffer was also zeroed (a fifth of a `screwPairs` call's time in wasm).
    static POSE_NUMBERS: std::cell::RefCell<Vec<f64>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Poses (7 numbers each, validated: see [`poses_from_array`]) from a `Float64Array` or an
/// array of numbers, at most [`crate::MAX_REFINED_POSES`] of them.
pub(crate) fn poses_from_js_array(value: &JsValue, at: &str) -> Result<Vec<Pose>, Error> {
    let max = crate::MAX_REFINED_POSES * POSE_STRIDE;
    let read = |numbers: &mut Vec<f64>| {
        read_f64_array(value, at, max, numbers)?;
        poses_from_array(numbers, at)
    };
    // Reading an array may run a caller's getter, which may call back into this module: the
    // inner call then finds the buffer borrowed and uses a fresh one.
    POSE_NUMBERS.with(|numbers| match numbers.try_borrow_mut() {
        Ok(mut numbers) => read(&mut numbers),
        Err(_) => read(&mut Vec::new()),
    })
}

/// [`f64_array`] into `out`, whose length becomes that of the list (its earlier contents are
/// overwritten, not cleared first).
fn read_f64_array(value: &JsValue, at: &str, max: usize, out: &mut Vec<f64>) -> Result<(), Error> {
    let list = NumberList::from_js(value, at, max)?;
    list.read(0..list.len(), out)
}

/// A list of numbers from JavaScript, a `Float64Array` or an array of numbers (non-numbers
/// become NaN and are caught by the caller's finiteness checks), for reading in chunks.
///
/// A `Float64Array` is copied into wasm memory only chunk by chunk, as the chunks are read, so
/// that a chunk is still in the cache when it is used: copying whole arrays of thousands of
/// poses first cost more than the screws computed from them. Its length and elements are read
/// through internal slots (the intrinsic getters of `%TypedArray%.prototype`, then `set` into
/// wasm memory), so no user code runs (not even a caller's own `length` getter), and nothing
/// is copied twice (a defensive `new Float64Array(value)` cost more than the screws it
/// carried). An array of numbers is read whole, at once: reading it may run user code.
pub(crate) struct NumberList<'a> {
    at: &'a str,
    len: usize,
    source: NumberSource,
}

enum NumberSource {
    /// The buffer and the byte offset of a `Float64Array`.
    View(JsValue, f64),
    /// The numbers of a plain array.
    Read(Vec<f64>),
}

impl<'a> NumberList<'a> {
    /// The list of `value` (named `at` in errors), of at most `max` numbers.
    pub(crate) fn from_js(value: &JsValue, at: &'a str, max: usize) -> Result<Self, Error> {
        let too_long = |len: usize| Error::OutOfRange {
            at: at.to_string(),
            value: format!("length {len}"),
            expected: format!("at most {max} numbers per call"),
        };
        // `ArrayBuffer.isView` reads an internal slot (never user code, false for proxies), so
        // `instanceof` on a view is safe too.
        if ArrayBuffer::is_view(value) && value.is_instance_of::<Float64Array>() {
            let slot = |k| typed_array_slot(value, k).map_err(|e| unreadable(at, &e));
            let number = |v: JsValue| v.as_f64().unwrap_or(0.0);
            let len = number(slot(LENGTH)?) as usize;
            if len > max {
                return Err(too_long(len));
            }
            let source = NumberSource::View(slot(BUFFER)?, number(slot(BYTE_OFFSET)?));
            return Ok(NumberList { at, len, source });
        }
        let value = plain(value, at)?;
        let Some(a) = value.dyn_ref::<Array>() else {
            return Err(expected(
                at,
                "a Float64Array or an array of numbers",
                &value,
            ));
        };
        if a.length() as usize > max {
            return Err(too_long(a.length() as usize));
        }
        // Element by element: `new Float64Array(array)` would throw on a BigInt and turn
        // strings into numbers.
        let numbers: Vec<f64> = a.iter().map(|v| v.as_f64().unwrap_or(f64::NAN)).collect();
        Ok(NumberList {
            at,
            len: numbers.len(),
            source: NumberSource::Read(numbers),
        })
    }

    /// How many numbers the list has.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Copies the numbers `range` (within `0..len()`) into `out`, whose length becomes that of
    /// the range (its earlier contents are overwritten, not cleared first).
    pub(crate) fn read(&self, range: Range<usize>, out: &mut Vec<f64>) -> Result<(), Error> {
        match &self.source {
            NumberSource::Read(numbers) => {
                out.clear();
                out.extend_from_slice(&numbers[range]);
            }
            NumberSource::View(buffer, byte_offset) => {
                out.resize(range.len(), 0.0);
                // A detached buffer reads as length 0 and is not touched (`set` would throw on
                // it); one detached since (by user code run by a later argument) throws, which
                // is caught.
                if !range.is_empty() {
                    let offset = byte_offset + (range.start * 8) as f64;
                    Float64View::new(buffer, offset, range.len() as f64)
                        .and_then(|view| set_from_typed_array(out, &view))
                        .map_err(|e| unreadable(self.at, &e))?;
                }
            }
        }
        Ok(())
    }
}

/// The error of an argument whose reading threw `e`.
fn unreadable(at: &str, e: &JsValue) -> Error {
    Error::Parse {
        at: at.to_string(),
        message: format!("cannot read the argument: {}", js_message(e)),
    }
}

/// The message of a thrown JavaScript value (`Error.message`, or its string form).
fn js_message(value: &JsValue) -> String {
    match value.dyn_ref::<js_sys::Error>() {
        Some(e) => e.message().into(),
        None => value.as_string().unwrap_or_else(|| format!("{value:?}")),
    }
}

#[wasm_bindgen]
extern "C" {
    /// The global `structuredClone`, with a thrown exception returned as `Err`.
    #[wasm_bindgen(catch, js_name = structuredClone)]
    fn structured_clone(value: &JsValue) -> Result<JsValue, JsValue>;

    /// `Float64Array.prototype.set` called on `target` (a view of wasm memory): copies a typed
    /// array's elements through internal slots, with a thrown exception returned as `Err`.
    #[wasm_bindgen(catch, js_namespace = ["Float64Array", "prototype", "set"], js_name = call)]
    fn set_from_typed_array(target: &mut [f64], source: &JsValue) -> Result<(), JsValue>;

    /// A `Float64Array` made here as a view of part of another one's buffer.
    #[wasm_bindgen(js_name = Float64Array)]
    type Float64View;

    /// `new Float64Array(buffer, byteOffset, length)`, with a thrown exception (a detached
    /// buffer, a range beyond its end) returned as `Err`.
    #[wasm_bindgen(catch, constructor, js_class = "Float64Array")]
    fn new(buffer: &JsValue, byte_offset: f64, length: f64) -> Result<Float64View, JsValue>;
}

/// The intrinsic getters of typed arrays read by [`typed_array_slot`], in this order.
const TYPED_ARRAY_SLOTS: [&str; 3] = ["length", "buffer", "byteOffset"];
const LENGTH: usize = 0;
const BUFFER: usize = 1;
const BYTE_OFFSET: usize = 2;

thread_local! {
    /// The intrinsic getters [`TYPED_ARRAY_SLOTS`] of typed arrays (on
    /// `%TypedArray%.prototype`), looked up once.
    static TYPED_ARRAY_GETTERS: [Option<js_sys::Function>; 3] = {
        let prototype = Object::get_prototype_of(&Float64Array::new_with_length(0));
        let typed_array_prototype = Object::get_prototype_of(&prototype);
        TYPED_ARRAY_SLOTS.map(|name| {
            let descriptor =
                Object::get_own_property_descriptor(&typed_array_prototype, &name.into());
            Reflect::get(&descriptor, &"get".into())
                .ok()
                .and_then(|getter| getter.dyn_into().ok())
        })
    };
}

/// The internal slot [`TYPED_ARRAY_SLOTS`]`[k]` of a typed array `view`, read by the intrinsic
/// getter (not `view.length` and so on, which may be own properties with getters that run user
/// code).
fn typed_array_slot(view: &JsValue, k: usize) -> Result<JsValue, JsValue> {
    TYPED_ARRAY_GETTERS.with(|getters| match &getters[k] {
        Some(getter) => getter.call0(view),
        None => Err(JsValue::from_str("typed arrays have no such getter")),
    })
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
    structured_clone(value).map_err(|e| Error::Parse {
        at: at.to_string(),
        message: format!("cannot read the argument: {}", js_message(&e)),
    })
}

/// Deserialises a JavaScript value with serde-wasm-bindgen, naming the offending element:
/// `at` prefixes the path found inside the value, `what` names the input in the message
/// (`invalid motion document: missing field 'origin'`, as the JSON parser words it).
pub(crate) fn from_js<T: DeserializeOwned>(
    value: &JsValue,
    at: &str,
    what: &str,
) -> Result<T, Error> {
    let de = serde_wasm_bindgen::Deserializer::from(value.clone());
    serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let message = js_message(&JsValue::from(e.into_inner()));
        Error::Parse {
            at: if path == "." { String::new() } else { path },
            message: format!("invalid {what}: {message}"),
        }
        .within(at)
    })
}

/// Serialises a value to plain JavaScript objects and arrays.
pub(crate) fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::new())
        .map_err(|e| JsError::new(&js_message(&JsValue::from(e))))
}

// ---- strictness that serde-wasm-bindgen lacks -------------------------------------------------
//
// serde-wasm-bindgen reads only the fields a struct names (so `#[serde(deny_unknown_fields)]`
// never fires) and does not reject arrays longer than a fixed-size array. The JSON parser does
// both; these checks make a JS object fail exactly where its JSON text would.

/// A deserializer that answers every request with an error, except that a struct request
/// reports the struct's field names: serde's own list, in declaration order.
struct FieldsProbe;

#[derive(Debug)]
enum ProbeError {
    Fields(&'static [&'static str]),
    Other,
}

impl std::fmt::Display for ProbeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("field probe")
    }
}

impl std::error::Error for ProbeError {}

impl serde::de::Error for ProbeError {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        ProbeError::Other
    }
}

impl<'de> serde::Deserializer<'de> for FieldsProbe {
    type Error = ProbeError;

    fn deserialize_any<V: serde::de::Visitor<'de>>(self, _: V) -> Result<V::Value, ProbeError> {
        Err(ProbeError::Other)
    }

    fn deserialize_struct<V: serde::de::Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        _visitor: V,
    ) -> Result<V::Value, ProbeError> {
        Err(ProbeError::Fields(fields))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        option unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier
        ignored_any
    }
}

/// The field names of a struct deriving `Deserialize` (empty for other types).
pub(crate) fn fields_of<T: DeserializeOwned>() -> &'static [&'static str] {
    match T::deserialize(FieldsProbe) {
        Err(ProbeError::Fields(fields)) => fields,
        _ => &[],
    }
}

fn get(object: &JsValue, key: &str, at: &str) -> Result<JsValue, Error> {
    Reflect::get(object, &JsValue::from_str(key)).map_err(|e| Error::Parse {
        at: at.to_string(),
        message: js_message(&e),
    })
}

/// Rejects keys of `object` that are not in `allowed`, in serde's words.
pub(crate) fn check_keys(
    object: &JsValue,
    allowed: &'static [&'static str],
    at: &str,
    what: &str,
) -> Result<(), Error> {
    let Some(obj) = object.dyn_ref::<Object>() else {
        return Ok(());
    };
    for key in Object::keys(obj).iter() {
        let key = key.as_string().unwrap_or_default();
        if !allowed.contains(&key.as_str()) {
            let message =
                <serde::de::value::Error as serde::de::Error>::unknown_field(&key, allowed);
            return Err(Error::Parse {
                at: at.to_string(),
                message: format!("invalid {what}: {message}"),
            });
        }
    }
    Ok(())
}

/// Rejects a value that is not a JavaScript object (before serde words it as
/// `expected struct RawDocument`).
pub(crate) fn check_object(
    value: &JsValue,
    at: &str,
    what: &str,
    shape: &str,
) -> Result<(), Error> {
    if value.is_object() && !Array::is_array(value) {
        Ok(())
    } else {
        Err(Error::Parse {
            at: at.to_string(),
            message: format!(
                "invalid {what}: expected an object {shape}, got {}",
                type_name(value)
            ),
        })
    }
}

/// Rejects an array-like `value` whose length is not exactly `len` (shorter ones were already
/// rejected by serde).
fn check_len(value: &JsValue, len: usize, at: &str, what: &str) -> Result<(), Error> {
    if is_absent(value) || !value.is_object() {
        return Ok(());
    }
    let found = get(value, "length", at)?.as_f64().unwrap_or(len as f64);
    if found != len as f64 {
        return Err(Error::Parse {
            at: at.to_string(),
            message: format!(
                "invalid {what}: invalid length {found}, expected an array of length {len}"
            ),
        });
    }
    Ok(())
}

/// `parent.field`, or `field` at the top level.
fn join(parent: &str, field: &str) -> String {
    if parent.is_empty() {
        field.to_string()
    } else {
        format!("{parent}.{field}")
    }
}

fn check_pose_shape(value: &JsValue, at: &str, what: &str) -> Result<(), Error> {
    let fields = fields_of::<RawPose>();
    check_keys(value, fields, at, what)?;
    check_len(&get(value, "origin", at)?, 3, &join(at, "origin"), what)?;
    check_len(&get(value, "rotation", at)?, 4, &join(at, "rotation"), what)?;
    let basis = get(value, "basis", at)?;
    let basis_at = join(at, "basis");
    check_len(&basis, 3, &basis_at, what)?;
    if Array::is_array(&basis) {
        for (k, v) in Array::from(&basis).iter().enumerate() {
            check_len(&v, 3, &format!("{basis_at}[{k}]"), what)?;
        }
    }
    Ok(())
}

// ---- poses and documents ----------------------------------------------------------------------

const POSE_SHAPE: &str = "{origin, rotation} or {origin, basis}";

/// A pose object `{origin, rotation}` or `{origin, basis}`, validated like a pose of a motion
/// document; errors are prefixed with `at` (e.g. `pose.rotation: zero quaternion`).
pub(crate) fn pose_from_js(value: &JsValue, at: &str) -> Result<Pose, Error> {
    let value = &plain(value, at)?;
    check_object(value, at, "pose", POSE_SHAPE)?;
    let raw: RawPose = from_js(value, at, "pose")?;
    check_pose_shape(value, at, "pose")?;
    raw.to_pose().map_err(|e| e.within(at))
}

/// A motion document object, through the same [`RawDocument::validate`] as the JSON parser.
pub(crate) fn document_from_js(value: &JsValue) -> Result<MotionDocument, Error> {
    const WHAT: &str = "motion document";
    let value = &plain(value, "")?;
    check_object(value, "", WHAT, "{closed?, name?, poses: [...]}")?;
    let poses = get(value, "poses", "")?;
    let poses = if Array::is_array(&poses) {
        Array::from(&poses).to_vec()
    } else {
        Vec::new()
    };
    for (i, p) in poses.iter().enumerate() {
        check_object(p, &format!("poses[{i}]"), WHAT, POSE_SHAPE)?;
    }
    let raw: RawDocument = from_js(value, "", WHAT)?;
    check_keys(value, fields_of::<RawDocument>(), "", WHAT)?;
    for (i, p) in poses.iter().enumerate() {
        check_pose_shape(p, &format!("poses[{i}]"), WHAT)?;
    }
    raw.validate()
}

/// A pose as the plain object `{origin: [x, y, z], rotation: [w, x, y, z]}`.
pub(crate) fn pose_to_js(pose: &Pose) -> Result<JsValue, JsError> {
    to_js(&RawPose::from_pose(pose))
}

/// A motion document as a plain object (every pose as `origin` + `rotation`).
pub(crate) fn document_to_js(doc: &MotionDocument) -> Result<JsValue, JsError> {
    to_js(&doc.to_raw())
}

/// An optional local point `[x, y, z]` (absent: the local origin).
pub(crate) fn point_from_js(value: &JsValue, at: &str) -> Result<DVec3, Error> {
    if is_absent(value) {
        return Ok(DVec3::ZERO);
    }
    let value = &plain(value, at)?;
    let p: [f64; 3] = from_js(value, at, "point")?;
    check_len(value, 3, at, "point")?;
    if !p.iter().all(|v| v.is_finite()) {
        return Err(Error::NonFinite { at: at.to_string() });
    }
    Ok(DVec3::from_array(p))
}

// ---- typed arrays -----------------------------------------------------------------------------

/// Writes one pose in the [`POSE_STRIDE`] layout into `out` (7 numbers).
#[inline]
pub(crate) fn write_pose(out: &mut [f64], p: &Pose) {
    let q = p.rotation_wxyz();
    out.copy_from_slice(&[p.origin.x, p.origin.y, p.origin.z, q[0], q[1], q[2], q[3]]);
}

/// `count` poses `pose(k)` in the [`POSE_STRIDE`] layout (the bulk functions' inner loop: one
/// zeroed allocation, no capacity checks).
#[inline]
pub(crate) fn poses_from_fn(count: usize, mut pose: impl FnMut(usize) -> Pose) -> Vec<f64> {
    let mut out = vec![0.0; count * POSE_STRIDE];
    for (k, chunk) in out.chunks_exact_mut(POSE_STRIDE).enumerate() {
        write_pose(chunk, &pose(k));
    }
    out
}

/// Poses in the [`POSE_STRIDE`] layout.
pub(crate) fn poses_to_array(poses: &[Pose]) -> Vec<f64> {
    poses_from_fn(poses.len(), |k| poses[k])
}

/// Poses as column-major 4×4 `f32` matrices ([`MATRIX_STRIDE`] layout) — the only place in the
/// JS API where `f64` becomes `f32`.
pub(crate) fn poses_to_matrices(poses: &[Pose]) -> Vec<f32> {
    let mut out = Vec::with_capacity(poses.len() * MATRIX_STRIDE);
    for p in poses {
        out.extend(p.to_matrix().to_cols_array().iter().map(|v| *v as f32));
    }
    out
}

/// Poses from the [`POSE_STRIDE`] layout, each validated by [`Pose::from_wxyz`]; errors name
/// `at[i]`.
pub(crate) fn poses_from_array(data: &[f64], at: &str) -> Result<Vec<Pose>, Error> {
    if data.len() % POSE_STRIDE != 0 {
        return Err(Error::OutOfRange {
            at: at.to_string(),
            value: format!("length {}", data.len()),
            expected: format!(
                "a multiple of {POSE_STRIDE} (origin x, y, z and quaternion w, x, y, z per pose)"
            ),
        });
    }
    let mut poses = Vec::with_capacity(data.len() / POSE_STRIDE);
    // The valid poses in one go; `from_wxyz` only to describe what is wrong.
    while !push_valid_poses(&data[poses.len() * POSE_STRIDE..], &mut poses) {
        let (i, c) = (poses.len(), &data[poses.len() * POSE_STRIDE..]);
        let pose = Pose::from_wxyz([c[0], c[1], c[2]], [c[3], c[4], c[5], c[6]])
            .map_err(|e| e.within(&format!("{at}[{i}]")))?;
        poses.push(pose);
    }
    Ok(poses)
}

/// Appends the poses of `numbers` (the [`POSE_STRIDE`] layout, a whole number of poses) to
/// `out`, as [`Pose::from_wxyz`] makes them, up to the first invalid one; returns whether they
/// were all valid. (Out of line: one copy for every batch of poses from JavaScript.)
#[inline(never)]
pub(crate) fn push_valid_poses(numbers: &[f64], out: &mut Vec<Pose>) -> bool {
    let (before, count) = (out.len(), numbers.len() / POSE_STRIDE);
    out.extend(
        numbers
            .chunks_exact(POSE_STRIDE)
            .map_while(|c| Pose::from_valid_wxyz([c[0], c[1], c[2]], [c[3], c[4], c[5], c[6]])),
    );
    out.len() - before == count
}

/// Appends one kinematics sample in the [`KINEMATICS_STRIDE`] layout.
pub(crate) fn push_kinematics(out: &mut Vec<f64>, u: f64, k: &Kinematics) {
    out.push(u);
    for v in [
        k.position,
        k.velocity,
        k.acceleration,
        k.angular_velocity,
        k.angular_acceleration,
    ] {
        out.extend_from_slice(&v.to_array());
    }
}

/// The kinematics of one body point as a plain object.
pub(crate) fn kinematics_to_js(k: &Kinematics) -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Out {
        position: [f64; 3],
        velocity: [f64; 3],
        acceleration: [f64; 3],
        angular_velocity: [f64; 3],
        angular_acceleration: [f64; 3],
    }
    to_js(&Out {
        position: k.position.to_array(),
        velocity: k.velocity.to_array(),
        acceleration: k.acceleration.to_array(),
        angular_velocity: k.angular_velocity.to_array(),
        angular_acceleration: k.angular_acceleration.to_array(),
    })
}

/// The display parameters of a screw, as the `ScrewInfo` union of the TypeScript types.
#[derive(Serialize)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub(crate) enum ScrewInfo {
    /// The two poses coincide.
    Identity {
        /// Always 0.
        angle: f64,
        /// Always 0.
        slide: f64,
    },
    /// A pure translation.
    Translation {
        /// Unit direction.
        direction: [f64; 3],
        /// Always 0.
        angle: f64,
        /// Translation length.
        slide: f64,
    },
    /// A general screw.
    General {
        /// The paper's axis point `P` (at the height of the origins' midpoint).
        point: [f64; 3],
        /// The axis point closest to the world origin.
        foot: [f64; 3],
        /// Unit axis direction.
        direction: [f64; 3],
        /// Rotation angle in `(0, π]`.
        angle: f64,
        /// Slide along the axis.
        slide: f64,
        /// `slide / angle`.
        pitch: f64,
    },
}

impl From<crate::ScrewKind> for ScrewInfo {
    fn from(kind: crate::ScrewKind) -> Self {
        match kind {
            crate::ScrewKind::Identity => ScrewInfo::Identity {
                angle: 0.0,
                slide: 0.0,
            },
            crate::ScrewKind::Translation {
                direction,
                distance,
            } => ScrewInfo::Translation {
                direction: direction.to_array(),
                angle: 0.0,
                slide: distance,
            },
            crate::ScrewKind::General(p) => ScrewInfo::General {
                point: p.point.to_array(),
                foot: p.foot.to_array(),
                direction: p.axis.to_array(),
                angle: p.angle,
                slide: p.slide,
                pitch: p.pitch,
            },
        }
    }
}
