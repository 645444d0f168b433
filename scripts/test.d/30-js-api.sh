#!/usr/bin/env bash
# Stage: the JS API of the built npm package, method by method (tests/js/*.test.mjs with
# `node --test`): typed-array layouts, known poses, and every bad input with both its Error
# message and the unchanged state of the object. Builds pkg/ and www/pkg first (no-ops when up
# to date).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

PACK=0 ./scripts/build-pkg.sh
# tests/js/files.test.mjs loads the playground's build (feature `files`), made here once and
# reused by the e2e stage.
BUILD_ONLY=1 SKIP_SETUP=1 ./scripts/serve.sh
header "node --test tests/js/"
node --test tests/js/
