//! glTF 2.0: the GLB container (always, so meshes and imports can recognise it), and with the
//! feature `gltf` the motion export, the control-pose import and meshes of user objects.

#[cfg(feature = "gltf")]
pub(crate) mod export;
pub(crate) mod glb;
#[cfg(feature = "gltf")]
pub(crate) mod import;
#[cfg(feature = "gltf")]
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
