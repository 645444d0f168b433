//! Helpers of the core's glTF tests (`interop.rs`, `export_tolerance.rs`).

use glam::{DQuat, DVec3};
use gltf_json as json;
use screwbender::{split_glb, Pose};

/// The exported animation's keyframes, read back from the GLB: `(times, poses)` of animation
/// `a` (`f32` values as stored; quaternions as stored, not normalised).
pub fn glb_keyframes(glb: &[u8], a: usize) -> (Vec<f64>, Vec<Pose>) {
    let (text, bin) = split_glb(glb).unwrap();
    let bin = bin.unwrap();
    let root = json::Root::from_slice(text).unwrap();
    let read = |acc: json::Index<json::Accessor>| -> Vec<f64> {
        let acc = &root.accessors[acc.value()];
        let view = &root.buffer_views[acc.buffer_view.unwrap().value()];
        let start = view.byte_offset.map_or(0, |o| o.0 as usize);
        bin[start..start + view.byte_length.0 as usize]
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes(b.try_into().unwrap()) as f64)
            .collect()
    };
    let anim = &root.animations[a];
    let times = read(anim.samplers[0].input);
    let t = read(anim.samplers[0].output);
    let r = read(anim.samplers[1].output);
    let poses = (0..times.len())
        .map(|k| {
            Pose::new(
                DVec3::new(t[3 * k], t[3 * k + 1], t[3 * k + 2]),
                DQuat::from_xyzw(r[4 * k], r[4 * k + 1], r[4 * k + 2], r[4 * k + 3]),
            )
        })
        .collect();
    (times, poses)
}
