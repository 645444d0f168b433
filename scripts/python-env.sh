#!/usr/bin/env bash
# The Python test environment: a virtual environment in .venv/ (ignored) with the pinned
# python/requirements-dev.txt, installed by uv (scripts/lib.sh `uv_bin`). Run by the Python stage (scripts/test.d/python.sh), and started
# early in the background by scripts/test.sh so that the install (mostly one core, and the
# network on a fresh machine) runs beside the Rust stages; a lock makes the stage wait for it.
#
#   PYTHON=python3.12 scripts/python-env.sh     # another interpreter (default python3)
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

venv=$REPO_ROOT/.venv
py=${PYTHON:-python3}
exec 9>"$REPO_ROOT/.venv.lock"
flock 9
if [[ ! -x $venv/bin/python ]]; then
  timed "python venv" "$py" -m venv "$venv"
fi
uv=$(uv_bin)
timed "uv pip install (pinned)" "$uv" pip install --quiet --python "$venv/bin/python" \
  -r python/requirements-dev.txt
