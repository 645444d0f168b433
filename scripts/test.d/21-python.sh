#!/usr/bin/env bash
# Stage: the Python package `screwbender` (python/, the PyO3 crate crates/screwbender-py).
#
# Installs a virtual environment in .venv/ (ignored) with the pinned python/requirements-dev.txt
# (maturin, numpy, pytest, modern_robotics, pytransform3d, the notebook stack), builds the wheel
# with maturin (release) into artifacts/python/, installs that wheel into the venv, checks that
# its SIMD lanes are inlined (scripts/check-lanes-inlined.sh), and runs
# pytest on python/tests: the CLI's poses bit for bit (the CLI as the native test stage built
# it: scripts/lib.sh `test_cli`), the reference libraries, bad input, files,
# the notebook figure, the course notebook and, when a figure bundle exists, JupyterLab in
# headless Chromium.
#
#   PYTHON=python3.12 scripts/test.d/21-python.sh    # another interpreter (default python3)
#
# It runs beside the next stages (scripts/test.sh): its install, JupyterLab's start and the
# browser's waits leave a core idle much of the time. It needs www/'s modules: it starts before
# 22-first-frame builds them, and python/build-figure.sh waits for that build (or makes it)
# under www/'s build lock.
# test.sh: beside the next stages
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

venv=$REPO_ROOT/.venv
./scripts/python-env.sh

SCREWBENDER_CLI=$(timed "the CLI (the reference)" test_cli)
export SCREWBENDER_CLI

if [[ -x python/build-figure.sh ]]; then
  timed "figure bundle" python/build-figure.sh
fi

rm -rf artifacts/python
mkdir -p artifacts/python
# maturin reads python/pyproject.toml (which names the crate's Cargo.toml) from its directory.
timed "maturin build --release" bash -c 'cd python && "$1" build --release --quiet \
  -o ../artifacts/python --interpreter "$2"' _ "$venv/bin/maturin" "$venv/bin/python"
wheel=$(ls artifacts/python/screwbender-*.whl)
timed "pip install the wheel" "$venv/bin/pip" install --quiet --disable-pip-version-check \
  --force-reinstall --no-deps "$wheel"

# The lanes check (scripts/check-lanes-inlined.sh) on the extension module just built: a release
# build of the core, so no release CLI is compiled for that check alone.
module=$(cd / && "$venv/bin/python" -c 'import screwbender._screwbender as m; print(m.__file__)')
./scripts/check-lanes-inlined.sh "$module"

header "pytest python/tests"
# From a directory outside python/, so `import screwbender` is the installed wheel and not the
# source folder.
cd "$REPO_ROOT/python/tests"
timed "pytest" "$venv/bin/python" -m pytest -q -p no:cacheprovider \
  --rootdir="$REPO_ROOT/python/tests" .
log "python: $(basename "$wheel") built and tested"
