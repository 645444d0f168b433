//! Exports for the playground's teaching views (screw axes, split/tweak step-through, polygon
//! subdivision, frame independence): thin, validating wrappers around
//! [`screwbender::split_tweak_step`], [`screwbender::compare_frames`], [`screwbender::subdivide_decoupled`] and
//! the point version of [`screwbender::Subdivision`].
//!
//! Layouts: poses 7 `f64` each (see [`super::convert`]); planar points 2 `f64` each (`x, y`);
//! 3-D points 3 `f64` each (`x, y, z`). Every function validates all of its input first and
//! throws an `Error` naming the bad element.

use glam::{DVec2, DVec3};
use js_sys::{Float64Array, Object, Reflect, Uint32Array, Uint8Array};
use serde::Serialize;
use wasm_bindgen::prelude::*;

use super::convert::{
    boolean, count, f64_array, is_absent, point_from_js, poses_from_js_array, poses_to_array,
    to_js, ScrewInfo,
};
use super::options::{self, default_subdivision};
use screwbender::presets;
use screwbender::{
    compare_frames, split_tweak_levels, subdivide_decoupled, Error, ErrorKind, Polyscrew,
    Subdivision, MAX_REFINED_POSES,
};

/// Numbers per planar point in a polygon `Float64Array`: `x, y`.
pub const POINT2_STRIDE: usize = 2;

/// Numbers per 3-D point: `x, y, z`.
pub const POINT3_STRIDE: usize = 3;

#[wasm_bindgen(typescript_custom_section)]
const TS_TEACHING: &'static str = r#"
/** A planar polygon preset (docs/math/presets.md §2.4). */
export interface PolygonPresetInfo {
  id: 'polygon_l' | 'polygon_star' | 'polygon_split_tweak';
  figure: string;
  /** Vertices `[x, y]`, a cycle. */
  points: [number, number][];
}
/** @deprecated Renamed to `PolygonPresetInfo`. */
export type PolygonSceneInfo = PolygonPresetInfo;

/** One subdivision step taken apart (see `splitTweakStep`). Poses: 7 numbers each. */
export interface SplitTweakStep {
  /** The step's input, `n` poses (a cycle; open motions include their dummy poses). */
  input: Float64Array;
  /** The split sequence `Z`, `2n` poses: `Z[2i] = P[i]`, `Z[2i+1]` = screw midpoint. */
  split: Float64Array;
  /** The step's output `Q`, `2n` poses (one subdivision step of `input`). */
  output: Float64Array;
  /** 1 where the scheme's tweak moves slot `j`, else 0 (`2n` entries). */
  tweaked: Uint8Array;
  /**
   * The slot of each helper pose. Split-then-tweak rules: one helper per tweaked slot (the pose
   * the tweak moves towards or away from); direct rules: two per moved slot (the inner screws of
   * the rule, whose midpoint is the output).
   */
  helperSlots: Uint32Array;
  /** The helper poses, in the order of `helperSlots` (7 numbers each). */
  helpers: Float64Array;
  /** `[start, length]` of the part of `output` that belongs to the motion. */
  kept: [number, number];
}

/** Trajectories of body points with the local origin moved (see `compareFrames`). */
export interface FrameComparison {
  /** Screw scheme: per body point, `length` positions (3 numbers each), point after point. */
  screw: Float64Array;
  /** Decoupled scheme, same layout. */
  decoupled: Float64Array;
  /** Positions per trajectory. */
  length: number;
  /** Largest change of a screw trajectory point against the unmoved origin. */
  screwDeviation: number;
  /** The same for the decoupled scheme. */
  decoupledDeviation: number;
}
"#;

/// Sets `key` on a fresh plain object (the keys are ours, so this cannot fail in practice).
fn set(obj: &Object, key: &str, value: &JsValue) -> Result<(), JsError> {
    Reflect::set(obj, &JsValue::from_str(key), value)
        .map(|_| ())
        .map_err(|_| JsError::new(&format!("cannot set {key}")))
}

/// An optional `closed` flag (default `true`).
fn closed_flag(value: &JsValue) -> Result<bool, Error> {
    if is_absent(value) {
        Ok(true)
    } else {
        boolean(value, "closed")
    }
}

/// Poses in the 7-per-pose layout, validated.
fn poses_arg(value: &JsValue) -> Result<Vec<screwbender::Pose>, Error> {
    poses_from_js_array(value, "poses")
}

