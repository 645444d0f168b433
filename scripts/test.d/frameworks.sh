#!/usr/bin/env bash
# Stage: the framework example apps (examples/react, examples/vue, examples/svelte) against the npm
# package as it ships (the tarball of scripts/build-pkg.sh, reused when the npm stage made it).
#
#   1. copy each app into a mktemp dir with the tarball as screwbender.tgz; `npm ci` from its own
#      lockfile, the three in parallel (only the npm registry; npm's cache makes a re-run quick);
#   2. type-check the typed usage of each framework: tsc --strict (React 19 JSX), vue-tsc --strict
#      with strictTemplates (Vue 3 templates), svelte-check (Svelte 5), each with files that must
#      compile and @ts-expect-error / @vue-expect-error lines the typings must refuse;
#   3. check npm/custom-elements.json against the element and the typings (manifest.test.mjs);
#   4. `vite build` each app (and React's again with NODE_ENV=development, where StrictMode mounts
#      twice), then drive the builds in headless Chromium (tests/frameworks/apps.test.mjs): all of
#      it on WebGPU, and on WebGL2 the state reaching a drawn figure (the second renderer module).
#
#   E2E_BACKENDS=webgpu scripts/test.d/frameworks.sh   # one backend only
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

APPS=(react vue svelte)
NPM_CI=(npm ci --no-audit --no-fund --loglevel=error --prefer-offline)

tarball=
if [[ -f pkg/package.json ]]; then
  version=$(node -p 'require("./pkg/package.json").version')
  tarball=$REPO_ROOT/artifacts/npm/screwbender-$version.tgz
fi
if [[ -z $tarball || ! -f $tarball ]]; then
  ./scripts/build-pkg.sh
  version=$(node -p 'require("./pkg/package.json").version')
  tarball=$REPO_ROOT/artifacts/npm/screwbender-$version.tgz
fi
[[ -f $tarball ]] || die "no tarball $tarball"

work=$(mktemp -d "${TMPDIR:-/tmp}/screwbender-frameworks.XXXXXX")
trap 'rm -rf "$work"' EXIT

# run_all LABEL CMD...: CMD in every app's folder at once (output in $work/<app>.log); fails
# with the log of each app whose command failed.
run_all() {
  local label=$1 pids=() failed=0 i
  shift
  for app in "${APPS[@]}"; do
    (cd "$work/$app" && "$@") >"$work/$app.log" 2>&1 &
    pids+=($!)
  done
  for i in "${!APPS[@]}"; do
    if ! wait "${pids[$i]}"; then
      failed=1
      log "${APPS[$i]}: $label failed:"
      cat "$work/${APPS[$i]}.log" >&2
    fi
  done
  ((failed == 0)) || die "$label failed"
}

header "copy the apps, npm ci (in parallel)"
for app in "${APPS[@]}"; do
  mkdir "$work/$app"
  tar -C "examples/$app" --exclude=node_modules --exclude=dist --exclude=dist-dev --exclude='*.tgz' -cf - . |
    tar -C "$work/$app" -xf -
  cp "$tarball" "$work/$app/screwbender.tgz"
done
timed "npm ci (react, vue, svelte)" run_all "npm ci" "${NPM_CI[@]}"

header "type checks (tsc, vue-tsc, svelte-check; in parallel)"
timed "type checks" run_all "type check" npm run --silent typecheck

header "the Custom Elements Manifest against the element and its typings"
node --test tests/frameworks/manifest.test.mjs

header "vite build (in parallel)"
build() {
  ./node_modules/.bin/vite build --logLevel warn
  # StrictMode's double mount happens in React's development build only.
  if [[ -f src/main.tsx ]]; then
    NODE_ENV=development ./node_modules/.bin/vite build --logLevel warn --outDir dist-dev
  fi
}
timed "vite build" run_all "vite build" build

for backend in ${E2E_BACKENDS:-webgpu webgl2}; do
  header "the apps in Chromium: $backend"
  # On WebGL2 (the package's second renderer module, which the bundle must carry too), the apps'
  # state reaching a drawn figure; everything else is the same on both backends.
  pattern=()
  [[ $backend == webgl2 ]] && pattern=(--test-name-pattern "state reaches the figure")
  FRAMEWORK_APPS=$work E2E_BACKEND=$backend timed "apps $backend" \
    node --test --test-concurrency=1 "${pattern[@]}" tests/frameworks/apps.test.mjs
done
log "framework apps (React, Vue, Svelte): typed, built and driven"
