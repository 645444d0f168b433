#!/usr/bin/env bash
# Bundles the notebook figure into python/screwbender/static/figure.js (python/widget/build.mjs)
# from the playground's renderer modules in www/pkg-webgpu and www/pkg-gl, building them first
# when they are missing (scripts/serve.sh's build; in the test suite stage 40-e2e has built them).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/lib.sh"
cd "$REPO_ROOT"
if [[ ! -f www/pkg-webgpu/screwbender_bg.wasm || ! -f www/pkg-gl/screwbender_bg.wasm ]]; then
  BUILD_ONLY=1 scripts/serve.sh
fi
node python/widget/build.mjs www
