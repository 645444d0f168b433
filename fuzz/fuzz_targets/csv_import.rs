//! CSV import: `parse_csv_poses` on arbitrary text never panics, and what it accepts is valid.
#![no_main]

use libfuzzer_sys::fuzz_target;
use screwbender::parse_csv_poses;

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(doc) = parse_csv_poses(text) {
        assert!(doc.poses.len() >= 2, "{} poses accepted", doc.poses.len());
        for (i, p) in doc.poses.iter().enumerate() {
            common::assert_sane(p, &format!("pose {i}"));
        }
    }
});
