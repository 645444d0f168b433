#!/usr/bin/env bash
# Vendor KaTeX (npm `katex`, MIT) into www/vendor/ for the lessons' math (www/js/lessons/).
# The lessons render with KaTeX's `output: 'mathml'`: MathML needs neither KaTeX's CSS nor its
# fonts and writes no inline styles, so the page's CSP stays as it is. Only the ES module is
# copied, minified with the esbuild that vite brings (the copy is committed too, like the
# other vendored files, so www/ works without this step).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
node_modules/.bin/esbuild node_modules/katex/dist/katex.mjs --minify --format=esm --log-level=warning \
  --outfile=www/vendor/katex.min.mjs
cp node_modules/katex/LICENSE www/vendor/katex.LICENSE
