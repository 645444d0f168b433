//! Parses and validates every `src/render/*.wgsl` with naga, so a shader error fails CI without a
//! GPU. Also checks that the uniform block has the size the Rust mirror (`Globals`, 128 bytes)
//! uploads. Native only (naga is a native dev-dependency; the test reads files).
#![cfg(not(target_arch = "wasm32"))]

use std::path::Path;

fn shaders() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/render");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("src/render/ exists")
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "wgsl"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable shader");
            (p.file_name().unwrap().to_string_lossy().into_owned(), text)
        })
        .collect();
    out.sort();
    out
}

fn validate(name: &str, text: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(text)
        .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(text)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{name}: {}", e.emit_to_string(text)));
    module
}

#[test]
fn every_shader_parses_and_validates() {
    let all = shaders();
    assert!(
        all.len() >= 2,
        "expected mesh.wgsl and line.wgsl, found {all:?}"
    );
    for (name, text) in &all {
        let module = validate(name, text);
        for entry in ["vs_main", "fs_main"] {
            assert!(
                module.entry_points.iter().any(|e| e.name == entry),
                "{name}: missing entry point {entry}"
            );
        }
    }
}

#[test]
fn globals_block_is_128_bytes_in_every_shader() {
    for (name, text) in shaders() {
        let module = validate(&name, &text);
        let (_, ty) = module
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some("Globals"))
            .unwrap_or_else(|| panic!("{name}: no Globals struct"));
        let size = ty.inner.size(module.to_ctx());
        assert_eq!(
            size, 128,
            "{name}: Globals is {size} bytes, Rust uploads 128"
        );
    }
}

#[test]
fn a_broken_shader_is_rejected() {
    // Guards the test itself: naga must really reject bad WGSL.
    let bad = "@vertex fn vs_main() -> @builtin(position) vec4<f32> { return 1.0; }";
    let parsed = naga::front::wgsl::parse_str(bad);
    let invalid = match parsed {
        Err(_) => true,
        Ok(m) => naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(&m)
        .is_err(),
    };
    assert!(invalid);
}
