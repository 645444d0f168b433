#!/usr/bin/env bash
# Build the npm package `screwbender` (the math-only WebAssembly module, no renderer) into pkg/,
# then pack it into a tarball.
#
#   ./scripts/build-pkg.sh               # pkg/ and artifacts/npm/screwbender-<version>.tgz
#   PACK=0 ./scripts/build-pkg.sh        # pkg/ only
#   PKG_DIR=/tmp/p ./scripts/build-pkg.sh  # another output directory
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
TARGET_DIR=${CARGO_TARGET_DIR:-$REPO_ROOT/target}
WASM_OPT=$REPO_ROOT/node_modules/.bin/wasm-opt

want=$(locked_wasm_bindgen_version)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}') || true
[[ $have == "$want" ]] || die "wasm-bindgen $want needed (Cargo.lock), found '${have:-none}': run scripts/setup.sh"
[[ -x $WASM_OPT ]] || die "$WASM_OPT missing: run npm ci at the repo root (scripts/setup.sh)"

header "cargo build (wasm32, wasm-release, no features)"
timed "cargo build" cargo build -p screwbender-web --lib --profile wasm-release --target "$WASM_TARGET"

# Skip wasm-bindgen and wasm-opt (~20 s) when neither the module nor the packaging changed.
input=$TARGET_DIR/$WASM_TARGET/wasm-release/screwbender_web.wasm
stamp=$(cat "$input" npm/* scripts/build-pkg.sh Cargo.lock | sha256sum | cut -d' ' -f1)
if [[ -f $PKG_DIR/.build-stamp && $(cat "$PKG_DIR/.build-stamp") == "$stamp" &&
  -f $PKG_DIR/screwbender_bg.wasm ]]; then
  log "pkg/ is up to date with the wasm module and npm/: not regenerating"
else
  header "wasm-bindgen --target web"
  rm -rf "$PKG_DIR"
  mkdir -p "$PKG_DIR"
  timed "wasm-bindgen" wasm-bindgen --target web --out-dir "$PKG_DIR" --out-name screwbender "$input"

  header "wasm-opt -Os"
  # The features rustc enables by default for wasm32 (wasm-opt must accept what the module uses).
  timed "wasm-opt" "$WASM_OPT" -Os \
    --enable-bulk-memory --enable-reference-types --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-mutable-globals --enable-multivalue --enable-simd \
    "$PKG_DIR/screwbender_bg.wasm" -o "$PKG_DIR/screwbender_bg.opt.wasm"
  mv "$PKG_DIR/screwbender_bg.opt.wasm" "$PKG_DIR/screwbender_bg.wasm"
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
