//! The `Motion` JavaScript class: an editable motion document plus subdivision options, and the
//! smooth motion they define.
//!
//! Every mutator builds the new state, validates it completely (poses, options, the memory guard
//! [`screwbender::MAX_REFINED_POSES`]) and only then stores it, so after any thrown error the object
//! keeps its previous state and keeps working. The refined motion is computed lazily and cached
//! until the next change.

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
use screwbender::{
    screw, Error, ErrorKind, Motion, MotionDocument, Polyscrew, Pose, Rules, ScrewBender,
    Subdivision, SubdivisionBuffers, MAX_REFINED_POSES,
};

/// What a `Motion` stores: always valid (see [`State::check`]).
#[derive(Clone, Debug)]
struct State {
    doc: MotionDocument,
    subdivision: Subdivision,
}

impl State {
    /// Everything that can make a state unusable ([`MotionDocument::check_with`]).
    fn check(&self) -> Result<(), Error> {
        self.doc.check_with(&self.subdivision)
    }

    /// The parameter interval `[0, n)` (closed) or `[0, m − 1]` (open).
    fn domain(&self) -> (f64, f64) {
        let n = self.doc.poses.len();
        let spans = if self.doc.closed { n } else { n - 1 };
        (0.0, spans as f64)
    }
}

#[derive(Debug)]
struct Inner {
    state: State,
    /// The subdivided motion of `state`, computed on first use.
    refined: Option<ScrewBender>,
    /// The last subdivided motion after a change made it stale: the next subdivision is
    /// rebuilt in its memory ([`ScrewBender::rebuild`]) instead of fresh memory.
    spare: Option<ScrewBender>,
    /// The subdivision's working sequences, kept from one subdivision to the next.
    buffers: SubdivisionBuffers<Pose>,
}

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
    inner: RefCell<Inner>,
}

fn busy() -> JsError {
    JsError::new("Motion: re-entrant call (the motion is already in use)")
}

impl MotionHandle {
    fn from_state(state: State) -> Result<MotionHandle, Error> {
        state.check()?;
        Ok(MotionHandle {
            inner: RefCell::new(Inner {
                state,
                refined: None,
                spare: None,
                buffers: SubdivisionBuffers::new(),
            }),
        })
    }

    /// A copy of the current state.
    fn state(&self) -> Result<State, JsError> {
        Ok(self.inner.try_borrow().map_err(|_| busy())?.state.clone())
    }

    /// The document and subdivision options (for the other API modules: export, analysis).
    pub(crate) fn snapshot(&self) -> Result<(MotionDocument, Subdivision), JsError> {
        self.read(|s| (s.doc.clone(), s.subdivision))
    }

    /// Reads the state without copying.
    fn read<R>(&self, f: impl FnOnce(&State) -> R) -> Result<R, JsError> {
        Ok(f(&self.inner.try_borrow().map_err(|_| busy())?.state))
    }

    /// Applies `change` to a copy of the state, validates the copy and only then stores it.
    fn update(&self, change: impl FnOnce(&mut State) -> Result<(), Error>) -> Result<(), JsError> {
        let mut inner = self.inner.try_borrow_mut().map_err(|_| busy())?;
        let mut next = inner.state.clone();
        change(&mut next)?;
        next.check()?;
        inner.state = next;
        if let Some(stale) = inner.refined.take() {
            inner.spare = Some(stale);
        }
        Ok(())
    }

