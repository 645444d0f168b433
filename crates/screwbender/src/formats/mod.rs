//! Files in and out: the JSON motion document, CSV, glTF 2.0 (motions with the feature `gltf`,
//! meshes with `json`), and the
//! sampling that turns a motion into keyframes within a tolerance.
//!
//! From the bottom up: `keyframes.rs` (what every keyframe import shares), `document.rs`,
//! `sampling.rs`, `tracks.rs` (a document sampled in time as the exports do; keyframe tracks for
//! three.js), `csv.rs`, `gltf/` (the GLB container, export, import, meshes), `reduce.rs` (fewer
//! control poses from dense imported ones) and `interop.rs`, which picks a format for the CLI and
//! the JS API. Object meshes are read here too: `obj.rs` (Wavefront OBJ), `gltf/mesh.rs` and
//! `base64.rs` (the `data:` URIs of embedded glTF buffers); the shapes themselves are in
//! `presets::mesh`.

#[cfg(feature = "json")]
pub(crate) mod base64;
pub(crate) mod csv;
pub(crate) mod document;
pub(crate) mod gltf;
#[cfg(feature = "gltf")]
pub(crate) mod interop;
pub(crate) mod keyframes;
pub(crate) mod obj;
pub(crate) mod reduce;
pub(crate) mod sampling;
pub(crate) mod tracks;