/// Planar points `x, y` (finite, whole pairs), at most [`MAX_REFINED_POSES`].
fn points2_arg(value: &JsValue, at: &str) -> Result<Vec<DVec2>, Error> {
    let data = f64_array(value, at, MAX_REFINED_POSES * POINT2_STRIDE)?;
    if data.len() % POINT2_STRIDE != 0 {
        return Err(Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: format!("length {}", data.len()),
                expected: "an even number of values (x, y per point)".into(),
            },
        ));
    }
    if let Some(k) = data.iter().position(|v| !v.is_finite()) {
        return Err(Error::new(
            format!("{at}[{}]", k / POINT2_STRIDE),
            ErrorKind::NonFinite,
        ));
    }
    Ok(data
        .chunks_exact(POINT2_STRIDE)
        .map(|c| DVec2::new(c[0], c[1]))
        .collect())
}

/// 3-D points `x, y, z` (finite, whole triples), at most 64.
fn points3_arg(value: &JsValue, at: &str) -> Result<Vec<DVec3>, Error> {
    const MAX_POINTS: usize = 64;
    let data = f64_array(value, at, MAX_POINTS * POINT3_STRIDE)?;
    if data.len() % POINT3_STRIDE != 0 {
        return Err(Error::new(
            at.to_string(),
            ErrorKind::OutOfRange {
                value: format!("length {}", data.len()),
                expected: "a multiple of 3 (x, y, z per point)".into(),
            },
        ));
    }
    if let Some(k) = data.iter().position(|v| !v.is_finite()) {
        return Err(Error::new(
            format!("{at}[{}]", k / POINT3_STRIDE),
            ErrorKind::NonFinite,
        ));
    }
    Ok(data
        .chunks_exact(POINT3_STRIDE)
        .map(|c| DVec3::new(c[0], c[1], c[2]))
        .collect())
}

/// The planar polygon presets of A4 (paper Figs. 2–3): `polygon_l`, `polygon_star`,
/// `polygon_split_tweak`.
#[wasm_bindgen(js_name = polygonPresets, unchecked_return_type = "PolygonPresetInfo[]")]
pub fn polygon_presets() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Info {
        id: &'static str,
        figure: &'static str,
        points: Vec<[f64; 2]>,
    }
    let list: Vec<Info> = presets::polygon_presets()
        .into_iter()
        .map(|p| Info {
            id: p.id,
            figure: p.figure,
            points: p.vertices.iter().map(|v| v.to_array()).collect(),
        })
        .collect();
    to_js(&list)
}

/// Former name of `polygonPresets()`, kept for one release.
///
/// @deprecated Renamed to `polygonPresets()`.
#[wasm_bindgen(js_name = polygonScenes, unchecked_return_type = "PolygonPresetInfo[]")]
pub fn polygon_scenes_alias() -> Result<JsValue, JsError> {
    polygon_presets()
}

/// Subdivides a planar polygon with the point versions of the rules (docs/math/point-rules.md; the same code as the
/// pose rules with `blend(a, t, b) = a + t (b − a)`).
///
/// `points`: `x, y` per vertex (at least 2 vertices); `closed` (default `true`): a cycle, else an
/// open polyline (extended at its ends as in docs/math/open-sequences.md); `options`: `Partial<SubdivisionOptions>`
/// (default 4-point, direct rules, 5 levels). Returns `x, y` per refined vertex.
#[wasm_bindgen(js_name = subdividePolygon)]
pub fn subdivide_polygon(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
) -> Result<Vec<f64>, JsError> {
    let points = points2_arg(&points, "points")?;
    let closed = closed_flag(&closed)?;
    let sub = options::apply(default_subdivision(), &options)?;
    let refined = sub.apply(&points, closed)?;
    Ok(refined.iter().flat_map(|p| [p.x, p.y]).collect())
}

/// The screw of every span of a pose sequence (`i → i + 1`, and the closing span of a cycle), for
/// display — like `Motion.spanScrews()` but for any sequence, e.g. a refined level.
#[wasm_bindgen(js_name = spanScrewsOf, unchecked_return_type = "ScrewInfo[]")]
pub fn span_screws_of(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
) -> Result<JsValue, JsError> {
    let poses = poses_arg(&poses)?;
    let closed = closed_flag(&closed)?;
    let screws = Polyscrew::new(poses, closed)?;
    let infos: Vec<ScrewInfo> = screws
        .spans()
        .iter()
        .map(|s| s.parameters().into())
        .collect();
    to_js(&infos)
}

