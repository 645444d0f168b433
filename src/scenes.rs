//! Preset scenes reproducing the paper's figures (spec `scenes.md`, part A).
//!
//! The papers publish no pose data; these values were chosen by the spec to match each figure's
//! description. Poses are computed from their definitions (`Rz(90°·i)`, …) rather than copied
//! from the six-decimal tables, so circles and helices are exact to rounding.

use glam::{DQuat, DVec2, DVec3};
use serde::Serialize;

use crate::pose::Pose;
use crate::scheme::Scheme;

/// The object drawn at each pose of a scene (dimensions in scene units, local frame).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum Shape {
    /// A bar from local `(0,0,0)` to `(length,0,0)` with a square cross-section.
    Bar {
        /// Length along local x.
        length: f64,
        /// Side of the square cross-section.
        section: f64,
    },
    /// A box with the given side lengths; `base` puts the local origin at the centre of its
    /// bottom face (local z up), otherwise at its centre.
    Block {
        /// Side lengths along local x, y, z.
        size: [f64; 3],
        /// Origin at the bottom face instead of the centre.
        base: bool,
    },
    /// A cylinder about local z, centred on the origin.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Height along local z.
        height: f64,
    },
    /// A cone about local z, centred on the origin (apex up).
    Cone {
        /// Base radius.
        radius: f64,
        /// Height along local z.
        height: f64,
    },
    /// A sphere centred on the origin.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// A five-point star prism in the local xy plane, extruded along z, centred.
    StarPrism {
        /// Outer radius of the star points.
        outer: f64,
        /// Inner radius.
        inner: f64,
        /// Thickness along z.
        thickness: f64,
    },
    /// A pendulum: a sphere (bob) at the origin and a rod up to the pivot at `(0,0,rod)`.
    Pendulum {
        /// Rod length.
        rod: f64,
        /// Bob radius.
        bob: f64,
    },
    /// An asymmetric wedge (a stand-in for the paper's bunny), origin at its base.
    Wedge {
        /// Side lengths along local x, y, z.
        size: [f64; 3],
    },
}

/// A preset: control poses, default options and the object to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Identifier used on the command line and in the page (`l_cycle_rotated`, …).
    pub id: &'static str,
    /// The scene's label in `scenes.md` (`A2`, …).
    pub label: &'static str,
    /// Which figure of the paper it reproduces (V1 / V2 numbering).
    pub figure: &'static str,
    /// What the viewer should see.
    pub description: &'static str,
    /// Cycle or open sequence.
    pub closed: bool,
    /// The control poses.
    pub poses: Vec<Pose>,
    /// The scheme the figure uses.
    pub scheme: Scheme,
    /// Default subdivision levels.
    pub levels: u32,
    /// The object to draw.
    pub shape: Shape,
    /// Per-control-pose shapes for the morph scene (A8), else empty.
    pub morph_shapes: Vec<Shape>,
}

/// A planar polygon preset for the polygon view (scene A4).
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonScene {
    /// Identifier (`polygon_l`, `polygon_star`, `polygon_split_tweak`).
    pub id: &'static str,
    /// Which figure it reproduces.
    pub figure: &'static str,
    /// The vertices (cyclic).
    pub vertices: Vec<DVec2>,
}

fn rz(deg: f64) -> DQuat {
    DQuat::from_rotation_z(deg.to_radians())
}
fn rx(deg: f64) -> DQuat {
    DQuat::from_rotation_x(deg.to_radians())
}
fn ry(deg: f64) -> DQuat {
    DQuat::from_rotation_y(deg.to_radians())
}
fn pose(o: [f64; 3], q: DQuat) -> Pose {
    Pose::new(DVec3::from_array(o), q.normalize())
}

const L_ORIGINS: [[f64; 3]; 6] = [
    [0.0, 0.0, 0.0],
    [6.0, 0.0, 0.0],
    [6.0, 2.0, 0.0],
    [2.0, 2.0, 0.0],
    [2.0, 6.0, 0.0],
    [0.0, 6.0, 0.0],
];
const BAR: Shape = Shape::Bar {
    length: 2.0,
    section: 0.3,
};

