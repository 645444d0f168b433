//! CSV for plotting tools and spreadsheets: control poses in, sampled poses and body-point
//! trajectories out.
//!
//! Input ([`parse_csv_poses`]): one pose per line, `x,y,z,qw,qx,qy,qz` (quaternion scalar first),
//! `#` starts a comment, blank lines are skipped. An optional header line names the columns; with
//! a header the columns may come in any order and extra columns (such as `t,u` of
//! [`poses_csv`]'s output) are ignored, so exported samples read back. A header may also name a
//! `time` column (seconds, every row) and a `velocity` column (poses per second, blank where
//! free): the key times and velocities of [`control_poses_csv`]'s output, so a design reads back
//! whole. A last pose repeating the first (within [`crate::REPEAT_TOLERANCE`]) marks a cycle and
//! is dropped (its time is the cycle's end time). Errors name the line (`line 3`) and column.

use std::io::{self, Write};

use glam::DVec3;

use crate::error::{Error, ErrorKind};
use crate::formats::document::MotionDocument;
use crate::formats::keyframes::{last_repeats_first, MAX_KEYFRAME_FILE_BYTES};
use crate::formats::sampling::Sample;
use crate::pose::Pose;

/// Largest CSV text accepted by [`parse_csv_poses`], in bytes (the glTF limit, 64 MiB).
pub const MAX_CSV_BYTES: usize = MAX_KEYFRAME_FILE_BYTES;

/// The pose columns, in the headerless order.
pub const POSE_COLUMNS: [&str; 7] = ["x", "y", "z", "qw", "qx", "qy", "qz"];

/// Parses control poses from CSV text (see the module docs).
///
/// Errors: text over [`MAX_CSV_BYTES`] (`csv`); a missing column, text in a number field, a
/// header without one of the pose columns ([`ErrorKind::Parse`](crate::ErrorKind::Parse) at `line N`); NaN or infinity
/// ([`ErrorKind::NonFinite`](crate::ErrorKind::NonFinite) at `line N, column qw`); a bad quaternion (`line N.rotation: zero quaternion`);
/// fewer than 2 poses.
pub fn parse_csv_poses(text: &str) -> Result<MotionDocument, Error> {
    crate::error::check_size(text.len(), MAX_CSV_BYTES, "csv")?;
    // Column index of x, y, z, qw, qx, qy, qz, and how many fields a line must have.
    let mut columns: Option<([usize; 7], usize)> = None;
    // Column index of the key times and velocities, when the header names them.
    let (mut time_col, mut velocity_col) = (None, None);
    let mut times = Vec::new();
    let mut velocities: Vec<Option<f64>> = Vec::new();
    let mut poses = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let at = format!("line {}", i + 1);
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if columns.is_none() && poses.is_empty() && fields[0].parse::<f64>().is_err() {
            // A header: every pose column must be named.
            let mut map = [0; 7];
            for (k, name) in POSE_COLUMNS.iter().enumerate() {
                map[k] = fields
                    .iter()
                    .position(|f| f.eq_ignore_ascii_case(name))
                    .ok_or_else(|| {
                        Error::new(
                            at.clone(),
                            ErrorKind::Parse {
                                message: format!(
                                    "header has no column '{name}' (expected {})",
                                    POSE_COLUMNS.join(",")
                                ),
                            },
                        )
                    })?;
            }
            columns = Some((map, fields.len()));
            let named = |n: &str| fields.iter().position(|f| f.eq_ignore_ascii_case(n));
            time_col = named("time");
            velocity_col = named("velocity");
            continue;
        }
        let (map, width) = *columns.get_or_insert(([0, 1, 2, 3, 4, 5, 6], 7));
        if fields.len() < width {
            return Err(Error::new(
                at,
                ErrorKind::Parse {
                    message: format!(
                        "{} field(s), expected {width} ({})",
                        fields.len(),
                        POSE_COLUMNS.join(",")
                    ),
                },
            ));
        }
        let mut v = [0.0; 7];
        for (k, &c) in map.iter().enumerate() {
            let name = POSE_COLUMNS[k];
            let x: f64 = fields[c].parse().map_err(|_| {
                Error::new(
                    format!("{at}, column {name}"),
                    ErrorKind::Parse {
                        message: format!("'{}' is not a number", fields[c]),
                    },
                )
            })?;
            if !x.is_finite() {
                return Err(Error::new(
                    format!("{at}, column {name}"),
                    ErrorKind::NonFinite,
                ));
            }
            v[k] = x;
        }
        let number = |c: usize, name: &str| -> Result<Option<f64>, Error> {
            let f = fields.get(c).copied().unwrap_or("");
            if f.is_empty() {
                return Ok(None);
            }
            let x: f64 = f.parse().map_err(|_| {
                Error::new(
                    format!("{at}, column {name}"),
                    ErrorKind::Parse {
                        message: format!("'{f}' is not a number"),
                    },
                )
            })?;
            if !x.is_finite() {
                return Err(Error::new(
                    format!("{at}, column {name}"),
                    ErrorKind::NonFinite,
                ));
            }
            Ok(Some(x))
        };
        if let Some(c) = time_col {
            let t = number(c, "time")?.ok_or_else(|| {
                Error::new(
                    format!("{at}, column time"),
                    ErrorKind::Parse {
                        message: "no time (every row of a time column needs one)".into(),
                    },
                )
            })?;
            times.push(t);
        }
        if let Some(c) = velocity_col {
            velocities.push(number(c, "velocity")?);
        }
        let pose = Pose::from_wxyz([v[0], v[1], v[2]], [v[3], v[4], v[5], v[6]]).map_err(|e| {
            // Name the line, not an empty path.
            e.within(&at)
        })?;
        poses.push(pose);
    }
    let repeats = last_repeats_first(&poses);
    if repeats {
        poses.pop();
        // The repeated row's time ends the cycle (n + 1 times); a cycle has n velocities.
        velocities.truncate(poses.len());
    }
    if poses.len() < 2 {
        return Err(Error::new(
            "csv",
            ErrorKind::TooFewPoses {
                found: poses.len(),
                min: 2,
            },
        ));
    }
    let mut doc = MotionDocument::new(poses, repeats);
    if time_col.is_some() {
        doc.times = Some(times);
    }
    if velocities.iter().any(Option::is_some) {
        doc.velocities = Some(velocities);
    }
    Ok(doc)
}

