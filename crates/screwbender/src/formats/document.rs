//! The JSON motion document: the file format of the CLI, the page and the npm package.
//!
//! ```json
//! {"closed": true,
//!  "poses": [{"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]},
//!            {"origin": [4, 0, 0], "basis": [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]}]}
//! ```
//!
//! A pose gives `origin` and either `rotation` (a unit quaternion `[w, x, y, z]`, scalar first) or
//! `basis` (the three column vectors `I, J, K`). `closed` defaults to `true`; `name` is optional.
//! Optional key timing (docs/math/timing.md): `times` (seconds at which each control pose is
//! reached; a cycle has one more, pose 0 again) and `velocities` (`p'` at each key in poses per
//! second, `null` where free). Output always writes `origin` and `rotation`, and the timing only
//! when the document has one. Errors name the bad element, e.g. `poses[3].rotation: zero
//! quaternion`, `times[2]: …`.

use serde::{Deserialize, Serialize};

use crate::error::{Error, ErrorKind};
use crate::pose::Pose;
use crate::subdivision::Subdivision;
use crate::timing::Timing;

/// Largest motion-document text accepted by [`MotionDocument::from_json`]: 16 MiB (about 150 000
/// poses). Larger input is rejected before parsing.
pub const MAX_DOCUMENT_BYTES: usize = 16 << 20;

/// A motion: control poses and whether they form a cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionDocument {
    /// Optional display name.
    pub name: Option<String>,
    /// Whether the poses form a cycle (the last joined back to the first).
    pub closed: bool,
    /// The control poses.
    pub poses: Vec<Pose>,
    /// When each control pose is reached, in seconds (`n` times for an open motion, `n + 1` for a
    /// cycle); `None`: one second per span from 0.
    pub times: Option<Vec<f64>>,
    /// The velocity `p'` at each key in poses per second (`n` entries, `None` where free);
    /// `None`: all free.
    pub velocities: Option<Vec<Option<f64>>>,
}

/// One pose as it appears in a file, before validation.
///
/// Exactly one of `rotation` and `basis` must be present.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPose {
    /// Origin `[x, y, z]`.
    pub origin: [f64; 3],
    /// Unit quaternion `[w, x, y, z]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotation: Option<[f64; 4]>,
    /// Basis vectors `[I, J, K]` (columns of the rotation matrix).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub basis: Option<[[f64; 3]; 3]>,
}

/// The document as it appears in a file, before validation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDocument {
    /// Optional display name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Cycle or open sequence (default `true`).
    #[serde(default = "default_closed")]
    pub closed: bool,
    /// The poses.
    pub poses: Vec<RawPose>,
    /// Key times in seconds (optional).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub times: Option<Vec<f64>>,
    /// Key velocities in poses per second, `null` where free (optional).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocities: Option<Vec<Option<f64>>>,
}

fn default_closed() -> bool {
    true
}

impl RawPose {
    /// Validates one pose (see [`Pose::from_wxyz`] and [`Pose::from_basis`]).
    pub fn to_pose(&self) -> Result<Pose, Error> {
        match (&self.rotation, &self.basis) {
            (Some(q), None) => Pose::from_wxyz(self.origin, *q),
            (None, Some(b)) => Pose::from_basis(self.origin, *b),
            (Some(_), Some(_)) => Err(Error::new(
                String::new(),
                ErrorKind::Parse {
                    message: "give either 'rotation' or 'basis', not both".into(),
                },
            )),
            (None, None) => Err(Error::new(
                String::new(),
                ErrorKind::Parse {
                    message: "missing 'rotation' (quaternion [w,x,y,z]) or 'basis' ([I,J,K])"
                        .into(),
                },
            )),
        }
    }

    /// The file form of a pose (`origin` + `rotation`).
    pub fn from_pose(p: &Pose) -> RawPose {
        RawPose {
            origin: p.origin.to_array(),
            rotation: Some(p.rotation_wxyz()),
            basis: None,
        }
    }
}

