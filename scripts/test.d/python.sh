#!/usr/bin/env bash
# Stage: the Python package `screwbender` (python/, the PyO3 crate crates/screwbender-py).
#
# Installs a virtual environment in .venv/ (ignored) with the pinned python/requirements-dev.txt
# (maturin, zig, numpy, pytest, modern_robotics, pytransform3d, the notebook stack), makes in
# artifacts/python/ the sdist and builds the one wheel from it, as pip builds an sdist (release,
# stable ABI: tag cp39-abi3, linked by zig against glibc 2.28: tag manylinux_2_28, both checked;
# the figure bundle inside): every test below then also tests the sdist. Installs that wheel into the venv,
# checks that its SIMD lanes are inlined (scripts/check-lanes-inlined.sh), and runs pytest on
# python/tests: the CLI's poses bit for bit (the CLI as the native test stage built it:
# scripts/lib.sh `test_cli`), the reference libraries, bad input, files, the notebook figure,
# the course notebook and JupyterLab in headless Chromium (the browser tests need the figure
# bundle; without it they skip, and with CI=true a skipped test fails the stage:
# python/tests/conftest.py).
#
# Beside that pytest, the same wheel in clean virtual environments of the oldest CPython the
# package supports (3.9) and the newest one on the machine (pyenv's, part of the machine image, or
# pythonX.Y on PATH), made with python/requirements-compat.txt while the wheel builds: the
# package's tests on each but the notebook and browser ones (they test the Jupyter stack and the
# JS bundle, the same on every CPython). With CI=true a missing interpreter fails
# the stage; elsewhere it is a warning and that interpreter is left out.
#
#   PYTHON=python3.12 scripts/test.d/python.sh    # another interpreter for .venv (default python3)
#
# It runs beside the other stages (scripts/stages.txt): its install, JupyterLab's start and the
# browser's waits leave a core idle much of the time. It needs www/'s modules: it may start before
# the first-frame stage builds them, and python/build-figure.sh waits for that build (or makes it)
# under www/'s build lock.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

venv=$REPO_ROOT/.venv

# check_wheel_tag WHEEL: the tag is cp39-abi3 and manylinux_2_28 for this machine's
# architecture, and the extension module asks for no glibc symbol version newer than 2.28 (the
# tag's promise, which pip takes on trust).
check_wheel_tag() {
  local name newest_glibc
  name=$(basename "$1")
  [[ $name == screwbender-*-cp39-abi3-manylinux_2_28_$(uname -m).whl ]] ||
    die "the wheel is $name: wanted the tag cp39-abi3-manylinux_2_28_$(uname -m)"
  command -v objdump >/dev/null || die "objdump is missing (Debian: binutils)"
  mkdir -p "$REPO_ROOT/artifacts/python/unpacked"
  "$venv/bin/python" -m zipfile -e "$1" "$REPO_ROOT/artifacts/python/unpacked"
  newest_glibc=$(objdump -T "$REPO_ROOT"/artifacts/python/unpacked/screwbender/_screwbender*.so |
    grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n1)
  rm -rf "$REPO_ROOT/artifacts/python/unpacked"
  [[ -n $newest_glibc ]] || die "no GLIBC_ symbol versions in the extension module of $name"
  [[ $(printf '%s\n' "$newest_glibc" GLIBC_2.28 | sort -V | tail -n1) == GLIBC_2.28 ]] ||
    die "$name needs $newest_glibc, newer than its tag's glibc 2.28"
  log "wheel tag: $name (the newest glibc symbol it needs: $newest_glibc)"
}

# prepare_venv PYTHON: a clean venv of PYTHON in $compat with requirements-compat.txt (a download
# and an install, mostly waiting: done at the start, beside the builds).
prepare_venv() {
  local py=$1 label dir
  label=$("$py" -c 'import platform; print(platform.python_version())')
  dir=$compat/$label
  timed "venv of CPython $label" "$py" -m venv "$dir"
  timed "uv pip install requirements-compat.txt (CPython $label)" "$(uv_bin)" pip install --quiet \
    --python "$dir/bin/python" -r python/requirements-compat.txt
}

# test_wheel_on PYTHON: the wheel into PYTHON's venv (prepare_venv's); then the tests, not
# notebook ones.
test_wheel_on() {
  local py=$1 label dir
  label=$("$py" -c 'import platform; print(platform.python_version())')
  dir=$compat/$label
  timed "pip install the wheel (CPython $label)" "$dir/bin/pip" install --quiet \
    --disable-pip-version-check --no-deps "$wheel"
  (
    cd python/tests
    timed "pytest (CPython $label)" "$dir/bin/python" -m pytest -q -p no:cacheprovider \
      --rootdir=. . --ignore=test_jupyterlab.py --ignore=test_notebook.py \
      --ignore=test_marimo.py \
      -k "not static_page and not static_copies"
  )
}

