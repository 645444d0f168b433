//! TypeScript definitions of the plain objects the JS API takes and returns, emitted into the
//! generated `.d.ts` and referenced from the exports through `unchecked_param_type` /
//! `unchecked_return_type`.
//!
//! The values themselves are built by `convert/` (pose and document objects, `ScrewInfo`),
//! `options.rs` (`SubdivisionOptions`) and `presets.rs` (`PresetInfo`, `Shape`); nothing ties
//! the two at compile time, so `tests/js/api.test.mjs` checks the shapes at run time.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
/** A 3-vector `[x, y, z]`. */
export type Vec3 = [number, number, number];

/** A unit quaternion `[w, x, y, z]`, scalar first (Hamilton convention). */
export type Quat = [number, number, number, number];

/**
 * A rigid pose as returned by the API: `p_world = origin + R p_local`, with `R` the rotation of
 * the unit quaternion `rotation`.
 */
export interface Pose {
  origin: Vec3;
  rotation: Quat;
}

/**
 * A pose as accepted by the API: the origin (coordinates within ±1e100) and either a unit
 * quaternion `[w, x, y, z]` (norm within 1e-3 of 1; normalised) or the basis vectors `I, J, K`
 * (the columns of the rotation matrix; orthonormal within 1e-4 and right-handed).
 */
export type PoseInput =
  | { origin: Vec3; rotation: Quat; basis?: undefined }
  | { origin: Vec3; basis: [Vec3, Vec3, Vec3]; rotation?: undefined };

/** A motion document as accepted by the API (the JSON file format). `closed` defaults to true. */
export interface MotionDocumentInput {
  name?: string;
  closed?: boolean;
  /** When each control pose is reached, in seconds, strictly increasing (n times for an open motion, n + 1 for a cycle: the last is pose 0 again); default 1 s per span from 0. */
  times?: number[];
  /** The rate du/dt at each key in poses per second (one per control pose, >= 0, `null` or `undefined` where free, so that `toDocument()`'s output is accepted back); the retiming is refused where a velocity makes time run backwards. */
  velocities?: (number | null | undefined)[];
  poses: PoseInput[];
}

/** A motion document as returned by the API (every pose as origin + rotation). */
export interface MotionDocument {
  name?: string;
  closed: boolean;
  /** Key times in seconds (present only when set). */
  times?: number[];
  /** Key velocities in poses per second, `null` (in JSON text) or `undefined` (in this object) where free; present only when set. */
  velocities?: (number | null | undefined)[];
  poses: Pose[];
}

/** Subdivision schemes; `'j'` is the J_s family (parameter `s`: 1 B-spline, 0 4-point, 0.5 Jarek). */
export type SchemeName = 'bspline' | 'fourpoint' | 'jarek' | 'j';

/** Rule sets: `'direct'` (revised paper, V2) or `'split'` (split-then-tweak, first version V1). */
export type RulesName = 'direct' | 'split';

/** The subdivision options of a `Motion`. */
export interface SubdivisionOptions {
  scheme: SchemeName;
  /** The J_s parameter `s` (used by scheme `'j'`; for the named schemes their own value), from -4 to 4. */
  s: number;
  /** @deprecated The former name of `s`: still read by `setOptions` (an error if it disagrees with `s`), never returned by `options()`. */
  j?: number;
  rules: RulesName;
  /** Subdivision levels, a whole number >= 0 (limited by `limits().maxRefinedPoses`). */
  levels: number;
}

/** Kinematics of one body point (world frame, per coarse parameter unit). */
export interface Kinematics {
  position: Vec3;
  velocity: Vec3;
  acceleration: Vec3;
  angularVelocity: Vec3;
  angularAcceleration: Vec3;
}

/** The display parameters of a screw motion. Angles in radians. */
export type ScrewInfo =
  | { kind: 'identity'; angle: 0; slide: 0 }
  | { kind: 'translation'; direction: Vec3; angle: 0; slide: number }
  | {
      kind: 'general';
      /** The paper's axis point P (on the axis, at the height of the two origins' midpoint). */
      point: Vec3;
      /** The axis point closest to the world origin. */
      foot: Vec3;
      /** Unit axis direction. */
      direction: Vec3;
      /** Rotation angle in (0, pi], right-hand rule about `direction`. */
      angle: number;
      /** Translation along the axis. */
      slide: number;
      /** `slide / angle`. */
      pitch: number;
    };

/** Ids of the presets (see `presets()`). */
export type PresetId =
  | 'l_cycle_parallel'
  | 'l_cycle_rotated'
  | 'l_cycle_edit'
  | 'pendulum'
  | 'spinning_block'
  | 'cylinder5'
  | 'pip_morph5'
  | 'circle4'
  | 'bunny6'
  | 'helix_open'
  | 'triangle7'
  | 'rb_sphere7'
  | 'rb_ibeam7'
  | 'rb_molecule4';

/** The object drawn at each pose of a preset (scene units, local frame). */
export type Shape =
  | { kind: 'bar'; length: number; section: number }
  | { kind: 'block'; size: Vec3; base: boolean }
  | { kind: 'cylinder'; radius: number; height: number }
  | { kind: 'cone'; radius: number; height: number }
  | { kind: 'sphere'; radius: number }
  | { kind: 'starPrism'; outer: number; inner: number; thickness: number }
  | { kind: 'pendulum'; rod: number; bob: number }
  | { kind: 'wedge'; size: Vec3 }
  | { kind: 'triangle'; x: Vec3; y: Vec3; thickness: number }
  | { kind: 'iBeam'; flange: Vec3; web: number; webSection: [number, number] }
  | { kind: 'molecule'; ring: number; atom: number };

/** A preset as listed by `presets()`. */
export interface PresetInfo {
  id: PresetId;
  /** The preset's name in words, e.g. `L cycle, rotated poses`. */
  name: string;
  /** Copies of the object the strobe draws when the preset loads (fewer for bulky objects). */
  strobe: number;
  /** The control pose selected when the preset loads (absent: none). */
  selected?: number;
  /** The body points (local coordinates) whose trajectories a figure draws: the object's origin and a characteristic far point. */
  bodyPoints: Vec3[];
  label: string;
  figure: string;
  description: string;
  closed: boolean;
  scheme: SchemeName;
  levels: number;
  poseCount: number;
  shape: Shape;
  /** One shape per control pose for the morph scene, else empty. */
  morphShapes: Shape[];
}

/** @deprecated Renamed to `PresetId`. */
export type SceneId = PresetId;
/** @deprecated Renamed to `PresetInfo`. */
export type SceneInfo = PresetInfo;

/** Size limits of the API. */
export interface Limits {
  /** Most refined poses a motion may have (the memory guard; more throws). */
  maxRefinedPoses: number;
  /** Most subdivision levels any front end accepts (0 to this): one level more never fits `maxRefinedPoses`, whatever the poses. */
  maxLevels: number;
  /** Subdivision levels of a new motion when the options do not say. */
  defaultLevels: number;
  /** Most values per bulk call (`screwPoses`, `screwPairs`, `posesAt`, `sample`, ...). */
  maxBatch: number;
  /** Largest JSON motion document accepted, in bytes. */
  maxDocumentBytes: number;
  /** Numbers per pose in pose arrays: origin x, y, z, quaternion w, x, y, z. */
  poseStride: 7;
  /** Numbers per pose in matrix arrays: a column-major 4x4 matrix. */
  matrixStride: 16;
  /** Numbers per sample of `sampleKinematics`. */
  kinematicsStride: 16;
}
"#;
