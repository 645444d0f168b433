//! The serde bridge: JavaScript values to and from Rust types, with the element path of a bad
//! value in the error, and checks of an object's keys against a type's fields.

use js_sys::{Array, Object, Reflect};
use screwbender::{Error, ErrorKind};
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::{JsCast, JsError, JsValue};

use super::values::{is_absent, js_message, type_name};

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
        Error::new(
            if path == "." { String::new() } else { path },
            ErrorKind::Parse {
                message: format!("invalid {what}: {message}"),
            },
        )
        .within(at)
    })
}

/// Serialises a value to plain JavaScript objects and arrays.
pub(crate) fn to_js<T: Serialize + ?Sized>(value: &T) -> Result<JsValue, JsError> {
    // Structs with flattened fields (a comparison row's converged metrics) serialize as maps:
    // as plain objects, they read like every other struct.
    value
        .serialize(&serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true))
        .map_err(|e| JsError::new(&js_message(&JsValue::from(e))))
}

// ---- strictness that serde-wasm-bindgen lacks -------------------------------------------------
//
// serde-wasm-bindgen reads only the fields a struct names (so `#[serde(deny_unknown_fields)]`
// never fires) and does not reject arrays longer than a fixed-size array. The JSON parser does
// both; these checks make a JS object fail exactly where its JSON text would.

/// A deserializer that answers every request with an error, except that a struct request
/// reports the struct's field names: serde's own list, in declaration order.
pub(crate) struct FieldsProbe;

#[derive(Debug)]
pub(crate) enum ProbeError {
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

pub(crate) fn get(object: &JsValue, key: &str, at: &str) -> Result<JsValue, Error> {
    Reflect::get(object, &JsValue::from_str(key)).map_err(|e| {
        Error::new(
            at.to_string(),
            ErrorKind::Parse {
                message: js_message(&e),
            },
        )
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
            return Err(Error::new(
                at.to_string(),
                ErrorKind::Parse {
                    message: format!("invalid {what}: {message}"),
                },
            ));
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
        Err(Error::new(
            at.to_string(),
            ErrorKind::Parse {
                message: format!(
                    "invalid {what}: expected an object {shape}, got {}",
                    type_name(value)
                ),
            },
        ))
    }
}

/// Rejects an array-like `value` whose length is not exactly `len` (shorter ones were already
/// rejected by serde).
pub(crate) fn check_len(value: &JsValue, len: usize, at: &str, what: &str) -> Result<(), Error> {
    if is_absent(value) || !value.is_object() {
        return Ok(());
    }
    let found = get(value, "length", at)?.as_f64().unwrap_or(len as f64);
    if found != len as f64 {
        return Err(Error::new(
            at.to_string(),
            ErrorKind::Parse {
                message: format!(
                    "invalid {what}: invalid length {found}, expected an array of length {len}"
                ),
            },
        ));
    }
    Ok(())
}

/// `parent.field`, or `field` at the top level.
pub(crate) fn join(parent: &str, field: &str) -> String {
    if parent.is_empty() {
        field.to_string()
    } else {
        format!("{parent}.{field}")
    }
}
