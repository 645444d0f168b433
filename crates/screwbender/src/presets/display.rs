//! How a front end shows a preset: its name in words, how many copies of the object the strobe
//! draws, and the pose selected when it loads. One table, so the page, the element, Python and
//! the command line name and show a preset alike.

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
}
