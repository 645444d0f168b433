#!/usr/bin/env bash
# Playground end-to-end tests (tests/e2e/, playwright-core + Debian Chromium).
# Builds the playground first (scripts/serve.sh: its three wasm modules, shared with the npm build).
#
# Every test file runs on WebGPU. A file whose behaviour depends on how the page draws (pixels,
# the renderer's start-up and fallback, canvas captures) says so in a line of its own near the
# top,
#     // e2e-backends: webgpu webgl2
# and runs again with WebGL2 forced. Picking, layout, files, lessons and the analysis views are
# computed on the CPU, the same on either backend, so running them twice would test nothing new.
# Files run E2E_JOBS at a time (default 2: most of a test's wall time is waiting on frames that
# SwiftShader draws on the other core); each file has its own server and browser.
# Screenshots land in artifacts/e2e-webgpu/ and artifacts/e2e-webgl2/.
#
#   SKIP_E2E_BUILD=1 scripts/test.d/40-e2e.sh      # reuse www/ as built
#   E2E_BACKENDS=webgl2 scripts/test.d/40-e2e.sh   # one backend only
#   E2E_FILES="tests/e2e/viewer.test.mjs" scripts/test.d/40-e2e.sh   # some files only
#   E2E_JOBS=1 scripts/test.d/40-e2e.sh            # one file at a time
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if [[ ${SKIP_E2E_BUILD:-0} != 1 ]]; then
  BUILD_ONLY=1 SKIP_SETUP=1 ./scripts/serve.sh
fi

if [[ -n ${E2E_FILES:-} ]]; then
  read -r -a all <<<"$E2E_FILES"
else
  mapfile -t all < <(LC_ALL=C find tests/e2e -maxdepth 1 -name '*.test.mjs' | LC_ALL=C sort)
fi
((${#all[@]})) || die "no e2e test files"

for backend in ${E2E_BACKENDS:-webgpu webgl2}; do
  files=()
  for f in "${all[@]}"; do
    if [[ $backend == webgpu ]] || head -n 20 "$f" | grep -qE '^// e2e-backends:.*\bwebgl2\b'; then
      files+=("$f")
    fi
  done
  header "e2e: $backend (${#files[@]} files)"
  E2E_BACKEND=$backend timed "e2e $backend" \
    node --test --test-concurrency="${E2E_JOBS:-2}" "${files[@]}"
done
