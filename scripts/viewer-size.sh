#!/usr/bin/env bash
# Measures what a browser downloads to show one read-only <screw-bender> figure from the npm
# package built in PKG (default pkg/, by scripts/build-pkg.sh, whose viewer sources are minified),
# gzip -9 per file, and fails over budget:
#   WebGPU path: viewer.js, the figure's JS and CSS, viewer/pkg/ (glue + WebGPU-only wasm)
#                ≤ WEBGPU_GZIP_BUDGET bytes (default 290 000);
#   WebGL2 path: the same JS and CSS and viewer/pkg-gl/ (glue + WebGL2 wasm), not the WebGPU
#                module ≤ WEBGL_GZIP_BUDGET bytes (default 1 200 000).
# js/share-link.js (the share-link decoder's chunk of the bundle) is imported only for a
# `share` payload, so neither path counts it. Nor does either count viewer/vendor/bunny.obj (the Stanford bunny),
# which a figure fetches only to show the bunny6 preset; it is logged apart.
# Also checks that neither wasm carries a name section and that the WebGPU module has no GL
# backend or shader translator (no naga/glow/WebGL2RenderingContext in its glue or wasm) and no
# file import (the figure reads a glTF or CSV `src` with the `screwbender/full` module).
#
#   ./scripts/viewer-size.sh [PKG]
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

pkg=${1:-pkg}
WEBGPU_GZIP_BUDGET=${WEBGPU_GZIP_BUDGET:-290000}
WEBGL_GZIP_BUDGET=${WEBGL_GZIP_BUDGET:-1200000}
v=$pkg/viewer
[[ -f $v/pkg/screwbender_bg.wasm && -f $v/pkg-gl/screwbender_bg.wasm ]] || die "no viewer modules in $pkg (scripts/build-pkg.sh)"

gz() { # FILE...: total gzip -9 bytes
  local total=0 f
  for f in "$@"; do total=$((total + $(gzip -9c "$f" | wc -c))); done
  echo "$total"
}

mapfile -t common < <(LC_ALL=C find "$pkg/viewer.js" "$v/js" "$v/css" -type f -not -path '*/js/share-link.js' | LC_ALL=C sort)
common_gz=$(gz "${common[@]}")
glue_gz=$(gz "$v/pkg/screwbender.js")
webgpu_wasm_gz=$(gz "$v/pkg/screwbender_bg.wasm")
gl_gz=$(gz "$v/pkg-gl/screwbender.js" "$v/pkg-gl/screwbender_bg.wasm")
webgpu_total=$((common_gz + glue_gz + webgpu_wasm_gz))
webgl_total=$((common_gz + gl_gz))

log "viewer JS + CSS (${#common[@]} files): $common_gz bytes gzip; WebGPU glue $glue_gz"
log "WebGPU wasm: $(wc -c <"$v/pkg/screwbender_bg.wasm") bytes, $webgpu_wasm_gz gzip"
log "WebGL2 module (glue + wasm): $(wc -c <"$v/pkg-gl/screwbender_bg.wasm") bytes wasm, $gl_gz gzip"
[[ -f $v/vendor/bunny.obj ]] && log "bunny6 preset's mesh (fetched only for that preset, not counted): $(gz "$v/vendor/bunny.obj") bytes gzip"
log "one read-only figure, WebGPU: $webgpu_total bytes gzip (budget $WEBGPU_GZIP_BUDGET)"
log "one read-only figure, WebGL2: $webgl_total bytes gzip (budget $WEBGL_GZIP_BUDGET)"

node -e '
  const fs = require("fs");
  for (const f of process.argv.slice(1)) {
    const m = new WebAssembly.Module(fs.readFileSync(f));
    const names = WebAssembly.Module.customSections(m, "name").length;
    if (names) { console.error(`${f} carries a name section`); process.exit(1); }
  }
' "$v/pkg/screwbender_bg.wasm" "$v/pkg-gl/screwbender_bg.wasm" || die "a viewer wasm carries a name section"
if grep -q -E 'WebGL2RenderingContext|getContext\(.webgl' "$v/pkg/screwbender.js"; then
  die "the WebGPU-only viewer module has WebGL glue: was it built with the webgl feature?"
fi
if grep -q importMotionFile "$v/pkg/screwbender.js"; then
  die "the WebGPU-only viewer module has file import: was it built with the files feature?"
fi
((webgpu_total <= WEBGPU_GZIP_BUDGET)) || die "WebGPU figure: $webgpu_total bytes gzip, over the budget of $WEBGPU_GZIP_BUDGET"
((webgl_total <= WEBGL_GZIP_BUDGET)) || die "WebGL2 figure: $webgl_total bytes gzip, over the budget of $WEBGL_GZIP_BUDGET"
log "viewer sizes within budget"