fn l_cycle(angles: [f64; 6]) -> Vec<Pose> {
    L_ORIGINS
        .iter()
        .zip(angles)
        .map(|(o, a)| pose(*o, rz(a)))
        .collect()
}

fn cylinder5() -> Vec<Pose> {
    vec![
        pose([0.0, 0.0, 0.0], DQuat::IDENTITY),
        pose([4.0, 1.0, 1.0], rz(72.0) * rx(40.0)),
        pose([5.0, 5.0, 2.0], rz(144.0) * ry(45.0)),
        pose([1.0, 6.0, 0.5], rz(216.0) * rx(-35.0)),
        pose([-2.0, 3.0, -1.0], rz(288.0) * ry(-40.0)),
    ]
}

/// All pose scenes A1–A11 (A4, the polygons, are in [`polygon_scenes`]), in `scenes.md` order.
pub fn scenes() -> Vec<Scene> {
    let base = |id, label, figure, description, poses, scheme, shape| Scene {
        id,
        label,
        figure,
        description,
        closed: true,
        poses,
        scheme,
        levels: 5,
        shape,
        morph_shapes: Vec::new(),
    };
    let pivot = DVec3::new(0.0, 0.0, 4.0);
    let pend = |deg: f64| {
        let q = ry(deg);
        Pose::new(pivot + q * DVec3::new(0.0, 0.0, -4.0), q)
    };
    let block = |i: i32| {
        let a = (-90.0 * i as f64).to_radians();
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        pose(
            [1.5 * a.cos(), 1.5 * a.sin(), 0.5 * (i % 2) as f64],
            rz(90.0 * i as f64) * rx(20.0 * sign),
        )
    };
    let circle = |i: i32| {
        let q = rz(90.0 * i as f64);
        Pose::new(q * DVec3::new(3.0, 0.0, 0.0), q)
    };
    let helix = |i: i32| {
        let q = rz(45.0 * i as f64);
        Pose::new(
            q * DVec3::new(3.0, 0.0, 0.0) + DVec3::new(0.0, 0.0, 0.6 * i as f64),
            q,
        )
    };
    vec![
        base(
            "l_cycle_parallel",
            "A1",
            "Fig. 1 (a–e)",
            "Six parallel poses on an L: the smoothed paths equal the polygon subdivision of the origins.",
            l_cycle([0.0; 6]),
            Scheme::FourPoint,
            BAR,
        ),
        base(
            "l_cycle_rotated",
            "A2",
            "Fig. 1 (f–j), Fig. 4, Fig. 8 (V1) / Fig. 7 (V2)",
            "The L cycle with four rotated poses: smooth screw motions; 4-point passes through every control pose.",
            l_cycle([-60.0, 0.0, 0.0, 45.0, 90.0, 45.0]),
            Scheme::FourPoint,
            BAR,
        ),
        base(
            "l_cycle_edit",
            "A3",
            "Fig. 5 (V1) / Fig. 10 (V2)",
            "Interactive editing: drag or rotate the top-left pose; only spans within the locality bound change.",
            l_cycle([-60.0, 0.0, 0.0, 45.0, 90.0, 45.0]),
            Scheme::FourPoint,
            BAR,
        ),
        base(
            "pendulum",
            "A5",
            "Fig. 6 left (V1) / Fig. 5 left (V2)",
            "Two poses, 4-point, cyclic: a smooth pendulum swing about the pivot (0,0,4).",
            vec![pend(-35.0), pend(35.0)],
            Scheme::FourPoint,
            Shape::Pendulum { rod: 4.0, bob: 0.5 },
        ),
        base(
            "spinning_block",
            "A6",
            "Fig. 6 right (V1) / Fig. 5 right (V2)",
            "Four poses, B-spline: a tall block spinning a full turn per cycle while wobbling.",
            (0..4).map(block).collect(),
            Scheme::BSpline,
            Shape::Block {
                size: [0.6, 0.6, 2.4],
                base: true,
            },
        ),
        base(
            "cylinder5",
            "A7",
            "Fig. 7a (V1) / Fig. 6a (V2)",
            "Five poses, non-planar cycle: a cylinder tumbling smoothly through the control poses.",
            cylinder5(),
            Scheme::FourPoint,
            Shape::Cylinder {
                radius: 0.5,
                height: 2.0,
            },
        ),
        Scene {
            morph_shapes: vec![
                Shape::Cone {
                    radius: 0.6,
                    height: 1.5,
                },
                Shape::StarPrism {
                    outer: 0.8,
                    inner: 0.35,
                    thickness: 0.4,
                },
                Shape::Block {
                    size: [1.0, 0.6, 1.4],
                    base: false,
                },
                Shape::Cylinder {
                    radius: 0.5,
                    height: 1.5,
                },
                Shape::Sphere { radius: 0.7 },
            ],
            ..base(
                "pip_morph5",
                "A8",
                "Fig. 7b (V1) / Fig. 6b (V2)",
                "The cylinder motion with a different shape at each control pose, morphing in between.",
                cylinder5(),
                Scheme::FourPoint,
                Shape::Cylinder {
                    radius: 0.5,
                    height: 1.5,
                },
            )
        },
        base(
            "circle4",
            "A9",
            "Fig. 9 (V1) / Fig. 8 (V2)",
            "Four poses on a circle: every screw scheme keeps the circle exactly; decoupled smoothing does not.",
            (0..4).map(circle).collect(),
            Scheme::FourPoint,
            Shape::Block {
                size: [1.0, 0.4, 0.4],
                base: false,
            },
        ),
        base(
            "bunny6",
            "A10",
            "Fig. 9 (V2)",
            "Six non-planar poses with inconsistent rotations: the polyscrew has corners, 4-point is smooth.",
            vec![
                pose([0.0, 0.0, 0.0], DQuat::IDENTITY),
                pose([3.0, -1.0, 1.0], rz(30.0) * rx(25.0)),
                pose([6.0, 0.5, 2.0], rz(-20.0) * ry(-30.0)),
                pose([6.5, 4.0, 1.0], rz(40.0) * rx(-35.0)),
                pose([3.0, 5.5, 0.0], rz(-30.0) * ry(30.0)),
                pose([0.0, 3.5, 1.5], rz(20.0) * rx(20.0)),
            ],
            Scheme::FourPoint,
            Shape::Wedge {
                size: [1.2, 0.6, 0.8],
            },
        ),
        Scene {
            closed: false,
            levels: 4,
            ..base(
                "helix_open",
                "A11",
                "open-sequence rule (spec §7)",
                "Six poses sampled from a helix, open: every scheme reproduces the helix exactly.",
                (0..6).map(helix).collect(),
                Scheme::FourPoint,
                BAR,
            )
        },
    ]
}

