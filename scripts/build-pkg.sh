#!/usr/bin/env bash
# Build the npm package `screwbender` into pkg/, then pack it into a tarball: the math-only
# WebAssembly module (the main entry, no renderer), the `screwbender/full` entry (the math plus
# files, comparison methods, three.js tracks and the teaching functions, in pkg/full/) and the `screwbender/viewer` entry
# (the <screw-bender> element: www/js/element, www/js/view and the renderer's modules in
# pkg/viewer/).
#
#   ./scripts/build-pkg.sh               # pkg/ and artifacts/npm/screwbender-<version>.tgz
#   PACK=0 ./scripts/build-pkg.sh        # pkg/ only
#   PKG_DIR=/tmp/p ./scripts/build-pkg.sh  # another output directory
#
# The viewer also carries the bunny6 preset's mesh, viewer/vendor/bunny.obj (with bunny.NOTICE:
# its origin and terms), beside the sources that fetch it.
#
# The viewer has two renderer modules: viewer/pkg/ with feature webgpu (no wgpu-core, GL backend
# or shader translation: the browser compiles the WGSL; no file import either: the element reads
# a glTF or CSV `src` with the `screwbender/full` module, fetched for that only) and
# viewer/pkg-gl/ with webgl,gltf-mesh (WebGL2 through wgpu's GL backend and naga; the
# playground's module, built once for both), which the element imports only when WebGPU has no
# usable adapter. Both go through wasm-bindgen --remove-name-section and wasm-opt -Oz.
#
# Steps: cargo build --profile wasm-release (release, with the dependencies optimised for size:
# see Cargo.toml) for wasm32 without features (so no wgpu), wasm-bindgen
# --target web (one .wasm and its ES-module glue, usable from browsers with or without a
# bundler), wasm-opt -Os from npm's binaryen (Debian's wasm-opt 108 breaks externref modules),
# then the package files from npm/ with the version taken from Cargo.toml. Needs the wasm32
# target, wasm-bindgen-cli matching Cargo.lock and the root node_modules (scripts/setup.sh).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

PKG_DIR=${PKG_DIR:-$REPO_ROOT/pkg}
PACK_DIR=${PACK_DIR:-$REPO_ROOT/artifacts/npm}
TARGET_DIR=$(cargo_target_dir)
WASM_OPT=$REPO_ROOT/node_modules/.bin/wasm-opt

# node_types DIR: wasm-bindgen's init types name DOM types (RequestInfo, Response, BufferSource)
# and the WebAssembly namespace, which a Node-only TypeScript project (lib es2022, types node, no
# skipLibCheck) does not have. Replace them by structural types declared in the file itself:
# URL, Request, Response, ArrayBuffer and WebAssembly.Module values still match them.
node_types() {
  header "types without the DOM lib ($(basename "$1"))"
  node - "$1/screwbender.d.ts" "$1/screwbender_bg.wasm.d.ts" <<'JS'
const fs = require('fs');
const decls = `
/** A URL (a \`URL\` object or anything with its \`href\`); declared here so that these types need no DOM lib. */
export interface UrlLike { readonly href: string }
/** A fetch \`Request\` (anything with its \`url\`). */
export interface RequestLike { readonly url: string }
/** A fetch \`Response\` (anything with its \`arrayBuffer()\`). */
export interface ResponseLike { arrayBuffer(): Promise<ArrayBuffer> }
/** The bytes of a .wasm file (the DOM's \`BufferSource\`). */
export type BytesLike = ArrayBuffer | ArrayBufferView;
/** A compiled \`WebAssembly.Module\` (which has no members of its own). */
export type WasmModuleLike = object;
/** The module's \`WebAssembly.Memory\`. */
export interface WasmMemoryLike { readonly buffer: ArrayBuffer; grow(delta: number): number }
/** The module's \`WebAssembly.Table\` of JavaScript values. */
export interface WasmTableLike { readonly length: number; get(index: number): unknown; grow(delta: number, value?: unknown): number; set(index: number, value?: unknown): void }
`;
const swaps = [
  ['RequestInfo | URL | Response | BufferSource | WebAssembly.Module', 'string | UrlLike | RequestLike | ResponseLike | BytesLike | WasmModuleLike'],
  ['BufferSource | WebAssembly.Module', 'BytesLike | WasmModuleLike'],
  ['WebAssembly.Memory', 'WasmMemoryLike'],
  ['WebAssembly.Table', 'WasmTableLike'],
];
for (const [i, file] of process.argv.slice(2).entries()) {
  let text = fs.readFileSync(file, 'utf8');
  for (const [from, to] of swaps) text = text.split(from).join(to);
  if (i === 0) {
    text = text.replace(/^export type InitInput =/m, `${decls.trim()}\n\nexport type InitInput =`);
  } else {
    // The module's own exports: the memory and table types from the main file.
    text = `import type { WasmMemoryLike, WasmTableLike } from './screwbender.js';\n${text}`;
  }
  // Doc comments may name them (`WebAssembly.instantiate`); code may not.
  const code = text.split('\n').filter((line) => !/^\s*(\*|\/\*\*)/.test(line)).join('\n');
  const left = code.match(/\b(RequestInfo|BufferSource|WebAssembly\.\w+)\b/);
  if (left) throw new Error(`${file}: ${left[0]} is still named (a new wasm-bindgen output?)`);
  fs.writeFileSync(file, text);
}
JS
}

