#!/usr/bin/env bash
# Vendor the Stanford bunny (npm package `bunny`; origin and terms in www/vendor/bunny.NOTICE)
# into www/vendor/bunny.obj for the bunny preset's object: the package's positions and triangles
# as OBJ, turned from its y-up to the page's z-up, (x, y, z) -> (x, -z, y). The copy is committed
# too, so www/ works without this step.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mkdir -p www/vendor
node -e '
const bunny = require("./node_modules/bunny");
const out = [
  "# The Stanford bunny (Stanford 3D Scanning Repository, http://graphics.stanford.edu/data/3Dscanrep/),",
  "# from the npm package bunny 1.0.1; see bunny.NOTICE. z up. Made by scripts/serve.d/30-bunny.sh.",
];
for (const [x, y, z] of bunny.positions) out.push(`v ${x} ${-z} ${y}`);
for (const [a, b, c] of bunny.cells) out.push(`f ${a + 1} ${b + 1} ${c + 1}`);
require("fs").writeFileSync("www/vendor/bunny.obj", out.join("\n") + "\n");
'
