//! Motion files read from a path, for the front ends that have a file system (the command line
//! and Python): every file is checked against its size limit before it is read, and a `.gltf`
//! finds its buffers beside it by their URIs, percent-decoded as the glTF specification asks
//! (a buffer `my%20motion.bin` is the file `my motion.bin`).

use std::fmt;
use std::path::{Path, PathBuf};

use crate::error::{Error, ErrorKind};
use crate::formats::document::{MotionDocument, MAX_DOCUMENT_BYTES};
use crate::formats::gltf::import::{NodeSelection, MAX_GLTF_BYTES};
use crate::formats::interop::import_motion_file;

/// Why a file could not be read: the system refused it, or its content (or size) is bad.
#[derive(Debug)]
pub enum FileError {
    /// The file system's error (not found, no permission, …) for `path`.
    Io {
        /// The file as the caller named it.
        path: PathBuf,
        /// The system's error.
        error: std::io::Error,
    },
    /// The file was read but is not acceptable: too large, or a bad element inside it.
    Content {
        /// The file as the caller named it.
        path: PathBuf,
        /// What is wrong, naming the element.
        error: Error,
    },
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FileError::Io { path, error } => write!(f, "{}: {error}", path.display()),
            FileError::Content { path, error } => write!(f, "{}: {error}", path.display()),
        }
    }
}

impl std::error::Error for FileError {}

/// The bytes of the file at `path`, refused before reading when larger than `limit`.
pub fn read_limited(path: &Path, limit: usize) -> Result<Vec<u8>, FileError> {
    let io = |error| FileError::Io {
        path: path.to_path_buf(),
        error,
    };
    let meta = std::fs::metadata(path).map_err(io)?;
    if meta.len() > limit as u64 {
        return Err(FileError::Content {
            path: path.to_path_buf(),
            error: Error::new(
                "",
                ErrorKind::Parse {
                    message: format!(
                        "{} bytes is larger than the limit of {limit} bytes",
                        meta.len()
                    ),
                },
            ),
        });
    }
    std::fs::read(path).map_err(io)
}

/// A relative URI's `%XX` escapes decoded into a file name (UTF-8).
pub fn decode_uri(uri: &str) -> Result<String, Error> {
    let bad = |message: String| Error::new("uri", ErrorKind::Parse { message });
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = uri
                .get(i + 1..i + 3)
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| bad(format!("bad percent escape in '{uri}'")))?;
            out.push(hex);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| bad(format!("'{uri}' is not UTF-8")))
}

/// The control poses of the file at `path` (`.json`, `.csv`, `.glb`, `.gltf`; see
/// [`import_motion_file`]); a `.gltf`'s buffers are read beside it ([`decode_uri`]), each under
/// the same size limit. Errors name the file and the element inside it.
pub fn import_motion_path(
    path: &Path,
    selection: &NodeSelection,
) -> Result<MotionDocument, FileError> {
    let bytes = read_limited(path, MAX_GLTF_BYTES)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut resolve = |uri: &str| -> Result<Vec<u8>, Error> {
        let buffer = dir.join(decode_uri(uri)?);
        read_limited(&buffer, MAX_GLTF_BYTES).map_err(|e| {
            Error::new(
                "",
                ErrorKind::Parse {
                    message: e.to_string(),
                },
            )
        })
    };
    let name = path
        .file_name()
        .and_then(|f| f.to_str())
        .unwrap_or_default();
    import_motion_file(name, &bytes, &mut resolve, selection).map_err(|error| FileError::Content {
        path: path.to_path_buf(),
        error,
    })
}

/// The JSON motion document at `path`, refused before reading when larger than
/// [`MAX_DOCUMENT_BYTES`], validated.
pub fn read_document_path(path: &Path) -> Result<MotionDocument, FileError> {
    let bytes = read_limited(path, MAX_DOCUMENT_BYTES)?;
    let content = |error| FileError::Content {
        path: path.to_path_buf(),
        error,
    };
    let text = String::from_utf8(bytes).map_err(|e| {
        content(Error::new(
            "",
            ErrorKind::Parse {
                message: format!("not UTF-8 text: {e}"),
            },
        ))
    })?;
    MotionDocument::from_json(&text).map_err(content)
}
