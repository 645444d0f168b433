//! The `Motion` JavaScript class: an editable motion document plus subdivision options, and the
//! smooth motion they define.
//!
//! A wrapper of the core's [`EditableMotion`], which the Python class wraps too: every mutator
//! converts its arguments and hands them to it, which validates the new state completely (poses,
//! options, the memory guard [`screwbender::MAX_REFINED_POSES`]) and only then stores it, so after
//! any thrown error the object keeps its previous state and keeps working. The refined motion is
//! computed lazily and cached until the next change.

use std::cell::RefCell;

use wasm_bindgen::prelude::*;

use super::convert::{
    self, check_index, count, document_from_js, document_to_js, f64_array, finite, is_absent,
    kinematics_to_js, point_from_js, pose_from_js, pose_to_js, poses_from_fn, poses_from_js_array,
    poses_to_array, poses_to_matrices, push_kinematics, string, to_js, write_f64_array, ScrewInfo,
    KINEMATICS_STRIDE,
};
use super::options::{self, default_subdivision};
use super::presets::find_preset;
use screwbender::frontend::EditableMotion;
use screwbender::{
    Error, ErrorKind, Motion, MotionDocument, Polyscrew, Pose, Rules, ScrewBender, Subdivision,
    MAX_REFINED_POSES,
};

/// A motion: control poses (a cycle or an open sequence) smoothed by screw subdivision.
///
/// Built from a motion document (`{closed?, name?, poses: [{origin, rotation} | {origin,
/// basis}]}`), a JSON text, a scene preset or a pose `Float64Array`. Parameters `u` are in
/// coarse units: control pose `i` sits at `u = i`. Bulk results are typed arrays (7 numbers per
/// pose: origin `x, y, z`, quaternion `w, x, y, z`; or 16 per column-major `f32` matrix).
/// Every method that takes input throws an `Error` naming the bad element and then leaves the
/// motion unchanged.
#[wasm_bindgen(js_name = Motion)]
#[derive(Debug)]
pub struct MotionHandle {
    // Exported methods take `&self` and convert their input before borrowing this cell; the
    // conversion reads plain-data copies (`convert::plain`), so user code (a throwing getter, a
    // proxy) runs only inside a caught call and no JS exception can cross a Rust frame, which
    // would skip the release of wasm-bindgen's borrow of the object or of this cell.
    inner: RefCell<EditableMotion>,
}

fn busy() -> JsError {
    JsError::new("Motion: re-entrant call (the motion is already in use)")
}

impl MotionHandle {
    fn from_state(doc: MotionDocument, subdivision: Subdivision) -> Result<MotionHandle, Error> {
        Ok(MotionHandle {
            inner: RefCell::new(EditableMotion::new(doc, subdivision)?),
        })
    }

    /// The document and subdivision options (for the other API modules: export, analysis).
    pub(crate) fn snapshot(&self) -> Result<(MotionDocument, Subdivision), JsError> {
        self.read(|m| (m.document().clone(), m.subdivision()))
    }

    /// Reads the motion without copying.
    fn read<R>(&self, f: impl FnOnce(&EditableMotion) -> R) -> Result<R, JsError> {
        Ok(f(&*self.inner.try_borrow().map_err(|_| busy())?))
    }

    /// Applies an edit of the core's (validated there; on error nothing changes).
    fn edit<R>(
        &self,
        change: impl FnOnce(&mut EditableMotion) -> Result<R, Error>,
    ) -> Result<R, JsError> {
        Ok(change(
            &mut *self.inner.try_borrow_mut().map_err(|_| busy())?,
        )?)
    }

    /// Runs `f` on the refined motion, subdividing first if needed. `f` must not call into
    /// JavaScript.
    pub(crate) fn with_refined<R>(&self, f: impl FnOnce(&ScrewBender) -> R) -> Result<R, JsError> {
        let mut inner = self.inner.try_borrow_mut().map_err(|_| busy())?;
        Ok(f(inner.refined()?))
    }
}

/// Uniform parameters as in [`Motion::sample`]: `[start, end)` for a cycle, `[start, end]`
/// inclusive for an open motion.
pub(crate) fn sample_parameters(
    domain: (f64, f64),
    closed: bool,
    count: usize,
) -> impl Iterator<Item = f64> {
    let (a, b) = domain;
    let denom = if closed {
        count as f64
    } else {
        count.saturating_sub(1).max(1) as f64
    };
    (0..count).map(move |k| a + (b - a) * k as f64 / denom)
}