want=$(locked_wasm_bindgen_version)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}') || true
[[ $have == "$want" ]] || die "wasm-bindgen $want needed (Cargo.lock), found '${have:-none}': run scripts/setup.sh"
[[ -x $WASM_OPT ]] || die "$WASM_OPT missing: run npm ci at the repo root (scripts/setup.sh)"

# Panic locations name each source file by its path, and those of the dependencies lie under
# cargo's registry in $CARGO_HOME: a module built in another home directory would differ, in
# content and in size (which is budgeted). Mapped to machine-independent names (`serde_json-1.0.x/
# src/…`, as the workspace's own are relative); in the wasm-release profile only, which nothing
# but this script builds, so the dependencies are not rebuilt back and forth. (The standard
# library's `/rustc/<commit>/…` paths come precompiled and are not remapped.)
remap=()
for registry in "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/; do
  [[ -d $registry ]] && remap+=("\"--remap-path-prefix=$registry=\"")
done
cargo_wasm_release() {
  cargo build -p screwbender-web --lib --profile wasm-release --target "$WASM_TARGET" \
    --config "target.$WASM_TARGET.rustflags=[$(IFS=,; echo "${remap[*]}")]" "$@"
}

header "cargo build (wasm32, wasm-release, no features)"
timed "cargo build" cargo_wasm_release

# The features rustc enables by default for wasm32 (wasm-opt must accept what the modules use).
WASM_OPT_FEATURES=(--enable-bulk-memory --enable-reference-types --enable-nontrapping-float-to-int
  --enable-sign-ext --enable-mutable-globals --enable-multivalue --enable-simd)

