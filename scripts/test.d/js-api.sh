#!/usr/bin/env bash
# Stage: the JS API of the built npm package, method by method (tests/js/*.test.mjs with
# `node --test`): typed-array layouts, known poses, and every bad input with both its Error
# message and the unchanged state of the object. Builds pkg/ first (a no-op when up to date).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

# The tests load pkg/ (the main entry, tests/js/package.mjs) and pkg/full/ (the files, methods,
# tracks and teaching parts, tests/js/full-package.mjs).
PACK=0 ./scripts/build-pkg.sh
header "node --test tests/js/"
node --test tests/js/
