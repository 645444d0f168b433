#!/usr/bin/env bash
# Stage: glTF export checked by the Khronos glTF-Validator (npm `gltf-validator`, pinned in the
# root package.json; installed by `npm ci` in scripts/setup.sh).
#
# Builds the CLI, exports every preset with every scheme (bspline, fourpoint, jarek) as .glb and
# as .gltf + .bin into a temporary directory, and validates each file: 0 errors and 0 warnings
# (infos such as NODE_EMPTY for the empty 'control poses' node are allowed). Then checks that
# `screwbender import` gives back each preset's control poses from the .glb (the round trip).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

[[ -d node_modules/gltf-validator ]] || die "node_modules/gltf-validator is missing: run npm ci"

bin=$(timed "the CLI" test_cli)

work=$(mktemp -d "${TMPDIR:-/tmp}/screwbender-gltf.XXXXXX")
trap 'rm -rf "$work"' EXIT

header "export every preset × scheme"
mapfile -t presets < <("$bin" preset | awk '{print $1}')
((${#presets[@]} > 0)) || die "screwbender preset listed no presets"
files=()
for id in "${presets[@]}"; do
  "$bin" preset "$id" >"$work/$id.json"
  for scheme in bspline fourpoint jarek; do
    "$bin" export --format glb --scheme "$scheme" "$work/$id.json" -o "$work/$id-$scheme.glb" \
      --verbose 2>>"$work/summary.txt"
    "$bin" export --format gltf --scheme "$scheme" "$work/$id.json" -o "$work/$id-$scheme.gltf"
    [[ -s $work/$id-$scheme.bin ]] || die "no $id-$scheme.bin next to the .gltf"
    files+=("$work/$id-$scheme.glb" "$work/$id-$scheme.gltf")
  done
done
cat "$work/summary.txt"
log "${#files[@]} files exported"

header "Khronos glTF-Validator"
timed "gltf-validator (${#files[@]} files)" node tests/gltf/validate.mjs "${files[@]}"

header "three.js plays the morphing preset"
SCREWBENDER_BIN=$bin timed "node --test tests/gltf/morph.test.mjs" node --test tests/gltf/morph.test.mjs

header "import round trip"
for id in "${presets[@]}"; do
  "$bin" import "$work/$id-fourpoint.glb" -o "$work/$id-back.json"
  node -e '
    const [a, b] = process.argv.slice(1).map((f) => JSON.parse(require("fs").readFileSync(f, "utf8")));
    const tol = 1e-6;
    if (a.poses.length !== b.poses.length || (a.closed ?? true) !== (b.closed ?? true))
      throw new Error(`pose count or closed flag differ: ${a.poses.length} vs ${b.poses.length}`);
    a.poses.forEach((p, i) => {
      const q = b.poses[i];
      const s = Math.sign(p.rotation.reduce((acc, x, k) => acc + x * q.rotation[k], 0)) || 1;
      p.origin.forEach((x, k) => { if (Math.abs(x - q.origin[k]) > tol) throw new Error(`pose ${i} origin`); });
      p.rotation.forEach((x, k) => { if (Math.abs(x - s * q.rotation[k]) > tol) throw new Error(`pose ${i} rotation`); });
    });
  ' "$work/$id.json" "$work/$id-back.json" || die "$id: import did not give back the control poses"
done
log "glTF: ${#files[@]} files valid (0 errors, 0 warnings); ${#presets[@]} round trips within 1e-6"
