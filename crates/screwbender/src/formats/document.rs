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
//! Output always writes `origin` and `rotation`. Errors name the bad element, e.g.
//! `poses[3].rotation: zero quaternion`.

use serde::{Deserialize, Serialize};

use crate::error::{Error, ErrorKind};
use crate::pose::Pose;

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
        Ok(MotionDocument {
            name: self.name.clone(),
            closed: self.closed,
            poses,
        })
    }
}

impl MotionDocument {
    /// A document from poses.
    pub fn new(poses: Vec<Pose>, closed: bool) -> MotionDocument {
        MotionDocument {
            name: None,
            closed,
            poses,
        }
    }

    /// Parses and validates a JSON motion document.
    ///
    /// Syntax and type errors carry serde's line/column and, where it can tell, the field; value
    /// errors name the element (`poses[3].rotation: zero quaternion`).
    #[cfg(feature = "json")]
    pub fn from_json(text: &str) -> Result<MotionDocument, Error> {
        if text.len() > MAX_DOCUMENT_BYTES {
            return Err(Error::new(
                "document",
                ErrorKind::OutOfRange {
                    value: format!("{} bytes", text.len()),
                    expected: format!("at most {MAX_DOCUMENT_BYTES} bytes"),
                },
            ));
        }
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
        }
    }

    /// Pretty-printed JSON (two-space indent, one pose per line).
    #[cfg(feature = "json")]
    pub fn to_json(&self) -> String {
        let raw = self.to_raw();
        let mut s = String::from("{\n");
        if let Some(name) = &raw.name {
            s += &format!("  \"name\": {},\n", json_string(name));
        }
        s += &format!("  \"closed\": {},\n  \"poses\": [\n", raw.closed);
        for (i, p) in raw.poses.iter().enumerate() {
            let line = serde_json::to_string(p).expect("finite numbers always serialise");
            s += "    ";
            s += &line;
            s += if i + 1 < raw.poses.len() { ",\n" } else { "\n" };
        }
        s += "  ]\n}\n";
        s
    }
}

#[cfg(feature = "json")]
fn json_string(s: &str) -> String {
    serde_json::to_string(s).expect("strings always serialise")
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
