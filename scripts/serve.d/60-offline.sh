#!/usr/bin/env bash
# Build the template of the playground's offline figure (Share & embed → Download .html): one HTML
# file holding the <screw-bender> element's code, its stylesheet and the playground's wasm module
# (both backends), which works opened from file:// with no network. Made by 60-offline.mjs beside
# this file into www/pkg-offline/ (built output, like www/pkg-webgpu/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
node scripts/serve.d/60-offline.mjs
