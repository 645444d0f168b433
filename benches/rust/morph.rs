//! The morphing object of scene A8 (paper Fig. 7b) per frame: the hull morph (`morph_mesh`,
//! support points sampled over a sphere of directions: the shapes' convex hulls) against the PIP
//! morph (`PipMorph::mesh_at`, every pair of convex pieces), for one playback frame and for the
//! 40-copy strobe the page rebuilds when the strobe count changes; and what building the PIP
//! morph's pairs costs once per preset.
//!
//! Run: `cargo bench --bench morph`. The two routes are timed in alternating rounds and printed
//! as min / median / max (robust to a drifting machine), then criterion times one frame of each.

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::hint::black_box;
    use std::time::Instant;

    use criterion::{criterion_group, Criterion};
    use screwbender::presets::preset;
    use screwbender::{morph_mesh, morph_weights, PipMorph, MORPH_RESOLUTION};

    /// Copies in the strobe the page draws.
    const STROBE: usize = 40;

    /// `rounds` under `cargo bench`, one round otherwise (a smoke test in a debug build).
    fn rounds(rounds: usize) -> usize {
        if std::env::args().any(|a| a == "--bench") {
            rounds
        } else {
            1
        }
    }

    fn spread(mut v: Vec<f64>) -> [f64; 3] {
        v.sort_by(f64::total_cmp);
        [v[0], v[v.len() / 2], v[v.len() - 1]]
    }

    /// The strobe's parameters over A8's cycle of five spans (as the page spaces them).
    fn strobe_us() -> Vec<f64> {
        (0..STROBE)
            .map(|k| 5.0 * k as f64 / STROBE as f64)
            .collect()
    }

    fn report_interleaved() {
        let s = preset("pip_morph5").unwrap();
        let shapes = &s.morph_shapes;
        let t0 = Instant::now();
        let pip = PipMorph::from_shapes(shapes, true).unwrap();
        let build_once = t0.elapsed().as_secs_f64() * 1e3;
        let us = strobe_us();
        let hull_frame = |u: f64| {
            let w = morph_weights(shapes.len(), true, u);
            morph_mesh(shapes, &w, MORPH_RESOLUTION).unwrap()
        };
        let mut times: [Vec<f64>; 5] = Default::default();
        for _ in 0..rounds(10) {
            let t = Instant::now();
            for &u in &us {
                black_box(hull_frame(black_box(u)));
            }
            times[0].push(t.elapsed().as_secs_f64() * 1e3);
            let t = Instant::now();
            for &u in &us {
                black_box(pip.mesh_at(black_box(u)).unwrap());
            }
            times[1].push(t.elapsed().as_secs_f64() * 1e3);
            // One playback frame, averaged over the strobe's parameters.
            let t = Instant::now();
            for &u in &us {
                black_box(hull_frame(black_box(u + 0.01)));
            }
            times[2].push(t.elapsed().as_secs_f64() * 1e3 / STROBE as f64);
            let t = Instant::now();
            for &u in &us {
                black_box(pip.mesh_at(black_box(u + 0.01)).unwrap());
            }
            times[3].push(t.elapsed().as_secs_f64() * 1e3 / STROBE as f64);
            let t = Instant::now();
            black_box(PipMorph::from_shapes(black_box(shapes), true).unwrap());
            times[4].push(t.elapsed().as_secs_f64() * 1e3);
        }
        let triangles = |m: &screwbender::mesh::Mesh| m.triangle_count();
        let (hull_tris, pip_tris): (usize, usize) = us
            .iter()
            .map(|&u| {
                (
                    triangles(&hull_frame(u)),
                    triangles(&pip.mesh_at(u).unwrap()),
                )
            })
            .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
        let [hs, ps, hf, pf, build] = times.map(spread);
        let show = |v: [f64; 3]| format!("{:.3} / {:.3} / {:.3}", v[0], v[1], v[2]);
        println!(
            "A8 morph, ms (min / median / max of {} alternating rounds):\n  \
             strobe of {STROBE}: hull morph {} ({hull_tris} triangles), PIP morph {} ({pip_tris} triangles)\n  \
             one frame: hull morph {}, PIP morph {}\n  \
             building the PIP morph's pairs: {} (first build {build_once:.1})",
            rounds(10),
            show(hs),
            show(ps),
            show(hf),
            show(pf),
            show(build),
        );
    }

    fn frame(c: &mut Criterion) {
        report_interleaved();
        let s = preset("pip_morph5").unwrap();
        let shapes = s.morph_shapes.clone();
        let pip = PipMorph::from_shapes(&shapes, true).unwrap();
        let mut g = c.benchmark_group("A8 one frame");
        g.bench_function("hull morph", |b| {
            b.iter(|| {
                let w = morph_weights(shapes.len(), true, black_box(1.37));
                black_box(morph_mesh(&shapes, &w, MORPH_RESOLUTION).unwrap())
            })
        });
        g.bench_function("PIP morph", |b| {
            b.iter(|| black_box(pip.mesh_at(black_box(1.37)).unwrap()))
        });
        g.finish();
    }

    criterion_group!(benches, frame);
}

#[cfg(not(target_arch = "wasm32"))]
criterion::criterion_main!(native::benches);

#[cfg(target_arch = "wasm32")]
fn main() {}
