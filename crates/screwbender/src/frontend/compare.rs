//! The method comparison as every front end asks for it: a list of method names (or none: every
//! method that applies) and body points, resolved and run the same way, so that the CLI's
//! `compare`, JavaScript's `compareMethods` and Python's `compare_methods` return the same table
//! and refuse the same names with the same words.

use crate::error::{Error, ErrorKind};
use crate::methods::{compare_applicable, compare_methods, Method, MetricsOptions, MetricsTable};
use crate::pose::Pose;

/// The most body points one comparison measures (each adds a trajectory to every metric).
pub const MAX_BODY_POINTS: usize = 16;

/// The methods named in `names`, in order, each measured once; an unknown name is an error at
/// `methods[i]` (its index in the list). A front end whose names come as one comma-separated text
/// (the CLI's `--methods a,b`) splits it first ([`split_names`]).
pub fn parse_methods<S: AsRef<str>>(names: &[S]) -> Result<Vec<Method>, Error> {
    let mut chosen = Vec::with_capacity(names.len());
    for (i, name) in names.iter().enumerate() {
        let m = name
            .as_ref()
            .trim()
            .parse::<Method>()
            .map_err(|e| match e.kind() {
                ErrorKind::UnknownValue { value, expected } => Error::new(
                    format!("methods[{i}]"),
                    ErrorKind::UnknownValue {
                        value: value.clone(),
                        expected,
                    },
                ),
                _ => e.within(&format!("methods[{i}]")),
            })?;
        if !chosen.contains(&m) {
            chosen.push(m);
        }
    }
    Ok(chosen)
}

/// Method names given as texts of comma-separated names (`["rb,cc0", "slerp"]`), as one list.
pub fn split_names<S: AsRef<str>>(texts: &[S]) -> Vec<String> {
    texts
        .iter()
        .flat_map(|t| t.as_ref().split(','))
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(String::from)
        .collect()
}

/// Body points as the front ends receive them (`[x, y, z]` in the body's local frame): 1 to
/// [`MAX_BODY_POINTS`] of them, each finite; the error names `bodyPoints` or `bodyPoints[i]`.
pub fn body_points(points: &[[f64; 3]]) -> Result<Vec<glam::DVec3>, Error> {
    if points.is_empty() || points.len() > MAX_BODY_POINTS {
        return Err(Error::new(
            "bodyPoints",
            ErrorKind::OutOfRange {
                value: format!("{} points", points.len()),
                expected: format!("1 to {MAX_BODY_POINTS} points"),
            },
        ));
    }
    points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            if p.iter().all(|v| v.is_finite()) {
                Ok(glam::DVec3::from_array(*p))
            } else {
                Err(Error::new(format!("bodyPoints[{i}]"), ErrorKind::NonFinite))
            }
        })
        .collect()
}

/// The comparison table of the methods named in `names` on `poses`, or, with `None`, of every
/// method that applies ([`compare_applicable`]: one that does not support these poses is listed
/// as skipped). `body_points` replaces the default body points when given (checked by
/// [`body_points`]).
pub fn compare<S: AsRef<str>>(
    poses: &[Pose],
    closed: bool,
    names: Option<&[S]>,
    body_points: Option<&[[f64; 3]]>,
) -> Result<MetricsTable, Error> {
    let mut options = MetricsOptions::default();
    if let Some(points) = body_points {
        options.body_points = self::body_points(points)?;
    }
    match names {
        None => compare_applicable(poses, closed, &options),
        Some(names) => compare_methods(poses, closed, &parse_methods(names)?, &options),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn body_points_are_counted_then_checked_one_by_one() {
        let ok = body_points(&[[0.0, 1.0, 2.0], [3.0, 4.0, 5.0]]).unwrap();
        assert_eq!(
            ok,
            vec![
                glam::DVec3::new(0.0, 1.0, 2.0),
                glam::DVec3::new(3.0, 4.0, 5.0)
            ]
        );
        let none = body_points(&[]).unwrap_err();
        assert_eq!(none.path(), "bodyPoints");
        assert!(none.to_string().contains("1 to 16 points"), "{none}");
        let many = body_points(&[[0.0; 3]; MAX_BODY_POINTS + 1]).unwrap_err();
        assert!(many.to_string().contains("17 points"), "{many}");
        assert!(body_points(&[[0.0; 3]; MAX_BODY_POINTS]).is_ok());
        let bad = body_points(&[[0.0; 3], [1.0, f64::NAN, 0.0]]).unwrap_err();
        assert_eq!(bad.path(), "bodyPoints[1]");
        assert!(matches!(bad.kind(), ErrorKind::NonFinite));
    }
}
