#!/usr/bin/env bash
# Stage: the API documentation builds without warnings (no broken intra-doc links). The CLI
# separately: its binary `screwbender` and the core library would write the same page.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

export RUSTDOCFLAGS="-D warnings"
timed "rustdoc (core and web libs)" cargo doc --no-deps -p screwbender -p screwbender-web
timed "rustdoc (CLI)" cargo doc --no-deps -p screwbender-cli
