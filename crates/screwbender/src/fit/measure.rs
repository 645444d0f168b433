//! How far a given motion — control poses with key times, as a fit or a reduction leaves them —
//! is from measured poses: the residual report of [`fit_poses`](super::fit_poses), for a motion
//! that did not come out of this fit (a lesson checks the motion a student made, whichever way
//! it was made).

use super::model::{FitMethod, Model};
use super::residual::FitReport;
use super::{as_open, check_input, key_times};
use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;

/// The residuals of the motion of `method` whose control poses are those of `controls` against
/// the poses of `samples` at their times — the report [`fit_poses`](super::fit_poses) gives for
/// its own result (`iterations` 0).
///
/// Control pose `k` is reached at key time `controls.times[k]` (without times: spread uniformly
/// over the samples' times, as a fit places them); a sample at time `t` is compared with the
/// motion at the parameter `u` that is linear in time between consecutive key times, so a fit's
/// document is measured exactly as the fit measured it. Samples before the first or after the
/// last key time are compared with the motion's ends. A closed `controls` document is measured
/// as the open sequence of its poses, as a fit would produce it.
///
/// Errors (nothing is measured): `controls` with fewer than 2 poses, a pose or time that is not
/// finite, times not strictly increasing or not one per pose (`controls.poses[i]`,
/// `controls.times[i]`); the same for `samples` (`samples.…`); `radius` not a finite number > 0.
pub fn measure_fit(
    controls: &MotionDocument,
    samples: &MotionDocument,
    method: FitMethod,
    radius: f64,
) -> Result<FitReport, Error> {
    if !(radius.is_finite() && radius > 0.0) {
        return Err(Error::new(
            "radius",
            ErrorKind::OutOfRange {
                value: radius.to_string(),
                expected: "a finite number > 0 (scene units)".into(),
            },
        ));
    }
    let (controls, samples) = (as_open(controls), as_open(samples));
    check_input(&controls).map_err(|e| e.within("controls"))?;
    check_input(&samples).map_err(|e| e.within("samples"))?;
    let m = controls.poses.len();
    let keys = match &controls.times {
        Some(t) => t.clone(),
        None => key_times(&samples, m),
    };
    let model = Model::build(method, &controls.poses)?;
    let fitted = times_of(&samples)
        .into_iter()
        .map(|t| model.pose_at(parameter_at(&keys, t)));
    Ok(FitReport::measure(fitted, &samples.poses, radius, m, 0))
}

/// The sample times (`doc.times`, or one second apart).
fn times_of(doc: &MotionDocument) -> Vec<f64> {
    match &doc.times {
        Some(t) => t.clone(),
        None => (0..doc.poses.len()).map(|i| i as f64).collect(),
    }
}

/// The parameter `u ∈ [0, m − 1]` of time `t` for key times `keys` (strictly increasing):
/// `k + (t − T_k) / (T_{k+1} − T_k)` on the key span holding `t`, clamped at the ends.
fn parameter_at(keys: &[f64], t: f64) -> f64 {
    let last = keys.len() - 1;
    if t <= keys[0] {
        return 0.0;
    }
    if t >= keys[last] {
        return last as f64;
    }
    let k = keys.partition_point(|&x| x <= t) - 1;
    k as f64 + (t - keys[k]) / (keys[k + 1] - keys[k])
}

#[cfg(test)]
mod tests {
    use super::super::{fit_poses, ControlCount, FitOptions};
    use super::*;
    use crate::pose::Pose;
    use glam::{DQuat, DVec3};

    /// Samples of a helix at `n` times over 4 s, with a deterministic wobble of `wobble` scene
    /// units in the origins.
    fn helix(n: usize, wobble: f64) -> MotionDocument {
        let poses = (0..n)
            .map(|i| {
                let a = i as f64 / (n - 1) as f64 * 3.0;
                let w = wobble * ((i * 7919 % 13) as f64 / 6.0 - 1.0);
                Pose::new(
                    DVec3::new(2.0 * a.cos() + w, 2.0 * a.sin(), 0.4 * a),
                    DQuat::from_axis_angle(DVec3::Z, a),
                )
            })
            .collect();
        let mut doc = MotionDocument::new(poses, false);
        doc.times = Some((0..n).map(|i| 4.0 * i as f64 / (n - 1) as f64).collect());
        doc
    }

