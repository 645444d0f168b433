//! `screwbender import FILE.glb|.gltf|.csv|.json [--node NAME | --nodes A,B,…]
//! [--reduce every:K | fit:TOL[:RADIUS]] [-o motion.json]`: control poses from a glTF asset, a
//! CSV file or a motion document, as a JSON motion document. A file of more than
//! [`MANY_POSES`] poses (samples rather than keys) gets a note on standard error saying how many
//! it has and how to reduce them; `--reduce` keeps every K-th pose, or the fewest whose polyscrew
//! stays within TOL of all of them (docs/math/formats.md §7).

use std::path::Path;

use screwbender::frontend::files::import_motion_path;
use screwbender::{reduce_poses, NodeSelection, Reduction, MANY_POSES};

use crate::args::number;
use crate::cli::ImportArgs;
use crate::failure::Failure;
use crate::output::Output;

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
    let mut doc =
        import_motion_path(Path::new(&file), &selection).map_err(|e| Failure(e.to_string()))?;
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
