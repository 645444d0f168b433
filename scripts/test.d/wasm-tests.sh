#!/usr/bin/env bash
# Stage: the core's and the web crate's tests compiled to wasm32, in Node and (for the tests with
# `wasm_bindgen_test_configure!(run_in_browser)`) in headless Chromium through ChromeDriver; the
# web crate with its `teaching` functions (feature-gated out of the light npm module).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

# ChromeDriver makes a browser profile in $TMPDIR for each test binary and leaves it there (tens
# of MB each, one per test binary), so the stage gets a TMPDIR of its own, removed after it.
wasm_tmp=$(mktemp -d)
trap 'rm -rf "$wasm_tmp"' EXIT
TMPDIR="$wasm_tmp" cargo test --target "$WASM_TARGET" -p screwbender -p screwbender-web \
  --features screwbender-web/teaching --tests --lib