#[wasm_bindgen(js_class = Motion)]
impl MotionHandle {
    /// A motion from a motion document object, validated exactly like the JSON form (errors name
    /// the element, e.g. `poses[3].rotation: zero quaternion`). `options` defaults to
    /// `{scheme: 'fourpoint', rules: 'direct', levels: 5}`.
    #[wasm_bindgen(constructor)]
    pub fn new(
        #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivisionOptions>")]
        options: JsValue,
    ) -> Result<MotionHandle, JsError> {
        let doc = document_from_js(&document)?;
        let subdivision = options::apply(default_subdivision(), &options)?;
        Ok(MotionHandle::from_state(doc, subdivision)?)
    }

    /// A motion from the text of a JSON motion document (the CLI's file format).
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(
        #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivisionOptions>")]
        options: JsValue,
    ) -> Result<MotionHandle, JsError> {
        let doc = MotionDocument::from_json(&string(&text, "text")?)?;
        let subdivision = options::apply(default_subdivision(), &options)?;
        Ok(MotionHandle::from_state(doc, subdivision)?)
    }

    /// A motion from a pose `Float64Array` (7 numbers per pose: origin `x, y, z`, quaternion
    /// `w, x, y, z`). `closed` defaults to `true`.
    #[wasm_bindgen(js_name = fromPoses)]
    pub fn from_poses(
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] poses: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "boolean")] closed: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Partial<SubdivisionOptions>")]
        options: JsValue,
    ) -> Result<MotionHandle, JsError> {
        let poses = poses_from_js_array(&poses, "poses")?;
        let closed = if is_absent(&closed) {
            true
        } else {
            convert::boolean(&closed, "closed")?
        };
        let subdivision = options::apply(default_subdivision(), &options)?;
        let doc = MotionDocument::new(poses, closed);
        Ok(MotionHandle::from_state(doc, subdivision)?)
    }

    /// The preset `id` (see `presets()`), with the preset's scheme and levels and the direct
    /// rules; the document's name is the preset id.
    #[wasm_bindgen(js_name = fromPreset)]
    pub fn from_preset(
        #[wasm_bindgen(unchecked_param_type = "PresetId")] id: JsValue,
    ) -> Result<MotionHandle, JsError> {
        Ok(MotionHandle::preset_named(&id, "preset")?)
    }

    /// Former name of `Motion.fromPreset`, kept for one release (its errors name `scene`).
    ///
    /// @deprecated Renamed to `Motion.fromPreset`.
    #[wasm_bindgen(js_name = fromScene)]
    pub fn from_scene(
        #[wasm_bindgen(unchecked_param_type = "PresetId")] id: JsValue,
    ) -> Result<MotionHandle, JsError> {
        Ok(MotionHandle::preset_named(&id, "scene")?)
    }

    // ---- the document ------------------------------------------------------------------------

    /// The motion document as JSON text (two-space indent, one pose per line; poses as
    /// `origin` + `rotation`).
    #[wasm_bindgen(js_name = toJson)]
    pub fn to_json(&self) -> Result<String, JsError> {
        self.read(|m| m.document().to_json())
    }

    /// The motion document as a plain object.
    #[wasm_bindgen(js_name = toDocument, unchecked_return_type = "MotionDocument")]
    pub fn to_document(&self) -> Result<JsValue, JsError> {
        document_to_js(&self.snapshot()?.0)
    }

    /// Replaces the document by the JSON text `text` (options are kept).
    #[wasm_bindgen(js_name = loadJson)]
    pub fn load_json(
        &self,
        #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    ) -> Result<(), JsError> {
        let doc = MotionDocument::from_json(&string(&text, "text")?)?;
        self.edit(|m| m.set_document(doc))
    }

    /// Replaces the document by a motion document object (options are kept).
    #[wasm_bindgen(js_name = loadDocument)]
    pub fn load_document(
        &self,
        #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
    ) -> Result<(), JsError> {
        let doc = document_from_js(&document)?;
        self.edit(|m| m.set_document(doc))
    }

    /// The document's display name, if any.
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> Result<Option<String>, JsError> {
        self.read(|m| m.document().name.clone())
    }

    /// Sets (a string) or clears (`undefined` / `null`) the display name.
    #[wasm_bindgen(js_name = setName)]
    pub fn set_name(
        &self,
        #[wasm_bindgen(unchecked_optional_param_type = "string | null")] name: JsValue,
    ) -> Result<(), JsError> {
        let name = if is_absent(&name) {
            None
        } else {
            Some(string(&name, "name")?)
        };
        self.edit(|m| m.set_name(name))
    }

    /// Whether the control poses form a cycle.
    #[wasm_bindgen(getter)]
    pub fn closed(&self) -> Result<bool, JsError> {
        self.read(|m| m.document().closed)
    }

    /// Makes the motion a cycle (`true`) or an open sequence (`false`).
    #[wasm_bindgen(js_name = setClosed)]
    pub fn set_closed(
        &self,
        #[wasm_bindgen(unchecked_param_type = "boolean")] closed: JsValue,
    ) -> Result<(), JsError> {
        let closed = convert::boolean(&closed, "closed")?;
        self.edit(|m| m.set_closed(closed))
    }

    /// The key times in seconds (`n` for an open motion, `n + 1` for a cycle: the last is when
    /// pose 0 is reached again), or `undefined` for the uniform timing (pose `i` at `i` s).
    #[wasm_bindgen(getter, unchecked_return_type = "Float64Array | undefined")]
    pub fn times(&self) -> Result<Option<Vec<f64>>, JsError> {
        self.read(|m| m.document().times.clone())
    }

    /// Sets the key times (strictly increasing, finite; `null` / `undefined`: uniform). Throws
    /// naming `times` (count) or `times[i]`, and then leaves the motion unchanged; given
    /// velocities must still keep the retiming monotone with the new times.
    #[wasm_bindgen(js_name = setTimes)]
    pub fn set_times(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[] | null")] times: JsValue,
    ) -> Result<(), JsError> {
        let times = if is_absent(&times) {
            None
        } else {
            Some(f64_array(&times, "times", MAX_REFINED_POSES)?)
        };
        self.edit(|m| m.set_times(times))
    }

    /// The key velocities `p'(T_i)` in poses per second, one per control pose (`null` where
    /// free), or `undefined` when all are free.
    #[wasm_bindgen(getter, unchecked_return_type = "(number | null)[] | undefined")]
    pub fn velocities(&self) -> Result<JsValue, JsError> {
        Ok(match self.read(|m| m.document().velocities.clone())? {
            Some(v) => v
                .iter()
                .map(|v| v.map_or(JsValue::NULL, JsValue::from_f64))
                .collect::<js_sys::Array>()
                .into(),
            None => JsValue::UNDEFINED,
        })
    }

    /// Sets the key velocities (one per control pose: a number ≥ 0 in poses per second, or
    /// `null` for a free slope; `null` / `undefined` for all free). Throws naming `velocities`
    /// (count) or `velocities[i]` (negative, not finite, or making time run backwards next to
    /// that key), and then leaves the motion unchanged.
    #[wasm_bindgen(js_name = setVelocities)]
    pub fn set_velocities(
        &self,
        #[wasm_bindgen(unchecked_param_type = "(number | null)[] | null")] velocities: JsValue,
    ) -> Result<(), JsError> {
        let velocities = if is_absent(&velocities) {
            None
        } else {
            let list = convert::plain(&velocities, "velocities")?;
            Some(convert::from_js::<Vec<Option<f64>>>(
                &list,
                "velocities",
                "velocity list (numbers or null)",
            )?)
        };
        self.edit(|m| m.set_velocities(velocities))
    }

    /// The number of control poses.
    #[wasm_bindgen(getter, js_name = poseCount)]
    pub fn pose_count(&self) -> Result<usize, JsError> {
        self.read(|m| m.document().poses.len())
    }

    /// Control pose `i` as `{origin, rotation}`.
    #[wasm_bindgen(unchecked_return_type = "Pose")]
    pub fn pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
    ) -> Result<JsValue, JsError> {
        let i = convert::number(&i, "index")?;
        let pose = self.read(|m| -> Result<Pose, Error> {
            let poses = &m.document().poses;
            Ok(poses[check_index(i, "index", poses.len())?])
        })??;
        pose_to_js(&pose)
    }

    /// All control poses, 7 numbers per pose (origin `x, y, z`, quaternion `w, x, y, z`).
    pub fn poses(&self) -> Result<Vec<f64>, JsError> {
        self.read(|m| poses_to_array(&m.document().poses))
    }

    /// Replaces control pose `i`.
    #[wasm_bindgen(js_name = setPose)]
    pub fn set_pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
        #[wasm_bindgen(unchecked_param_type = "PoseInput")] pose: JsValue,
    ) -> Result<(), JsError> {
        let i = convert::number(&i, "index")?;
        let pose = pose_from_js(&pose, "pose")?;
        // A drag calls this every frame: the core re-subdivides only the window the moved pose
        // influences (bit-identical to a rebuild, independent of the pose count).
        self.edit(|m| m.set_pose(check_index(i, "index", m.document().poses.len())?, pose))
    }

    /// Inserts a pose between control poses `i` and `i + 1` (the new pose gets index `i + 1`,
    /// which is returned). Without `pose`, inserts the screw midpoint `screw(P_i, ½, P_{i+1})`
    /// (for a cycle, `P_{n−1}`'s successor is `P_0`; an open motion needs an explicit pose after
    /// its last one).
    #[wasm_bindgen(js_name = insertPose)]
    pub fn insert_pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "PoseInput")] pose: JsValue,
    ) -> Result<usize, JsError> {
        let i = convert::number(&i, "index")?;
        let pose = if is_absent(&pose) {
            None
        } else {
            Some(pose_from_js(&pose, "pose")?)
        };
        self.edit(|m| {
            let n = m.document().poses.len();
            // Without a pose, the last pose of an open motion has no successor.
            let last = if pose.is_some() || m.document().closed {
                n
            } else {
                n - 1
            };
            m.insert_pose(check_index(i, "index", last)?, pose)
        })
    }

    /// Removes control pose `i` (a motion keeps at least 2 poses).
    #[wasm_bindgen(js_name = removePose)]
    pub fn remove_pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
    ) -> Result<(), JsError> {
        let i = convert::number(&i, "index")?;
        self.edit(|m| m.remove_pose(check_index(i, "index", m.document().poses.len())?))
    }

    // ---- options -----------------------------------------------------------------------------

    /// The subdivision options `{scheme, j, rules, levels}` (`j` is the J_s parameter of the
    /// scheme: 1 B-spline, 0 4-point, ½ Jarek).
    #[wasm_bindgen(unchecked_return_type = "SubdivisionOptions")]
    pub fn options(&self) -> Result<JsValue, JsError> {
        to_js(&options::to_output(&self.snapshot()?.1))
    }

    /// Where the current options give a poor result without an error, one sentence each
    /// naming the span (the split-then-tweak 4-point and Jarek rules across half a turn or
    /// more: docs/math/subdivision.md §4); empty when the result is fine.
    pub fn warnings(&self) -> Result<Vec<String>, JsError> {
        self.read(EditableMotion::warnings)
    }

    /// Changes several options at once (validated together: e.g. `{scheme: 'j', s: 0.3,
    /// rules: 'direct'}` from the split rules is fine; `j` is read as the deprecated name of
    /// `s`).
    #[wasm_bindgen(js_name = setOptions)]
    pub fn set_options(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
    ) -> Result<(), JsError> {
        let next = options::apply(self.snapshot()?.1, &options)?;
        self.edit(|m| m.set_subdivision(next))
    }

    /// The scheme name (`'j'` for the J_s family).
    #[wasm_bindgen(getter, unchecked_return_type = "SchemeName")]
    pub fn scheme(&self) -> Result<String, JsError> {
        self.read(|m| options::scheme_name(&m.subdivision().scheme).to_string())
    }

    /// Sets the scheme: `'bspline'`, `'fourpoint'`, `'jarek'`, or `'j'` (the J_s family with the
    /// current J_s parameter; see `setS`).
    #[wasm_bindgen(js_name = setScheme)]
    pub fn set_scheme(
        &self,
        #[wasm_bindgen(unchecked_param_type = "SchemeName")] name: JsValue,
    ) -> Result<(), JsError> {
        let name = string(&name, "scheme")?;
        self.edit(|m| {
            let mut next = m.subdivision();
            next.scheme = options::parse_scheme(&name, next.scheme.s())?;
            m.set_subdivision(next)
        })
    }

    /// The J_s parameter `s` of the current scheme (1 B-spline, 0 4-point, ½ Jarek).
    #[wasm_bindgen(getter)]
    pub fn s(&self) -> Result<f64, JsError> {
        self.read(|m| m.subdivision().scheme.s())
    }

    /// Deprecated name of the `s` getter.
    #[wasm_bindgen(getter)]
    pub fn j(&self) -> Result<f64, JsError> {
        self.s()
    }

    /// Switches to the J_s family with parameter `s`, from −4 to 4 ([`screwbender::MAX_J_PARAMETER`];
    /// needs the direct rules).
    #[wasm_bindgen(js_name = setS)]
    pub fn set_s(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] s: JsValue,
    ) -> Result<(), JsError> {
        self.set_j_s(&s, "s")
    }

    /// Deprecated name of `setS` (errors name `j`).
    #[wasm_bindgen(js_name = setJ)]
    pub fn set_j(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] s: JsValue,
    ) -> Result<(), JsError> {
        self.set_j_s(&s, "j")
    }

    /// The rule set: `'direct'` (revised paper) or `'split'` (first version).
    #[wasm_bindgen(getter, unchecked_return_type = "RulesName")]
    pub fn rules(&self) -> Result<String, JsError> {
        self.read(|m| options::rules_name(&m.subdivision().rules).to_string())
    }

    /// Sets the rule set (`'direct'` or `'split'`).
    #[wasm_bindgen(js_name = setRules)]
    pub fn set_rules(
        &self,
        #[wasm_bindgen(unchecked_param_type = "RulesName")] name: JsValue,
    ) -> Result<(), JsError> {
        let rules: Rules = string(&name, "rules")?.parse()?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.rules = rules;
                Ok(())
            })
        })
    }

    /// The number of subdivision levels.
    #[wasm_bindgen(getter)]
    pub fn levels(&self) -> Result<u32, JsError> {
        self.read(|m| m.subdivision().levels)
    }

    /// Sets the number of levels (a whole number ≥ 0). Checked at once against the memory guard
    /// (`limits().maxRefinedPoses`), so a too-large value throws here and is never stored.
    #[wasm_bindgen(js_name = setLevels)]
    pub fn set_levels(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] levels: JsValue,
    ) -> Result<(), JsError> {
        let levels = options::parse_levels(convert::number(&levels, "levels")?)?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.levels = levels;
                Ok(())
            })
        })
    }

    // ---- the smooth motion -------------------------------------------------------------------

    /// The number of refined poses (`n·2^levels` for a cycle, `(m−1)·2^levels + 1` open).
    #[wasm_bindgen(getter, js_name = refinedCount)]
    pub fn refined_count(&self) -> Result<usize, JsError> {
        Ok(self.read(EditableMotion::refined_count)??)
    }

    /// The parameter interval `[start, end]`: `[0, n]` for a cycle of `n` poses (periodic),
    /// `[0, m − 1]` for an open sequence.
    #[wasm_bindgen(unchecked_return_type = "[number, number]")]
    pub fn domain(&self) -> Result<JsValue, JsError> {
        let (a, b) = self.read(EditableMotion::domain)?;
        to_js(&[a, b])
    }

    /// Subdivides (if not done since the last change) and returns the refined poses, 7 numbers
    /// per pose. Refined pose `j` sits at `u = j / 2^levels`.
    pub fn subdivide(&self) -> Result<Vec<f64>, JsError> {
        self.with_refined(|m| poses_to_array(m.refined().poses()))
    }

    /// `subdivide()` into `out`, a `Float64Array` of exactly `7 · refinedCount` numbers, and
    /// returns `out`: a caller that keeps `out` from one call to the next needs no fresh array
    /// per call (in Chromium a fresh array of 2048 poses cost about a quarter of the call).
    /// Throws naming `out` if it is not such an array, and then writes nothing.
    #[wasm_bindgen(js_name = subdivideInto, unchecked_return_type = "Float64Array")]
    pub fn subdivide_into(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array")] out: JsValue,
    ) -> Result<JsValue, JsError> {
        write_f64_array(&out, "out", &self.subdivide()?)?;
        Ok(out)
    }

    /// The refined poses as column-major 4×4 `f32` matrices (16 numbers per pose).
    #[wasm_bindgen(js_name = refinedMatrices)]
    pub fn refined_matrices(&self) -> Result<Vec<f32>, JsError> {
        self.with_refined(|m| poses_to_matrices(m.refined().poses()))
    }

    /// The pose at parameter `u` (cycles wrap `u`; open motions extrapolate their end screws).
    #[wasm_bindgen(js_name = poseAt, unchecked_return_type = "Pose")]
    pub fn pose_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] u: JsValue,
    ) -> Result<JsValue, JsError> {
        let u = finite(&u, "u")?;
        pose_to_js(&self.with_refined(|m| m.pose_at(u))?)
    }

    /// The poses at the parameters `us`, 7 numbers per pose.
    #[wasm_bindgen(js_name = posesAt)]
    pub fn poses_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] us: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let us = batch(&us, "us")?;
        self.with_refined(|m| poses_from_fn(us.len(), |k| m.pose_at(us[k])))
    }

    /// `count` poses at uniformly spaced parameters (`[0, n)` for a cycle, `[0, m − 1]`
    /// inclusive for an open motion), 7 numbers per pose.
    pub fn sample(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let count = self::count(&count, "count", MAX_REFINED_POSES)?;
        self.with_refined(|m| poses_to_array(&m.sample(count)))
    }

    /// Like `sample`, as column-major 4×4 `f32` matrices (16 numbers per pose).
    #[wasm_bindgen(js_name = sampleMatrices)]
    pub fn sample_matrices(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
    ) -> Result<Vec<f32>, JsError> {
        let count = self::count(&count, "count", MAX_REFINED_POSES)?;
        self.with_refined(|m| poses_to_matrices(&m.sample(count)))
    }

    /// Closed-form kinematics at `u` of the body point with local coordinates `local` (default
    /// the local origin): position, velocity, acceleration, angular velocity and angular
    /// acceleration, world frame, per coarse parameter unit. At a refined knot the value of the
    /// span that starts there is returned.
    #[wasm_bindgen(js_name = kinematicsAt, unchecked_return_type = "Kinematics")]
    pub fn kinematics_at(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] u: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Vec3")] local: JsValue,
    ) -> Result<JsValue, JsError> {
        let u = finite(&u, "u")?;
        let local = point_from_js(&local, "local")?;
        let k = self.with_refined(|m| m.refined().point_kinematics(u, local))?;
        kinematics_to_js(&k)
    }

    /// Kinematics of the body point `local` at the `count` parameters of `sample(count)`,
    /// 16 numbers per sample: `u`, position, velocity, acceleration, angular velocity, angular
    /// acceleration (`x, y, z` each).
    #[wasm_bindgen(js_name = sampleKinematics)]
    pub fn sample_kinematics(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] count: JsValue,
        #[wasm_bindgen(unchecked_optional_param_type = "Vec3")] local: JsValue,
    ) -> Result<Vec<f64>, JsError> {
        let count = self::count(&count, "count", MAX_REFINED_POSES)?;
        let local = point_from_js(&local, "local")?;
        let (domain, closed) = self.read(|m| (m.domain(), m.document().closed))?;
        self.with_refined(|m| {
            let mut out = Vec::with_capacity(count * KINEMATICS_STRIDE);
            for u in sample_parameters(domain, closed, count) {
                push_kinematics(&mut out, u, &m.refined().point_kinematics(u, local));
            }
            out
        })
    }

    /// The screw of every control span (`i → i + 1`, and `n − 1 → 0` for a cycle) for display:
    /// kind, axis point and direction, angle, slide, pitch.
    #[wasm_bindgen(js_name = spanScrews, unchecked_return_type = "ScrewInfo[]")]
    pub fn span_screws(&self) -> Result<JsValue, JsError> {
        let (doc, _) = self.snapshot()?;
        let control = Polyscrew::new(doc.poses, doc.closed)?;
        let infos: Vec<ScrewInfo> = control
            .spans()
            .iter()
            .map(|s| s.parameters().into())
            .collect();
        to_js(&infos)
    }
}

