#!/usr/bin/env bash
# Stage: one contract for every front end (tests/conformance/run.mjs): one table of cases —
# options, bad options, the method comparison, each export — through the npm package's wasm API
# in Node, the playground page in Chromium, the command line and Python; their results and error
# words must agree. Uses what the stages before it built: pkg/ (the npm stage), the debug CLI
# (the native tests), the venv with the wheel (the Python stage, which this stage waits for) and
# www/ (the first-frame stage). It runs alone (scripts/stages.txt): a browser and three front ends.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

SCREWBENDER_CLI=$(test_cli)
export SCREWBENDER_CLI
timed "conformance" node tests/conformance/run.mjs
