//! Core benchmarks: screw evaluations (full one at a time, full in a batch, and cached), subdivision of 32 poses × 6 levels per
//! scheme and rule set, and nalgebra's `UnitDualQuaternion::sclerp` on the same pose pairs.
//!
//! Run: `cargo bench --bench core`. Before timing, the accuracy of both screw implementations is
//! printed against screws constructed exactly (rotation about a known axis + slide), and the
//! three full-screw routes are timed in alternating bursts (ratios robust to a drifting machine).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};

/// `rounds` under `cargo bench`, one round otherwise: `cargo test --all-targets` runs this file
/// once as a smoke test in a debug build, where the full interleaved reports took minutes
/// (cargo passes `--bench` only to a benchmark run).
fn rounds(rounds: usize) -> usize {
    if std::env::args().any(|a| a == "--bench") {
        rounds
    } else {
        1
    }
}
use glam::{DQuat, DVec3};
use nalgebra::{Isometry3, Quaternion, Translation3, UnitDualQuaternion, UnitQuaternion};
use screwbender::{
    screw, Blend, Pose, Rules, Scheme, Screw, ScrewBender, Subdivision, SubdivisionBuffers,
};

/// Pairs per batch (fixed seed).
const PAIRS: usize = 1024;

struct Rng(u64);
impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn vec(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.range(-s, s), self.range(-s, s), self.range(-s, s))
    }
    fn axis(&mut self) -> DVec3 {
        loop {
            let v = self.vec(1.0);
            if v.length() > 0.1 {
                return v.normalize();
            }
        }
    }
    fn pose(&mut self) -> Pose {
        let q = DQuat::from_axis_angle(self.axis(), self.range(0.0, std::f64::consts::PI));
        Pose::new(self.vec(5.0), q)
    }
}

/// Pose pairs related by a known screw (angle below π − 0.01 so sclerp is defined), with the
/// exact pose at `t = 0.3`.
fn pairs(rng: &mut Rng) -> Vec<(Pose, Pose, Pose)> {
    (0..PAIRS)
        .map(|_| {
            let a = rng.pose();
            let (axis, point) = (rng.axis(), rng.vec(5.0));
            let (angle, slide) = (
                rng.range(0.0, std::f64::consts::PI - 0.01),
                rng.range(-3.0, 3.0),
            );
            let at = |t: f64| {
                let r = DQuat::from_axis_angle(axis, t * angle);
                Pose::new(point - r * point + t * slide * axis, r).compose(&a)
            };
            (a, at(1.0), at(0.3))
        })
        .collect()
}

fn to_dq(p: &Pose) -> UnitDualQuaternion<f64> {
    let q = p.rotation;
    UnitDualQuaternion::from_isometry(&Isometry3::from_parts(
        Translation3::new(p.origin.x, p.origin.y, p.origin.z),
        UnitQuaternion::from_quaternion(Quaternion::new(q.w, q.x, q.y, q.z)),
    ))
}

fn dq_error(got: &UnitDualQuaternion<f64>, want: &Pose) -> f64 {
    let iso = got.to_isometry();
    let t = iso.translation.vector;
    let q = iso.rotation.quaternion();
    let p = Pose::new(
        DVec3::new(t.x, t.y, t.z),
        DQuat::from_xyzw(q.i, q.j, q.k, q.w),
    );
    p.distance(want)
}

fn report_accuracy(data: &[(Pose, Pose, Pose)]) {
    let ours = data
        .iter()
        .map(|(a, b, x)| screw(a, 0.3, b).distance(x))
        .fold(0.0, f64::max);
    let theirs = data
        .iter()
        .map(|(a, b, x)| dq_error(&to_dq(a).sclerp(&to_dq(b), 0.3), x))
        .fold(0.0, f64::max);
    println!("accuracy at t = 0.3 over {PAIRS} pairs (max |Δo| + angle): screwbender {ours:.2e}, nalgebra sclerp {theirs:.2e}");
}

/// The full screws `screw(a, 0.3, b)` of `data` through the batch route, into `out`.
fn batch_screws(data: &[(Pose, Pose, Pose)], out: &mut Vec<Pose>) {
    out.clear();
    Pose::blends(
        data.len(),
        |i| (&data[i].0, black_box(0.3), &data[i].1),
        out,
    );
    black_box(out);
}

