#!/usr/bin/env bash
# Vendor reveal.js (the npm package `reveal.js`, a devDependency; MIT, www/vendor/reveal.LICENSE) for
# the slide-deck example www/examples/slides.html: its ES module minified by esbuild (Vite's) into
# www/vendor/reveal.min.mjs, its stylesheet and one theme (serif: system fonts, nothing fetched
# from another origin). The copies are committed too, so www/ works without this step.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
dist=node_modules/reveal.js/dist
version=$(node -p 'require("./node_modules/reveal.js/package.json").version')
node_modules/.bin/esbuild "$dist/reveal.mjs" --minify --format=esm --legal-comments=inline \
  --banner:js="// reveal.js $version (npm package reveal.js); made by scripts/serve.d/50-reveal.sh." \
  --log-level=warning --outfile=www/vendor/reveal.min.mjs
cp "$dist/reveal.css" www/vendor/reveal.css
cp "$dist/theme/serif.css" www/vendor/reveal-serif.css
cp node_modules/reveal.js/LICENSE www/vendor/reveal.LICENSE
