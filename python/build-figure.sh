#!/usr/bin/env bash
# Bundles the notebook figure into python/screwbender/static/figure.js (python/widget/build.mjs)
# from the playground's renderer modules in www/pkg-webgpu and www/pkg-gl, building them first
# when they are missing (scripts/serve.sh's build). It reads www/ under the build's lock
# (scripts/lib.sh `www_lock`): in the test suite the Python stage runs beside the stage that
# builds www/.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/lib.sh"
cd "$REPO_ROOT"
www_lock
if [[ ! -f www/pkg-webgpu/screwbender_bg.wasm || ! -f www/pkg-gl/screwbender_bg.wasm ]]; then
  www_unlock
  BUILD_ONLY=1 scripts/serve.sh
  www_lock
fi
node scripts/element-api.mjs --python
node python/widget/build.mjs
www_unlock
