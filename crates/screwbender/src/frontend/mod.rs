//! What every front end shares: the page and its element (through the wasm API), the npm module,
//! the command line and the Python package each only convert their own types to and from these,
//! so that they resolve options, name things and word their errors the same way.
//!
//! * [`options`]: subdivision options (`scheme`, `s`, `rules`, `levels`) with their ids,
//!   aliases, ranges and defaults;
//! * [`editable`]: the editable motion the bindings wrap (validated edits, a cached refinement);
//! * [`compare`]: the method comparison (names, body points, which methods by default);
//! * [`export`] (feature `gltf`): export requests (sampling, the `.gltf` + `.bin` names);
//! * [`files`] (feature `gltf`): motion files read from a path under their size limits.

pub mod compare;
pub mod editable;
#[cfg(feature = "gltf")]
pub mod export;
#[cfg(feature = "gltf")]
pub mod files;
pub mod options;

pub use editable::EditableMotion;
pub use options::{
    default_subdivision, parse_levels, parse_levels_text, resolve, rules_display, rules_name,
    scheme_name, OptionsInput, DEFAULT_LEVELS, MAX_LEVELS, SCHEME_NAMES,
};
