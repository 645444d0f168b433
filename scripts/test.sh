#!/usr/bin/env bash
# Run every test of the project, installing what is missing first (scripts/setup.sh).
#
#   ./scripts/test.sh              # setup + all stages; fails fast on the first failing stage
#   SKIP_SETUP=1 ./scripts/test.sh # skip the install checks (fast local reruns)
#
# Stages: rustfmt, the core crate's dependency check, the import check (no circles, nothing
# imported from a crate root), clippy (native + wasm32, with and without
# `render`), native tests, doc tests, wasm tests (node, and headless Chromium for tests with
# `wasm_bindgen_test_configure!(run_in_browser)`), then scripts/test.d/.
#
# scripts/test.d/: every executable `*.sh` there is one more stage, run in sorted (C locale)
# order from the repo root after the Rust stages, with this script's environment (node_modules
# installed, CHROMEDRIVER set, Chromium at /usr/bin/chromium). A stage fails by exiting non-zero.
# Name them NN-what.sh (e.g. 10-npm-package.sh, 20-node-tests.sh, 50-e2e.sh) to fix the order.
#
# At the end (and after a failing stage) a table gives each stage's wall time; the last line is
# `stages: N passed, M failed`.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

if [[ ${SKIP_SETUP:-0} == 1 ]]; then
  log "SKIP_SETUP=1: not checking installs"
else
  setup_start=$SECONDS
  ./scripts/setup.sh
  log "setup took $((SECONDS - setup_start)) s"
fi

# wasm-bindgen-test-runner: drive Debian's Chromium through its ChromeDriver, with the extra
# Chrome flags that enable WebGPU/WebGL on SwiftShader (no GPU here) and keep Chromium off the
# network. SwiftShader is slow, hence the generous per-test-binary timeout (default 20 s).
export CHROMEDRIVER=${CHROMEDRIVER:-/usr/bin/chromedriver}
export WASM_BINDGEN_TEST_WEBDRIVER_JSON=${WASM_BINDGEN_TEST_WEBDRIVER_JSON:-$REPO_ROOT/webdriver.json}
export WASM_BINDGEN_TEST_TIMEOUT=${WASM_BINDGEN_TEST_TIMEOUT:-120}
# No incremental caches: the suite's runs are mostly cold (CI clones afresh), where they only cost
# time and disk. With the dependencies' line-tables-only debug info (Cargo.toml), the Rust stages'
# cold builds went from 3.9 GB to 2.4 GB and from 173 s to 148 s (a CI run once failed on a full
# disk). CARGO_INCREMENTAL=1 brings the caches back for edit-and-rerun loops.
export CARGO_INCREMENTAL=${CARGO_INCREMENTAL:-0}

passed=0

# The Python stage's environment installs in the background from here (scripts/python-env.sh;
# the stage waits for it); its output is in artifacts/python-env.log.
mkdir -p artifacts
./scripts/python-env.sh >artifacts/python-env.log 2>&1 &

stage_names=()
stage_secs=()
stage_cpus=()
clk_tck=$(getconf CLK_TCK)
# cpu_secs: the CPU seconds (user + system) of this shell's finished children so far, from
# /proc: with two cores, a stage whose CPU time is near twice its wall time cannot go faster by
# running beside another one, while a stage far below it waits on something.
cpu_secs() {
  local -a s
  read -r -a s </proc/$$/stat
  echo $(((s[15] + s[16]) / clk_tck))
}
# summary FAILED: the per-stage wall times, then the closing count line.
summary() {
  local i
  header "stage times (wall, and CPU of all processes)"
  for i in "${!stage_names[@]}"; do
    printf '%6d s %6d cpu s  %s\n' "${stage_secs[$i]}" "${stage_cpus[$i]}" "${stage_names[$i]}" >&2
  done
  printf '%6d s  total (setup included)\n' "$SECONDS" >&2
  printf 'stages: %d passed, %d failed\n' "$passed" "$1"
}

# stage NAME CMD...: one announced stage; stops the whole run at the first failure.
stage() {
  local name=$1 start=$SECONDS rc=0 cpu_start
  cpu_start=$(cpu_secs)
  shift
  header "stage $((passed + 1)): $name"
  "$@" || rc=$?
  stage_names+=("$name")
  stage_secs+=($((SECONDS - start)))
  stage_cpus+=($(($(cpu_secs) - cpu_start)))
  if ((rc != 0)); then
    log "stage '$name' FAILED (exit $rc) after $((SECONDS - start)) s"
    bg_join
    summary 1
    exit "$rc"
  fi
  passed=$((passed + 1))
  log "stage '$name' passed in $((SECONDS - start)) s"
}

