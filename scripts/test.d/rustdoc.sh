#!/usr/bin/env bash
# Stage: the API documentation builds without warnings (no broken intra-doc links), for the core
# and web libraries and the CLI. The CLI's binary `screwbender` and the core library would write
# the same page, so they are two invocations: the CLI first, then the libraries, whose pages are
# the ones left in target/doc. Both select the same three packages, so cargo resolves the same
# features for their dependencies and the second reuses what the first checked.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

export RUSTDOCFLAGS="-D warnings"
packages=(-p screwbender -p screwbender-web -p screwbender-cli)
timed "rustdoc (CLI)" cargo doc --no-deps "${packages[@]}" --bins
timed "rustdoc (core and web libs)" cargo doc --no-deps "${packages[@]}" --lib