    /// A fit's own document, measured again, gives the fit's report: both place the samples at
    /// the same parameters.
    #[test]
    fn a_fitted_document_measures_as_its_fit_reported() {
        let samples = helix(120, 0.02);
        for method in [FitMethod::ScrewBender, FitMethod::Se3BSpline] {
            let fit = fit_poses(
                &samples,
                &FitOptions {
                    method,
                    controls: ControlCount::Count(8),
                    ..FitOptions::default()
                },
            )
            .unwrap();
            let r = measure_fit(&fit.document, &samples, method, 1.0).unwrap();
            let f = fit.report;
            assert_eq!(r.controls, 8);
            assert_eq!(r.samples, 120);
            for (a, b) in [
                (r.rms_position, f.rms_position),
                (r.max_position, f.max_position),
                (r.rms_angle, f.rms_angle),
                (r.max_angle, f.max_angle),
                (r.rms_deviation, f.rms_deviation),
            ] {
                assert!((a - b).abs() <= 1e-12, "{method:?}: {a} vs {b}");
            }
            // Without its times the document is spread over the samples' times just the same.
            let mut bare = fit.document.clone();
            bare.times = None;
            let r2 = measure_fit(&bare, &samples, method, 1.0).unwrap();
            assert!((r2.rms_position - f.rms_position).abs() <= 1e-12);
        }
    }

    /// Every sample kept as a control pose at its own time: the B-spline passes near, not
    /// through, them (it approximates), so the residual is small but not zero; a wrong timing
    /// (the same poses spread over twice the time) is far off.
    #[test]
    fn key_times_place_the_samples_on_the_motion() {
        let samples = helix(60, 0.0);
        let kept = samples.clone();
        let r = measure_fit(&kept, &samples, FitMethod::ScrewBender, 1.0).unwrap();
        assert!(r.max_position < 0.01, "{r:?}");
        assert!(r.max_angle < 0.01, "{r:?}");
        let mut late = kept.clone();
        late.times = Some(late.times.unwrap().iter().map(|t| 2.0 * t).collect());
        let r = measure_fit(&late, &samples, FitMethod::ScrewBender, 1.0).unwrap();
        assert!(r.max_position > 1.0, "{r:?}");
    }

    #[test]
    fn parameters_are_linear_between_key_times_and_clamped() {
        let keys = [0.0, 1.0, 3.0];
        assert_eq!(parameter_at(&keys, -1.0), 0.0);
        assert_eq!(parameter_at(&keys, 0.5), 0.5);
        assert_eq!(parameter_at(&keys, 2.0), 1.5);
        assert_eq!(parameter_at(&keys, 3.0), 2.0);
        assert_eq!(parameter_at(&keys, 9.0), 2.0);
    }

    #[test]
    fn bad_input_names_the_document_and_element() {
        let samples = helix(10, 0.0);
        let one = MotionDocument::new(vec![Pose::IDENTITY], false);
        let e = measure_fit(&one, &samples, FitMethod::ScrewBender, 1.0).unwrap_err();
        assert_eq!(e.path(), "controls.poses");
        let mut bad = samples.clone();
        bad.times.as_mut().unwrap()[3] = f64::NAN;
        let e = measure_fit(&samples, &bad, FitMethod::ScrewBender, 1.0).unwrap_err();
        assert_eq!(e.path(), "samples.times[3]");
        let e = measure_fit(&samples, &samples, FitMethod::ScrewBender, 0.0).unwrap_err();
        assert_eq!(e.path(), "radius");
    }
}
