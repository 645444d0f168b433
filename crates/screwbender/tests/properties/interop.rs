//! glTF / CSV interchange without files: the exported animation re-sampled with glTF `LINEAR`
//! semantics stays within the stated tolerance of the true motion; export → import → export keeps
//! the control poses; malformed input is named. Runs natively and, compiled to wasm, in headless
//! Chromium.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use crate::support;

use glam::DVec3;
use screwbender::mesh::Mesh;
use screwbender::ErrorKind;
use screwbender::{
    import_glb, import_gltf, parse_csv_poses, poses_csv, presets, sample_polyscrew, split_glb,
    Error, GltfAsset, GltfMotion, Motion, NodeSelection, Pose, Rules, Scheme, ScrewBender,
    Subdivision, Timing, DEFAULT_TOLERANCE,
};

/// Extra deviation allowed on top of the tolerance for the `f32` storage of keyframes: value
/// rounding (about `6e-8 |x|` for coordinates up to ~10) plus time rounding (`6e-8 t` for `t` up
/// to ~10 s) times the origin's speed (up to ~10 units/s).
const F32_SLACK: f64 = 1e-5;

/// Control poses must survive export → import to this (the `f32` storage of glTF).
const ROUND_TRIP: f64 = 1e-6;

/// Probes per keyframe interval when re-sampling.
const PROBES: usize = 7;

/// The exported animation's keyframes of animation `a`, quaternions normalised.
fn keyframes(glb: &[u8], a: usize) -> (Vec<f64>, Vec<Pose>) {
    let (times, poses) = support::glb_keyframes(glb, a);
    let poses = poses
        .into_iter()
        .map(|p| Pose::new(p.origin, p.rotation.normalize()))
        .collect();
    (times, poses)
}

/// glTF LINEAR: lerp the translation, slerp the rotation between the stored quaternions as they
/// are (no sign fix-up: the exporter must store consistent signs).
fn gltf_linear(a: &Pose, b: &Pose, s: f64) -> Pose {
    let (qa, qb) = (a.rotation, b.rotation);
    let dot = qa.dot(qb);
    assert!(
        dot >= 0.0,
        "consecutive keyframe quaternions with dot {dot} < 0"
    );
    Pose::new(a.origin.lerp(b.origin, s), qa.slerp(qb, s))
}

struct Exported {
    glb: Vec<u8>,
    samples: usize,
}

fn export(motion: &ScrewBender, control: &[Pose], closed: bool, timing: &Timing) -> Exported {
    let n = control.len();
    let spans = if closed { n } else { n - 1 };
    let samples = sample_polyscrew(motion.refined(), spans, timing, DEFAULT_TOLERANCE).unwrap();
    let mesh = Mesh::cuboid(DVec3::splat(0.5));
    let asset = GltfAsset::new(&GltfMotion {
        name: Some("test"),
        samples: &samples,
        control,
        control_times: timing.knots(),
        control_velocities: None,
        closed,
        mesh: Some(&mesh),
        morph: None,
        tolerance: Some(DEFAULT_TOLERANCE),
        control_nodes: false,
    })
    .unwrap();
    Exported {
        glb: asset.to_glb(),
        samples: samples.len(),
    }
}

/// Worst `(origin deviation, angle deviation)` of the re-sampled animation from the motion.
fn worst_deviation(glb: &[u8], motion: &dyn Motion, timing: &Timing) -> (f64, f64) {
    let (times, poses) = keyframes(glb, 0);
    let t0 = timing.knots()[0];
    let mut worst = (0.0f64, 0.0f64);
    for k in 0..times.len() - 1 {
        for j in 0..=PROBES {
            let s = j as f64 / PROBES as f64;
            let t = times[k] + s * (times[k + 1] - times[k]);
            let played = gltf_linear(&poses[k], &poses[k + 1], s);
            let truth = motion.pose_at(timing.parameter(t + t0).0);
            worst.0 = worst.0.max(played.origin.distance(truth.origin));
            worst.1 = worst.1.max(played.angle_to(&truth));
        }
    }
    worst
}