    /// Runs `f` on the refined motion, subdividing first if needed. `f` must not call into
    /// JavaScript.
    pub(crate) fn with_refined<R>(&self, f: impl FnOnce(&ScrewBender) -> R) -> Result<R, JsError> {
        let mut inner = self.inner.try_borrow_mut().map_err(|_| busy())?;
        if inner.refined.is_none() {
            let Inner {
                state: s,
                refined,
                spare,
                buffers,
            } = &mut *inner;
            // The same motion as `ScrewBender::new` bit for bit; in the memory of the last one
            // when there is one (a subdivision into fresh memory pays a page fault per 4 KB).
            let motion = match spare.take() {
                Some(mut motion) => {
                    motion.rebuild(&s.doc.poses, s.doc.closed, s.subdivision, buffers)?;
                    motion
                }
                None => ScrewBender::new(s.doc.poses.clone(), s.doc.closed, s.subdivision)?,
            };
            *refined = Some(motion);
        }
        match &inner.refined {
            Some(motion) => Ok(f(motion)),
            None => Err(busy()),
        }
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
        Ok(MotionHandle::from_state(State { doc, subdivision })?)
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
        Ok(MotionHandle::from_state(State { doc, subdivision })?)
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
        Ok(MotionHandle::from_state(State { doc, subdivision })?)
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
        self.read(|s| s.doc.to_json())
    }

    /// The motion document as a plain object.
    #[wasm_bindgen(js_name = toDocument, unchecked_return_type = "MotionDocument")]
    pub fn to_document(&self) -> Result<JsValue, JsError> {
        document_to_js(&self.state()?.doc)
    }

    /// Replaces the document by the JSON text `text` (options are kept).
    #[wasm_bindgen(js_name = loadJson)]
    pub fn load_json(
        &self,
        #[wasm_bindgen(unchecked_param_type = "string")] text: JsValue,
    ) -> Result<(), JsError> {
        let doc = MotionDocument::from_json(&string(&text, "text")?)?;
        self.update(|s| {
            s.doc = doc;
            Ok(())
        })
    }

    /// Replaces the document by a motion document object (options are kept).
    #[wasm_bindgen(js_name = loadDocument)]
    pub fn load_document(
        &self,
        #[wasm_bindgen(unchecked_param_type = "MotionDocumentInput")] document: JsValue,
    ) -> Result<(), JsError> {
        let doc = document_from_js(&document)?;
        self.update(|s| {
            s.doc = doc;
            Ok(())
        })
    }

    /// The document's display name, if any.
    #[wasm_bindgen(getter)]
    pub fn name(&self) -> Result<Option<String>, JsError> {
        self.read(|s| s.doc.name.clone())
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
        self.update(|s| {
            s.doc.name = name;
            Ok(())
        })
    }

    /// Whether the control poses form a cycle.
    #[wasm_bindgen(getter)]
    pub fn closed(&self) -> Result<bool, JsError> {
        self.read(|s| s.doc.closed)
    }

    /// Makes the motion a cycle (`true`) or an open sequence (`false`).
    #[wasm_bindgen(js_name = setClosed)]
    pub fn set_closed(
        &self,
        #[wasm_bindgen(unchecked_param_type = "boolean")] closed: JsValue,
    ) -> Result<(), JsError> {
        let closed = convert::boolean(&closed, "closed")?;
        self.update(|s| {
            s.doc.set_closed(closed);
            Ok(())
        })
    }

    /// The key times in seconds (`n` for an open motion, `n + 1` for a cycle: the last is when
    /// pose 0 is reached again), or `undefined` for the uniform timing (pose `i` at `i` s).
    #[wasm_bindgen(getter, unchecked_return_type = "Float64Array | undefined")]
    pub fn times(&self) -> Result<Option<Vec<f64>>, JsError> {
        self.read(|s| s.doc.times.clone())
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
        self.update(|s| s.doc.set_timing(times, s.doc.velocities.clone()))
    }

