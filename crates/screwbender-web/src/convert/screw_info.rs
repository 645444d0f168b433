//! A screw's parameters as a plain JavaScript object (`screwInfo`, span screws).

use serde::Serialize;

/// The display parameters of a screw, as the `ScrewInfo` union of the TypeScript types.
#[derive(Serialize)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub(crate) enum ScrewInfo {
    /// The two poses coincide.
    Identity {
        /// Always 0.
        angle: f64,
        /// Always 0.
        slide: f64,
    },
    /// A pure translation.
    Translation {
        /// Unit direction.
        direction: [f64; 3],
        /// Always 0.
        angle: f64,
        /// Translation length.
        slide: f64,
    },
    /// A general screw.
    General {
        /// The paper's axis point `P` (at the height of the origins' midpoint).
        point: [f64; 3],
        /// The axis point closest to the world origin.
        foot: [f64; 3],
        /// Unit axis direction.
        direction: [f64; 3],
        /// Rotation angle in `(0, π]`.
        angle: f64,
        /// Slide along the axis.
        slide: f64,
        /// `slide / angle`.
        pitch: f64,
    },
}

impl From<screwbender::ScrewKind> for ScrewInfo {
    fn from(kind: screwbender::ScrewKind) -> Self {
        match kind {
            screwbender::ScrewKind::Identity => ScrewInfo::Identity {
                angle: 0.0,
                slide: 0.0,
            },
            screwbender::ScrewKind::Translation {
                direction,
                distance,
            } => ScrewInfo::Translation {
                direction: direction.to_array(),
                angle: 0.0,
                slide: distance,
            },
            screwbender::ScrewKind::General(p) => ScrewInfo::General {
                point: p.point.to_array(),
                foot: p.foot.to_array(),
                direction: p.axis.to_array(),
                angle: p.angle,
                slide: p.slide,
                pitch: p.pitch,
            },
        }
    }
}