/// Times the three full-screw routes (and the one-call screw at a second fraction) in
/// alternating bursts of `PAIRS` screws and prints the median time per screw of each and their
/// ratios. On a shared machine whose speed drifts from
/// one second to the next, back-to-back bursts compare like with like where criterion's
/// sequential groups (seconds apart) may not.
fn report_interleaved(data: &[(Pose, Pose, Pose)]) {
    use std::time::Instant;
    let dqs: Vec<_> = data.iter().map(|(a, b, _)| (to_dq(a), to_dq(b))).collect();
    let mut out = Vec::with_capacity(PAIRS);
    let mut times = [Vec::new(), Vec::new(), Vec::new(), Vec::new()];
    let mut ratios = [Vec::new(), Vec::new(), Vec::new()];
    for _ in 0..rounds(400) {
        let t0 = Instant::now();
        for (a, b, _) in data {
            black_box(screw(black_box(a), black_box(0.3), black_box(b)));
        }
        let t1 = Instant::now();
        batch_screws(data, &mut out);
        let t2 = Instant::now();
        for (a, b) in &dqs {
            black_box(black_box(a).sclerp(black_box(b), black_box(0.3)));
        }
        let t3 = Instant::now();
        // t = 0.9: tθ/2 beyond the one-call sine's unreduced branch (0.78) for the 45% of
        // the pairs whose angle exceeds 1.73 rad, in random order (its worst case).
        for (a, b, _) in data {
            black_box(screw(black_box(a), black_box(0.9), black_box(b)));
        }
        let t4 = Instant::now();
        let bursts = [(t0, t1), (t1, t2), (t2, t3), (t3, t4)];
        for (k, (from, to)) in bursts.into_iter().enumerate() {
            times[k].push((to - from).as_secs_f64() * 1e9 / PAIRS as f64);
        }
        // Each burst against its neighbouring sclerp burst: the per-round ratios.
        let sclerp = (t3 - t2).as_secs_f64();
        ratios[0].push(sclerp / (t1 - t0).as_secs_f64());
        ratios[1].push(sclerp / (t2 - t1).as_secs_f64());
        ratios[2].push(sclerp / (t4 - t3).as_secs_f64());
    }
    let [single, batch, sclerp, late] = times.map(|mut v| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    });
    let spreads = ratios.map(spread);
    let show = |[lo, mid, hi]: [f64; 3]| format!("{lo:.2} / {mid:.2} / {hi:.2}");
    println!(
        "interleaved medians per screw: screw(a, t, b) {single:.1} ns ({:.2} M/s), batch {batch:.1} ns \
         ({:.2} M/s), nalgebra sclerp {sclerp:.1} ns ({:.2} M/s); ratios vs sclerp: {:.2}x single, \
         {:.2}x batch",
        1e3 / single,
        1e3 / batch,
        1e3 / sclerp,
        sclerp / single,
        sclerp / batch
    );
    println!(
        "  per-round ratios vs sclerp (min / median / max): single {}, batch {}; \
         screw(a, 0.9, b) {late:.1} ns, {:.2}x sclerp (per round {})",
        show(spreads[0]),
        show(spreads[1]),
        sclerp / late,
        show(spreads[2])
    );
}

/// Nanoseconds per step of the dependent chain `x ← step(x)` (`steps` steps from `x`): min /
/// median / max over `runs` runs.
fn chain_ns<T: Copy>(runs: usize, steps: usize, x: T, step: impl Fn(T) -> T) -> [f64; 3] {
    let times = (0..runs)
        .map(|_| {
            let mut y = black_box(x);
            let t0 = std::time::Instant::now();
            for _ in 0..steps {
                y = step(y);
            }
            black_box(y);
            t0.elapsed().as_secs_f64() * 1e9 / steps as f64
        })
        .collect();
    spread(times)
}

