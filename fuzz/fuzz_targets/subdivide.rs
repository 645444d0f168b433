//! Subdivision with arbitrary poses and options: no panic; requests beyond the memory guard are
//! refused before allocating; accepted results are finite with unit rotations (every validated
//! input: origins within `MAX_COORDINATE`, `|s| ≤ MAX_J_PARAMETER`); a local update after a pose edit equals a full rebuild bit for bit;
//! sampling anywhere in the domain stays finite.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use screwbender::{Motion, Rules, Scheme, ScrewBender, Subdivision};

#[path = "common.rs"]
mod common;
use common::PoseIn;

/// Above this many output poses the target only checks `output_len` (throughput).
const MAX_WORK: usize = 1 << 10;

#[derive(Arbitrary, Debug)]
struct Input {
    poses: Vec<PoseIn>,
    closed: bool,
    scheme: u8,
    s: f64,
    split: bool,
    levels: u8,
    edit: Option<(u16, PoseIn)>,
    us: Vec<f64>,
}

fuzz_target!(|input: Input| {
    if input.poses.len() > 64 {
        return;
    }
    let poses: Vec<_> = input.poses.iter().filter_map(PoseIn::pose).collect();
    let scheme = match input.scheme % 4 {
        0 => Scheme::BSpline,
        1 => Scheme::FourPoint,
        2 => Scheme::Jarek,
        _ => Scheme::J(input.s),
    };
    let rules = if input.split {
        Rules::SplitThenTweak
    } else {
        Rules::Direct
    };
    let sub = Subdivision::new(scheme, rules, u32::from(input.levels % 26));
    let len = sub.output_len(poses.len(), input.closed);
    let (Ok(len), Ok(())) = (len, sub.validate()) else {
        // Refused requests are refused by every entry point, cheaply.
        assert!(sub.apply(&poses, input.closed).is_err());
        assert!(ScrewBender::new(poses, input.closed, sub).is_err());
        return;
    };
    if len > MAX_WORK {
        return;
    }
    // Validated poses and options: every result must be finite (nothing is exempt).
    let checked = common::scale_of(&poses) <= common::FINITE_CHECK_SCALE;
    assert!(checked, "a validated pose beyond MAX_COORDINATE");
    let out = sub.apply(&poses, input.closed).expect("valid request");
    assert_eq!(out.len(), len);
    if checked {
        for (k, p) in out.iter().enumerate() {
            common::assert_sane(p, &format!("refined[{k}]"));
        }
    }
    let Ok(mut motion) = ScrewBender::new(poses.clone(), input.closed, sub) else {
        assert!(!checked, "ScrewBender::new refused a checked input");
        return;
    };
    let (a, b) = motion.domain();
    for &u in input.us.iter().take(16) {
        if !u.is_finite() {
            continue;
        }
        let u = a + (b - a) * (u.fract() * 1.5 - 0.25);
        let p = motion.pose_at(u);
        if checked {
            common::assert_sane(&p, &format!("pose_at({u})"));
        }
    }
    if let Some((i, pose)) = &input.edit {
        let i = usize::from(*i) % poses.len();
        let Some(pose) = pose.pose() else { return };
        if motion.set_control_pose(i, pose).is_ok() {
            let mut edited = poses.clone();
            edited[i] = pose;
            if let Ok(full) = ScrewBender::new(edited, input.closed, sub) {
                let bits = |m: &ScrewBender| -> Vec<u64> {
                    m.refined()
                        .poses()
                        .iter()
                        .flat_map(|p| {
                            p.origin
                                .to_array()
                                .into_iter()
                                .chain(p.rotation.to_array())
                                .map(f64::to_bits)
                        })
                        .collect()
                };
                assert!(
                    bits(&motion) == bits(&full),
                    "local update differs from a rebuild"
                );
            }
        }
    }
});
