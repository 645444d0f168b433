#!/usr/bin/env bash
# The Stanford bunny for the bunny6 preset's object (origin and terms in
# crates/screwbender/assets/bunny.NOTICE). One copy is committed, the crate's
# crates/screwbender/assets/bunny.obj (compiled into the core with its `bunny` feature); the page
# fetches the same file, so the build copies it with its notice into www/vendor/ (ignored there).
#
#   scripts/serve.d/30-bunny.sh             # copy the crate's mesh into www/vendor/
#   scripts/serve.d/30-bunny.sh --from-npm  # remake the crate's mesh from the npm package `bunny`
#
# --from-npm writes the package's positions and triangles as OBJ, turned from its y-up to the
# page's z-up, (x, y, z) -> (x, -z, y).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
assets=crates/screwbender/assets
if [[ ${1:-} == --from-npm ]]; then
  node -e '
const bunny = require("./node_modules/bunny");
const out = [
  "# The Stanford bunny (Stanford 3D Scanning Repository, http://graphics.stanford.edu/data/3Dscanrep/),",
  "# from the npm package bunny 1.0.1; see bunny.NOTICE. z up. Made by scripts/serve.d/30-bunny.sh.",
];
for (const [x, y, z] of bunny.positions) out.push(`v ${x} ${-z} ${y}`);
for (const [a, b, c] of bunny.cells) out.push(`f ${a + 1} ${b + 1} ${c + 1}`);
require("fs").writeFileSync(process.argv[1], out.join("\n") + "\n");
' "$assets/bunny.obj"
fi
mkdir -p www/vendor
cp "$assets/bunny.obj" "$assets/bunny.NOTICE" www/vendor/
