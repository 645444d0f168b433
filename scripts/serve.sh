#!/usr/bin/env bash
# Build what the playground needs and serve www/ on 127.0.0.1.
#
#   ./scripts/serve.sh                # port 8080, or the next free one
#   PORT=9000 ./scripts/serve.sh      # exactly this port
#   SKIP_BUILD=1 ./scripts/serve.sh   # serve what is already built
#   BUILD_ONLY=1 ./scripts/serve.sh   # build www/ and exit (used by scripts/test.d/e2e.sh)
#
# Build: the page's three wasm modules (scripts/wasm-module.sh; pkg-gl and pkg-full are the npm
# package's builds, so whichever of the two scripts runs second only copies them), then every
# executable scripts/serve.d/*.sh in sorted order (hook for later build steps, e.g. vendoring
# uplot and lil-gui from node_modules into www/). Serve: scripts/serve.mjs (no-store caching,
# right MIME).
#
#   www/pkg-webgpu/  features webgpu,gltf-mesh: the first frame (the <screw-bender> figure's module)
#   www/pkg-gl/      features webgl,gltf-mesh: where WebGPU has no usable adapter (or ?backend=webgl2)
#   www/pkg-full/    features export,methods,tracks,teaching,fit, no renderer: the analysis views,
#                    fetched when first used (www/js/editor/modules.js)
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

WWW_DIR=www

build() {
  if [[ ${SKIP_SETUP:-0} != 1 ]]; then
    # Only what the build needs: no browser.
    ./scripts/setup.sh rust wasm-bindgen npm
  fi

  ./scripts/wasm-module.sh webgpu,gltf-mesh "$WWW_DIR/pkg-webgpu" -Oz
  ./scripts/wasm-module.sh webgl,gltf-mesh "$WWW_DIR/pkg-gl" -Oz
  ./scripts/wasm-module.sh export,methods,tracks,teaching,fit "$WWW_DIR/pkg-full" -Os
  # www/pkg/ is no module of the page's (nothing imports it): a stale copy is not served.
  rm -rf "$WWW_DIR/pkg"

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
  www_lock
  build
  www_unlock
fi

if [[ ${BUILD_ONLY:-0} == 1 ]]; then
  log "BUILD_ONLY=1: $WWW_DIR/ is built; not serving"
  exit 0
fi

header "serve"
exec node scripts/serve.mjs "$WWW_DIR"
