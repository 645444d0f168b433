//! Reading the motion document a command works on, from a file or standard input.

use std::io::Read;

use screwbender::frontend::files::read_document_path;
use screwbender::MotionDocument;

use crate::failure::Failure;

/// The motion document in `file` (`None` or `-`: standard input), validated; failures name the
/// file (or standard input) and the bad element.
pub fn read_document(file: Option<&str>) -> Result<MotionDocument, Failure> {
    let (name, text) = match file {
        None | Some("-") => {
            let mut text = String::new();
            std::io::stdin()
                .read_to_string(&mut text)
                .map_err(|e| Failure(format!("standard input: {e}")))?;
            ("standard input".to_string(), text)
        }
        Some(path) => {
            return read_document_path(std::path::Path::new(path))
                .map_err(|e| Failure(e.to_string()))
        }
    };
    MotionDocument::from_json(&text).map_err(|e| Failure(format!("{name}: {e}")))
}
