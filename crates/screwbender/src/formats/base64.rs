//! Base64 as glTF `data:` URIs carry it.
//!
//! Kept here rather than taken from the `base64` crate (which would keep the core's dependency
//! rules): this decoder accepts the standard and the URL-safe alphabet, with or without padding
//! and with line breaks, as embedded URIs from different tools come; that crate wants one
//! alphabet and one padding mode chosen up front, so matching this leniency would take a custom
//! engine configuration larger than the function itself.

/// Decodes standard base64 (padding optional); `None` on an invalid character.
pub(crate) fn decode(text: &str) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(text.len() * 3 / 4);
    let (mut acc, mut bits) = (0u32, 0u32);
    for c in text.bytes() {
        let v = match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' | b'-' => 62,
            b'/' | b'_' => 63,
            b'=' | b'\n' | b'\r' => continue,
            _ => return None,
        } as u32;
        acc = (acc << 6) | v;
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    Some(out)
}