impl RawDocument {
    /// Validates every pose, naming the first bad one (`poses[i]…`).
    pub fn validate(&self) -> Result<MotionDocument, Error> {
        let poses = self
            .poses
            .iter()
            .enumerate()
            .map(|(i, p)| p.to_pose().map_err(|e| e.within(&format!("poses[{i}]"))))
            .collect::<Result<Vec<_>, _>>()?;
        if poses.len() < 2 {
            return Err(Error::new(
                "poses",
                ErrorKind::TooFewPoses {
                    found: poses.len(),
                    min: 2,
                },
            ));
        }
        let doc = MotionDocument {
            name: self.name.clone(),
            closed: self.closed,
            poses,
            times: self.times.clone(),
            velocities: self.velocities.clone(),
        };
        doc.timing()?;
        Ok(doc)
    }
}

impl MotionDocument {
    /// A document from poses.
    pub fn new(poses: Vec<Pose>, closed: bool) -> MotionDocument {
        MotionDocument {
            name: None,
            closed,
            poses,
            times: None,
            velocities: None,
        }
    }

    /// The document's timing (docs/math/timing.md): its key times and velocities, uniform where
    /// absent. Errors name `times`, `times[i]`, `velocities` or `velocities[i]`.
    pub fn timing(&self) -> Result<Timing, Error> {
        Timing::for_keys(
            self.times.clone(),
            self.velocities.as_deref(),
            self.poses.len(),
            self.closed,
        )
    }

    /// Everything that can make this document unusable with `subdivision`: the options'
    /// combination ([`Subdivision::validate`]), the memory guard, which also refuses fewer than
    /// 2 poses ([`Subdivision::output_len`]), and the key timing ([`MotionDocument::timing`]).
    /// The JavaScript and Python motions keep every state they store valid by this check.
    pub fn check_with(&self, subdivision: &Subdivision) -> Result<(), Error> {
        subdivision.validate()?;
        subdivision.output_len(self.poses.len(), self.closed)?;
        self.timing()?;
        Ok(())
    }

    /// Sets the key times and velocities after checking them against the poses (see
    /// [`MotionDocument::timing`]); on an error the document is unchanged.
    pub fn set_timing(
        &mut self,
        times: Option<Vec<f64>>,
        velocities: Option<Vec<Option<f64>>>,
    ) -> Result<(), Error> {
        Timing::for_keys(
            times.clone(),
            velocities.as_deref(),
            self.poses.len(),
            self.closed,
        )?;
        self.times = times;
        self.velocities = velocities;
        Ok(())
    }

    /// Inserts `pose` as control pose `index` (`1 ≤ index ≤ n`, after pose `index − 1`) and
    /// keeps the timing's counts: the new key is reached halfway between its neighbours' times
    /// (one second after the last key at the end of an open motion) with a free velocity.
    pub fn insert_pose(&mut self, index: usize, pose: Pose) {
        let index = index.clamp(1, self.poses.len());
        if let Some(times) = &mut self.times {
            let t = match times.get(index) {
                Some(&next) => 0.5 * (times[index - 1] + next),
                None => times[index - 1] + 1.0,
            };
            times.insert(index, t);
        }
        if let Some(v) = &mut self.velocities {
            v.insert(index.min(v.len()), None);
        }
        self.poses.insert(index, pose);
    }

    /// Removes control pose `index` (`< n`) and its key time and velocity (removing pose 0 of a
    /// timed motion drops its time: the motion then starts at pose 1's time).
    pub fn remove_pose(&mut self, index: usize) {
        if let Some(times) = &mut self.times {
            if index < times.len() {
                times.remove(index);
            }
        }
        if let Some(v) = &mut self.velocities {
            if index < v.len() {
                v.remove(index);
            }
        }
        self.poses.remove(index);
    }

