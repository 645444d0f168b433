//! Procedural meshes of every scene object and the OBJ / glTF readers (`screwbender::mesh`),
//! natively and under wasm-bindgen-test (node).

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use glam::DVec3;
use screwbender::mesh::{Mesh, MAX_OBJ_TRIANGLES};
use screwbender::presets::{self, Shape};

/// Every triangle index in range, normals unit, and the mesh closed (each directed edge is
/// matched by its reverse, counting positions rather than vertex ids since flat faces duplicate
/// vertices).
fn check_closed_mesh(m: &Mesh, what: &str) {
    assert!(!m.indices.is_empty(), "{what}: empty");
    assert_eq!(m.positions.len(), m.normals.len(), "{what}");
    assert!(
        m.indices.iter().all(|&i| (i as usize) < m.positions.len()),
        "{what}: index range"
    );
    for n in &m.normals {
        assert!((n.length() - 1.0).abs() < 1e-9, "{what}: normal {n}");
    }
    let key = |p: DVec3| {
        let q = (p * 1e6).round();
        (q.x as i64, q.y as i64, q.z as i64)
    };
    let mut edges = std::collections::HashMap::new();
    for t in m.indices.chunks(3) {
        for k in 0..3 {
            let a = key(m.positions[t[k] as usize]);
            let b = key(m.positions[t[(k + 1) % 3] as usize]);
            if a != b {
                *edges.entry((a, b)).or_insert(0i32) += 1;
            }
        }
    }
    for (&(a, b), &c) in &edges {
        let back = edges.get(&(b, a)).copied().unwrap_or(0);
        assert_eq!(
            c, back,
            "{what}: edge {a:?}->{b:?} used {c} times, reverse {back}"
        );
    }
}

/// Signed volume by the divergence theorem (positive when triangles face outwards).
fn volume(m: &Mesh) -> f64 {
    m.indices
        .chunks(3)
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| m.positions[t[k] as usize]);
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

#[test]
fn every_scene_shape_is_a_closed_outward_mesh() {
    for scene in presets::all() {
        for shape in std::iter::once(&scene.shape).chain(&scene.morph_shapes) {
            let m = Mesh::from_shape(shape);
            if !matches!(shape, Shape::Pendulum { .. }) {
                check_closed_mesh(&m, scene.id);
            }
            assert!(volume(&m) > 0.0, "{}: {shape:?} faces inwards", scene.id);
        }
    }
}