/// The latency of the one-call screw and of nalgebra's `sclerp`, and of the steps their chains
/// are made of, each as a dependent chain (the next call's input waits for this call's result;
/// the `0 ·` joins cost one multiply and one add): the evidence of docs/speed/one-call-screw.md.
/// Cycles assume a 3-cycle `f64` add (Zen 4, as every x86-64 core since Haswell has 3 or 4).
fn report_latencies(data: &[(Pose, Pose, Pose)]) {
    let (runs, steps) = (rounds(30), if rounds(2) > 1 { 100_000 } else { 100 });
    let add = chain_ns(runs, steps, 1.0, |x| x + 1e-300)[0];
    let cycles = |ns: f64| 3.0 * ns / add;
    let mut rows: Vec<(&str, [f64; 3])> = vec![
        ("f64 add", chain_ns(runs, steps, 1.0, |x| x + 1e-300)),
        ("f64 mul", chain_ns(runs, steps, 1.0, |x| x * 0.999_999_999)),
        ("f64 div", chain_ns(runs, steps, 1.5, |x| 1.000_000_1 / x)),
        (
            "f64 sqrt + add",
            chain_ns(runs, steps, 2.0, |x: f64| x.sqrt() + 1.0),
        ),
        (
            "std acos + mul",
            chain_ns(runs, steps, 0.5, |x: f64| x.acos() * 0.3),
        ),
        ("std sin", chain_ns(runs, steps, 0.5, f64::sin)),
        (
            "std cos + mul",
            chain_ns(runs, steps, 0.5, |x: f64| x.cos() * 0.9),
        ),
        (
            "std atan2",
            chain_ns(runs, steps, 0.5, |x: f64| x.atan2(1.0)),
        ),
    ];
    let (a, b, _) = data[0];
    let join = |p: &Pose, r: f64| {
        let q = p.rotation;
        Pose::new(p.origin, DQuat::from_xyzw(q.x, q.y, q.z, q.w + 0.0 * r))
    };
    // Screw::between chained through b's rotation (relative rotation, sqrt, atan2,
    // coefficients); Screw::at chained through t (sin/cos and the evaluation).
    rows.push((
        "Screw::between",
        chain_ns(runs, steps, b, |b| join(&b, Screw::between(&a, &b).angle())),
    ));
    let span = Screw::between(&a, &b);
    rows.push((
        "Screw::at",
        chain_ns(runs, steps, 0.3, |t| 0.3 + 0.0 * span.at(t).rotation.w),
    ));
    rows.push((
        "screw(a, t, b)",
        chain_ns(runs, steps, b, |b| join(&b, screw(&a, 0.3, &b).rotation.w)),
    ));
    let (da, db) = (to_dq(&a), to_dq(&b));
    rows.push((
        "nalgebra sclerp",
        chain_ns(runs, steps, db, |b| {
            let r = da.sclerp(&b, 0.3);
            let mut d = *b.as_ref();
            d.real.w += 0.0 * r.as_ref().real.w;
            UnitDualQuaternion::new_unchecked(d)
        }),
    ));
    println!("dependent-chain latency per step, ns (min / median / max) and cycles at the min:");
    for (name, [lo, mid, hi]) in rows {
        println!(
            "  {name:<16} {lo:6.2} / {mid:6.2} / {hi:6.2} ns  {:6.1} cycles",
            cycles(lo)
        );
    }
}

fn screws(c: &mut Criterion) {
    let mut rng = Rng(42);
    let data = pairs(&mut rng);
    report_accuracy(&data);
    report_interleaved(&data);
    report_latencies(&data);
    if std::env::var_os("SCREWBENDER_BENCH_SCREWS_ONLY").is_some() {
        // The two reports above only (for quick A/B runs of the screw kernel).
        std::process::exit(0);
    }
    let mut g = c.benchmark_group("screw");
    g.throughput(Throughput::Elements(PAIRS as u64));
    g.bench_function("full screw(a, t, b)", |bench| {
        bench.iter(|| {
            for (a, b, _) in &data {
                black_box(screw(black_box(a), black_box(0.3), black_box(b)));
            }
        })
    });
    // The same full screws through the batch route (several at a time on SIMD lanes), as the
    // subdivision and JavaScript's `screwPairs` use it.
    let mut out = Vec::with_capacity(PAIRS);
    g.bench_function("batch Pose::blends (full screws)", |bench| {
        bench.iter(|| batch_screws(&data, &mut out))
    });
    let cached: Vec<Screw> = data.iter().map(|(a, b, _)| Screw::between(a, b)).collect();
    g.bench_function("cached Screw::at(t)", |bench| {
        bench.iter(|| {
            for s in &cached {
                black_box(s.at(black_box(0.3)));
            }
        })
    });
    let dqs: Vec<_> = data.iter().map(|(a, b, _)| (to_dq(a), to_dq(b))).collect();
    g.bench_function("nalgebra sclerp", |bench| {
        bench.iter(|| {
            for (a, b) in &dqs {
                black_box(black_box(a).sclerp(black_box(b), black_box(0.3)));
            }
        })
    });
    g.finish();
}