    /// Makes the motion a cycle or an open sequence, keeping the timing's counts: closing adds
    /// the return to pose 0 one mean span after the last time, opening drops it.
    pub fn set_closed(&mut self, closed: bool) {
        if closed != self.closed {
            if let Some(times) = &mut self.times {
                if closed {
                    let (first, last) = (times[0], times[times.len() - 1]);
                    let mean = (last - first) / (times.len() - 1).max(1) as f64;
                    times.push(last + mean);
                } else {
                    times.pop();
                }
            }
        }
        self.closed = closed;
    }

    /// Parses and validates a JSON motion document.
    ///
    /// Syntax and type errors carry serde's line/column and, where it can tell, the field; value
    /// errors name the element (`poses[3].rotation: zero quaternion`).
    #[cfg(feature = "json")]
    pub fn from_json(text: &str) -> Result<MotionDocument, Error> {
        crate::error::check_size(text.len(), MAX_DOCUMENT_BYTES, "document")?;
        let raw: RawDocument = serde_json::from_str(text).map_err(|e| {
            Error::new(
                String::new(),
                ErrorKind::Parse {
                    message: format!("invalid motion document: {e}"),
                },
            )
        })?;
        raw.validate()
    }

    /// The file form (every pose as `origin` + `rotation`).
    pub fn to_raw(&self) -> RawDocument {
        RawDocument {
            name: self.name.clone(),
            closed: self.closed,
            poses: self.poses.iter().map(RawPose::from_pose).collect(),
            times: self.times.clone(),
            velocities: self.velocities.clone(),
        }
    }

    /// Pretty-printed JSON (two-space indent, one pose per line).
    #[cfg(feature = "json")]
    pub fn to_json(&self) -> String {
        let mut out = Vec::new();
        self.write_json(&mut out)
            .expect("writing to memory cannot fail");
        String::from_utf8(out).expect("JSON is UTF-8")
    }

