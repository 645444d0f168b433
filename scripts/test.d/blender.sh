#!/usr/bin/env bash
# Stage: the Blender extension (blender/) in Blender 4.5 LTS, headless: `bpy` from PyPI in a
# virtual environment of CPython 3.11 (.venv-blender/, ignored; pinned tests/blender/
# requirements.txt), the extension zipped with the abi3 wheel that the Python stage built
# (scripts/build-blender-extension.sh), then pytest on tests/blender: the extension installed
# through Blender's own installer, its operators against the Python package, and the CLI's .glb
# exports (the CLI as the native test stage built it) through Blender's glTF importer.
#
# It runs beside the other stages (scripts/stages.txt), after the Python stage (whose wheel it
# bundles); the bpy install (scripts/blender-env.sh) starts earlier, beside the Rust stages, as it
# is mostly waiting on the network and the disk. With CI=true a
# missing CPython 3.11 fails the stage; elsewhere it is a warning and the stage does nothing.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if ! python_at 3.11 >/dev/null; then
  missing_python "3.11 (Blender 4.5's, for bpy)"
  exit 0
fi
venv=$REPO_ROOT/.venv-blender
./scripts/blender-env.sh

SCREWBENDER_BLENDER_ZIP=$(timed "the extension zip" ./scripts/build-blender-extension.sh)
SCREWBENDER_CLI=$(timed "the CLI (the reference)" test_cli)
export SCREWBENDER_BLENDER_ZIP SCREWBENDER_CLI

header "pytest tests/blender"
timed "pytest (Blender $("$venv/bin/pip" show bpy 2>/dev/null | sed -n 's/^Version: //p'))" \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir=tests/blender tests/blender
