#!/usr/bin/env bash
# Vendor the page's npm dependencies into www/vendor/ so www/ is a self-contained static folder
# (the copies are committed too, so the folder works even without this step).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
cp node_modules/lil-gui/dist/lil-gui.esm.min.js www/vendor/lil-gui.esm.min.js
cp node_modules/lil-gui/LICENSE* www/vendor/ 2>/dev/null || true
cp node_modules/uplot/dist/uPlot.esm.js www/vendor/uPlot.esm.js
cp node_modules/uplot/dist/uPlot.min.css www/vendor/uPlot.min.css
cp node_modules/uplot/LICENSE www/vendor/uPlot.LICENSE 2>/dev/null || true
# fflate (MIT): the zip of a lesson package for an LMS (www/js/lessons/package-dialog.js).
node_modules/.bin/esbuild node_modules/fflate/esm/browser.js --minify --format=esm --log-level=warning \
  --outfile=www/vendor/fflate.min.mjs
cp node_modules/fflate/LICENSE www/vendor/fflate.LICENSE
