//! The scene presets ([`screwbender::scenes`]) for JavaScript: a list to show, and lookup by id.

use std::sync::OnceLock;

use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::convert::to_js;
use super::options::scheme_name;
use screwbender::scenes::{self, Scene, Shape};
use screwbender::{Error, ErrorKind};

/// One scene preset as listed by `scenes()`.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct SceneInfo {
    id: &'static str,
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

/// The comma-separated scene ids, for error messages.
fn scene_ids() -> &'static str {
    static IDS: OnceLock<String> = OnceLock::new();
    IDS.get_or_init(|| {
        scenes::scenes()
            .iter()
            .map(|s| s.id)
            .collect::<Vec<_>>()
            .join(", ")
    })
}

/// The scene with this id, or an `UnknownValue` error listing the ids.
pub(crate) fn find_scene(id: &str) -> Result<Scene, Error> {
    scenes::scene(id).ok_or_else(|| {
        Error::new(
            "scene",
            ErrorKind::UnknownValue {
                value: id.to_string(),
                expected: scene_ids(),
            },
        )
    })
}

/// The scene presets reproducing the paper's figures (id, label, figure, description, closed,
/// default scheme and levels, pose count, the object to draw). Load one with
/// `Motion.fromScene(id)`.
#[wasm_bindgen(unchecked_return_type = "SceneInfo[]")]
pub fn scenes() -> Result<JsValue, JsError> {
    let list: Vec<SceneInfo> = scenes::scenes()
        .into_iter()
        .map(|s| SceneInfo {
            id: s.id,
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
