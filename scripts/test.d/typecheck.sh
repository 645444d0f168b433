#!/usr/bin/env bash
# Stage: the page's type check. TypeScript reads the plain ES modules of www/js by their JSDoc
# (www/jsconfig.json says which files and how strictly) and emits nothing. Besides the usual
# mistakes (a misspelt property, a wrong argument), it holds the contracts between the page's
# parts written there as typedefs, and the App's ownership of its state: outside www/js/app.js
# the motion, the display settings, playback and the selection are read-only, so a module that
# assigns to them fails here (they change through the App's commands and setters).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

[[ -x node_modules/.bin/tsc ]] || die "node_modules/.bin/tsc is missing: run npm ci"
timed "tsc --project www/jsconfig.json" node_modules/.bin/tsc --project www/jsconfig.json
# The element's typings, manifest and notebook traitlets are written from its declarations
# (scripts/element-api.mjs); the committed ones must be what the declarations give now.
timed "element API files up to date" node scripts/element-api.mjs --check
