//! The Rust core's side of the Python package's benchmarks (benches/python/bench.py): times
//! the same work as `Motion.subdivide()` and `screw(a, t, b)` on batches, natively, and prints
//! one line of seconds per repetition.
//!
//!   core_timing subdivide POSES LEVELS REPS    # Subdivision::apply + the (N, 7) rows
//!   core_timing serve                          # the same, one run per line read (see below)
//!   core_timing screw PAIRS REPS               # Pose::blends on PAIRS random pairs + rows
//!
//! The poses are the benchmark's own (a fixed pseudo-random cycle), so both sides do the same
//! work; the Python side reads them from this program's `poses` command.
//!
//! `serve` is for interleaving in one long-lived process, as warm as the Python process it is
//! compared with: each line `subdivide POSES LEVELS` on standard input runs one subdivision and
//! prints its seconds. Like `Motion.subdivide()`, a run subdivides into working memory kept
//! from the run before (`Subdivision::apply_into`) and writes the rows into a fresh array that
//! it hands over (here: drops), so both sides pay the same first touches of fresh memory.

use std::io::BufRead;
use std::time::Instant;

use glam::{DQuat, DVec3};
use screwbender::{Blend, Pose, Rules, Scheme, Subdivision, SubdivisionBuffers};

/// A fixed pseudo-random cycle of `n` poses (a small LCG: no dependency, the same everywhere).
fn poses(n: usize, seed: u64) -> Vec<Pose> {
    let mut state = seed;
    let mut next = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    (0..n)
        .map(|i| {
            let angle = std::f64::consts::TAU * i as f64 / n as f64;
            let origin = DVec3::new(4.0 * angle.cos(), 4.0 * angle.sin(), next());
            let q = DQuat::from_xyzw(next(), next(), next(), 1.5 + next()).normalize();
            Pose::new(origin, q)
        })
        .collect()
}

/// Poses as `x y z qw qx qy qz` rows (what the Python side returns).
fn rows(poses: &[Pose]) -> Vec<f64> {
    let mut out = vec![0.0; poses.len() * 7];
    for (slot, p) in out.chunks_exact_mut(7).zip(poses) {
        let [w, x, y, z] = p.rotation_wxyz();
        slot.copy_from_slice(&[p.origin.x, p.origin.y, p.origin.z, w, x, y, z]);
    }
    out
}

/// Runs `work` `reps` times and prints the seconds of each run on one line.
fn print_times(reps: usize, mut work: impl FnMut() -> Vec<f64>) {
    let times: Vec<String> = (0..reps)
        .map(|_| {
            let start = Instant::now();
            std::hint::black_box(work());
            start.elapsed().as_secs_f64().to_string()
        })
        .collect();
    println!("{}", times.join(" "));
}

fn arg(args: &[String], i: usize) -> usize {
    args.get(i)
        .and_then(|a| a.parse().ok())
        .unwrap_or_else(|| panic!("argument {i}: expected a whole number (see the file's doc)"))
}

/// The `serve` command: one timed subdivision per line of standard input.
fn serve() {
    let mut control: Vec<Pose> = Vec::new();
    let mut refined = Vec::new();
    let mut buffers = SubdivisionBuffers::new();
    for line in std::io::stdin().lock().lines() {
        let line = line.expect("standard input");
        let words: Vec<String> = line.split_whitespace().map(str::to_string).collect();
        if words.first().map(String::as_str) != Some("subdivide") {
            panic!("serve: expected `subdivide POSES LEVELS`, got {line:?}");
        }
        let (n, levels) = (arg(&words, 1), arg(&words, 2));
        if control.len() != n {
            control = poses(n, 1);
        }
        let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, levels as u32);
        let start = Instant::now();
        sub.apply_into(&control, true, &mut refined, &mut buffers)
            .expect("valid options");
        std::hint::black_box(rows(&refined));
        println!("{}", start.elapsed().as_secs_f64());
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    match args.get(1).map(String::as_str) {
        Some("poses") => {
            for p in poses(arg(&args, 2), arg(&args, 3) as u64) {
                let [w, x, y, z] = p.rotation_wxyz();
                let o = p.origin;
                println!("{:?} {:?} {:?} {w:?} {x:?} {y:?} {z:?}", o.x, o.y, o.z);
            }
        }
        Some("subdivide") => {
            let (n, levels, reps) = (arg(&args, 2), arg(&args, 3), arg(&args, 4));
            let control = poses(n, 1);
            let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, levels as u32);
            print_times(reps, || {
                rows(&sub.apply(&control, true).expect("valid options"))
            });
        }
        Some("serve") => serve(),
        Some("screw") => {
            let (n, reps) = (arg(&args, 2), arg(&args, 3));
            let (a, b) = (poses(n, 2), poses(n, 3));
            let ts: Vec<f64> = (0..n).map(|k| k as f64 / n as f64).collect();
            print_times(reps, || {
                let mut out = Vec::with_capacity(n);
                Pose::blends(n, |k| (&a[k], ts[k], &b[k]), &mut out);
                rows(&out)
            });
        }
        _ => eprintln!(
            "usage: core_timing poses N SEED | subdivide POSES LEVELS REPS | screw PAIRS REPS"
        ),
    }
}