/// A smooth-ish cycle of `n` poses: consecutive poses 0.3 rad and ~1 unit apart.
fn cycle(rng: &mut Rng, n: usize) -> Vec<Pose> {
    let mut poses = vec![rng.pose()];
    for _ in 1..n {
        let last = *poses.last().unwrap();
        let r = DQuat::from_axis_angle(rng.axis(), 0.3);
        poses.push(Pose::new(last.origin + rng.vec(1.0), r * last.rotation));
    }
    poses
}

/// Min / median / max of `v`.
fn spread(mut v: Vec<f64>) -> [f64; 3] {
    v.sort_by(f64::total_cmp);
    [v[0], v[v.len() / 2], v[v.len() - 1]]
}

/// `ScrewBender::new` against `Subdivision::apply` alone on the same 32 poses × 6 levels (2048
/// refined poses), in alternating runs: what building the motion adds to the subdivision —
/// the validation alone (the span screws are computed on first use), and the validation plus
/// the span screws (`new` then `refined().spans()`, a motion ready to evaluate). Printed as
/// min / median / max of the per-run ratios.
fn report_motion_overhead() {
    let poses = cycle(&mut Rng(7), 32);
    for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
        let s = Subdivision::new(scheme, Rules::Direct, 6);
        let (mut ratios, mut apply, mut new) = (Vec::new(), Vec::new(), Vec::new());
        let (mut ratios_spans, mut new_spans) = (Vec::new(), Vec::new());
        for _ in 0..rounds(300) {
            let t0 = std::time::Instant::now();
            for _ in 0..4 {
                black_box(s.apply(black_box(&poses), true).unwrap());
            }
            let t1 = std::time::Instant::now();
            for _ in 0..4 {
                black_box(ScrewBender::new(black_box(poses.clone()), true, s).unwrap());
            }
            let t2 = std::time::Instant::now();
            for _ in 0..4 {
                let m = ScrewBender::new(black_box(poses.clone()), true, s).unwrap();
                black_box(m.refined().spans().len());
            }
            let t3 = std::time::Instant::now();
            let (a, b, c) = (
                (t1 - t0).as_secs_f64(),
                (t2 - t1).as_secs_f64(),
                (t3 - t2).as_secs_f64(),
            );
            ratios.push(b / a);
            ratios_spans.push(c / a);
            apply.push(a * 1e6 / 4.0);
            new.push(b * 1e6 / 4.0);
            new_spans.push(c * 1e6 / 4.0);
        }
        // The span screws of the refined poses, one at a time (the route before batches) and
        // in batches (as `ScrewBender::new` builds them), alternating.
        let refined = s.apply(&poses, true).unwrap();
        let mut spans = (Vec::new(), Vec::new());
        for _ in 0..rounds(300) {
            let t0 = std::time::Instant::now();
            let one: Vec<Screw> = (0..refined.len())
                .map(|i| Screw::between(&refined[i], &refined[(i + 1) % refined.len()]))
                .collect();
            black_box(one);
            let t1 = std::time::Instant::now();
            let p = screwbender::Polyscrew::new(black_box(refined.clone()), true).unwrap();
            black_box(p.spans().len());
            let t2 = std::time::Instant::now();
            spans
                .0
                .push((t1 - t0).as_secs_f64() * 1e9 / refined.len() as f64);
            spans
                .1
                .push((t2 - t1).as_secs_f64() * 1e9 / refined.len() as f64);
        }
        println!(
            "  span screws per refined pose (medians): one at a time {:.1} ns, Polyscrew::new + spans() {:.1} ns",
            spread(spans.0)[1],
            spread(spans.1)[1]
        );
        let [r0, r1, r2] = spread(ratios);
        let [q0, q1, q2] = spread(ratios_spans);
        let (a, b, c) = (spread(apply)[1], spread(new)[1], spread(new_spans)[1]);
        println!(
            "ScrewBender::new / Subdivision::apply, {scheme} direct, 2048 refined poses: \
             {r0:.2} / {r1:.2} / {r2:.2}; with the span screws {q0:.2} / {q1:.2} / {q2:.2} \
             (min / median / max; medians {b:.1} and {c:.1} vs {a:.1} us)"
        );
    }
}

