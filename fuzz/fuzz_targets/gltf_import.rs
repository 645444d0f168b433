//! glTF import: control poses from `.glb` / `.gltf` bytes under every node selection, and the
//! page's mesh import (`Mesh::from_gltf`), never panic; accepted poses are valid.
#![no_main]

use libfuzzer_sys::fuzz_target;
use screwbender::mesh::Mesh;
use screwbender::{import_glb, import_gltf, is_glb, Error, NodeSelection};

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let selections = [
        NodeSelection::Auto,
        NodeSelection::Animated("control poses".into()),
        NodeSelection::Transforms(vec!["a".into(), "b".into()]),
    ];
    for selection in &selections {
        let result = if is_glb(data) {
            import_glb(data, selection)
        } else {
            // External buffers: the first resolves to the input itself, the others fail.
            let mut calls = 0;
            let mut resolve = |_uri: &str| -> Result<Vec<u8>, Error> {
                calls += 1;
                if calls == 1 {
                    Ok(data.to_vec())
                } else {
                    Err(Error::new("buffers".into(), ErrorKind::Parse { message: "not found".into() }))
                }
            };
            import_gltf(data, &mut resolve, selection)
        };
        if let Ok(doc) = result {
            assert!(doc.poses.len() >= 2);
            for (i, p) in doc.poses.iter().enumerate() {
                common::assert_sane(p, &format!("pose {i}"));
            }
        }
    }
    if let Ok(mesh) = Mesh::from_gltf(data) {
        assert!(mesh.triangle_count() > 0);
        assert!(mesh.positions.iter().all(|p| p.is_finite()));
        assert!(mesh
            .indices
            .iter()
            .all(|&i| (i as usize) < mesh.positions.len()));
    }
});