#[test]
fn every_preset_and_scheme_stays_within_tolerance() {
    for scene in presets::all() {
        for scheme in [Scheme::BSpline, Scheme::FourPoint, Scheme::Jarek] {
            let levels = if scheme == Scheme::FourPoint { 5 } else { 3 };
            let sub = Subdivision::new(scheme, Rules::Direct, levels);
            let sb = ScrewBender::new(scene.poses.clone(), scene.closed, sub).unwrap();
            let timing = Timing::uniform(scene.poses.len(), scene.closed);
            let e = export(&sb, &scene.poses, scene.closed, &timing);
            let (d, a) = worst_deviation(&e.glb, &sb, &timing);
            eprintln!(
                "{:<18} {scheme:<9} L{levels}: {:>5} samples, worst origin deviation {d:.2e}, \
                 angle {a:.1e}",
                scene.id, e.samples
            );
            assert!(
                d <= DEFAULT_TOLERANCE + F32_SLACK && a <= F32_SLACK,
                "{} {scheme}: origin deviation {d:e}, angle {a:e} ({} samples)",
                scene.id,
                e.samples
            );
        }
    }
}

#[test]
fn nonuniform_timing_stays_within_tolerance() {
    let scene = presets::preset("cylinder5").unwrap();
    let sb = ScrewBender::new(
        scene.poses.clone(),
        true,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 4),
    )
    .unwrap();
    let timing = Timing::new(vec![1.0, 1.5, 3.5, 4.0, 6.0, 6.2], true).unwrap();
    let e = export(&sb, &scene.poses, true, &timing);
    let (d, a) = worst_deviation(&e.glb, &sb, &timing);
    assert!(
        d <= DEFAULT_TOLERANCE + F32_SLACK && a <= DEFAULT_TOLERANCE + F32_SLACK,
        "origin deviation {d:e}, angle {a:e}"
    );
    // The control animation reaches pose i at T_i (shifted to start at 0).
    let (times, _) = keyframes(&e.glb, 1);
    assert_eq!(times.len(), 6);
    assert!((times[2] - 2.5).abs() < 1e-6);
}

#[test]
fn export_import_export_keeps_control_poses() {
    for scene in presets::all() {
        let sub = Subdivision::new(Scheme::FourPoint, Rules::Direct, 2);
        let sb = ScrewBender::new(scene.poses.clone(), scene.closed, sub).unwrap();
        let timing = Timing::uniform(scene.poses.len(), scene.closed);
        let first = export(&sb, &scene.poses, scene.closed, &timing);
        let doc = import_glb(&first.glb, &NodeSelection::Auto).unwrap();
        assert_eq!(doc.closed, scene.closed, "{}", scene.id);
        assert_eq!(doc.poses.len(), scene.poses.len(), "{}", scene.id);
        for (a, b) in doc.poses.iter().zip(&scene.poses) {
            assert!(a.approx_eq(b, ROUND_TRIP), "{}: {a:?} vs {b:?}", scene.id);
        }
        let sb2 = ScrewBender::new(doc.poses.clone(), doc.closed, sub).unwrap();
        let second = export(&sb2, &doc.poses, doc.closed, &timing);
        let again = import_glb(&second.glb, &NodeSelection::Auto).unwrap();
        for (a, b) in again.poses.iter().zip(&scene.poses) {
            assert!(a.approx_eq(b, ROUND_TRIP), "{}: {a:?} vs {b:?}", scene.id);
        }
    }
}

#[test]
fn the_object_node_can_be_imported_by_name() {
    let scene = presets::preset("circle4").unwrap();
    let sb = ScrewBender::new(
        scene.poses.clone(),
        true,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 1),
    )
    .unwrap();
    let timing = Timing::uniform(4, true);
    let e = export(&sb, &scene.poses, true, &timing);
    let doc = import_glb(&e.glb, &NodeSelection::Animated("test".into())).unwrap();
    // Every keyframe of the object (the last repeats the first: dropped, a cycle).
    assert_eq!(doc.poses.len(), e.samples - 1);
    assert!(doc.closed);
}

#[test]
fn csv_samples_read_back() {
    let scene = presets::preset("helix_open").unwrap();
    let sb = ScrewBender::new(
        scene.poses.clone(),
        false,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 2),
    )
    .unwrap();
    let n = scene.poses.len();
    let samples = sample_polyscrew(sb.refined(), n - 1, &Timing::uniform(n, false), 1e-3).unwrap();
    let doc = parse_csv_poses(&poses_csv(&samples)).unwrap();
    assert_eq!(doc.poses.len(), samples.len());
    for (a, b) in doc.poses.iter().zip(&samples) {
        assert!(a.approx_eq(&b.pose, 1e-12));
    }
}

