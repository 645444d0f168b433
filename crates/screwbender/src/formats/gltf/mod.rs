//! glTF 2.0: the GLB container (always, so meshes and imports can recognise it), meshes of user
//! objects with the feature `json` (they read the JSON chunk as plain JSON: a renderer module
//! draws a user's glTF object without gltf-json's document model), and with the feature `gltf`
//! the motion export and the control-pose import.

#[cfg(feature = "gltf")]
pub(crate) mod export;
pub(crate) mod glb;
#[cfg(feature = "gltf")]
pub(crate) mod import;
#[cfg(feature = "json")]
pub(crate) mod mesh;
#[cfg(feature = "gltf")]
pub(crate) mod names;

#[cfg(feature = "gltf")]
pub use export::{GltfAsset, GltfMotion, GENERATOR, OBJECT_NODE_NAME, PLACEHOLDER_HALF_EXTENTS};
pub use glb::{is_glb, split_glb};
#[cfg(feature = "gltf")]
pub use import::{import_glb, import_gltf, NodeSelection, MAX_GLTF_BYTES};
#[cfg(feature = "gltf")]
pub use names::{CONTROL_NODE_NAME, EXTRAS_KEY};
