#!/usr/bin/env bash
# Builds the web crate with FEATURES into one browser module in OUT_DIR: cargo build --profile
# wasm-release for wasm32, wasm-bindgen --target web (screwbender.js, screwbender_bg.wasm, the
# .d.ts; the glue minified), no name or producers section, wasm-opt at level OPT (-Oz, -Os).
#
#   scripts/wasm-module.sh FEATURES OUT_DIR OPT
#
# Used by scripts/build-pkg.sh (the npm package's modules) and scripts/serve.sh (the
# playground's, the same ones): the wasm-bindgen and wasm-opt output (minutes of work for a
# renderer module) is kept in the cargo target dir under wasm-modules/<hash of the cargo output, the
# features, OPT and this script>, so the second of the two builds, or a rebuild of an unchanged
# module, only copies it. Needs the wasm32 target, wasm-bindgen-cli matching Cargo.lock and the
# root node_modules (wasm-opt from npm's binaryen: Debian's wasm-opt 108 breaks externref modules).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

(($# == 3)) || die "usage: scripts/wasm-module.sh FEATURES OUT_DIR OPT"
features=$1 out=$2 opt=$3
WASM_OPT=$REPO_ROOT/node_modules/.bin/wasm-opt
[[ -x $WASM_OPT ]] || die "$WASM_OPT missing: run npm ci at the repo root (scripts/setup.sh)"
want=$(locked_wasm_bindgen_version)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}') || true
[[ $have == "$want" ]] || die "wasm-bindgen $want needed (Cargo.lock), found '${have:-none}': run scripts/setup.sh"

target_dir=$(cargo_target_dir)

# Panic locations name each source file by its path, and those of the dependencies lie under
# cargo's registry in $CARGO_HOME: a module built in another home directory would differ, in
# content and in size (which is budgeted). Mapped to machine-independent names (`serde_json-1.0.x/
# src/…`, as the workspace's own are relative); in the wasm-release profile only, which nothing
# but the module builds use, so the dependencies are not rebuilt back and forth. (The standard
# library's `/rustc/<commit>/…` paths come precompiled and are not remapped.)
remap=()
for registry in "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/; do
  [[ -d $registry ]] && remap+=("\"--remap-path-prefix=$registry=\"")
done

# Several of these may run at once (scripts/build-pkg.sh starts its modules together, so that one
# module's wasm-opt, which uses one core, runs beside the next module's cargo build). Each build
# writes the same output file, so the build and the copy of its output hold one lock; what
# follows works on the private copy.
work=$(mktemp -d)
started=
trap 'rm -rf "$work"; [[ -n $started ]] && rm -f "$started"' EXIT
input=$work/screwbender_web.wasm
feature_args=()
[[ -n $features ]] && feature_args=(--features "$features")
build_and_copy() {
  header "$(basename "$out"): cargo build (wasm32, wasm-release${features:+, features $features})"
  timed "cargo build" cargo build -p screwbender-web --lib --profile wasm-release --target "$WASM_TARGET" \
    --config "target.$WASM_TARGET.rustflags=[$(IFS=,; echo "${remap[*]}")]" "${feature_args[@]}"
  cp "$target_dir/$WASM_TARGET/wasm-release/screwbender_web.wasm" "$input"
}
# A cargo build that has nothing to do still takes seconds (it checks every dependency), and the
# suite asks for each module in several stages. So each FEATURES/OPT pair keeps a marker naming
# its last module and the compiler; when no file under crates/ or .cargo/, nor Cargo.toml or
# Cargo.lock, is newer than the marker (written before that build began, so that an edit during
# it counts), the kept module is used without asking cargo.
mkdir -p "$target_dir/wasm-modules"
marker=$target_dir/wasm-modules/last-$( (echo "$features $opt $have"; cat "${BASH_SOURCE[0]}") | sha256sum | cut -c1-16)
compiler=$(rustc -V)
stamp=
if [[ -f $marker ]]; then
  read -r kept kept_compiler <"$marker" || true
  if [[ $kept_compiler == "${compiler// /_}" && -f $target_dir/wasm-modules/$kept/screwbender_bg.wasm &&
    -z $(find crates Cargo.toml Cargo.lock .cargo -newer "$marker" -print -quit) ]]; then
    stamp=$kept
    log "$(basename "$out"): no source changed since its last build: no cargo build"
  fi
fi
if [[ -z $stamp ]]; then
  started=$(mktemp "$target_dir/wasm-modules/started.XXXXXX")
  (
    flock 9
    build_and_copy
  ) 9>"$target_dir/wasm-module.lock"
  stamp=$( (cat "$input" "${BASH_SOURCE[0]}" Cargo.lock; echo "$features $opt $have") | sha256sum | cut -d' ' -f1)
fi

WASM_OPT_FEATURES=(--enable-bulk-memory --enable-reference-types --enable-nontrapping-float-to-int
  --enable-sign-ext --enable-mutable-globals --enable-multivalue --enable-simd)

cache=$target_dir/wasm-modules/$stamp
# Two stages may ask for the same module at once (the npm package's build and the page's, beside
# it): the first makes it under the module's own lock, the other waits and copies it, rather than
# running the same minutes of wasm-opt a second time.
exec 8>"$cache.lock"
flock 8
if [[ ! -f $cache/screwbender_bg.wasm ]]; then
  tmp=$cache.tmp.$$
  rm -rf "$tmp"
  mkdir -p "$tmp"
  timed "wasm-bindgen" wasm-bindgen --target web --remove-name-section --remove-producers-section \
    --out-dir "$tmp" --out-name screwbender "$input"
  # --low-memory-unused lets wasm-opt fold `pointer + constant` into the loads' and stores'
  # offset fields: the two differ only where the 32-bit sum wraps around into the lowest
  # kilobyte, which Rust code never reaches (pointer arithmetic does not wrap; the stack lies
  # below 1 MB and the data above it).
  timed "wasm-opt $opt" "$WASM_OPT" "$opt" --low-memory-unused --strip-debug --strip-producers "${WASM_OPT_FEATURES[@]}" \
    "$tmp/screwbender_bg.wasm" -o "$tmp/screwbender_bg.opt.wasm"
  mv "$tmp/screwbender_bg.opt.wasm" "$tmp/screwbender_bg.wasm"
  rm -f "$tmp/package.json" "$tmp/.gitignore"
  # The glue minified (esbuild, as the viewer's sources: an ES module still, exports, import
  # names and import.meta.url kept): every page that shows a figure downloads it, and most of
  # it is the renderer's web-sys shims. About half its gzip size.
  "$REPO_ROOT/node_modules/.bin/esbuild" "$tmp/screwbender.js" --minify --format=esm --log-level=warning \
    --outfile="$tmp/screwbender.min.js"
  mv "$tmp/screwbender.min.js" "$tmp/screwbender.js"
  rm -rf "$cache"
  mv "$tmp" "$cache"
else
  log "$(basename "$out"): unchanged since the last build (wasm-modules/${stamp:0:12}): copied"
fi
flock -u 8
exec 8>&-
if [[ -n $started ]]; then
  echo "$stamp ${compiler// /_}" >"$started"
  mv "$started" "$marker"
  started=
fi
rm -rf "$out"
mkdir -p "$out"
cp "$cache"/* "$out/"
log "$(basename "$out"): $(wc -c <"$out/screwbender_bg.wasm") bytes wasm, $(gzip -9c "$out/screwbender_bg.wasm" | wc -c) bytes gzip"
