//! JSON motion documents: `MotionDocument::from_json` on arbitrary text never panics; what it
//! accepts is valid (≥ 2 finite poses with unit rotations) and reads back from its own `to_json`.
#![no_main]

use libfuzzer_sys::fuzz_target;
use screwbender::MotionDocument;

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(doc) = MotionDocument::from_json(text) else {
        return;
    };
    assert!(doc.poses.len() >= 2);
    for (i, p) in doc.poses.iter().enumerate() {
        common::assert_sane(p, &format!("poses[{i}]"));
    }
    let again = MotionDocument::from_json(&doc.to_json()).expect("to_json output reads back");
    assert_eq!(again.closed, doc.closed);
    assert_eq!(again.name, doc.name);
    assert_eq!(again.poses.len(), doc.poses.len());
    for (a, b) in doc.poses.iter().zip(&again.poses) {
        let tol = 1e-15 * (1.0 + a.origin.abs().max_element());
        assert!(
            (a.origin - b.origin).abs().max_element() <= tol,
            "origin changed: {a:?} → {b:?}"
        );
        assert!(
            a.rotation.dot(b.rotation).abs() >= 1.0 - 1e-15,
            "rotation changed: {a:?} → {b:?}"
        );
    }
});
