# shellcheck shell=bash
# Shared helpers for scripts/*.sh. Source it; do not execute it.

# Repository root, whatever the caller's working directory.
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export REPO_ROOT

# Never prompt (apt, npm, cargo): CI runs with no stdin.
export DEBIAN_FRONTEND=noninteractive

# cargo's bin dir may be missing from PATH in a non-login shell; wasm-bindgen lands there.
export PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"

# Line tables, not full debug info, for the workspace's own crates in the scripts' debug and
# test builds (their dependencies have only line tables already, Cargo.toml): a failing test
# still names its file and line, and the suite's cold debug builds take less of the processor
# (the wasm tests' above all, where the linker and wasm-bindgen carry the DWARF). Set here, so
# that every script's builds agree and share their artifacts; cargo run by hand keeps full debug
# info.
export CARGO_PROFILE_DEV_DEBUG=${CARGO_PROFILE_DEV_DEBUG:-line-tables-only}

# The only Rust target besides the host that this project builds for (used by the scripts).
# shellcheck disable=SC2034
WASM_TARGET=wasm32-unknown-unknown

log() { printf '[%s] %s\n' "$(date +%H:%M:%S)" "$*" >&2; }
die() { log "ERROR: $*"; exit 1; }

# header TEXT: a visible separator line, so each step is easy to find in CI logs.
header() { printf '\n==================== %s ====================\n' "$*" >&2; }

# timed LABEL CMD...: run CMD and report how long it took (install steps are slow; CI budget matters).
timed() {
  local label=$1 start rc=0
  shift
  start=$SECONDS
  "$@" || rc=$?
  if ((rc == 0)); then
    log "$label: done in $((SECONDS - start)) s"
  else
    log "$label: FAILED (exit $rc) after $((SECONDS - start)) s"
  fi
  return "$rc"
}

# Version of the wasm-bindgen crate in Cargo.lock: the CLI must match it exactly, or the
# generated JS glue and the wasm module disagree ("schema version mismatch").
locked_wasm_bindgen_version() {
  awk '
    $0 == "[[package]]" { name = "" }
    $1 == "name" && $3 == "\"wasm-bindgen\"" { name = "wasm-bindgen" }
    name == "wasm-bindgen" && $1 == "version" { gsub(/"/, "", $3); print $3; exit }
  ' "$REPO_ROOT/Cargo.lock"
}

# cargo_target_dir: where cargo builds, as cargo itself says (CARGO_TARGET_DIR, build.target-dir
# of a cargo config, or the workspace's target/).
cargo_target_dir() {
  cargo metadata --format-version 1 --no-deps | grep -o '"target_directory":"[^"]*"' | cut -d'"' -f4
}

# test_cli: the path of the `screwbender` CLI as the native test stage builds it (the dev
# profile, the workspace's features), after making sure it is up to date with the same cargo
# command, which does nothing when that stage ran. Stages that run the CLI use this build rather
# than compiling another one: a release build of the CLI is a long compile on one core (one
# codegen unit), and the CLI's outputs are the same at every opt-level (Rust neither
# reassociates nor fuses floating-point operations).
test_cli() {
  CARGO_INCREMENTAL=${CARGO_INCREMENTAL:-0} cargo test --workspace --all-targets --no-run -q >&2
  local bin
  bin=$(cargo_target_dir)/debug/screwbender
  [[ -x $bin ]] || die "no CLI at $bin after the test build"
  echo "$bin"
}

# www_lock / www_unlock: an exclusive hold on www/'s build (file descriptor 8), so that two
# scripts of the test suite running side by side never read www/ while the other writes it
# (scripts/serve.sh's build copies every module into place even when nothing changed). Not
# reentrant: release it before running a script that takes it.
www_lock() {
  exec 8>"$REPO_ROOT/www/.build.lock"
  flock 8
}
www_unlock() {
  flock -u 8
  exec 8>&-
}

# Run as root directly, otherwise through sudo (a developer's own machine).
as_root() {
  if ((EUID == 0)); then "$@"; else sudo "$@"; fi
}

# The uv that installs the test environments' pinned requirements (.venv, .venv-blender and the
# clean venvs of the Python stage): it resolves, downloads and links the same pinned wheels as
# pip with a small fraction of pip's processor time, and leaves the bytecode to be compiled on
# first import, of the modules a test imports only (docs/speed/suite.md has the measurements).
# The wheel itself is still built and installed with each venv's own pip, as users install it.
UV_VERSION=0.13.9

# uv_bin: the path of uv $UV_VERSION, installed on first use into .venv-uv/ (ignored) by a venv's
# pip; several stages may ask at once, so under a lock.
uv_bin() {
  local dir=$REPO_ROOT/.venv-uv
  (
    flock 9
    if [[ ! -x $dir/bin/uv || $("$dir/bin/uv" --version 2>/dev/null | awk '{print $2}') != "$UV_VERSION" ]]; then
      [[ -x $dir/bin/pip ]] || python3 -m venv "$dir" >&2
      "$dir/bin/pip" install --quiet --disable-pip-version-check "uv==$UV_VERSION" >&2
    fi
  ) 9>"$REPO_ROOT/.venv-uv.lock"
  echo "$dir/bin/uv"
}

# python_at X.Y: the path of CPython X.Y: pyenv's (`pyenv root`, default ~/.pyenv), else
# pythonX.Y on PATH; fails when there is none.
python_at() {
  local root=${PYENV_ROOT:-$HOME/.pyenv} p
  for p in "$root"/versions/"$1".*/bin/python"$1" "$(command -v "python$1" || true)"; do
    [[ -n $p && -x $p ]] && { echo "$p"; return 0; }
  done
  return 1
}

# newest_python_version: the newest X.Y of CPython 3 that python_at finds (empty if none).
newest_python_version() {
  local root=${PYENV_ROOT:-$HOME/.pyenv} v
  {
    for v in "$root"/versions/3.*; do
      [[ -d $v ]] && basename "$v" | grep -oE '^3\.[0-9]+'
    done
    compgen -c python3. | grep -oE '^python3\.[0-9]+$' | sed 's/^python//'
  } | sort -uV | tail -n1
}

# missing_python WHAT: no interpreter for WHAT: fails on CI, a loud warning elsewhere.
missing_python() {
  if [[ ${CI:-} == true ]]; then
    die "no CPython $1 on this machine (pyenv's versions are part of the machine image)"
  fi
  log "WARNING: no CPython $1 here: what needs it is NOT tested (CI fails on this)"
}
