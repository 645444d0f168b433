#!/usr/bin/env bash
# Bundles the notebook figure into python/screwbender/static/figure.js (python/widget/build.mjs)
# from the playground's wasm in www/pkg (or WASM_PKG_DIR), building that wasm first when it is
# missing (scripts/serve.sh's build; in the test suite stage 40-e2e has built it already).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/lib.sh"
cd "$REPO_ROOT"
pkg=${WASM_PKG_DIR:-www/pkg}
if [[ ! -f $pkg/screwbender_bg.wasm ]]; then
  [[ $pkg == www/pkg ]] || die "$pkg/screwbender_bg.wasm is missing"
  BUILD_ONLY=1 scripts/serve.sh
fi
node python/widget/build.mjs "$pkg"
