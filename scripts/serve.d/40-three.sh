#!/usr/bin/env bash
# Vendor three.js (the npm package `three`, a devDependency; MIT, www/vendor/three.LICENSE) for the
# three.js example www/examples/three.html: the names that www/examples/three.js imports, bundled
# and minified by esbuild (Vite's) into one ES module, www/vendor/three.min.mjs (a fraction of
# the whole library; docs/speed/code-notes.md). The copy is committed too, so www/ works without this
# step; a name the example starts to use must be added to the list below.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
names=(AmbientLight AnimationClip AnimationMixer AxesHelper Box3 BufferGeometry Color
  DirectionalLight Float32BufferAttribute GridHelper Line LineBasicMaterial LoopRepeat Mesh
  MeshStandardMaterial PerspectiveCamera QuaternionKeyframeTrack Scene Timer TorusKnotGeometry
  Vector3 VectorKeyframeTrack WebGLRenderer)
version=$(node -p 'require("./node_modules/three/package.json").version')
entry=$(mktemp "${TMPDIR:-/tmp}/three-entry.XXXXXX.mjs")
trap 'rm -f "$entry"' EXIT
list=$(IFS=,; echo "${names[*]}")
echo "export { ${list//,/, } } from '$PWD/node_modules/three/build/three.module.js';" >"$entry"
node_modules/.bin/esbuild "$entry" --bundle --minify --format=esm --legal-comments=inline \
  --banner:js="// three.js $version (npm package three), the names www/examples/three.js uses; made by scripts/serve.d/40-three.sh." \
  --log-level=warning --outfile=www/vendor/three.min.mjs
cp node_modules/three/LICENSE www/vendor/three.LICENSE
