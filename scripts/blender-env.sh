#!/usr/bin/env bash
# The Blender test environment: a virtual environment of CPython 3.11 (Blender 4.5's) in
# .venv-blender/ (ignored) with `bpy` from PyPI, pinned in tests/blender/requirements.txt. Run by
# the Blender stage (scripts/test.d/blender.sh), and started early beside the other stages by
# scripts/test.sh (scripts/stages.txt: setup-blender), as the install is mostly waiting on the
# network and the disk; a lock makes the stage wait for it. Prints nothing on stdout; exits 0
# without a CPython 3.11 unless CI=true (scripts/lib.sh `missing_python`).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

if ! py=$(python_at 3.11); then
  missing_python "3.11 (Blender 4.5's, for bpy)"
  exit 0
fi
venv=$REPO_ROOT/.venv-blender
exec 9>"$REPO_ROOT/.venv-blender.lock"
flock 9
if [[ ! -x $venv/bin/python ]]; then
  timed "venv of CPython 3.11" "$py" -m venv "$venv"
fi
uv=$(uv_bin)
timed "uv pip install bpy (pinned)" "$uv" pip install --quiet --python "$venv/bin/python" \
  -r tests/blender/requirements.txt
