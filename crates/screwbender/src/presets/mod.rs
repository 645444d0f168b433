//! Presets: named motions reproducing the papers' figures (docs/math/presets.md §2).
//!
//! The papers publish no pose data; these values were chosen by this project (docs/math/presets.md) to match each figure's
//! description. Poses are computed from their definitions (`Rz(90°·i)`, …) rather than copied
//! from the six-decimal tables, so circles and helices are exact to rounding.

use glam::{DQuat, DVec2, DVec3};
use serde::Serialize;

pub mod display;
pub(crate) mod hull;
pub mod mesh;
pub(crate) mod morph;
pub(crate) mod pieces;
pub(crate) mod trig;

pub use display::{body_points, display, object_body_points, PresetDisplay, DEFAULT_STROBE};

use crate::pose::Pose;
use crate::subdivision::scheme::Scheme;

/// The object drawn at each pose of a preset (dimensions in scene units, local frame).
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
    /// A flat triangle plate with vertices `(0,0,0)`, `x` and `y` (Chaudhry–Cameron's rigid
    /// triangle, scene B1), of the given thickness along local z.
    Triangle {
        /// Second vertex (local).
        x: [f64; 3],
        /// Third vertex (local).
        y: [f64; 3],
        /// Plate thickness.
        thickness: f64,
    },
    /// An I-beam (preset C2): two flanges `flange` (x, y, z sizes) at `z = ±web/2`, joined by a
    /// web of height `web` along local z and section `web_section` (x, y), centred.
    IBeam {
        /// Flange size along local x, y, z.
        flange: [f64; 3],
        /// Web height along local z.
        web: f64,
        /// Web section along local x, y.
        #[serde(rename = "webSection")]
        web_section: [f64; 2],
    },
    /// A benzene-like molecule (preset C3): six atoms on a ring in the local xy plane and one
    /// heavy atom bonded to the first, along +x.
    Molecule {
        /// Ring radius.
        ring: f64,
        /// Radius of the ring atoms (the heavy atom is twice as large).
        atom: f64,
    },
}

/// A preset: control poses, default options and the object to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Preset {
    /// Identifier used on the command line and in the page (`l_cycle_rotated`, …).
    pub id: &'static str,
    /// The preset's label in `presets.md` (`A2`, …).
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
    /// Per-control-pose shapes for the morph preset (A8), else empty.
    pub morph_shapes: Vec<Shape>,
}

/// A planar polygon preset for the polygon view (preset A4).
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonPreset {
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

/// All pose presets A1–A11 (A4, the polygons, are in [`polygon_presets`]), then B1 and C1–C3 (the
/// comparison papers' presets), in `presets.md` order.
pub fn all() -> Vec<Preset> {
    let base = |id, label, figure, description, poses, scheme, shape| Preset {
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
        Preset {
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
        Preset {
            closed: false,
            levels: 4,
            ..base(
                "helix_open",
                "A11",
                "open-sequence rule (docs/math/open-sequences.md)",
                "Six poses sampled from a helix, open: every scheme reproduces the helix exactly.",
                (0..6).map(helix).collect(),
                Scheme::FourPoint,
                BAR,
            )
        },
        Preset {
            closed: false,
            levels: 5,
            ..base(
                "triangle7",
                "B1",
                "Chaudhry–Cameron Figs. 4–8",
                "A rigid triangle sampled at 7 times of a tumbling motion: compare the rational C⁰ and C¹ motions (Methods view) with the screw schemes.",
                triangle7(),
                Scheme::FourPoint,
                Shape::Triangle {
                    x: [1.0, 0.0, 0.0],
                    y: [0.3, 0.8, 0.0],
                    thickness: 0.04,
                },
            )
        },
        Preset {
            closed: false,
            levels: 5,
            ..base(
                "rb_sphere7",
                "C1",
                "Ramamoorthi–Barr Figs. 1, 3–5",
                "Seven orientations about a fixed centre: Ramamoorthi–Barr's quaternion spline (Methods view) against the screw schemes.",
                quaternion_keys(&RB_SPHERE7).into_iter().map(|q| Pose::new(DVec3::ZERO, q)).collect(),
                Scheme::Jarek,
                Shape::Block {
                    size: [1.6, 0.5, 0.25],
                    base: false,
                },
            )
        },
        Preset {
            closed: false,
            levels: 5,
            ..base(
                "rb_ibeam7",
                "C2",
                "Ramamoorthi–Barr Fig. 6",
                "An I-beam flips smoothly along a parabola: keyframe rotations use all four quaternion components.",
                rb_ibeam7(),
                Scheme::Jarek,
                Shape::IBeam {
                    flange: [1.2, 0.4, 0.15],
                    web: 1.0,
                    web_section: [0.15, 0.4],
                },
            )
        },
        Preset {
            closed: false,
            levels: 5,
            ..base(
                "rb_molecule4",
                "C3",
                "Ramamoorthi–Barr Fig. 7 (stand-in)",
                "A molecule tumbles through four keyframes 95°–110° apart (synthetic stand-in for the paper's molecular-dynamics data).",
                quaternion_keys(&RB_MOLECULE4).into_iter().map(|q| Pose::new(DVec3::ZERO, q)).collect(),
                Scheme::Jarek,
                Shape::Molecule {
                    ring: 0.7,
                    atom: 0.16,
                },
            )
        },
    ]
}

/// Preset B1: the rigid motion `R(t) = Rot(axis (sin 2t, 0.5, cos t), 2.2t)`, `a(t) = (2t,
/// 0.8 sin 3t, 0.5t²)` sampled at `t = 0, 0.2, …, 1.2` (the pose's origin is vertex `a`).
fn triangle7() -> Vec<Pose> {
    (0..7)
        .map(|i| {
            let t = 0.2 * i as f64;
            let axis = DVec3::new((2.0 * t).sin(), 0.5, t.cos()).normalize();
            let a = DVec3::new(2.0 * t, 0.8 * (3.0 * t).sin(), 0.5 * t * t);
            Pose::new(a, DQuat::from_axis_angle(axis, 2.2 * t))
        })
        .collect()
}

/// Preset C1's keyframes `[w, x, y, z]` (docs/math/quaternion-splines.md §8).
const RB_SPHERE7: [[f64; 4]; 7] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.8, 0.6, 0.0, 0.0],
    [0.6, 0.48, 0.64, 0.0],
    [0.0, 0.6, 0.8, 0.0],
    [-0.6, 0.0, 0.8, 0.0],
    [-0.8, -0.36, 0.48, 0.0],
    [-0.6, -0.8, 0.0, 0.0],
];

