//! The presets ([`screwbender::presets`]) for JavaScript: a list to show, and lookup by id.

use std::sync::OnceLock;

use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::convert::to_js;
use super::options::scheme_name;
use screwbender::presets::{self, Preset, Shape};
use screwbender::{Error, ErrorKind};

/// One preset as listed by `presets()`.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct PresetInfo {
    id: &'static str,
    /// The name in words ([`presets::display`]).
    name: &'static str,
    /// Copies of the object the strobe draws when the preset loads.
    strobe: u32,
    /// The control pose selected when it loads, if any.
    selected: Option<usize>,
    /// The body points whose trajectories a figure draws ([`presets::body_points`]).
    body_points: Vec<[f64; 3]>,
    label: &'static str,
    figure: &'static str,
    description: &'static str,
    closed: bool,
    scheme: &'static str,
    levels: u32,
    pose_count: usize,
    shape: Shape,
    morph_shapes: Vec<Shape>,
}

/// The comma-separated preset ids, for error messages.
fn preset_ids() -> &'static str {
    static IDS: OnceLock<String> = OnceLock::new();
    IDS.get_or_init(|| {
        presets::all()
            .iter()
            .map(|s| s.id)
            .collect::<Vec<_>>()
            .join(", ")
    })
}

/// The preset with this id, or an `UnknownValue` error at `path` listing the ids.
pub(crate) fn find_preset(id: &str, path: &'static str) -> Result<Preset, Error> {
    presets::preset(id).ok_or_else(|| {
        Error::new(
            path,
            ErrorKind::UnknownValue {
                value: id.to_string(),
                expected: preset_ids(),
            },
        )
    })
}

/// The presets reproducing the papers' figures (id, name, label, figure, description, closed,
/// default scheme and levels, pose count, the object to draw, how the page shows it: strobe
/// count and the pose selected on load). Load one with
/// `Motion.fromPreset(id)`.
#[wasm_bindgen(unchecked_return_type = "PresetInfo[]")]
pub fn presets() -> Result<JsValue, JsError> {
    let list: Vec<PresetInfo> = presets::all()
        .into_iter()
        .map(|s| PresetInfo {
            id: s.id,
            name: presets::display(s.id).name,
            strobe: presets::display(s.id).strobe,
            selected: presets::display(s.id).selected,
            body_points: presets::body_points(&s.shape),
            label: s.label,
            figure: s.figure,
            description: s.description,
            closed: s.closed,
            scheme: scheme_name(&s.scheme),
            levels: s.levels,
            pose_count: s.poses.len(),
            shape: s.shape,
            morph_shapes: s.morph_shapes,
        })
        .collect();
    to_js(&list)
}

/// The body points (local coordinates) whose trajectories a figure draws for the named object
/// `object` (`bar`, `block`, `cylinder`, `cone`, `sphere`, `star`, `pendulum`, `wedge`), as
/// `presets()` gives them for a preset's own object; `undefined` for another name.
#[wasm_bindgen(js_name = objectBodyPoints, unchecked_return_type = "Vec3[] | undefined")]
pub fn object_body_points(
    #[wasm_bindgen(unchecked_param_type = "string")] object: JsValue,
) -> Result<JsValue, JsError> {
    match object
        .as_string()
        .and_then(|o| presets::object_body_points(&o))
    {
        Some(points) => to_js(&points),
        None => Ok(JsValue::UNDEFINED),
    }
}

/// Former name of `presets()`, kept for one release.
///
/// @deprecated Renamed to `presets()`.
#[wasm_bindgen(js_name = scenes, unchecked_return_type = "PresetInfo[]")]
pub fn scenes_alias() -> Result<JsValue, JsError> {
    presets()
}
