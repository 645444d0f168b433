//! `screwbender import FILE.glb|.gltf|.csv|.json [--node NAME | --nodes A,B,…]
//! [--reduce every:K | fit:TOL[:RADIUS]] [-o motion.json]`: control poses from a glTF asset, a
//! CSV file or a motion document, as a JSON motion document. A file of more than
//! [`MANY_POSES`] poses (samples rather than keys) gets a note on standard error saying how many
//! it has and how to reduce them; `--reduce` keeps every K-th pose, or the fewest whose polyscrew
//! stays within TOL of all of them (docs/math/formats.md §7).

use std::path::Path;

use screwbender::{
    import_motion_file, reduce_poses, Error, ErrorKind, NodeSelection, Reduction, MANY_POSES,
    MAX_GLTF_BYTES,
};

use crate::args::number;
use crate::cli::ImportArgs;
use crate::failure::Failure;
use crate::output::Output;

/// Reads a file of at most [`MAX_GLTF_BYTES`] (checked before reading).
fn read_limited(path: &Path) -> Result<Vec<u8>, Failure> {
    let shown = path.display();
    let meta = std::fs::metadata(path).map_err(|e| Failure(format!("{shown}: {e}")))?;
    if meta.len() > MAX_GLTF_BYTES as u64 {
        return Err(Failure(format!(
            "{shown}: {} bytes is larger than the limit of {MAX_GLTF_BYTES} bytes",
            meta.len()
        )));
    }
    std::fs::read(path).map_err(|e| Failure(format!("{shown}: {e}")))
}

/// Decodes `%XX` escapes of a relative URI into a file name.
fn uri_to_path(uri: &str) -> Result<String, Error> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = uri
                .get(i + 1..i + 3)
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| {
                    Error::new(
                        "uri",
                        ErrorKind::Parse {
                            message: format!("bad percent escape in '{uri}'"),
                        },
                    )
                })?;
            out.push(hex);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| {
        Error::new(
            "uri",
            ErrorKind::Parse {
                message: format!("'{uri}' is not UTF-8"),
            },
        )
    })
}

/// Parses `--reduce every:K` or `--reduce fit:TOL[:RADIUS]` (radius default 0: the origin).
fn reduction(text: &str) -> Result<Reduction, Failure> {
    let bad = || {
        Failure(format!(
            "--reduce: '{text}' is not every:K (a whole number ≥ 1) or fit:TOL[:RADIUS]"
        ))
    };
    match text.split(':').collect::<Vec<_>>()[..] {
        ["every", k] => match k.parse::<usize>() {
            Ok(k) if k >= 1 => Ok(Reduction::Every(k)),
            _ => Err(bad()),
        },
        ["fit", tol] => Ok(Reduction::Fit {
            tolerance: number("--reduce fit", tol)?,
            radius: 0.0,
        }),
        ["fit", tol, radius] => Ok(Reduction::Fit {
            tolerance: number("--reduce fit", tol)?,
            radius: number("--reduce radius", radius)?,
        }),
        _ => Err(bad()),
    }
}

/// Runs `screwbender import`; returns the document for standard output (empty with `-o`).
pub fn import(args: ImportArgs) -> Result<Output, Failure> {
    // `--node` and `--nodes` override each other: the last one given counts.
    let selection = match (args.node, args.nodes) {
        (Some(name), _) => NodeSelection::Animated(name),
        (None, Some(names)) => {
            NodeSelection::Transforms(names.split(',').map(|s| s.trim().to_string()).collect())
        }
        (None, None) => NodeSelection::Auto,
    };
    let reduce = args.reduce.as_deref().map(reduction).transpose()?;
    let (open, verbose, output) = (args.open, args.verbose, args.output);
    let file = args
        .file
        .ok_or_else(|| Failure("import needs a FILE (.glb, .gltf or .csv)".into()))?;
    let path = Path::new(&file);
    let bytes = read_limited(path)?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut resolve = |uri: &str| -> Result<Vec<u8>, Error> {
        let name = uri_to_path(uri)?;
        read_limited(&dir.join(name))
            .map_err(|Failure(message)| Error::new(String::new(), ErrorKind::Parse { message }))
    };
    let name = path.file_name().and_then(|f| f.to_str()).unwrap_or(&file);
    let result = import_motion_file(name, &bytes, &mut resolve, &selection);
    let mut doc = result.map_err(|e| Failure(format!("{file}: {e}")))?;
    if open {
        doc.set_closed(false);
    }
    let found = doc.poses.len();
    match reduce {
        Some(how) => {
            doc = reduce_poses(&doc, how).map_err(|e| Failure(format!("--reduce: {e}")))?;
            eprintln!(
                "screwbender: import: kept {} of {found} poses ({})",
                doc.poses.len(),
                match how {
                    Reduction::Every(k) => format!("every {k}th"),
                    Reduction::Fit { tolerance, radius } =>
                        format!("within {tolerance:e} at radius {radius}"),
                }
            );
        }
        None if found > MANY_POSES => eprintln!(
            "screwbender: import: {file} has {found} poses, more than make sense as control \
             poses (they look like samples); keep fewer with --reduce every:K or --reduce \
             fit:TOL"
        ),
        None => {}
    }
    if verbose {
        eprintln!(
            "screwbender: import: {} control poses ({}) from {file}",
            doc.poses.len(),
            if doc.closed { "cycle" } else { "open" }
        );
    }
    let text = Output::writer(move |w| doc.write_json(w));
    match output {
        Some(out) => {
            text.write_file(&out)?;
            Ok(Output::text(String::new()))
        }
        None => Ok(text),
    }
}