    /// The key velocities `p'(T_i)` in poses per second, one per control pose (`null` where
    /// free), or `undefined` when all are free.
    #[wasm_bindgen(getter, unchecked_return_type = "(number | null)[] | undefined")]
    pub fn velocities(&self) -> Result<JsValue, JsError> {
        Ok(match self.read(|s| s.doc.velocities.clone())? {
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
        self.update(|s| s.doc.set_timing(s.doc.times.clone(), velocities))
    }

    /// The number of control poses.
    #[wasm_bindgen(getter, js_name = poseCount)]
    pub fn pose_count(&self) -> Result<usize, JsError> {
        self.read(|s| s.doc.poses.len())
    }

    /// Control pose `i` as `{origin, rotation}`.
    #[wasm_bindgen(unchecked_return_type = "Pose")]
    pub fn pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
    ) -> Result<JsValue, JsError> {
        let i = convert::number(&i, "index")?;
        let pose = self.read(|s| -> Result<Pose, Error> {
            Ok(s.doc.poses[check_index(i, "index", s.doc.poses.len())?])
        })??;
        pose_to_js(&pose)
    }

    /// All control poses, 7 numbers per pose (origin `x, y, z`, quaternion `w, x, y, z`).
    pub fn poses(&self) -> Result<Vec<f64>, JsError> {
        self.read(|s| poses_to_array(&s.doc.poses))
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
        let mut inner = self.inner.try_borrow_mut().map_err(|_| busy())?;
        let i = check_index(i, "index", inner.state.doc.poses.len())?;
        let mut next = inner.state.clone();
        next.doc.poses[i] = pose;
        next.check()?;
        // A drag calls this every frame: keep the refined motion and re-subdivide only the window
        // the moved pose influences (bit-identical to a rebuild, independent of the pose count).
        let Inner {
            refined, buffers, ..
        } = &mut *inner;
        if let Some(motion) = refined.as_mut() {
            motion.set_control_pose_with(i, pose, buffers)?;
        }
        inner.state = next;
        Ok(())
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
        let mut inserted = 0;
        self.update(|s| {
            let n = s.doc.poses.len();
            let i = match pose {
                Some(_) => check_index(i, "index", n)?,
                // Without a pose, the last pose of an open motion has no successor.
                None => check_index(i, "index", if s.doc.closed { n } else { n - 1 })?,
            };
            let new = match pose {
                Some(p) => p,
                None => screw(&s.doc.poses[i], 0.5, &s.doc.poses[(i + 1) % n]),
            };
            s.doc.insert_pose(i + 1, new);
            inserted = i + 1;
            Ok(())
        })?;
        Ok(inserted)
    }

    /// Removes control pose `i` (a motion keeps at least 2 poses).
    #[wasm_bindgen(js_name = removePose)]
    pub fn remove_pose(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] i: JsValue,
    ) -> Result<(), JsError> {
        let i = convert::number(&i, "index")?;
        self.update(|s| {
            let i = check_index(i, "index", s.doc.poses.len())?;
            s.doc.remove_pose(i);
            Ok(())
        })
    }

    // ---- options -----------------------------------------------------------------------------

    /// The subdivision options `{scheme, j, rules, levels}` (`j` is the J_s parameter of the
    /// scheme: 1 B-spline, 0 4-point, ½ Jarek).
    #[wasm_bindgen(unchecked_return_type = "SubdivisionOptions")]
    pub fn options(&self) -> Result<JsValue, JsError> {
        to_js(&options::to_output(&self.state()?.subdivision))
    }

    /// Where the current options give a poor result without an error, one sentence each
    /// naming the span (the split-then-tweak 4-point and Jarek rules across half a turn or
    /// more: docs/math/subdivision.md §4); empty when the result is fine.
    pub fn warnings(&self) -> Result<Vec<String>, JsError> {
        self.read(|s| {
            s.subdivision
                .warnings(&s.doc.poses, s.doc.closed)
                .iter()
                .map(ToString::to_string)
                .collect()
        })
    }

    /// Changes several options at once (validated together: e.g. `{scheme: 'j', s: 0.3,
    /// rules: 'direct'}` from the split rules is fine; `j` is read as the deprecated name of
    /// `s`).
    #[wasm_bindgen(js_name = setOptions)]
    pub fn set_options(
        &self,
        #[wasm_bindgen(unchecked_param_type = "Partial<SubdivisionOptions>")] options: JsValue,
    ) -> Result<(), JsError> {
        let current = self.state()?.subdivision;
        let next = options::apply(current, &options)?;
        self.update(|s| {
            s.subdivision = next;
            Ok(())
        })
    }