/// Step `level` of the subdivision of `poses` (level `level` → `level + 1`; `0` refines the
/// control poses), with the split sequence and the tweak shown separately (paper Figs. 3–4,
/// docs/math/subdivision.md). `options` as for `Motion` (its `levels` is ignored); `closed` defaults to `true`.
/// Open sequences are refined on their extended cycle (docs/math/open-sequences.md): `kept` says which output poses
/// belong to the motion.
#[wasm_bindgen(js_name = splitTweakStep, unchecked_return_type = "SplitTweakStep")]
pub fn split_tweak_step_js(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
    #[wasm_bindgen(unchecked_param_type = "boolean")] closed: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
    #[wasm_bindgen(unchecked_param_type = "number")] level: JsValue,
) -> Result<JsValue, JsError> {
    let poses = poses_arg(&poses)?;
    let closed = closed_flag(&closed)?;
    let level = count(&level, "level", 30)?;
    let sub = Subdivision {
        levels: level as u32 + 1,
        ..options::apply(default_subdivision(), &options)?
    };
    let steps = split_tweak_levels(&poses, closed, sub)?;
    let step = steps.last().ok_or_else(|| JsError::new("no step"))?;
    let obj = Object::new();
    let poses_js =
        |p: &[screwbender::Pose]| JsValue::from(Float64Array::from(&poses_to_array(p)[..]));
    set(&obj, "input", &poses_js(&step.input))?;
    set(&obj, "split", &poses_js(&step.split))?;
    set(&obj, "output", &poses_js(&step.output))?;
    let tweaked: Vec<u8> = step.tweaked.iter().map(|t| u8::from(*t)).collect();
    set(&obj, "tweaked", &Uint8Array::from(&tweaked[..]).into())?;
    let slots: Vec<u32> = step.helpers.iter().map(|(j, _)| *j as u32).collect();
    set(&obj, "helperSlots", &Uint32Array::from(&slots[..]).into())?;
    let helpers: Vec<screwbender::Pose> = step.helpers.iter().map(|(_, h)| *h).collect();
    set(&obj, "helpers", &poses_js(&helpers))?;
    set(&obj, "kept", &to_js(&[step.kept.0, step.kept.1])?)?;
    Ok(obj.into())
}

/// Subdivides `poses` with origin and rotation decoupled (origins by the point rule, rotations by
/// the same rules on rotation-only poses; [`screwbender::DecoupledPose`]). Same arguments as
/// `subdividePolygon` but 7 numbers per pose; returns 7 numbers per refined pose.
#[wasm_bindgen(js_name = subdivideDecoupled)]
pub fn subdivide_decoupled_js(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
) -> Result<Vec<f64>, JsError> {
    let poses = poses_arg(&poses)?;
    let closed = closed_flag(&closed)?;
    let sub = options::apply(default_subdivision(), &options)?;
    Ok(poses_to_array(&subdivide_decoupled(&poses, closed, &sub)?))
}

/// Frame (in)dependence (docs/math/properties.md §1, paper Fig. 9 V1 / Fig. 8 V2): re-expresses `poses` with the
/// local origin at the body point `offset` (`[x, y, z]`, local coordinates), subdivides by screws
/// and decoupled, and returns the trajectories of the body `points` (3 numbers each, given in the
/// original local frame, at most 64) and how far they moved compared with `offset = 0`.
#[wasm_bindgen(js_name = compareFrames, unchecked_return_type = "FrameComparison")]
pub fn compare_frames_js(
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
    #[wasm_bindgen(unchecked_param_type = "boolean")] closed: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Vec3")] offset: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] points: JsValue,
) -> Result<JsValue, JsError> {
    let poses = poses_arg(&poses)?;
    let closed = closed_flag(&closed)?;
    let sub = options::apply(default_subdivision(), &options)?;
    if is_absent(&offset) {
        return Err(Error::new(
            "offset",
            ErrorKind::Parse {
                message: "expected [x, y, z]".into(),
            },
        )
        .into());
    }
    let c = point_from_js(&offset, "offset")?;
    let points = points3_arg(&points, "points")?;
    let cmp = compare_frames(&poses, closed, &sub, c, &points)?;
    let flat = |v: &[DVec3]| -> JsValue {
        let data: Vec<f64> = v.iter().flat_map(|p| p.to_array()).collect();
        Float64Array::from(&data[..]).into()
    };
    let obj = Object::new();
    set(&obj, "screw", &flat(&cmp.screw))?;
    set(&obj, "decoupled", &flat(&cmp.decoupled))?;
    set(&obj, "length", &JsValue::from_f64(cmp.len as f64))?;
    set(
        &obj,
        "screwDeviation",
        &JsValue::from_f64(cmp.screw_deviation),
    )?;
    set(
        &obj,
        "decoupledDeviation",
        &JsValue::from_f64(cmp.decoupled_deviation),
    )?;
    Ok(obj.into())
}