./scripts/python-env.sh

# The clean venvs of the oldest and the newest CPython, made beside the builds below (their
# downloads and installs wait on the network and the disk); compat_pid is waited for before the
# wheel goes into them.
compat=$(mktemp -d)
compat_log=$(mktemp)
trap 'rm -rf "$compat" "$compat_log"' EXIT
oldest=$(python_at 3.9) || missing_python "3.9 (the oldest that python/pyproject.toml allows)"
newest_version=$(newest_python_version)
newest=
if [[ -n $newest_version && $newest_version != 3.9 ]]; then
  newest=$(python_at "$newest_version")
else
  missing_python "newer than 3.9"
fi
(for py in $oldest $newest; do prepare_venv "$py"; done) >"$compat_log" 2>&1 &
compat_pid=$!

SCREWBENDER_CLI=$(timed "the CLI (the reference)" test_cli)
export SCREWBENDER_CLI

if [[ -x python/build-figure.sh ]]; then
  timed "figure bundle" python/build-figure.sh
fi

rm -rf artifacts/python
mkdir -p artifacts/python
# maturin reads python/pyproject.toml (which names the crate's Cargo.toml) from its directory.
timed "maturin sdist" bash -c 'cd python && "$1" sdist -o ../artifacts/python' _ "$venv/bin/maturin"
sdist=$(ls artifacts/python/screwbender-*.tar.gz)
# The wheel from the sdist, as `pip install screwbender-*.tar.gz` builds it (maturin's PEP 517
# backend, the release profile), in this build's target directory (the dependencies the other
# stages compiled are reused where their flags agree). Without pip's build isolation: the venv's
# pinned maturin, which finds zig (`python3 -m ziglang`, the venv's bin first on PATH) beside it,
# where an isolated build environment has maturin but not zig. No cache: pip would otherwise
# hand back a wheel it built before from an sdist of the same bytes.
# zig's linker drops the whole symbol table for the strip-debug flag that cargo's release profile
# passes by default (`strip = "debuginfo"`), and the lanes check below reads the symbols: no strip.
timed "pip wheel the sdist (abi3, manylinux_2_28, zig)" env CARGO_PROFILE_RELEASE_STRIP=none \
  CARGO_TARGET_DIR="$(cargo_target_dir)" MATURIN_PEP517_ARGS="--zig --compatibility manylinux_2_28" \
  PATH="$venv/bin:$PATH" "$venv/bin/pip" wheel --quiet --disable-pip-version-check --no-deps --no-cache-dir \
  --no-build-isolation -w artifacts/python "$sdist"
wheel=$(ls artifacts/python/screwbender-*.whl)
check_wheel_tag "$wheel"
if [[ -f python/screwbender/static/figure.js ]]; then
  listing=$("$venv/bin/python" -m zipfile -l "$wheel")
  [[ $listing == *screwbender/static/figure.js* ]] ||
    die "$(basename "$wheel") (built from $(basename "$sdist")) has no figure bundle"
fi
timed "pip install the wheel" "$venv/bin/pip" install --quiet --disable-pip-version-check \
  --force-reinstall --no-deps "$wheel"

# The lanes check (scripts/check-lanes-inlined.sh) on the extension module just built: a release
# build of the core, so no release CLI is compiled for that check alone.
module=$(cd / && "$venv/bin/python" -c 'import screwbender._screwbender as m; print(m.__file__)')
./scripts/check-lanes-inlined.sh "$module"

# The wheel on the oldest and the newest CPython, beside the main pytest
# (whose notebook and browser tests leave a core idle most of the time); their output follows it.
wait "$compat_pid" || { cat "$compat_log" >&2; die "the clean venvs could not be made"; }
(
  for py in $oldest $newest; do
    test_wheel_on "$py"
  done
) >>"$compat_log" 2>&1 &
compat_pid=$!

header "pytest python/tests"
# From a directory outside python/, so `import screwbender` is the installed wheel and not the
# source folder.
cd "$REPO_ROOT/python/tests"
rc=0
timed "pytest" "$venv/bin/python" -m pytest -q -p no:cacheprovider \
  --junit-xml="$REPO_ROOT/artifacts/python/pytest.xml" --rootdir="$REPO_ROOT/python/tests" . || rc=$?
cd "$REPO_ROOT"

header "the wheel on the oldest and the newest CPython"
compat_rc=0
wait "$compat_pid" || compat_rc=$?
cat "$compat_log" >&2
((rc == 0)) || die "pytest python/tests failed"
((compat_rc == 0)) || die "the wheel on the oldest or the newest CPython failed"
log "python: $(basename "$wheel"), built from $(basename "$sdist"), tested" \
  "(wheel $(stat -c %s "$wheel") B, sdist $(stat -c %s "$sdist") B)"
