#!/usr/bin/env bash
# Playground end-to-end tests (tests/e2e/, playwright-core + Debian Chromium).
# Builds the playground first (scripts/serve.sh: its three wasm modules, shared with the npm build).
#
# Each test file names its backends on a line of its own near the top (tests/e2e/run.mjs):
#     // e2e-backends: webgpu webgl2 (why)
# Every file runs on WebGPU. A file whose behaviour depends on how the page draws (pixels, the
# renderer's start-up and fallback, canvas captures) runs again with WebGL2 forced, and holds only
# such tests: picking, layout, menus, files, lessons and the analysis views are computed on the
# CPU, the same on either backend, so running them twice would test nothing new; they live in
# WebGPU-only files beside it (playground-render / playground, viewer-render / viewer, media and
# video-export / view-menu). Pictures for the docs are scripts/docs-shots.mjs's, not the tests'. One pool of jobs (a file on a backend),
# E2E_JOBS at a time (default 2), the longest first; each file has its own server and browser.
# Screenshots land in artifacts/e2e-webgpu/ and artifacts/e2e-webgl2/.
#
#   SKIP_E2E_BUILD=1 scripts/test.d/e2e.sh      # reuse www/ as built
#   E2E_BACKENDS=webgl2 scripts/test.d/e2e.sh   # one backend only
#   E2E_FILES="tests/e2e/viewer.test.mjs" scripts/test.d/e2e.sh   # some files only
#   E2E_JOBS=1 scripts/test.d/e2e.sh            # one file at a time
#
# It runs alone (scripts/stages.txt): its files already share both cores, and frame waits under
# more load only grow.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if [[ ${SKIP_E2E_BUILD:-0} != 1 ]]; then
  BUILD_ONLY=1 SKIP_SETUP=1 ./scripts/serve.sh
fi

files=()
[[ -n ${E2E_FILES:-} ]] && read -r -a files <<<"$E2E_FILES"
timed "e2e" node tests/e2e/run.mjs "${files[@]}"
