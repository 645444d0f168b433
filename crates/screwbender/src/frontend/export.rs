//! Export requests as every front end makes them: how the keyframes are sampled, and the file
//! names of a `.gltf` and its `.bin` buffer, so that the CLI's, Python's and the page's files
//! of the same motion are the same bytes under the same names.

use std::path::{Path, PathBuf};

use crate::error::{Error, ErrorKind};
use crate::formats::sampling::DEFAULT_TOLERANCE;
use crate::formats::tracks::SamplingMode;

/// The sampling of an export: fixed-rate keyframes at `fps`, else adaptive ones within
/// `tolerance` (default [`DEFAULT_TOLERANCE`]); both at once is an error at `fps`.
pub fn sampling(tolerance: Option<f64>, fps: Option<f64>) -> Result<SamplingMode, Error> {
    match (tolerance, fps) {
        (Some(_), Some(_)) => Err(Error::new(
            "fps",
            ErrorKind::Unsupported {
                reason: "give either tolerance (adaptive sampling) or fps (fixed rate), not both"
                    .into(),
            },
        )),
        (_, Some(fps)) => Ok(SamplingMode::FixedRate(fps)),
        (tolerance, None) => Ok(SamplingMode::Adaptive(
            tolerance.unwrap_or(DEFAULT_TOLERANCE),
        )),
    }
}

/// The `.gltf` + `.bin` pair written for `out`: a `.gltf`, `.glb` or `.bin` extension of `out`
/// is replaced, anything else is kept (`out.v2` gives `out.v2.gltf` + `out.v2.bin`).
pub fn gltf_paths(out: &Path) -> (PathBuf, PathBuf) {
    let text = out.to_string_lossy();
    let stem = [".gltf", ".glb", ".bin"]
        .iter()
        .find_map(|ext| text.strip_suffix(ext))
        .unwrap_or(&text);
    (
        PathBuf::from(format!("{stem}.gltf")),
        PathBuf::from(format!("{stem}.bin")),
    )
}

/// The name by which a `.gltf` refers to its buffer file `bin` (the file name alone: the two
/// files sit side by side).
pub fn bin_name(bin: &Path) -> Result<String, Error> {
    bin.file_name()
        .and_then(|f| f.to_str())
        .map(String::from)
        .ok_or_else(|| {
            Error::new(
                "output",
                ErrorKind::Parse {
                    message: format!("{}: not a valid file name", bin.display()),
                },
            )
        })
}