fn sample_glb() -> Vec<u8> {
    let scene = presets::preset("pendulum").unwrap();
    let sb = ScrewBender::new(
        scene.poses.clone(),
        true,
        Subdivision::new(Scheme::FourPoint, Rules::Direct, 1),
    )
    .unwrap();
    export(&sb, &scene.poses, true, &Timing::uniform(2, true)).glb
}

/// The GLB with its JSON chunk replaced by `f(json)` (re-padded).
fn with_json(glb: &[u8], f: impl Fn(&mut serde_json::Value)) -> Vec<u8> {
    let (text, bin) = split_glb(glb).unwrap();
    let mut v: serde_json::Value = serde_json::from_slice(text).unwrap();
    f(&mut v);
    let mut text = serde_json::to_vec(&v).unwrap();
    while text.len() % 4 != 0 {
        text.push(b' ');
    }
    let bin = bin.unwrap();
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut out = Vec::new();
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(total as u32).to_le_bytes());
    out.extend_from_slice(&(text.len() as u32).to_le_bytes());
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&text);
    out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
    out.extend_from_slice(b"BIN\0");
    out.extend_from_slice(bin);
    out
}

fn import_err(glb: &[u8]) -> Error {
    import_glb(glb, &NodeSelection::Auto).unwrap_err()
}

#[test]
fn truncated_glb_is_named() {
    let glb = sample_glb();
    let e = import_err(&glb[..glb.len() / 2]);
    assert_eq!(e.path(), "glb");
    assert!(e.to_string().contains("truncated"), "{e}");
    assert_eq!(import_err(&glb[..10]).path(), "glb");
    // A consistent header whose chunk runs past the end.
    let mut bad = glb.clone();
    bad[12..16].copy_from_slice(&(glb.len() as u32).to_le_bytes());
    assert!(
        import_err(&bad).path().starts_with("glb chunk"),
        "{}",
        import_err(&bad)
    );
}