#[test]
fn volumes_match_the_dimensions() {
    let block = Mesh::from_shape(&Shape::Block {
        size: [1.0, 2.0, 3.0],
        base: true,
    });
    assert!((volume(&block) - 6.0).abs() < 1e-12);
    let (lo, hi) = block.bounds().unwrap();
    assert!(
        lo.z.abs() < 1e-12 && (hi.z - 3.0).abs() < 1e-12,
        "base at z = 0"
    );
    let bar = Mesh::from_shape(&Shape::Bar {
        length: 2.0,
        section: 0.5,
    });
    let (lo, hi) = bar.bounds().unwrap();
    assert!(
        lo.x.abs() < 1e-12 && (hi.x - 2.0).abs() < 1e-12,
        "bar spans x in [0, 2]"
    );
    let sphere = Mesh::from_shape(&Shape::Sphere { radius: 1.0 });
    let v = volume(&sphere);
    assert!(
        (v - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.1,
        "sphere volume {v}"
    );
    let cyl = Mesh::from_shape(&Shape::Cylinder {
        radius: 1.0,
        height: 2.0,
    });
    assert!((volume(&cyl) - 2.0 * std::f64::consts::PI).abs() < 0.05);
    let cone = Mesh::from_shape(&Shape::Cone {
        radius: 1.0,
        height: 3.0,
    });
    assert!((volume(&cone) - std::f64::consts::PI).abs() < 0.05);
}

#[test]
fn obj_parses_polygons_and_negative_indices() {
    let text = "# a unit square pyramid\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n\
                f 4 3 2 1\nf 1 2 5\nf 2/7/1 3/8/2 5\nf -3 -2 -1\nf 4 1 5\n";
    let m = Mesh::from_obj(text).unwrap();
    assert_eq!(m.triangle_count(), 6);
    check_closed_mesh(&m, "pyramid");
    assert!((volume(&m) - 1.0 / 3.0).abs() < 1e-12);
    let n = m.clone().normalized(2.0);
    let (lo, hi) = n.bounds().unwrap();
    assert!(((hi - lo).max_element() - 2.0).abs() < 1e-12);
    assert!(((lo + hi) / 2.0).length() < 1e-12);
}

#[test]
fn bad_obj_is_rejected_with_a_line_number() {
    let cases = [
        ("v 0 0\n", "obj line 1"),
        ("v 0 0 x\n", "obj line 1"),
        ("v 0 0 NaN\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj line 1"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "obj line 4"),
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", "obj line 3"),
        ("v 0 0 0\n", "obj"),
        ("", "obj"),
    ];
    for (text, at) in cases {
        let e = Mesh::from_obj(text).unwrap_err();
        assert_eq!(e.path(), at, "{text:?}: {e}");
    }
}

#[test]
fn obj_size_limits() {
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for _ in 0..=MAX_OBJ_TRIANGLES {
        text.push_str("f 1 2 3\n");
    }
    let e = Mesh::from_obj(&text).unwrap_err();
    assert!(e.to_string().contains("triangles"), "{e}");
}

/// A glTF with one triangle pair (a unit square in z = 0) embedded as base64.
fn square_gltf(positions: [f32; 12]) -> String {
    let mut bytes = Vec::new();
    for p in positions {
        bytes.extend_from_slice(&p.to_le_bytes());
    }
    for i in [0u16, 1, 2, 0, 2, 3] {
        bytes.extend_from_slice(&i.to_le_bytes());
    }
    let b64 = base64(&bytes);
    format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":{},"uri":"data:application/octet-stream;base64,{b64}"}}],
        "bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":12}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}},
                     {{"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}]}}"#,
        bytes.len()
    )
}

fn base64(bytes: &[u8]) -> String {
    const T: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::new();
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16
            | (*c.get(1).unwrap_or(&0) as u32) << 8
            | *c.get(2).unwrap_or(&0) as u32;
        for k in 0..4 {
            if k <= c.len() {
                s.push(T[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

#[test]
fn gltf_embedded_and_glb() {
    let square = [0., 0., 0., 1., 0., 0., 1., 1., 0., 0., 1., 0.];
    let text = square_gltf(square);
    let m = Mesh::from_gltf(text.as_bytes()).unwrap();
    assert_eq!(m.triangle_count(), 2);
    assert!(m.normals.iter().all(|n| (*n - DVec3::Z).length() < 1e-12));
    // The same as a GLB: JSON chunk padded to 4 bytes, no BIN chunk needed (data URI).
    let mut json = text.into_bytes();
    while json.len() % 4 != 0 {
        json.push(b' ');
    }
    let mut glb = b"glTF".to_vec();
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&(20 + json.len() as u32).to_le_bytes());
    glb.extend_from_slice(&(json.len() as u32).to_le_bytes());
    glb.extend_from_slice(b"JSON");
    glb.extend_from_slice(&json);
    assert_eq!(Mesh::from_gltf(&glb).unwrap(), m);
}

#[test]
fn bad_gltf_is_rejected() {
    let mut nan = [0f32; 12];
    nan[4] = f32::NAN;
    for bad in [
        "not json".to_string(),
        "{}".to_string(),
        square_gltf(nan),
        square_gltf([0.; 12]).replace("\"count\":6", "\"count\":60"),
        square_gltf([0.; 12]).replace("data:application/octet-stream;base64,", "file.bin#"),
    ] {
        let e = Mesh::from_gltf(bad.as_bytes()).unwrap_err();
        assert!(e.path().starts_with("gltf"), "{e}");
    }
    assert!(Mesh::from_gltf(b"glTF\x02\0\0\0").is_err());
}
