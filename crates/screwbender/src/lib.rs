//! # ScrewBender
//!
//! Smooth rigid-body motions from a few control poses, by subdividing a *polyscrew* — the cycle
//! (or sequence) of poses joined by screw motions — with Split&Tweak rules on screws
//! (A. Powell and J. Rossignac, *ScrewBender: Polyscrew Subdivision for Smoothing Interpolating
//! Motions*). Cubic B-spline, 4-point and Jarek schemes, both rule sets of the paper's two
//! versions, and the J_s family that contains them.
//!
//! ```
//! use screwbender::{presets, Closure, Motion, Rules, Scheme, ScrewBender, Subdivision};
//!
//! let preset = presets::preset("circle4").unwrap();
//! let smooth = ScrewBender::new(
//!     preset.poses.clone(),
//!     Closure::Closed,
//!     Subdivision::new(Scheme::FourPoint, Rules::Direct, 5),
//! )?;
//! // 4 control poses × 2⁵ = 128 refined poses; the screw schemes keep the circle exactly.
//! assert_eq!(smooth.refined().poses().len(), 128);
//! for u in [0.3, 1.7, 2.25, 3.9] {
//!     let radius = smooth.pose_at(u).origin.length();
//!     assert!((radius - 3.0).abs() < 1e-12);
//! }
//! // 4-point interpolates: control pose 1 sits at u = 1.
//! assert!(smooth.pose_at(1.0).approx_eq(&preset.poses[1], 1e-12));
//! # Ok::<(), screwbender::Error>(())
//! ```
//!
//! ## Conventions
//!
//! Quaternions are Hamilton and written **`[w, x, y, z]`, scalar first** in every file and API
//! ([`quat_from_wxyz`] / [`quat_to_wxyz`] convert glam's storage); angles in radians; frames
//! right-handed, a pose maps local to world (`p_world = O + R p_local`); **`screw(a, t, b)`** is
//! *start, fraction, end*; control pose `i` sits at `u = i`. `q` and `−q` are the same rotation,
//! so poses are compared with [`Pose::approx_eq`] / [`Pose::distance`]. The full statement, with
//! the slot convention, the input tolerances and a glossary, is the repository's
//! `docs/math/conventions.md`.
//!
//! ## Where each rule comes from
//!
//! The repository's own notes explain every rule in `docs/math/` (`screw.md`, `point-rules.md`,
//! `subdivision.md`, `open-sequences.md`, …); a "§" in a comment of this crate points there.
//!
//! * The screw between two poses: paper §3 (after Rossignac & Kim); computed here by the closed
//!   form of the SE(3) log/exp ([`Screw`]), with the paper's construction in [`PaperScrew`]
//!   (signed angle and the `O₀ + O₁` misprint corrected).
//! * Point rules (cubic B-spline, Dyn–Levin–Gregory 4-point, Jarek): paper §2 / Figs. 2–3; on
//!   points through the same generic code ([`Blend`]).
//! * Direct rules [`Rules::Direct`]: revised paper (V2) §4, "ScrewBender".
//! * Split-then-tweak rules [`Rules::SplitThenTweak`]: first version (V1) §4, with the 4-point and
//!   Jarek new-pose tweaks' argument order corrected (`screw(m, 5/4, L_c)`, not
//!   `screw(L_c, 5/4, m)`).
//! * The J_s family [`Scheme::J`]: Rossignac & Schaefer's J-splines, applied to screws.
//! * Open sequences: paper §4 ("extend with dummy screws … remove 3 or 5 spans"), made precise by
//!   extrapolating the end screws (docs/math/open-sequences.md).
//!
//! ## Many screws at once
//!
//! [`Blend::blends`], [`Blend::midpoints`] and [`Blend::sample_cycle`] evaluate batches; for
//! poses they run independent screws side by side on SIMD lanes: natively eight or four at a
//! time where x86-64 has AVX-512 or AVX2 (detected at run time) and two elsewhere; on wasm32
//! four at a time (in two SIMD registers) when built with `simd128` (as this repository's
//! `.cargo/config.toml` builds it), one at a time without. The results are identical bit for
//! bit to one-at-a-time calls, whatever the processor. Subdivision steps are written as such
//! batches.
//!
//! ## Layout
//!
//! The vocabulary types sit at the top ([`Pose`], [`Motion`], [`Polyscrew`], [`ScrewBender`],
//! [`Timing`], [`Error`]); below them, folders by kind: `lanes` (SIMD lanes and their
//! backends), `screw` (construction, kernel, batches), `subdivision` (rules, schemes, blends,
//! the teaching variants), `formats` (JSON, CSV, glTF, sampling), [`presets`] (the named motions, meshes,
//! morph) and [`methods`] (the comparison methods). Every public item is re-exported here, flat.
//! This crate has no WebAssembly or GPU code: the JavaScript API and the renderer are the crate
//! `screwbender-web`, the command-line tool `screwbender-cli`.
//!
//! ## Features
//!
//! * `json` (default): [`MotionDocument::from_json`] / [`MotionDocument::to_json`], metrics as
//!   JSON and meshes from glTF ([`mesh::Mesh::from_gltf`]) (serde_json).
//! * `gltf` (default, implies `json`): glTF 2.0 export and import of motions
//!   ([`export_motion`], [`import_motion_file`], [`GltfAsset`]) (gltf-json).
//!
//! ## Robustness
//!
//! Input from users goes through validating constructors ([`Pose::from_wxyz`],
//! [`Pose::from_basis`], [`MotionDocument::from_json`]) that return an [`Error`] naming the bad
//! element. The math itself never fails: every screw is finite for finite input, including
//! identical poses, pure translations, angles down to the last bit and half turns (with a
//! deterministic tie-break, see [`Screw`]).

