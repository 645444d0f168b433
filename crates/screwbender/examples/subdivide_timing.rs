//! The native side of the wasm-vs-native comparison (`node benches/wasm/compare.mjs --native PKG`):
//! times the work of one JS `subdivide()` after `setLevels(6)` — a motion rebuilt in its own
//! memory by [`ScrewBender::rebuild`] with kept [`SubdivisionBuffers`], then the refined poses
//! written out as 7 numbers each — so that the wasm module and the native code are timed on the
//! same subdivision of the same poses.
//!
//! ```text
//! cargo run --release -p screwbender --example subdivide_timing -- POSES_FILE SCHEME REPS BURSTS [OUT_FILE]
//! ```
//!
//! `POSES_FILE` holds the closed control cycle, 7 numbers per pose (origin `x, y, z`, quaternion
//! `w, x, y, z`) separated by white space; `SCHEME` is `bspline`, `fourpoint` or `jarek` (direct
//! rules, 6 levels). Prints one line per burst: the mean ms per call over `REPS` calls. With
//! `OUT_FILE`, first writes the refined poses there (7 numbers per line, shortest round-trip
//! decimals), so that the caller can check that both sides computed the same numbers.
//!
//! Built with `--features lane-cap`, `SCREWBENDER_MAX_LANES=2` (or 4, 8) caps the batches' lanes,
//! so that native code is timed at wasm SIMD's width.

use std::hint::black_box;
use std::time::Instant;

use screwbender::{Pose, Rules, Scheme, ScrewBender, Subdivision, SubdivisionBuffers};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The lane cap is read by the library only in a build with the feature: without it the
    // variable would be ignored and the widest lanes timed instead of the width asked for.
    if cfg!(not(feature = "lane-cap")) && std::env::var_os("SCREWBENDER_MAX_LANES").is_some() {
        return Err("SCREWBENDER_MAX_LANES needs a build with --features lane-cap".into());
    }
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (file, scheme, reps, bursts, out_file) = match &args[..] {
        [file, scheme, reps, bursts] => (file, scheme, reps, bursts, None),
        [file, scheme, reps, bursts, out] => (file, scheme, reps, bursts, Some(out)),
        _ => return Err("usage: subdivide_timing POSES_FILE SCHEME REPS BURSTS [OUT_FILE]".into()),
    };
    let numbers = std::fs::read_to_string(file)?
        .split_whitespace()
        .map(str::parse::<f64>)
        .collect::<Result<Vec<f64>, _>>()?;
    if numbers.is_empty() || numbers.len() % 7 != 0 {
        return Err(format!("{file}: {} numbers, not 7 per pose", numbers.len()).into());
    }
    let control = numbers
        .chunks_exact(7)
        .enumerate()
        .map(|(i, p)| {
            Pose::from_wxyz([p[0], p[1], p[2]], [p[3], p[4], p[5], p[6]])
                .map_err(|e| format!("pose {i}: {e}"))
        })
        .collect::<Result<Vec<Pose>, _>>()?;
    let scheme = match scheme.as_str() {
        "bspline" => Scheme::BSpline,
        "fourpoint" => Scheme::FourPoint,
        "jarek" => Scheme::Jarek,
        other => return Err(format!("unknown scheme {other}").into()),
    };
    let (reps, bursts): (usize, usize) = (reps.parse()?, bursts.parse()?);
    let subdivision = Subdivision::new(scheme, Rules::Direct, 6);
    let mut motion = ScrewBender::new(control.clone(), true, subdivision)?;
    let mut buffers = SubdivisionBuffers::new();
    // As `poses_to_array` in the web crate: a fresh vector per call, 7 numbers per pose.
    let mut call = || -> Result<Vec<f64>, screwbender::Error> {
        motion.rebuild(&control, true, subdivision, &mut buffers)?;
        let refined = motion.refined().poses();
        let mut out = Vec::with_capacity(7 * refined.len());
        for p in refined {
            out.extend(p.origin.to_array());
            out.extend([p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z]);
        }
        Ok(out)
    };
    if let Some(out_file) = out_file {
        let numbers = call()?;
        let lines: Vec<String> = numbers
            .chunks_exact(7)
            .map(|p| {
                p.iter()
                    .map(|v| format!("{v:?}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect();
        std::fs::write(out_file, lines.join("\n") + "\n")?;
    }
    // Warm-up, as the JS side's first bursts.
    for _ in 0..reps {
        black_box(call()?);
    }
    for _ in 0..bursts {
        let t0 = Instant::now();
        for _ in 0..reps {
            black_box(call()?);
        }
        println!("{}", t0.elapsed().as_secs_f64() * 1e3 / reps as f64);
    }
    Ok(())
}