stage "rustfmt" cargo fmt --all -- --check
stage "core has no web dependencies" ./scripts/check-core-deps.sh
stage "no import circles" python3 scripts/check-imports.py
stage "ARCHITECTURE.md's trees match the files" python3 scripts/check-architecture.py
stage "clippy native (all targets)" cargo clippy --workspace --all-targets -- -D warnings
stage "clippy $WASM_TARGET (core and web libs)" \
  cargo clippy -p screwbender -p screwbender-web --lib --target "$WASM_TARGET" -- -D warnings
stage "clippy $WASM_TARGET (web lib, features render)" \
  cargo clippy -p screwbender-web --lib --target "$WASM_TARGET" --features render -- -D warnings
stage "native tests (all targets)" cargo test --workspace --all-targets
stage "doc tests" cargo test --workspace --doc
# The API documentation builds without warnings: no broken intra-doc links. (The CLI separately:
# its binary `screwbender` and the core library would write the same page.)
stage "rustdoc (core and web libs)" env RUSTDOCFLAGS="-D warnings" cargo doc --no-deps -p screwbender -p screwbender-web
stage "rustdoc (CLI)" env RUSTDOCFLAGS="-D warnings" cargo doc --no-deps -p screwbender-cli
# The web crate's tests with its `teaching` functions (feature-gated out of the light npm module).
# ChromeDriver makes a browser profile in $TMPDIR for each test binary and leaves it there (about
# 28 MB each, 19 per run of this stage), so the stage gets a TMPDIR of its own, removed after it.
wasm_tmp=$(mktemp -d)
trap 'rm -rf "$wasm_tmp"' EXIT
stage "wasm tests (node + headless Chromium)" \
  env TMPDIR="$wasm_tmp" \
  cargo test --target "$WASM_TARGET" -p screwbender -p screwbender-web --features screwbender-web/teaching --tests --lib
rm -rf "$wasm_tmp"

# Stages beside others: a test.d stage with the line `# test.sh: beside the next stages` in its
# first lines starts in the background (its output kept in a file) while the next stages run, and
# is waited for before a stage with the line `# test.sh: alone` and at the end; then its output is
# printed whole and its time counted. For stages that leave a core idle much of the time (an
# install, a server starting, a browser waiting for a page), so that two of them share the two.
bg_name=
bg_pid=
bg_log=
bg_start=0
bg_join() {
  [[ -n $bg_pid ]] || return 0
  local rc=0 cpu_start
  cpu_start=$(cpu_secs)
  wait "$bg_pid" || rc=$?
  cat "$bg_log"
  rm -f "$bg_log"
  stage_names+=("$bg_name (beside the next stages)")
  local end=$SECONDS
  [[ -s $bg_log.end ]] && end=$(<"$bg_log.end")
  rm -f "$bg_log.end"
  stage_secs+=($((end - bg_start)))
  stage_cpus+=($(($(cpu_secs) - cpu_start)))
  bg_pid=
  if ((rc != 0)); then
    log "stage '$bg_name' FAILED (exit $rc) after $((end - bg_start)) s"
    summary 1
    exit "$rc"
  fi
  passed=$((passed + 1))
  log "stage '$bg_name' passed in $((end - bg_start)) s (beside the next stages)"
}
bg_stage() {
  bg_join
  bg_name=$1
  shift
  bg_log=$(mktemp)
  bg_start=$SECONDS
  header "stage $((passed + 1)): $bg_name (starts now, runs beside the next stages; output when it ends)"
  {
    local rc=0
    "$@" || rc=$?
    echo "$SECONDS" >"$bg_log.end"
    exit "$rc"
  } >"$bg_log" 2>&1 &
  bg_pid=$!
}

# Extra stages from other parts of the project (JS package, node tests, Playwright e2e).
if [[ -d scripts/test.d ]]; then
  mapfile -t hooks < <(LC_ALL=C find scripts/test.d -maxdepth 1 -type f -name '*.sh' | LC_ALL=C sort)
  for hook in "${hooks[@]}"; do
    if [[ ! -x $hook ]]; then
      log "WARNING: $hook is not executable, so it is not run (chmod +x it)"
    elif grep -qx '# test.sh: beside the next stages' < <(head -n 30 "$hook"); then
      bg_stage "${hook#scripts/}" "./$hook"
    else
      if grep -qx '# test.sh: alone' < <(head -n 30 "$hook"); then bg_join; fi
      stage "${hook#scripts/}" "./$hook"
    fi
  done
fi
bg_join

summary 0
