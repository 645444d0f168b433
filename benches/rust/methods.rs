//! Benchmarks of the comparison methods: the Ramamoorthi–Barr construction on scene C1
//! `rb_sphere7` (7 keyframes, zero end velocities, α = 1000, S = 5) up to 4 variable frames, the
//! Chaudhry–Cameron fits of scene B1 `triangle7`, evaluation of each peer, and the whole metrics
//! table on scene A2 `l_cycle_rotated`; and on that scene the SE(3) cumulative B-spline evaluated
//! at as many parameters as ScrewBender's B-spline subdivision makes poses at 17 levels (786 432);
//! and the fit of 10 000 samples by 50 control poses of either motion (`fit`).
//!
//! Run: `cargo bench --bench methods`. Inputs are fixed (scene data); nothing is random.
//! Native only: criterion is not a wasm32 dependency, so on wasm32 this is an empty program.

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::hint::black_box;

    use criterion::{criterion_group, Criterion};
    use glam::{DQuat, DVec3};
    use screwbender::methods::{
        compare_methods, fit_quaternion_spline, Continuity, EndCondition, Method, MetricsOptions,
        RationalMotion, ReferenceTriangle, Se3BSpline, TriangleSample,
    };
    use screwbender::{Motion, Pose, Rules, Scheme, ScrewBender, Subdivision};

    use testkit::methods::{sphere7, sphere7_options};

    fn triangle7() -> Vec<TriangleSample> {
        (0..7)
            .map(|i| {
                let t = 0.2 * i as f64;
                let axis = DVec3::new((2.0 * t).sin(), 0.5, t.cos()).normalize();
                let a = DVec3::new(2.0 * t, 0.8 * (3.0 * t).sin(), 0.5 * t * t);
                let pose = Pose::new(a, DQuat::from_axis_angle(axis, 2.2 * t));
                TriangleSample::from_pose(t, &pose, &ReferenceTriangle::SCENE_B1)
            })
            .collect()
    }

    fn l_cycle_rotated() -> Vec<Pose> {
        screwbender::presets::preset("l_cycle_rotated")
            .expect("preset A2 exists")
            .poses
    }

    /// Evaluates 1000 poses `step` apart and sums their origins (so none is optimised away).
    fn sum_origins(m: &dyn Motion, step: f64) -> DVec3 {
        (0..1000).fold(DVec3::ZERO, |acc, i| {
            acc + black_box(m.pose_at(i as f64 * step)).origin
        })
    }

    fn ramamoorthi_barr(c: &mut Criterion) {
        let (t, k) = sphere7();
        let mut g = c.benchmark_group("ramamoorthi-barr rb_sphere7");
        g.sample_size(20);
        g.bench_function("keyframe velocities only", |b| {
            b.iter(|| {
                fit_quaternion_spline(black_box(&t), black_box(&k), false, &sphere7_options(0))
            })
        });
        g.bench_function("+4 variable frames (incremental)", |b| {
            b.iter(|| {
                fit_quaternion_spline(black_box(&t), black_box(&k), false, &sphere7_options(4))
            })
        });
        g.finish();
    }

    fn chaudhry_cameron(c: &mut Criterion) {
        let s = triangle7();
        let mut g = c.benchmark_group("chaudhry-cameron triangle7");
        for (name, cont) in [
            ("fit C0", Continuity::C0),
            (
                "fit C1 (18)",
                Continuity::C1(EndCondition::ZeroCurvatureStart),
            ),
        ] {
            g.bench_function(name, |b| {
                b.iter(|| RationalMotion::fit(black_box(&s), cont))
            });
        }
        let m = RationalMotion::fit(&s, Continuity::C1(EndCondition::ZeroCurvatureStart)).unwrap();
        g.bench_function("1000 poses C1", |b| b.iter(|| sum_origins(&m, 1.2e-3)));
        g.finish();
    }

    fn peers(c: &mut Criterion) {
        let poses = l_cycle_rotated();
        let mut g = c.benchmark_group("1000 poses on l_cycle_rotated");
        for m in [
            Method::Slerp,
            Method::Decoupled,
            Method::Kks,
            Method::Rb,
            Method::Cc0,
        ] {
            let motion = m.build(&poses, true).unwrap();
            g.bench_function(m.name(), |b| b.iter(|| sum_origins(motion.as_ref(), 6e-3)));
        }
        g.finish();
        let mut g = c.benchmark_group("metrics");
        g.sample_size(10);
        g.bench_function("table, all methods, l_cycle_rotated", |b| {
            b.iter(|| {
                compare_methods(
                    black_box(&poses),
                    true,
                    &Method::applicable(true),
                    &MetricsOptions::default(),
                )
            })
        });
        g.finish();
    }

    /// The SE(3) cumulative B-spline against ScrewBender's B-spline subdivision, both producing
    /// `6 · 2¹⁷` poses of the cycle `l_cycle_rotated` (the ratio of the two is the figure of
    /// interest: the spline costs three screws and three compositions per pose, subdivision a few
    /// screws per refined pose and level, shared across the levels).
    fn lie_spline(c: &mut Criterion) {
        const LEVELS: u32 = 17;
        let poses = l_cycle_rotated();
        let count = poses.len() << LEVELS;
        let mut g = c.benchmark_group("786432 poses on l_cycle_rotated");
        g.sample_size(10);
        let spline = Se3BSpline::new(&poses, true).unwrap();
        let step = poses.len() as f64 / count as f64;
        g.bench_function("se3bspline pose_at", |b| {
            b.iter(|| {
                (0..count).fold(DVec3::ZERO, |acc, i| {
                    acc + spline.pose_at(black_box(i as f64 * step)).origin
                })
            })
        });
        g.bench_function("se3bspline kinematics_at", |b| {
            b.iter(|| {
                (0..count).fold(DVec3::ZERO, |acc, i| {
                    acc + spline
                        .kinematics_at(black_box(i as f64 * step), DVec3::ZERO)
                        .unwrap()
                        .acceleration
                })
            })
        });
        g.bench_function("bspline subdivision, 17 levels", |b| {
            b.iter(|| {
                let s = Subdivision::new(Scheme::BSpline, Rules::Direct, LEVELS);
                let sb = ScrewBender::new(black_box(poses.clone()), true, s).unwrap();
                sb.refined().poses().len()
            })
        });
        g.finish();
    }

    /// Fitting (docs/math/fitting.md): 10 000 samples of a wandering SE(3) spline, with a
    /// deterministic wobble of 0.01, fitted by 50 control poses, least squares.
    fn fit(c: &mut Criterion) {
        use screwbender::{fit_poses, ControlCount, FitMethod, FitOptions, MotionDocument};
        let controls: Vec<Pose> = (0..60)
            .map(|k| {
                let a = k as f64 * 0.3;
                Pose::new(
                    DVec3::new(3.0 * a.cos(), 2.0 * a.sin() + 0.2 * a, 0.4 * a),
                    DQuat::from_axis_angle(DVec3::new(0.2, 1.0, 0.4).normalize(), a),
                )
            })
            .collect();
        let truth = Se3BSpline::new(&controls, false).expect("valid controls");
        let n = 10_000;
        let poses: Vec<Pose> = (0..n)
            .map(|i| {
                let mut p = truth.pose_at(59.0 * i as f64 / (n - 1) as f64);
                p.origin.z += 0.01 * (i as f64 * 1.7).sin();
                p
            })
            .collect();
        let doc = MotionDocument::new(poses, false);
        let mut g = c.benchmark_group("fit");
        g.sample_size(10);
        for method in [FitMethod::Se3BSpline, FitMethod::ScrewBender] {
            let options = FitOptions {
                method,
                controls: ControlCount::Count(50),
                ..FitOptions::default()
            };
            g.bench_function(
                format!("{} 10000 samples, 50 controls", method.name()),
                |b| {
                    b.iter(|| {
                        black_box(fit_poses(&doc, &options).expect("fits"))
                            .report
                            .iterations
                    })
                },
            );
        }
        g.finish();
    }

    criterion_group!(
        benches,
        ramamoorthi_barr,
        chaudhry_cameron,
        peers,
        lie_spline,
        fit
    );
}

#[cfg(not(target_arch = "wasm32"))]
criterion::criterion_main!(native::benches);

#[cfg(target_arch = "wasm32")]
fn main() {}
