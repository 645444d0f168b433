//! The names an exported glTF asset uses, which the import looks for to read it back.

/// Name of the empty node animated through the control poses.
pub const CONTROL_NODE_NAME: &str = "control poses";

/// Key of this crate's data in glTF `extras`.
pub const EXTRAS_KEY: &str = "screwbender";