/// The scene with this id, if any.
pub fn scene(id: &str) -> Option<Scene> {
    scenes().into_iter().find(|s| s.id == id)
}

/// The planar polygon presets of scene A4 (paper Figs. 2–3).
pub fn polygon_scenes() -> Vec<PolygonScene> {
    let v = |pts: &[[f64; 2]]| pts.iter().map(|p| DVec2::from_array(*p)).collect();
    vec![
        PolygonScene {
            id: "polygon_l",
            figure: "Fig. 2",
            vertices: v(&[
                [0.0, 0.0],
                [6.0, 0.0],
                [6.0, 2.0],
                [2.0, 2.0],
                [2.0, 6.0],
                [0.0, 6.0],
            ]),
        },
        PolygonScene {
            id: "polygon_star",
            figure: "Fig. 2",
            // A five-point star, outer radius 5, inner 2, first point up.
            vertices: (0..10)
                .map(|k| {
                    let r = if k % 2 == 0 { 5.0 } else { 2.0 };
                    let a = (90.0 + 36.0 * k as f64).to_radians();
                    DVec2::new(r * a.cos(), r * a.sin())
                })
                .collect(),
        },
        PolygonScene {
            id: "polygon_split_tweak",
            figure: "Fig. 3",
            vertices: v(&[[0.0, 0.0], [4.0, 0.0], [5.0, 3.0], [2.0, 5.0], [-1.0, 3.0]]),
        },
    ]
}