mod closure;
mod error;
mod fit;
mod formats;
pub mod frontend;
mod lanes;
pub mod methods;
mod motion;
mod polyscrew;
mod pose;
pub mod presets;
mod screw;
mod screwbender;
mod subdivision;
mod timing;

/// Triangle meshes of the objects: [`mesh::Mesh`] and the shapes (`presets/mesh.rs`), and the
/// limits of the files it is read from (`formats/obj.rs`, `formats/gltf/mesh.rs`).
pub mod mesh {
    #[cfg(feature = "json")]
    pub use crate::formats::gltf::mesh::MAX_GLTF_MESH_BYTES;
    pub use crate::formats::obj::{MAX_OBJ_BYTES, MAX_OBJ_TRIANGLES};
    pub use crate::presets::mesh::*;
}

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
struct ReadmeDoctests;

pub use closure::Closure;
pub use error::{Error, ErrorKind};
pub use fit::{
    fit_poses, measure_fit, ControlCount, FitMethod, FitOptions, FitReport, FittedMotion,
    RobustLoss, DEFAULT_FIT_ITERATIONS, FIT_LEVELS, MAX_FIT_CONTROLS, ROBUST_SCALE_FACTOR,
};
pub use formats::csv::{
    control_poses_csv, parse_csv_poses, poses_csv, trajectory_csv, write_poses_csv,
    write_trajectory_csv, MAX_CSV_BYTES, POSE_COLUMNS,
};
pub use formats::document::{MotionDocument, RawDocument, RawPose, MAX_DOCUMENT_BYTES};
#[cfg(feature = "gltf")]
pub use formats::gltf::{
    import_glb, import_gltf, GltfAsset, GltfMotion, NodeSelection, CONTROL_NODE_NAME, EXTRAS_KEY,
    GENERATOR, MAX_GLTF_BYTES, OBJECT_NODE_NAME, PLACEHOLDER_HALF_EXTENTS,
};
pub use formats::gltf::{is_glb, split_glb};
#[cfg(feature = "gltf")]
pub use formats::interop::{
    export_motion, import_motion_file, mesh_radius, ExportFormat, ExportSamples, ExportSettings,
    ExportedMotion, ImportKind, PresetObject,
};
pub use formats::keyframes::REPEAT_TOLERANCE;
pub use formats::reduce::{reduce_poses, Reduction, MANY_POSES};
pub use formats::sampling::{
    check_timing, check_tolerance, interpolate_linear, linear_deviation, sample_fixed_rate,
    sample_motion, sample_polyscrew, sample_polyscrew_within, sample_screwbender, trajectory,
    Deviation, Sample, DEFAULT_TOLERANCE, MAX_SAMPLES, MAX_SAMPLE_ANGLE, MIN_TOLERANCE,
};
pub use formats::tracks::{
    consistent_rotations, keyframe_tracks, sample_document, DocumentSamples, KeyframeTracks,
    SamplingMode,
};
pub use motion::{Kinematics, Motion};
pub use polyscrew::Polyscrew;
pub use pose::{
    quat_from_wxyz, quat_to_wxyz, Pose, MAX_COORDINATE, ORTHONORMAL_TOLERANCE,
    UNIT_QUATERNION_TOLERANCE,
};
pub use presets::morph::{
    morph_mesh, morph_weights, BlendMesh, PipMorph, CREASE_COSINE, MORPH_RESOLUTION,
};
pub use presets::pieces::{
    ConvexPiece, PipShape, CONVEX_TOLERANCE, MAX_PIECES, MAX_PIECE_VERTICES,
};
pub use screw::{
    screw, screw_paper, BasisPair, PaperScrew, Screw, ScrewKind, ScrewParameters, ANGLE_EPSILON,
    HALF_TURN_EPSILON, LENGTH_EPSILON, PAPER_CROSS_EPSILON,
};
pub use screwbender::ScrewBender;

/// Former name of [`presets`], kept for one release.
#[deprecated(
    since = "0.2.0",
    note = "renamed to `presets` (`presets::preset`, `presets::all`)"
)]
pub mod scenes {
    pub use crate::presets::{
        mesh, object_shape, PolygonPreset as PolygonScene, Preset as Scene, Shape,
    };

    /// Former name of [`crate::presets::preset`].
    pub fn scene(id: &str) -> Option<Scene> {
        crate::presets::preset(id)
    }

    /// Former name of [`crate::presets::all`].
    pub fn scenes() -> Vec<Scene> {
        crate::presets::all()
    }

    /// Former name of [`crate::presets::polygon_presets`].
    pub fn polygon_scenes() -> Vec<PolygonScene> {
        crate::presets::polygon_presets()
    }
}
pub use subdivision::blend::Blend;
pub use subdivision::componentwise::{
    compare_frames, move_local_origin, subdivide_decoupled, DecoupledPose, FrameComparison,
};
pub use subdivision::scheme::{Rules, Scheme, MAX_J_PARAMETER};
pub use subdivision::split_tweak::{split, split_tweak_levels, split_tweak_step, SplitTweakStep};
pub use subdivision::warnings::{Warning, HALF_TURN_TOLERANCE};
pub use subdivision::{Subdivision, SubdivisionBuffers, MAX_REFINED_POSES};
pub use timing::Timing;
