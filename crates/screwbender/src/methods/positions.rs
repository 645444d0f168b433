//! Catmull–Rom interpolation of points: the translation part of the decoupled methods and of the
//! Ramamoorthi–Barr motion (which, like the paper's animations, interpolates the origins simply).

use glam::DVec3;

use crate::error::{check_finite, Error, ErrorKind};
use crate::timing::check_increasing_times;

/// A C¹ cubic Hermite interpolant of points `p_i` at times `t_i` with Catmull–Rom tangents
/// `m_i = (p_{i+1} − p_{i−1}) / (t_{i+1} − t_{i−1})` (the central difference; for uniform times
/// `(p_{i+1} − p_{i−1})/2`).
///
/// Open: end tangents are the one-sided chords `(p_1 − p_0)/(t_1 − t_0)` and
/// `(p_n − p_{n−1})/(t_n − t_{n−1})` (as if reflected phantom points `2p_0 − p_1` were added), so
/// uniformly sampled straight lines are reproduced exactly. Closed: indices wrap, with the
/// period end `t_n` as the time of `p_0` after one cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct CatmullRom {
    /// Knot times; for a closed curve one more than points (the period end).
    times: Vec<f64>,
    points: Vec<DVec3>,
    tangents: Vec<DVec3>,
    closed: bool,
}

impl CatmullRom {
    /// The interpolant. `times` must be finite, strictly increasing and have `points.len()`
    /// entries (open) or `points.len() + 1` (closed, the last being the period end); at least 2
    /// finite points. Errors name `points`, `points[i]`, `times` or `times[i]`.
    pub fn new(times: &[f64], points: &[DVec3], closed: bool) -> Result<CatmullRom, Error> {
        let n = points.len();
        if n < 2 {
            return Err(Error::new(
                "points",
                ErrorKind::TooFewPoses { found: n, min: 2 },
            ));
        }
        if times.len() != n + usize::from(closed) {
            return Err(Error::new(
                "times",
                ErrorKind::OutOfRange {
                    value: format!("{} times", times.len()),
                    expected: format!(
                        "{} (one per point{})",
                        n + usize::from(closed),
                        if closed { " plus the period end" } else { "" }
                    ),
                },
            ));
        }
        for (i, p) in points.iter().enumerate() {
            check_finite(&p.to_array(), &format!("points[{i}]"))?;
        }
        check_increasing_times(times, "")?;
        let tangents = (0..n)
            .map(|i| {
                if closed {
                    let period = times[n] - times[0];
                    let (tp, pp) = if i == 0 {
                        (times[n - 1] - period, points[n - 1])
                    } else {
                        (times[i - 1], points[i - 1])
                    };
                    let tn = times[i + 1];
                    let pn = points[(i + 1) % n];
                    (pn - pp) / (tn - tp)
                } else if i == 0 {
                    (points[1] - points[0]) / (times[1] - times[0])
                } else if i == n - 1 {
                    (points[n - 1] - points[n - 2]) / (times[n - 1] - times[n - 2])
                } else {
                    (points[i + 1] - points[i - 1]) / (times[i + 1] - times[i - 1])
                }
            })
            .collect();
        Ok(CatmullRom {
            times: times.to_vec(),
            points: points.to_vec(),
            tangents,
            closed,
        })
    }

    /// Position, velocity and acceleration at `t` (closed curves wrap, open ones extrapolate
    /// their end pieces; at a knot the next piece is used).
    pub fn eval(&self, t: f64) -> (DVec3, DVec3, DVec3) {
        let n = self.points.len();
        let pieces = if self.closed { n } else { n - 1 };
        let (t0, tend) = (self.times[0], self.times[pieces]);
        let t = if self.closed && t.is_finite() {
            t0 + (t - t0).rem_euclid(tend - t0)
        } else {
            t
        };
        let j = self
            .times
            .partition_point(|&k| k <= t)
            .saturating_sub(1)
            .min(pieces - 1);
        let dt = self.times[j + 1] - self.times[j];
        let k = (j + 1) % n;
        let [p, v, a, _] = super::polynomial::hermite_d3(
            self.points[j],
            self.tangents[j],
            self.points[k],
            self.tangents[k],
            dt,
            (t - self.times[j]) / dt,
        );
        (p, v, a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_lines_and_interpolates() {
        let pts: Vec<DVec3> = (0..5)
            .map(|i| DVec3::new(i as f64, 2.0 * i as f64, 1.0))
            .collect();
        let times = [0.0, 1.0, 2.0, 3.0, 4.0];
        let c = CatmullRom::new(&times, &pts, false).unwrap();
        for t in [0.0, 0.3, 1.7, 3.99, 4.0] {
            let (p, v, a) = c.eval(t);
            assert!((p - DVec3::new(t, 2.0 * t, 1.0)).length() < 1e-14);
            assert!((v - DVec3::new(1.0, 2.0, 0.0)).length() < 1e-14 && a.length() < 1e-13);
        }
        let ring: Vec<DVec3> = (0..4)
            .map(|i| DVec3::new((i as f64).cos(), (i as f64).sin(), 0.0))
            .collect();
        let c = CatmullRom::new(&[0.0, 1.0, 2.0, 3.0, 4.0], &ring, true).unwrap();
        assert!(CatmullRom::new(&[0.0, 1.0], &ring, true).is_err());
        assert!(CatmullRom::new(&[0.0, 1.0, 1.0, 3.0, 4.0], &ring, true).is_err());
        assert!(CatmullRom::new(&[0.0], &ring[..1], false).is_err());
        for (i, p) in ring.iter().enumerate() {
            assert!((c.eval(i as f64).0 - *p).length() < 1e-15);
        }
        assert!((c.eval(4.0).0 - ring[0]).length() < 1e-15);
        assert!((c.eval(-0.5).0 - c.eval(3.5).0).length() < 1e-15);
        // C¹ at the wrap.
        let (_, v0, _) = c.eval(0.0);
        let (_, v1, _) = c.eval(4.0 - 1e-9);
        assert!((v0 - v1).length() < 1e-7);
    }
}
