//! Lists of numbers from JavaScript (`Float64Array` or arrays of numbers), read in chunks through
//! the typed arrays' internal slots.

use std::ops::Range;

use js_sys::{Array, ArrayBuffer, Float64Array, Object, Reflect};
use screwbender::{Error, ErrorKind};
use wasm_bindgen::{JsCast, JsValue};

use super::values::{
    expected, plain, set_from_typed_array, set_typed_array_from, unreadable, Float64View,
};

/// A list of at most `max` numbers from a `Float64Array` or a plain array (non-numbers become
/// NaN and are caught by the caller's finiteness checks). The length is checked before copying.
pub(crate) fn f64_array(value: &JsValue, at: &str, max: usize) -> Result<Vec<f64>, Error> {
    let mut out = Vec::new();
    read_f64_array(value, at, max, &mut out)?;
    Ok(out)
}

/// [`f64_array`] into `out`, whose length becomes that of the list (its earlier contents are
/// overwritten, not cleared first).
pub(crate) fn read_f64_array(
    value: &JsValue,
    at: &str,
    max: usize,
    out: &mut Vec<f64>,
) -> Result<(), Error> {
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

pub(crate) enum NumberSource {
    /// The buffer and the byte offset of a `Float64Array`.
    View(JsValue, f64),
    /// The numbers of a plain array.
    Read(Vec<f64>),
}

impl<'a> NumberList<'a> {
    /// The list of `value` (named `at` in errors), of at most `max` numbers.
    pub(crate) fn from_js(value: &JsValue, at: &'a str, max: usize) -> Result<Self, Error> {
        let too_long = |len: usize| {
            Error::new(
                at.to_string(),
                ErrorKind::OutOfRange {
                    value: format!("length {len}"),
                    expected: format!("at most {max} numbers per call"),
                },
            )
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

/// Copies `numbers` into the caller's `Float64Array` `target` (named `at` in errors), which must
/// have exactly their length: the output of a bulk function written into memory the caller
/// keeps. A fresh array per call costs its allocation and first touch, a sizeable part of a
/// `subdivide()` call, which filling a kept one avoids (docs/speed/code-notes.md).
///
/// Its length, buffer and offset are read through internal slots (no user code runs); a
/// detached buffer reads as length 0 and is refused like any other wrong length.
pub(crate) fn write_f64_array(target: &JsValue, at: &str, numbers: &[f64]) -> Result<(), Error> {
    let slot = |k| typed_array_slot(target, k).map_err(|e| unreadable(at, &e));
    let number = |v: JsValue| v.as_f64().unwrap_or(-1.0);
    if !(ArrayBuffer::is_view(target)
        && target.is_instance_of::<Float64Array>()
        && number(slot(LENGTH)?) == numbers.len() as f64)
    {
        let what = format!("a Float64Array of length {}", numbers.len());
        return Err(expected(at, &what, target));
    }
    Float64View::new(
        &slot(BUFFER)?,
        number(slot(BYTE_OFFSET)?),
        numbers.len() as f64,
    )
    .and_then(|view| set_typed_array_from(&view, numbers))
    .map_err(|e| unreadable(at, &e))
}

/// The intrinsic getters of typed arrays read by [`typed_array_slot`], in this order.
pub(crate) const TYPED_ARRAY_SLOTS: [&str; 3] = ["length", "buffer", "byteOffset"];

pub(crate) const LENGTH: usize = 0;

pub(crate) const BUFFER: usize = 1;

pub(crate) const BYTE_OFFSET: usize = 2;

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
/// code). Out of line: its thread-local's initialiser was copied into every caller.
#[inline(never)]
pub(crate) fn typed_array_slot(view: &JsValue, k: usize) -> Result<JsValue, JsValue> {
    TYPED_ARRAY_GETTERS.with(|getters| match &getters[k] {
        Some(getter) => getter.call0(view),
        None => Err(JsValue::from_str("typed arrays have no such getter")),
    })
}