# Skip wasm-bindgen and wasm-opt when neither the module nor the packaging changed.
input=$TARGET_DIR/$WASM_TARGET/wasm-release/screwbender_web.wasm
stamp=$(cat "$input" npm/* scripts/build-pkg.sh Cargo.lock | sha256sum | cut -d' ' -f1)

# wasm_module FEATURES OUT_DIR OPT [node]: the web crate built with FEATURES into OUT_DIR by
# scripts/wasm-module.sh (which keeps its wasm-bindgen and wasm-opt output, shared with the
# playground's build, scripts/serve.sh). With `node`, a module that Node and a Node-only
# TypeScript project use directly: types without the DOM lib and the synchronous Node entry node.js.
wasm_module() {
  local features=$1 out=$2 opt=$3 node=${4:-}
  "$REPO_ROOT/scripts/wasm-module.sh" "$features" "$out" "$opt"
  if [[ $node == node ]]; then
    node_types "$out"
    cp npm/node.js "$out/node.js"
  fi
}

# The other modules are built together, after the main module's: wasm-module.sh runs their cargo
# builds one at a time, and each module's wasm-opt (one core) runs beside the next one's build.
# Each job's log is printed whole when all are done; a failed job fails the build.
module_logs=$(mktemp -d)
module_jobs=()
start_module() { # LABEL FEATURES OUT_DIR OPT [node]
  local label=$1
  shift
  wasm_module "$@" >"$module_logs/$label.log" 2>&1 &
  module_jobs+=("$label:$!")
}
wait_modules() {
  local job rc failed=0
  for job in "${module_jobs[@]}"; do
    rc=0
    wait "${job#*:}" || rc=$?
    cat "$module_logs/${job%%:*}.log" >&2
    ((rc == 0)) || { log "module ${job%%:*}: FAILED (exit $rc)"; failed=1; }
  done
  module_jobs=()
  ((failed == 0)) || die "a wasm module failed to build"
}

if [[ -f $PKG_DIR/.build-stamp && $(cat "$PKG_DIR/.build-stamp") == "$stamp" &&
  -f $PKG_DIR/screwbender_bg.wasm ]]; then
  log "pkg/ is up to date with the wasm module and npm/: not regenerating"
else
  header "wasm-bindgen --target web"
  rm -rf "$PKG_DIR"
  mkdir -p "$PKG_DIR"
  timed "wasm-bindgen" wasm-bindgen --target web --out-dir "$PKG_DIR" --out-name screwbender "$input"

  header "wasm-opt -Os --converge"
  # --converge repeats the passes while they still shrink the module: about 110 bytes gzip of
  # the math module's budget, for a few seconds more. --low-memory-unused (here and for the other
  # modules below) lets wasm-opt fold `pointer + constant` into the loads' and stores' offset
  # fields: the two differ only where the 32-bit sum wraps around into the lowest kilobyte,
  # which Rust code never reaches (pointer arithmetic does not wrap; the stack lies below 1 MB
  # and the data above it). About 1,050 bytes gzip of the math module.
  timed "wasm-opt" "$WASM_OPT" -Os --converge --low-memory-unused "${WASM_OPT_FEATURES[@]}" \
    "$PKG_DIR/screwbender_bg.wasm" -o "$PKG_DIR/screwbender_bg.opt.wasm"
  mv "$PKG_DIR/screwbender_bg.opt.wasm" "$PKG_DIR/screwbender_bg.wasm"

  node_types "$PKG_DIR"
fi

# The viewer's renderer modules (the WebGL2 one, the longest build, first). Without `files`:
# glTF's document model and the JSON parsing of its structs are a large part of a module that
# every figure downloads; a figure with a .glb or .csv `src` fetches full/.
if [[ ${VIEWER:-1} == 1 ]]; then
  start_module viewer-gl webgl,gltf-mesh "$PKG_DIR/viewer/pkg-gl" -Oz
  start_module viewer webgpu "$PKG_DIR/viewer/pkg" -Oz
fi
# The `screwbender/full` entry (full/): the math module plus file export and import (glTF, CSV),
# the comparison methods, the three.js keyframe tracks and the teaching views' functions (no
# renderer), for developers who want those without the playground. A module of its own, so that
# the main entry stays light; -Os like the main module (speed matters more than a few KB here).
if [[ ${FULL:-1} == 1 ]]; then
  start_module full export,methods,tracks,teaching,fit "$PKG_DIR/full" -Os node
fi
wait_modules

if [[ ${VIEWER:-1} == 1 ]]; then
  viewer=$PKG_DIR/viewer
  rm -rf "$viewer/js" "$viewer/css"
  header "viewer: sources"
  mkdir -p "$viewer/js" "$viewer/css"
  # The element and the view it is built on (www/js/element/, www/js/figure/), bundled by esbuild
  # (Vite's) into one minified module, viewer/js/screw-bender.js, with the share-link decoder in
  # a chunk of its own (share-link.js beside it, imported only for a `share` payload): a figure
  # downloads all of them, and one file gzips smaller than the files one by one. The bundle sits
  # where www/js/assets.js does (one folder under viewer/), so the stylesheet and the mesh are
  # where it looks by default (../css/, ../vendor/); viewer.js (npm/) tells it where the
  # package keeps the WebAssembly modules. The readable sources are www/js/.
  "$REPO_ROOT/node_modules/.bin/esbuild" www/js/element/screw-bender.js --bundle --minify --format=esm \
    --splitting --chunk-names='[name]' --outdir="$viewer/js" --log-level=warning
  cp www/css/screw-bender.css "$viewer/css/"
  # The Stanford bunny of the bunny6 preset (viewer.js names it), with its origin and terms;
  # fetched only when a figure shows that preset.
  mkdir -p "$viewer/vendor"
  cp crates/screwbender/assets/bunny.obj crates/screwbender/assets/bunny.NOTICE "$viewer/vendor/"
  # The figure's stylesheet too (its comments are for readers of www/css/).
  "$REPO_ROOT/node_modules/.bin/esbuild" "$viewer/css/screw-bender.css" --minify --log-level=warning --outfile="$viewer/css/screw-bender.css.min"
  mv "$viewer/css/screw-bender.css.min" "$viewer/css/screw-bender.css"
  # The element's types (viewer.d.ts), its entries in React's, Vue's and Svelte's typings, and
  # from its declarations (scripts/element-api.mjs) element-types.d.ts and its Custom Elements
  # Manifest (package.json's "customElements" field).
  cp npm/viewer.js npm/viewer.d.ts npm/react.d.ts npm/vue.d.ts npm/svelte.d.ts "$PKG_DIR/"
  node scripts/element-api.mjs --npm-out "$PKG_DIR"
fi

header "package files"
cp npm/node.js npm/README.md "$PKG_DIR/"
for f in LICENSE LICENSE-MIT LICENSE-APACHE; do
  [[ -f $f ]] && cp "$f" "$PKG_DIR/"
done
version=$(cargo metadata --no-deps --format-version 1 |
  node -e 'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>{
    const p=JSON.parse(s).packages.find(p=>p.name==="screwbender");process.stdout.write(p.version)})')
node -e '
  const fs = require("fs");
  const [template, out, version] = process.argv.slice(1);
  const pkg = JSON.parse(fs.readFileSync(template, "utf8"));
  pkg.version = version;
  for (const f of ["LICENSE", "LICENSE-MIT", "LICENSE-APACHE"])
    if (fs.existsSync(require("path").join(require("path").dirname(out), f))) pkg.files.push(f);
  fs.writeFileSync(out, JSON.stringify(pkg, null, 2) + "\n");
' npm/package.json "$PKG_DIR/package.json" "$version"

echo "$stamp" >"$PKG_DIR/.build-stamp"

wasm=$PKG_DIR/screwbender_bg.wasm
log "screwbender $version: $(wc -c <"$wasm") bytes wasm, $(gzip -9c "$wasm" | wc -c) bytes gzip"

if [[ ${PACK:-1} == 1 ]]; then
  header "npm pack"
  mkdir -p "$PACK_DIR"
  tarball=$(cd "$PKG_DIR" && npm pack --silent --pack-destination "$PACK_DIR")
  log "tarball: $PACK_DIR/$tarball ($(wc -c <"$PACK_DIR/$tarball") bytes)"
fi
