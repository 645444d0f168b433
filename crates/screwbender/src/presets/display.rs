//! How a front end shows a preset: its name in words, how many copies of the object the strobe
//! draws, the pose selected when it loads, and the body points whose trajectories are drawn.
//! One table, so the page, the element, Python and the command line name and show a preset
//! alike.

use super::{object_shape, Shape};

/// How to show one preset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PresetDisplay {
    /// The preset's name in words (the paper's label and figure are its subtitle).
    pub name: &'static str,
    /// Copies of the object along the motion: fewer where the object is bulky, so the strobe
    /// stays readable, as in the papers' figures.
    pub strobe: u32,
    /// The control pose selected when the preset loads (the editing scene starts with the pose
    /// its text asks to drag), if any.
    pub selected: Option<usize>,
}

/// The strobe count of a preset whose object is slim (a bar, a frame).
pub const DEFAULT_STROBE: u32 = 64;

/// How to show the preset `id` (an unknown id gets its id as the name and the defaults).
pub fn display(id: &'static str) -> PresetDisplay {
    let (name, strobe, selected) = match id {
        "l_cycle_parallel" => ("L cycle, parallel poses", DEFAULT_STROBE, None),
        "l_cycle_rotated" => ("L cycle, rotated poses", DEFAULT_STROBE, None),
        "l_cycle_edit" => ("L cycle, editing", DEFAULT_STROBE, Some(4)),
        "pendulum" => ("Pendulum", 18, None),
        "spinning_block" => ("Spinning block", 14, None),
        "cylinder5" => ("Tumbling cylinder", 36, None),
        "pip_morph5" => ("Morphing shapes", 36, None),
        "circle4" => ("Circle", 40, None),
        "bunny6" => ("Inconsistent rotations", DEFAULT_STROBE, None),
        "helix_open" => ("Helix (open)", DEFAULT_STROBE, None),
        "triangle7" => ("Tumbling triangle", 40, None),
        "rb_sphere7" => ("Turning about a centre", 20, None),
        "rb_ibeam7" => ("Flipping I-beam", 30, None),
        "rb_molecule4" => ("Tumbling molecule", 24, None),
        other => (other, DEFAULT_STROBE, None),
    };
    PresetDisplay {
        name,
        strobe,
        selected,
    }
}

/// The body points whose trajectories a figure draws for an object of this shape (local
/// coordinates): its origin and a characteristic far point (the end of a bar, a corner of a
/// block, the rim of a cylinder, both vertices of a triangle besides the origin), so that a
/// trajectory shows the turning as well as the travel.
pub fn body_points(shape: &Shape) -> Vec<[f64; 3]> {
    const O: [f64; 3] = [0.0; 3];
    match *shape {
        Shape::Bar { length, .. } => vec![O, [length, 0.0, 0.0]],
        Shape::Block { size, base } => {
            let z = if base { size[2] } else { size[2] / 2.0 };
            vec![O, [size[0] / 2.0, size[1] / 2.0, z]]
        }
        Shape::Cylinder { radius, height } => vec![O, [radius, 0.0, height / 2.0]],
        Shape::Cone { height, .. } => vec![[0.0, 0.0, -height / 2.0], [0.0, 0.0, height / 2.0]],
        Shape::Sphere { radius } => vec![O, [radius, 0.0, 0.0]],
        Shape::StarPrism { outer, .. } => vec![O, [0.0, outer, 0.0]],
        Shape::Pendulum { rod, .. } => vec![O, [0.0, 0.0, rod]],
        Shape::Wedge { size } => vec![O, [size[0], 0.0, 0.0]],
        Shape::Triangle { x, y, .. } => vec![O, x, y],
        Shape::IBeam { flange, web, .. } => {
            vec![O, [flange[0] / 2.0, 0.0, (web + flange[2]) / 2.0]]
        }
        Shape::Molecule { ring, .. } => vec![O, [ring * 1.9, 0.0, 0.0]],
    }
}

/// The body points of a named object ([`object_shape`]), if the name is one.
pub fn object_body_points(kind: &str) -> Option<Vec<[f64; 3]>> {
    object_shape(kind).map(|shape| body_points(&shape))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_has_a_name_a_strobe_and_a_valid_selection() {
        for p in crate::presets::all() {
            let d = display(p.id);
            assert_ne!(d.name, p.id, "{} has no name in words", p.id);
            assert!((1..=256).contains(&d.strobe), "{}", p.id);
            assert!(d.selected.is_none_or(|i| i < p.poses.len()), "{}", p.id);
        }
    }

    #[test]
    fn body_points_are_the_origin_and_points_on_the_object() {
        // The far points lie on the object: within its bounding radius and not at its origin.
        for p in crate::presets::all() {
            let points = body_points(&p.shape);
            assert!(points.len() >= 2, "{}", p.id);
            let mesh = crate::presets::mesh::Mesh::from_shape(&p.shape);
            let reach = mesh
                .positions
                .iter()
                .map(|q| q.length())
                .fold(0.0, f64::max);
            for q in &points {
                let r = glam::DVec3::from_array(*q).length();
                assert!(
                    r <= reach + 1e-12,
                    "{}: {q:?} beyond the object ({reach})",
                    p.id
                );
            }
            assert!(points.iter().any(|q| *q != [0.0; 3]), "{}", p.id);
        }
        assert_eq!(
            object_body_points("bar"),
            Some(vec![[0.0; 3], [2.0, 0.0, 0.0]])
        );
        assert_eq!(object_body_points("teapot"), None);
    }
}
