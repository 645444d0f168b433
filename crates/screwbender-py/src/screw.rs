//! `screw(a, t, b)` on numpy arrays: one pair at one or many fractions (the logarithm computed
//! once), or batches of pairs (the core's SIMD batch route, bit for bit the same screws).

use numpy::PyArrayDyn;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use screwbender::{Blend, Pose, Screw};

use crate::convert::{detached, parameters, pose_array, poses_to_array, shape_text};

/// Pairs per chunk of the batch route: the chunk's poses stay in the nearest caches.
const PAIRS_PER_CHUNK: usize = 256;

/// `screw(a, t, b)`: the pose after the fraction `t` of the screw motion from `a` to `b` (`t = 0`
/// is `a`, `t = 1` is `b`, any real `t` extrapolates). `a`, `b`: one pose each (`(7,)` or
/// `(4, 4)`) with `t` a number or an array, or batches `(n, 7)` / `(n, 4, 4)` (one side may be a
/// single pose) with `t` a number or `(n,)`; rows `x y z qw qx qy qz`.
#[pyfunction]
pub fn screw<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let a = pose_array(a, "a", None)?;
    let (ts, t_shape) = parameters(t, "t")?;
    let b = pose_array(b, "b", None)?;
    match (a.single, b.single) {
        (true, true) => {
            let (start, end) = (a.poses[0], b.poses[0]);
            let poses = detached(py, || {
                if ts.len() == 1 {
                    vec![screwbender::screw(&start, ts[0], &end)]
                } else {
                    let s = Screw::between(&start, &end);
                    ts.iter().map(|&t| s.at(t)).collect()
                }
            })?;
            poses_to_array(py, &t_shape, &poses)
        }
        _ => {
            let n = if a.single {
                b.poses.len()
            } else {
                a.poses.len()
            };
            let counts_match = (a.single || a.poses.len() == n) && (b.single || b.poses.len() == n);
            let t_ok = t_shape.is_empty() || t_shape == [n];
            if !counts_match || !t_ok {
                return Err(PyValueError::new_err(format!(
                    "b: {} start pose(s), {} end pose(s) and t of shape {}: give batches of the same length n (or one pose) and t as a number or of shape ({n},)",
                    a.poses.len(),
                    b.poses.len(),
                    shape_text(&t_shape),
                )));
            }
            let poses = detached(py, || pairs(&a.poses, &ts, &b.poses, n))?;
            poses_to_array(py, &[n], &poses)
        }
    }
}

/// `screw(a[k], t[k], b[k])` for `k < n`; a list of one pose (or one fraction) is used for all.
fn pairs(a: &[Pose], ts: &[f64], b: &[Pose], n: usize) -> Vec<Pose> {
    let pick = |list: &[Pose], k: usize| if list.len() == 1 { 0 } else { k };
    let mut out = Vec::with_capacity(n);
    for first in (0..n).step_by(PAIRS_PER_CHUNK) {
        let last = (first + PAIRS_PER_CHUNK).min(n);
        Pose::blends(
            last - first,
            |k| {
                let k = first + k;
                let t = if ts.len() == 1 { ts[0] } else { ts[k] };
                (&a[pick(a, k)], t, &b[pick(b, k)])
            },
            &mut out,
        );
    }
    out
}
