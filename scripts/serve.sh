#!/usr/bin/env bash
# Build what the playground needs and serve www/ on 127.0.0.1.
#
#   ./scripts/serve.sh                # port 8080, or the next free one
#   PORT=9000 ./scripts/serve.sh      # exactly this port
#   SKIP_BUILD=1 ./scripts/serve.sh   # serve what is already built
#   SERVE_FEATURES= ./scripts/serve.sh  # build the wasm without the wgpu renderer
#   BUILD_ONLY=1 ./scripts/serve.sh   # build www/ and exit (used by scripts/test.d/40-e2e.sh)
#
# Build: release wasm32 cdylib -> wasm-bindgen --target web -> www/pkg/, then every executable
# scripts/serve.d/*.sh in sorted order (hook for later build steps, e.g. vendoring uplot and
# lil-gui from node_modules into www/). Serve: scripts/serve.mjs (no-store caching, right MIME).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

# Cargo features of the playground build: `render` is the wgpu renderer.
SERVE_FEATURES=${SERVE_FEATURES-render}
# The web crate and its [lib] name: the wasm file is <name>.wasm; the page imports it as
# pkg/screwbender.js (wasm-bindgen --out-name).
WEB_CRATE=screwbender-web
CRATE_LIB=screwbender_web
WWW_DIR=www

build() {
  if [[ ${SKIP_SETUP:-0} != 1 ]]; then
    # Only what the build needs: no browser.
    ./scripts/setup.sh rust wasm-bindgen npm
  fi

  header "build: wasm (release${SERVE_FEATURES:+, features $SERVE_FEATURES})"
  local features=() target_dir
  [[ -n $SERVE_FEATURES ]] && features=(--features "$SERVE_FEATURES")
  timed "cargo build" cargo build -p "$WEB_CRATE" --lib --release --target "$WASM_TARGET" "${features[@]}"

  # Honour CARGO_TARGET_DIR / build.target-dir: ask cargo where the artifacts are.
  target_dir=$(cargo metadata --format-version 1 --no-deps |
    grep -o '"target_directory":"[^"]*"' | cut -d'"' -f4)
  timed "wasm-bindgen" wasm-bindgen --target web --out-dir "$WWW_DIR/pkg" --out-name screwbender \
    "$target_dir/$WASM_TARGET/release/$CRATE_LIB.wasm"

  if [[ -d scripts/serve.d ]]; then
    local hook
    while IFS= read -r hook; do
      if [[ -x $hook ]]; then
        header "build: ${hook#scripts/}"
        "./$hook"
      fi
    done < <(LC_ALL=C find scripts/serve.d -maxdepth 1 -type f -name '*.sh' | LC_ALL=C sort)
  fi
}

if [[ ${SKIP_BUILD:-0} == 1 ]]; then
  log "SKIP_BUILD=1: serving $WWW_DIR/ as it is"
else
  build
fi

if [[ ${BUILD_ONLY:-0} == 1 ]]; then
  log "BUILD_ONLY=1: $WWW_DIR/ is built; not serving"
  exit 0
fi

header "serve"
exec node scripts/serve.mjs "$WWW_DIR"