/// The control poses of `doc` as CSV, header `x,y,z,qw,qx,qy,qz,time,velocity`: one row per
/// pose with its key time (seconds; one per span from 0 when the document has none) and
/// velocity (blank where free), and for a cycle a last row repeating pose 0 at the cycle's end
/// time. [`parse_csv_poses`] reads it back to the same document (full `f64` precision).
pub fn control_poses_csv(doc: &MotionDocument) -> String {
    let n = doc.poses.len();
    let rows = n + usize::from(doc.closed);
    let mut out = String::from("x,y,z,qw,qx,qy,qz,time,velocity\n");
    for k in 0..rows {
        let p = &doc.poses[k % n];
        let (o, q) = (p.origin, p.rotation);
        let t = doc.times.as_ref().map_or(k as f64, |t| t[k]);
        let v = if k < n {
            doc.velocities
                .as_ref()
                .and_then(|v| v[k])
                .map_or(String::new(), |v| v.to_string())
        } else {
            String::new()
        };
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{t},{v}\n",
            o.x, o.y, o.z, q.w, q.x, q.y, q.z
        ));
    }
    out
}

/// Sampled poses as CSV: header `t,u,x,y,z,qw,qx,qy,qz`, one sample per line (full `f64`
/// precision, shortest round-trip form).
pub fn poses_csv(samples: &[Sample]) -> String {
    to_text(|w| write_poses_csv(w, samples))
}

/// Writes [`poses_csv`]'s text to `w` line by line, without building it in memory first.
///
/// Errors: only those of `w`.
pub fn write_poses_csv<W: Write + ?Sized>(w: &mut W, samples: &[Sample]) -> io::Result<()> {
    w.write_all(b"t,u,x,y,z,qw,qx,qy,qz\n")?;
    for p in samples {
        let [x, y, z] = p.pose.origin.to_array();
        let [qw, qx, qy, qz] = p.pose.rotation_wxyz();
        writeln!(w, "{},{},{x},{y},{z},{qw},{qx},{qy},{qz}", p.time, p.u)?;
    }
    Ok(())
}

/// The world trajectory of the body point `local` as CSV: header `t,u,x,y,z`.
pub fn trajectory_csv(samples: &[Sample], local: DVec3) -> String {
    to_text(|w| write_trajectory_csv(w, samples, local))
}

/// Writes [`trajectory_csv`]'s text to `w` line by line, without building it in memory first.
///
/// Errors: only those of `w`.
pub fn write_trajectory_csv<W: Write + ?Sized>(
    w: &mut W,
    samples: &[Sample],
    local: DVec3,
) -> io::Result<()> {
    w.write_all(b"t,u,x,y,z\n")?;
    for p in samples {
        let q = p.pose.transform_point(local);
        writeln!(w, "{},{},{},{},{}", p.time, p.u, q.x, q.y, q.z)?;
    }
    Ok(())
}

/// The text a writer of this module produces (they write only UTF-8, and a `Vec` never fails).
fn to_text(write: impl FnOnce(&mut Vec<u8>) -> io::Result<()>) -> String {
    let mut out = Vec::new();
    write(&mut out).expect("writing to memory cannot fail");
    String::from_utf8(out).expect("the CSV writers write UTF-8")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headerless_with_comments() {
        let doc = parse_csv_poses("# poses\n0,0,0,1,0,0,0\n\n1,0,0, 1,0,0,0 # moved\n").unwrap();
        assert_eq!(doc.poses.len(), 2);
        assert!(!doc.closed);
        assert_eq!(doc.poses[1].origin.x, 1.0);
    }

    #[test]
    fn header_in_any_order_and_repeat_closes() {
        let text = "t,qw,qx,qy,qz,x,y,z\n0,1,0,0,0,0,0,0\n1,1,0,0,0,1,0,0\n2,1,0,0,0,1,1,0\n\
                    3,1,0,0,0,0,0,0\n";
        let doc = parse_csv_poses(text).unwrap();
        assert!(doc.closed);
        assert_eq!(doc.poses.len(), 3);
        assert_eq!(doc.poses[2].origin.y, 1.0);
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = parse_csv_poses("0,0,0,1,0,0,0\n1,0,0,1,0,0\n").unwrap_err();
        assert_eq!(e.path(), "line 2");
        let e = parse_csv_poses("0,0,0,1,0,0,0\n1,0,abc,1,0,0,0\n").unwrap_err();
        assert_eq!(e.path(), "line 2, column z");
        let e = parse_csv_poses("0,0,0,1,0,0,0\n1,0,0,NaN,0,0,0\n").unwrap_err();
        assert_eq!(e.path(), "line 2, column qw");
        let e = parse_csv_poses("0,0,0,1,0,0,0\n1,0,0,0,0,0,0\n").unwrap_err();
        assert_eq!(e.to_string(), "line 2.rotation: zero quaternion");
        let e = parse_csv_poses("x,y,z,qw\n").unwrap_err();
        assert_eq!(e.path(), "line 1");
        assert!(parse_csv_poses("0,0,0,1,0,0,0\n").is_err());
    }
}
