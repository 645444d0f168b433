#!/usr/bin/env bash
# Vendor mediabunny (the npm package `mediabunny`, a devDependency; MPL-2.0, www/vendor/mediabunny.LICENSE)
# for the playground's video export (www/js/editor/media.js): the names media.js imports, bundled
# and minified by esbuild into one ES module, www/vendor/mediabunny.min.mjs (the muxers only: the
# frames are encoded by the page's own WebCodecs VideoEncoder). The copy is committed too, so www/
# works without this step; a name media.js starts to use must be added to the list below.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
names=(BufferTarget EncodedPacket EncodedVideoPacketSource Mp4OutputFormat Output WebMOutputFormat)
version=$(node -p 'require("./node_modules/mediabunny/package.json").version')
entry=$(mktemp "${TMPDIR:-/tmp}/mediabunny-entry.XXXXXX.mjs")
trap 'rm -f "$entry"' EXIT
list=$(IFS=,; echo "${names[*]}")
echo "export { ${list//,/, } } from '$PWD/node_modules/mediabunny/dist/modules/src/index.js';" >"$entry"
node_modules/.bin/esbuild "$entry" --bundle --minify --format=esm --platform=browser --legal-comments=inline \
  --banner:js="// mediabunny $version (npm package mediabunny, MPL-2.0), the names www/js/editor/media.js uses; made by scripts/serve.d/50-mediabunny.sh." \
  --log-level=warning --outfile=www/vendor/mediabunny.min.mjs
cp node_modules/mediabunny/LICENSE www/vendor/mediabunny.LICENSE
