#!/usr/bin/env bash
# Stage: the playground's first visit on a budget (scripts/first-frame-size.sh: everything headless
# Chromium downloads until the page is idle, gzip -9 per file; a plain visit on WebGPU ≤ 500 KB,
# on WebGL2 ≤ 1 MB, a lesson link ≤ 600 KB). Builds www/ first as scripts/serve.sh does (its WebGL2
# and full wasm modules are the npm package's, so after the npm stage it only copies those; stage
# 40 then reuses them all).
#
#   SKIP_E2E_BUILD=1 scripts/test.d/first-frame.sh   # measure www/ as built
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if [[ ${SKIP_E2E_BUILD:-0} != 1 ]]; then
  BUILD_ONLY=1 SKIP_SETUP=1 ./scripts/serve.sh
fi
timed "first-visit sizes" ./scripts/first-frame-size.sh www