#[test]
fn malformed_json_and_missing_animations_are_named() {
    let glb = sample_glb();
    let e = import_err(&with_json(&glb, |v| {
        v.as_object_mut().unwrap().remove("animations");
    }));
    assert_eq!(e.path(), "animations");
    let mut text = br#"{"asset":{"version":"2.0"},"nodes":[{"#.to_vec();
    let mut none = |_: &str| -> Result<Vec<u8>, Error> { Ok(Vec::new()) };
    let e = import_gltf(&text, &mut none, &NodeSelection::Auto).unwrap_err();
    assert_eq!(e.path(), "gltf");
    text.clear();
    text.extend_from_slice(br#"{"asset":{"version":"1.0"}}"#);
    let e = import_gltf(&text, &mut none, &NodeSelection::Auto).unwrap_err();
    assert_eq!(e.path(), "asset.version");
}

#[test]
fn bad_accessors_are_named() {
    let glb = sample_glb();
    // The control animation's input accessor claims more elements than its view holds.
    let v: serde_json::Value = serde_json::from_slice(split_glb(&glb).unwrap().0).unwrap();
    let control_input = v["animations"][1]["samplers"][0]["input"].as_u64().unwrap();
    let e = import_err(&with_json(&glb, |v| {
        v["accessors"][control_input as usize]["count"] = 1000.into();
    }));
    assert_eq!(
        e.path(),
        format!("animations[1].accessors[{control_input}]")
    );
    assert!(e.to_string().contains("truncated"), "{e}");
    // Integer keyframes are refused with the accessor named.
    let e = import_err(&with_json(&glb, |v| {
        v["accessors"][control_input as usize]["componentType"] = 5125.into();
    }));
    assert_eq!(
        e.path(),
        format!("animations[1].accessors[{control_input}]")
    );
    // A node name that does not exist.
    let e = import_glb(&glb, &NodeSelection::Animated("nope".into())).unwrap_err();
    assert!(e.to_string().contains("no node named 'nope'"), "{e}");
}

#[test]
fn nan_keyframes_are_named() {
    let glb = sample_glb();
    let (text, _) = split_glb(&glb).unwrap();
    let v: serde_json::Value = serde_json::from_slice(text).unwrap();
    let out = v["animations"][1]["samplers"][0]["output"]
        .as_u64()
        .unwrap() as usize;
    let view = v["accessors"][out]["bufferView"].as_u64().unwrap() as usize;
    let offset = v["bufferViews"][view]["byteOffset"].as_u64().unwrap() as usize;
    let bin_start = 12 + 8 + text.len() + 8;
    let mut bad = glb.clone();
    bad[bin_start + offset..bin_start + offset + 4].copy_from_slice(&f32::NAN.to_le_bytes());
    let e = import_err(&bad);
    assert_eq!(e.path(), format!("animations[1].accessors[{out}][0]"));
    assert!(matches!(e.kind(), ErrorKind::NonFinite));
}

#[test]
fn corrupted_bytes_never_panic() {
    // Deterministic pseudo-random byte changes anywhere in the file: an error or a document,
    // never a panic.
    let glb = sample_glb();
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for _ in 0..2000 {
        let mut bad = glb.clone();
        for _ in 0..1 + next() % 3 {
            let i = (next() % bad.len() as u64) as usize;
            bad[i] = next() as u8;
        }
        let _ = import_glb(&bad, &NodeSelection::Auto);
        let cut = (next() % bad.len() as u64) as usize;
        let _ = import_glb(&bad[..cut], &NodeSelection::Auto);
    }
}

/// The default object of an export: the preset's mesh for a document named after a preset, its
/// morph only while the poses still match the preset's shapes, nothing for an unnamed document.
#[test]
fn preset_object_follows_the_document() {
    use screwbender::{MotionDocument, PresetObject};
    let named = |id: &str, drop_last: bool| {
        let s = presets::preset(id).unwrap();
        let mut poses = s.poses.clone();
        if drop_last {
            poses.pop();
        }
        let mut doc = MotionDocument::new(poses, s.closed);
        doc.name = Some(id.into());
        doc
    };
    let morphing = PresetObject::of(&named("pip_morph5", false));
    let shape = Mesh::from_shape(&presets::preset("pip_morph5").unwrap().shape);
    assert_eq!(morphing.mesh.as_ref(), Some(&shape));
    let morph = morphing.morph.expect("pip_morph5 has one shape per pose");
    assert!(morph.radius() > 0.0);
    let edited = PresetObject::of(&named("pip_morph5", true));
    assert!(edited.mesh.is_some() && edited.morph.is_none());
    let rigid = PresetObject::of(&named("pendulum", false));
    assert!(rigid.mesh.is_some() && rigid.morph.is_none());
    let mut unnamed = named("pendulum", false);
    unnamed.name = None;
    let none = PresetObject::of(&unnamed);
    assert!(none.mesh.is_none() && none.morph.is_none());
}

/// A build without the compiled-in bunny (the page's wasm) draws and exports the bunny from the
/// OBJ text it fetches (`www/vendor/bunny.obj`, which the page's build copies from the crate's
/// asset): the mesh made from that text is the command line's, so both exports of `bunny6` carry
/// the same bytes.
#[cfg(all(feature = "bunny", not(target_arch = "wasm32")))]
#[test]
fn the_fetched_bunny_is_the_compiled_in_bunny() {
    use screwbender::{MotionDocument, PresetObject};
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let page = std::fs::read_to_string(root.join("assets/bunny.obj")).unwrap();
    let s = presets::preset("bunny6").unwrap();
    let mut doc = MotionDocument::new(s.poses.clone(), s.closed);
    doc.name = Some("bunny6".into());
    let compiled = PresetObject::of(&doc).mesh.unwrap();
    assert_eq!(compiled, Mesh::bunny());
    let fetched = PresetObject::of_preset("bunny6", &doc)
        .with_bunny_obj("bunny6", &page)
        .unwrap();
    assert_eq!(fetched.mesh.as_ref(), Some(&compiled));
    assert!(fetched.morph.is_none());
    // Other presets keep their objects; a bad file is an error at `bunny`.
    let pendulum = PresetObject::of_preset("pendulum", &doc)
        .with_bunny_obj("pendulum", &page)
        .unwrap();
    assert_eq!(
        pendulum.mesh,
        PresetObject::of_preset("pendulum", &doc).mesh
    );
    let bad = PresetObject::of_preset("bunny6", &doc).with_bunny_obj("bunny6", "v 1 2\n");
    assert!(bad.unwrap_err().path().starts_with("bunny"));
}
