//! `screwbender export` of the presets whose object is more than a shape: `bunny6` writes the
//! Stanford bunny (not the wedge that stands in for it without the core's `bunny` feature), and
//! `pip_morph5` writes its morph (one mesh with a morph target per span).
#![cfg(not(target_arch = "wasm32"))]

mod support;

use std::path::Path;

use screwbender::mesh::Mesh;
use support::run;

fn export_glb(id: &str) -> Vec<u8> {
    let doc = run(&["preset", id], "");
    assert_eq!(doc.code, 0, "{}", doc.stderr);
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "cli_preset_objects-{id}-{}.glb",
        std::process::id()
    ));
    let out = run(
        &["export", "--format", "glb", "-o", path.to_str().unwrap()],
        &doc.stdout,
    );
    assert_eq!(out.code, 0, "{}", out.stderr);
    let bytes = std::fs::read(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    bytes
}

/// The JSON chunk of a `.glb`.
fn glb_json(glb: &[u8]) -> serde_json::Value {
    let len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    serde_json::from_slice(&glb[20..20 + len]).unwrap()
}

#[test]
fn the_bunny_preset_exports_the_stanford_bunny() {
    let glb = export_glb("bunny6");
    let mesh = Mesh::from_gltf(&glb).unwrap();
    let bunny = Mesh::bunny();
    assert_eq!(bunny.triangle_count(), 3674);
    assert_eq!(mesh.triangle_count(), bunny.triangle_count());
    let wedge = Mesh::from_shape(&screwbender::scenes::scene("bunny6").unwrap().shape);
    assert_ne!(mesh.triangle_count(), wedge.triangle_count());
    // The same vertices, stored as f32, in the same order.
    let (lo, hi) = mesh.bounds().unwrap();
    let (blo, bhi) = bunny.bounds().unwrap();
    assert!((lo - blo).length() < 1e-6 && (hi - bhi).length() < 1e-6);
    assert!(((hi - lo).max_element() - screwbender::mesh::BUNNY_SIZE).abs() < 1e-6);
}

#[test]
fn the_morph_preset_exports_one_morphing_mesh_per_span() {
    let root = glb_json(&export_glb("pip_morph5"));
    let meshes = root["meshes"].as_array().unwrap();
    assert_eq!(meshes.len(), 5, "one per span of the cycle");
    for m in meshes {
        let prim = &m["primitives"][0];
        assert_eq!(prim["targets"].as_array().unwrap().len(), 1);
        assert_eq!(m["weights"], serde_json::json!([0.0]));
    }
    // The object's animation keys the spans' weights and visibility.
    let channels = root["animations"][0]["channels"].as_array().unwrap();
    let paths: Vec<&str> = channels
        .iter()
        .map(|c| c["target"]["path"].as_str().unwrap())
        .collect();
    assert_eq!(paths.iter().filter(|p| **p == "weights").count(), 5);
    assert_eq!(paths.iter().filter(|p| **p == "scale").count(), 5);
    // The control poses still import back.
    let object = &root["nodes"][0];
    assert!(object.get("mesh").is_none());
    assert_eq!(object["children"].as_array().unwrap().len(), 5);
}