    /// The scheme name (`'j'` for the J_s family).
    #[wasm_bindgen(getter, unchecked_return_type = "SchemeName")]
    pub fn scheme(&self) -> Result<String, JsError> {
        self.read(|s| options::scheme_name(&s.subdivision.scheme).to_string())
    }

    /// Sets the scheme: `'bspline'`, `'fourpoint'`, `'jarek'`, or `'j'` (the J_s family with the
    /// current J_s parameter; see `setS`).
    #[wasm_bindgen(js_name = setScheme)]
    pub fn set_scheme(
        &self,
        #[wasm_bindgen(unchecked_param_type = "SchemeName")] name: JsValue,
    ) -> Result<(), JsError> {
        let name = string(&name, "scheme")?;
        self.update(|s| {
            s.subdivision.scheme = options::parse_scheme(&name, s.subdivision.scheme.s())?;
            Ok(())
        })
    }

    /// The J_s parameter `s` of the current scheme (1 B-spline, 0 4-point, ½ Jarek).
    #[wasm_bindgen(getter)]
    pub fn s(&self) -> Result<f64, JsError> {
        self.read(|s| s.subdivision.scheme.s())
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
        self.read(|s| options::rules_name(&s.subdivision.rules).to_string())
    }

    /// Sets the rule set (`'direct'` or `'split'`).
    #[wasm_bindgen(js_name = setRules)]
    pub fn set_rules(
        &self,
        #[wasm_bindgen(unchecked_param_type = "RulesName")] name: JsValue,
    ) -> Result<(), JsError> {
        let rules: Rules = string(&name, "rules")?.parse()?;
        self.update(|s| {
            s.subdivision.rules = rules;
            Ok(())
        })
    }

    /// The number of subdivision levels.
    #[wasm_bindgen(getter)]
    pub fn levels(&self) -> Result<u32, JsError> {
        self.read(|s| s.subdivision.levels)
    }

    /// Sets the number of levels (a whole number ≥ 0). Checked at once against the memory guard
    /// (`limits().maxRefinedPoses`), so a too-large value throws here and is never stored.
    #[wasm_bindgen(js_name = setLevels)]
    pub fn set_levels(
        &self,
        #[wasm_bindgen(unchecked_param_type = "number")] levels: JsValue,
    ) -> Result<(), JsError> {
        let levels = options::parse_levels(convert::number(&levels, "levels")?)?;
        self.update(|s| {
            s.subdivision.levels = levels;
            Ok(())
        })
    }

    // ---- the smooth motion -------------------------------------------------------------------

    /// The number of refined poses (`n·2^levels` for a cycle, `(m−1)·2^levels + 1` open).
    #[wasm_bindgen(getter, js_name = refinedCount)]
    pub fn refined_count(&self) -> Result<usize, JsError> {
        Ok(self.read(|s| s.subdivision.output_len(s.doc.poses.len(), s.doc.closed))??)
    }

    /// The parameter interval `[start, end]`: `[0, n]` for a cycle of `n` poses (periodic),
    /// `[0, m − 1]` for an open sequence.
    #[wasm_bindgen(unchecked_return_type = "[number, number]")]
    pub fn domain(&self) -> Result<JsValue, JsError> {
        let (a, b) = self.read(State::domain)?;
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
        let (domain, closed) = self.read(|s| (s.domain(), s.doc.closed))?;
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
        let state = self.state()?;
        let control = Polyscrew::new(state.doc.poses, state.doc.closed)?;
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
        MotionHandle::from_state(State { doc, subdivision })
    }
    /// Switches to the J_s family with parameter `s` given under the name `at` (`setS` and
    /// its deprecated alias `setJ`).
    fn set_j_s(&self, s: &JsValue, at: &str) -> Result<(), JsError> {
        let s = options::check_s(finite(s, at)?, at)?;
        self.update(|st| {
            st.subdivision.scheme = screwbender::Scheme::J(s);
            Ok(())
        })
    }
}
