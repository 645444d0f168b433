//! The GLB container: a 12-byte header, then a JSON chunk and an optional binary chunk. Read by
//! the glTF import and by meshes loaded from `.glb` files.

use crate::error::{Error, ErrorKind};
use crate::formats::keyframes::MAX_KEYFRAME_FILE_BYTES;

/// A parse error at `at`.
pub(crate) fn parse_err(at: impl Into<String>, message: impl Into<String>) -> Error {
    Error::new(
        at,
        ErrorKind::Parse {
            message: message.into(),
        },
    )
}

/// Whether `bytes` starts with the GLB magic `glTF`.
pub fn is_glb(bytes: &[u8]) -> bool {
    bytes.starts_with(b"glTF")
}

pub(crate) fn check_size(len: usize, at: &str) -> Result<(), Error> {
    if len > MAX_KEYFRAME_FILE_BYTES {
        Err(Error::new(
            at,
            ErrorKind::OutOfRange {
                value: format!("{len} bytes"),
                expected: format!("at most {MAX_KEYFRAME_FILE_BYTES} bytes"),
            },
        ))
    } else {
        Ok(())
    }
}

fn u32_at(bytes: &[u8], offset: usize) -> Option<u32> {
    Some(u32::from_le_bytes(
        bytes.get(offset..offset + 4)?.try_into().ok()?,
    ))
}

/// Splits a GLB container into its JSON chunk and optional BIN chunk.
///
/// Errors (path `glb`): bad magic or version, a length field that disagrees with the data
/// (truncated file), a missing JSON chunk.
pub fn split_glb(bytes: &[u8]) -> Result<(&[u8], Option<&[u8]>), Error> {
    check_size(bytes.len(), "glb")?;
    if !is_glb(bytes) {
        return Err(parse_err("glb", "not a GLB file (no 'glTF' magic)"));
    }
    let version = u32_at(bytes, 4).ok_or_else(|| parse_err("glb", "truncated header"))?;
    if version != 2 {
        return Err(parse_err(
            "glb",
            format!("version {version}, only glTF 2 is supported"),
        ));
    }
    let length = u32_at(bytes, 8).ok_or_else(|| parse_err("glb", "truncated header"))? as usize;
    if length != bytes.len() {
        return Err(parse_err(
            "glb",
            format!(
                "header says {length} bytes, the file has {} (truncated or corrupt)",
                bytes.len()
            ),
        ));
    }
    let mut offset = 12;
    let mut chunks = Vec::new();
    while offset < bytes.len() {
        let (Some(len), Some(kind)) = (u32_at(bytes, offset), u32_at(bytes, offset + 4)) else {
            return Err(parse_err(
                format!("glb chunk at byte {offset}"),
                "truncated chunk header",
            ));
        };
        let start = offset + 8;
        let end = start
            .checked_add(len as usize)
            .filter(|&e| e <= bytes.len())
            .ok_or_else(|| {
                parse_err(
                    format!("glb chunk at byte {offset}"),
                    format!("chunk of {len} bytes runs past the end of the file"),
                )
            })?;
        chunks.push((kind, &bytes[start..end]));
        offset = end;
    }
    match chunks.first() {
        Some((0x4E4F_534A, text)) => Ok((text, chunks.get(1).map(|c| c.1))),
        _ => Err(parse_err("glb", "the first chunk is not JSON")),
    }
}