/// Preset C3's keyframes `[w, x, y, z]` (100°, 110°, 95° steps).
const RB_MOLECULE4: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.642788, 0.541675, 0.541675, 0.0],
    [0.054934, -0.003061, 0.996766, 0.058567],
    [0.069242, 0.546219, 0.644468, 0.530576],
];

/// Unit quaternions from six-decimal `[w, x, y, z]` tables (normalised).
fn quaternion_keys(keys: &[[f64; 4]]) -> Vec<DQuat> {
    keys.iter()
        .map(|&[w, x, y, z]| DQuat::from_xyzw(x, y, z, w).normalize())
        .collect()
}

/// Preset C2: origin `(2t, 0, 4 − 0.45 (t−3)²)` and the keyframe rotations of docs/math/presets.md §4.2, `t = 0..6`.
fn rb_ibeam7() -> Vec<Pose> {
    const Q: [[f64; 4]; 7] = [
        [1.0, 0.0, 0.0, 0.0],
        [0.887011, 0.442275, 0.132682, 0.0],
        [0.667239, 0.439770, 0.600518, -0.027812],
        [0.484342, 0.057554, 0.835811, 0.252034],
        [0.515119, 0.025519, 0.533823, 0.670100],
        [0.279926, 0.427214, 0.607723, 0.608114],
        [-0.172827, 0.217600, 0.605166, 0.746026],
    ];
    quaternion_keys(&Q)
        .into_iter()
        .enumerate()
        .map(|(i, q)| {
            let t = i as f64;
            Pose::new(DVec3::new(2.0 * t, 0.0, 4.0 - 0.45 * (t - 3.0).powi(2)), q)
        })
        .collect()
}

/// The preset with this id, if any.
pub fn preset(id: &str) -> Option<Preset> {
    all().into_iter().find(|s| s.id == id)
}

/// The planar polygon presets of A4 (paper Figs. 2–3).
pub fn polygon_presets() -> Vec<PolygonPreset> {
    let v = |pts: &[[f64; 2]]| pts.iter().map(|p| DVec2::from_array(*p)).collect();
    vec![
        PolygonPreset {
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
        PolygonPreset {
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
        PolygonPreset {
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

    /// The computed poses agree with the six-decimal tables of `presets.md`.
    #[test]
    #[allow(clippy::approx_constant)] // the tables' printed values are the point of the test
    fn presets_match_the_spec_tables() {
        let s = preset("l_cycle_rotated").unwrap();
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
        let s = preset("pendulum").unwrap();
        assert!(close(
            &s.poses[0],
            [2.294306, 0.0, 0.723392],
            [0.953717, 0.0, -0.300706, 0.0]
        ));
        let s = preset("spinning_block").unwrap();
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
        let s = preset("cylinder5").unwrap();
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
        let s = preset("bunny6").unwrap();
        assert!(close(
            &s.poses[3],
            [6.5, 4.0, 1.0],
            [0.896201, -0.282571, -0.102847, 0.326190]
        ));
        let s = preset("helix_open").unwrap();
        assert!(!s.closed);
        assert!(close(
            &s.poses[5],
            [-2.121320, -2.121320, 3.0],
            [0.382683, 0.0, 0.0, -0.923880]
        ));
        let s = preset("circle4").unwrap();
        assert!(close(&s.poses[2], [-3.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]));
        let star = &polygon_presets()[1].vertices;
        assert!((star[1] - DVec2::new(-1.175571, 1.618034)).length() < 2e-6);
        assert!((star[4] - DVec2::new(-2.938926, -4.045085)).length() < 2e-6);
    }

    #[test]
    fn ids_are_unique() {
        let all = all();
        for (i, a) in all.iter().enumerate() {
            assert!(all[i + 1..].iter().all(|b| b.id != a.id));
        }
        assert_eq!(all.len(), 14);
    }

    #[test]
    fn comparison_presets_match_the_spec_tables() {
        // B1 (presets.md): vertex a and q at t = 0.2 and t = 1.2, six decimals.
        let b1 = preset("triangle7").unwrap();
        assert!(close(
            &b1.poses[1],
            [0.4, 0.451714, 0.02],
            [0.975897, 0.072814, 0.093490, 0.183254]
        ));
        assert!(close(
            &b1.poses[6],
            [2.4, -0.354016, 0.72],
            [0.248175, 0.714976, 0.529249, 0.383555]
        ));
        // C2 keeps the negative w of its last key; its origin follows the parabola.
        let c2 = preset("rb_ibeam7").unwrap();
        assert!(close(
            &c2.poses[6],
            [12.0, 0.0, -0.05],
            [-0.172827, 0.217600, 0.605166, 0.746026]
        ));
        for id in ["triangle7", "rb_sphere7", "rb_ibeam7", "rb_molecule4"] {
            assert!(!preset(id).unwrap().closed, "{id} is an open sequence");
        }
    }
}