/// Nanoseconds per refined pose of 4-point direct subdivisions of an 8-pose cycle into 2¹² and
/// 2²⁰ poses, into caller-owned buffers (`apply_into`, reused from run to run) and by `apply`
/// (fresh result memory each time), in alternating runs. Printed as min / median / max.
fn report_large_subdivisions() {
    let poses = cycle(&mut Rng(11), 8);
    let (small, large) = (
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 9),
        // 2^20 poses; 2^13 in a smoke test (a debug build would take minutes).
        Subdivision::new(
            Scheme::FourPoint,
            Rules::Direct,
            if rounds(2) > 1 { 17 } else { 10 },
        ),
    );
    let mut out = Vec::new();
    let mut buffers = SubdivisionBuffers::new();
    // Grow the caller's memory once, as a session's first subdivision does.
    large
        .apply_into(&poses, true, &mut out, &mut buffers)
        .unwrap();
    let mut times: [Vec<f64>; 4] = Default::default();
    for _ in 0..rounds(12) {
        let runs: [(&Subdivision, bool); 4] = [
            (&small, true),
            (&large, true),
            (&small, false),
            (&large, false),
        ];
        for (k, (s, into)) in runs.into_iter().enumerate() {
            let reps = if s.levels == 9 { 256 } else { 1 };
            let t0 = std::time::Instant::now();
            for _ in 0..reps {
                if into {
                    s.apply_into(black_box(&poses), true, &mut out, &mut buffers)
                        .unwrap();
                    black_box(&out);
                } else {
                    black_box(s.apply(black_box(&poses), true).unwrap());
                }
            }
            let total = (8usize << s.levels) * reps;
            times[k].push(t0.elapsed().as_secs_f64() * 1e9 / total as f64);
        }
    }
    let [small_into, large_into, small_apply, large_apply] = times.map(spread);
    let show = |v: [f64; 3]| format!("{:.1} / {:.1} / {:.1}", v[0], v[1], v[2]);
    println!(
        "ns per refined pose, 4-point direct, 8-pose cycle (min / median / max): apply_into 2^12 {}, \
         2^{big} {} (median ratio {:.2}); apply 2^12 {}, 2^{big} {} (median ratio {:.2})",
        show(small_into),
        show(large_into),
        large_into[1] / small_into[1],
        show(small_apply),
        show(large_apply),
        large_apply[1] / small_apply[1],
        big = large.levels + 3,
    );
}

fn subdivision(c: &mut Criterion) {
    report_motion_overhead();
    report_large_subdivisions();
    let poses = cycle(&mut Rng(7), 32);
    let mut g = c.benchmark_group("subdivide 32 poses x 6 levels");
    for rules in [Rules::Direct, Rules::SplitThenTweak] {
        for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
            let s = Subdivision::new(scheme, rules, 6);
            // Each result is dropped before the next subdivision, as in an interactive loop.
            // (`iter_batched` would keep a batch of results alive, so that each subdivision
            // timed the page faults of fresh memory for its result.)
            g.bench_function(format!("{scheme} {rules}"), |bench| {
                bench.iter(|| black_box(s.apply(black_box(&poses), true).unwrap()))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, screws, subdivision);
criterion_main!(benches);