/// A batch of finite parameters, at most [`MAX_REFINED_POSES`] long.
pub(crate) fn batch(value: &JsValue, at: &str) -> Result<Vec<f64>, Error> {
    let values = f64_array(value, at, MAX_REFINED_POSES)?;
    if let Some(k) = values.iter().position(|v| !v.is_finite()) {
        return Err(Error::new(format!("{at}[{k}]"), ErrorKind::NonFinite));
    }
    Ok(values)
}

impl MotionHandle {
    /// The preset whose id is the string `id`; errors name `path`.
    fn preset_named(id: &JsValue, path: &'static str) -> Result<MotionHandle, Error> {
        let preset = find_preset(&string(id, path)?, path)?;
        let mut doc = MotionDocument::new(preset.poses, preset.closed);
        doc.name = Some(preset.id.to_string());
        let subdivision = Subdivision::new(preset.scheme, Rules::Direct, preset.levels);
        MotionHandle::from_state(doc, subdivision)
    }
    /// Switches to the J_s family with parameter `s` given under the name `at` (`setS` and
    /// its deprecated alias `setJ`).
    fn set_j_s(&self, s: &JsValue, at: &str) -> Result<(), JsError> {
        let s = options::check_s(finite(s, at)?, at)?;
        self.edit(|m| {
            m.update(|_, sub| {
                sub.scheme = screwbender::Scheme::J(s);
                Ok(())
            })
        })
    }
}