    /// Writes [`MotionDocument::to_json`]'s text to `w` pose by pose, without building it (or
    /// the file form of every pose) in memory first.
    ///
    /// Errors: only those of `w`.
    #[cfg(feature = "json")]
    pub fn write_json<W: std::io::Write + ?Sized>(&self, w: &mut W) -> std::io::Result<()> {
        w.write_all(b"{\n")?;
        if let Some(name) = &self.name {
            w.write_all(b"  \"name\": ")?;
            serde_json::to_writer(&mut *w, name)?;
            w.write_all(b",\n")?;
        }
        writeln!(w, "  \"closed\": {},", self.closed)?;
        if let Some(times) = &self.times {
            w.write_all(b"  \"times\": ")?;
            serde_json::to_writer(&mut *w, times)?;
            w.write_all(b",\n")?;
        }
        if let Some(v) = &self.velocities {
            w.write_all(b"  \"velocities\": ")?;
            serde_json::to_writer(&mut *w, v)?;
            w.write_all(b",\n")?;
        }
        w.write_all(b"  \"poses\": [\n")?;
        for (i, p) in self.poses.iter().enumerate() {
            w.write_all(b"    ")?;
            serde_json::to_writer(&mut *w, &RawPose::from_pose(p))?;
            w.write_all(if i + 1 < self.poses.len() {
                b",\n"
            } else {
                b"\n"
            })?;
        }
        w.write_all(b"  ]\n}\n")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_basis_form() {
        let text = r#"{"closed": false, "poses": [
            {"origin": [0,0,0], "rotation": [1,0,0,0]},
            {"origin": [4,0,0], "basis": [[0,1,0],[-1,0,0],[0,0,1]]}]}"#;
        let doc = MotionDocument::from_json(text).unwrap();
        assert!(!doc.closed);
        let q = doc.poses[1].rotation_wxyz();
        let h = 0.5f64.sqrt();
        assert!((q[0] - h).abs() < 1e-15 && (q[3] - h).abs() < 1e-15);
        let again = MotionDocument::from_json(&doc.to_json()).unwrap();
        assert_eq!(again, doc);
    }

    #[test]
    fn key_timing_round_trips_and_old_files_are_unchanged() {
        let old = "{\n  \"name\": \"x\",\n  \"closed\": false,\n  \"poses\": [\n    \
                   {\"origin\":[0.0,0.0,0.0],\"rotation\":[1.0,0.0,0.0,0.0]},\n    \
                   {\"origin\":[1.0,0.0,0.0],\"rotation\":[1.0,0.0,0.0,0.0]}\n  ]\n}\n";
        let doc = MotionDocument::from_json(old).unwrap();
        assert_eq!(doc.times, None);
        assert_eq!(
            doc.to_json(),
            old,
            "a file without timing is written back byte for byte"
        );
        let timed = old.replace(
            "\"closed\": false,\n",
            "\"closed\": false,\n  \"times\": [0.5,2.0],\n  \"velocities\": [null,0.25],\n",
        );
        let doc = MotionDocument::from_json(&timed).unwrap();
        assert_eq!(doc.times, Some(vec![0.5, 2.0]));
        assert_eq!(doc.velocities, Some(vec![None, Some(0.25)]));
        assert_eq!(doc.to_json(), timed);
        let t = doc.timing().unwrap();
        assert!((t.parameter(2.0).1 - 0.25).abs() < 1e-12);
    }

    #[test]
    fn bad_key_timing_is_named_and_changes_nothing() {
        let base = r#"{"closed": true, "poses": [{"origin":[0,0,0],"rotation":[1,0,0,0]},
            {"origin":[1,0,0],"rotation":[1,0,0,0]}],"#;
        for (extra, path) in [
            (r#""times": [0, 1]}"#, "times"),
            (r#""times": [0, 2, 1]}"#, "times[2]"),
            (r#""velocities": [-1, null]}"#, "velocities[0]"),
            (r#""velocities": [null, 9]}"#, "velocities[1]"),
            (r#""velocities": [null]}"#, "velocities"),
        ] {
            let e = MotionDocument::from_json(&format!("{base}{extra}")).unwrap_err();
            assert_eq!(e.path(), path, "{extra}: {e}");
        }
        let mut doc = MotionDocument::from_json(&format!("{base}\"times\": [0, 1, 3]}}")).unwrap();
        let before = doc.clone();
        assert!(doc.set_timing(Some(vec![0.0, 1.0]), None).is_err());
        assert!(doc
            .set_timing(None, Some(vec![Some(f64::NAN), None]))
            .is_err());
        assert_eq!(doc, before);
        // Editing poses keeps the counts valid.
        doc.insert_pose(1, Pose::IDENTITY);
        assert_eq!(doc.times, Some(vec![0.0, 0.5, 1.0, 3.0]));
        doc.timing().unwrap();
        doc.set_closed(false);
        doc.timing().unwrap();
        doc.remove_pose(0);
        doc.timing().unwrap();
        doc.set_closed(true);
        doc.timing().unwrap();
    }

    #[test]
    fn errors_name_the_element() {
        let cases = [
            (
                r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]},{"origin":[0,0,0],"rotation":[0,0,0,0]}]}"#,
                "poses[1].rotation: zero quaternion",
            ),
            (
                r#"{"poses":[{"origin":[0,0,0],"rotation":[1,0,0,0]}]}"#,
                "poses: 1 pose(s) given, at least 2 needed",
            ),
            (
                r#"{"poses":[{"origin":[0,0,0]},{"origin":[0,0,0],"rotation":[1,0,0,0]}]}"#,
                "poses[0]: missing 'rotation' (quaternion [w,x,y,z]) or 'basis' ([I,J,K])",
            ),
        ];
        for (text, msg) in cases {
            assert_eq!(
                MotionDocument::from_json(text).unwrap_err().to_string(),
                msg
            );
        }
        let e = MotionDocument::from_json(r#"{"poses":[{"origin":[0,0],"rotation":[1,0,0,0]}]}"#)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("invalid motion document") && e.contains("line 1"),
            "{e}"
        );
        let e = MotionDocument::from_json(r#"{"poses":[], "clossed": true}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("clossed"), "{e}");
    }
}