/// The named objects of the playground's object menu (`bar`, `block`, `cylinder`, `cone`,
/// `sphere`, `star`, `pendulum`, `wedge`) with their default dimensions.
pub fn object_shape(kind: &str) -> Option<Shape> {
    Some(match kind {
        "bar" => Shape::Bar {
            length: 2.0,
            section: 0.3,
        },
        "block" => Shape::Block {
            size: [1.2, 0.6, 0.4],
            base: false,
        },
        "cylinder" => Shape::Cylinder {
            radius: 0.4,
            height: 1.6,
        },
        "cone" => Shape::Cone {
            radius: 0.5,
            height: 1.4,
        },
        "sphere" => Shape::Sphere { radius: 0.5 },
        "star" => Shape::StarPrism {
            outer: 0.8,
            inner: 0.35,
            thickness: 0.3,
        },
        "pendulum" => Shape::Pendulum { rod: 4.0, bob: 0.5 },
        "wedge" => Shape::Wedge {
            size: [1.2, 0.6, 0.8],
        },
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(p: &Pose, o: [f64; 3], q: [f64; 4]) -> bool {
        let expect = Pose::new(
            DVec3::from_array(o),
            DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize(),
        );
        p.approx_eq(&expect, 2e-6)
    }

    /// The computed poses agree with the six-decimal tables of `scenes.md`.
    #[test]
    #[allow(clippy::approx_constant)] // the tables' printed values are the point of the test
    fn scenes_match_the_spec_tables() {
        let s = scene("l_cycle_rotated").unwrap();
        assert!(close(
            &s.poses[0],
            [0.0, 0.0, 0.0],
            [0.866025, 0.0, 0.0, -0.5]
        ));
        assert!(close(
            &s.poses[4],
            [2.0, 6.0, 0.0],
            [0.707107, 0.0, 0.0, 0.707107]
        ));
        let s = scene("pendulum").unwrap();
        assert!(close(
            &s.poses[0],
            [2.294306, 0.0, 0.723392],
            [0.953717, 0.0, -0.300706, 0.0]
        ));
        let s = scene("spinning_block").unwrap();
        assert!(close(
            &s.poses[1],
            [0.0, -1.5, 0.5],
            [0.696364, -0.122788, -0.122788, 0.696364]
        ));
        assert!(close(
            &s.poses[3],
            [0.0, 1.5, 0.5],
            [0.696364, -0.122788, 0.122788, -0.696364]
        ));
        let s = scene("cylinder5").unwrap();
        assert!(close(
            &s.poses[2],
            [5.0, 5.0, 2.0],
            [0.285494, -0.363954, 0.118256, 0.878662]
        ));
        assert!(close(
            &s.poses[3],
            [1.0, 6.0, 0.5],
            [0.294715, -0.092923, 0.285988, -0.907039]
        ));
        let s = scene("bunny6").unwrap();
        assert!(close(
            &s.poses[3],
            [6.5, 4.0, 1.0],
            [0.896201, -0.282571, -0.102847, 0.326190]
        ));
        let s = scene("helix_open").unwrap();
        assert!(!s.closed);
        assert!(close(
            &s.poses[5],
            [-2.121320, -2.121320, 3.0],
            [0.382683, 0.0, 0.0, -0.923880]
        ));
        let s = scene("circle4").unwrap();
        assert!(close(&s.poses[2], [-3.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]));
        let star = &polygon_scenes()[1].vertices;
        assert!((star[1] - DVec2::new(-1.175571, 1.618034)).length() < 2e-6);
        assert!((star[4] - DVec2::new(-2.938926, -4.045085)).length() < 2e-6);
    }

    #[test]
    fn ids_are_unique() {
        let all = scenes();
        for (i, a) in all.iter().enumerate() {
            assert!(all[i + 1..].iter().all(|b| b.id != a.id));
        }
        assert_eq!(all.len(), 10);
    }
}
