#!/usr/bin/env bash
# Playground end-to-end tests (tests/e2e/, playwright-core + Debian Chromium), run twice:
# once with the WebGPU flags (expects the WebGPU backend) and once forcing WebGL2.
# Builds the playground first (scripts/serve.sh: its three wasm modules, shared with the npm build).
# Screenshots of every preset land in artifacts/e2e-webgpu/ and artifacts/e2e-webgl2/.
#
#   SKIP_E2E_BUILD=1 scripts/test.d/40-e2e.sh   # reuse www/ as built
#   E2E_BACKENDS=webgl2 scripts/test.d/40-e2e.sh  # one backend only
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if [[ ${SKIP_E2E_BUILD:-0} != 1 ]]; then
  BUILD_ONLY=1 SKIP_SETUP=1 ./scripts/serve.sh
fi

for backend in ${E2E_BACKENDS:-webgpu webgl2}; do
  header "e2e: $backend"
  E2E_BACKEND=$backend timed "e2e $backend" node --test --test-concurrency=1 tests/e2e/
done
