#!/usr/bin/env bash
# The Blender extension (blender/) as the zip that Blender installs (Preferences > Get Extensions >
# Install from Disk): the Python package's abi3 wheel from artifacts/python/ (made by
# scripts/test.d/python.sh, or `maturin build` as python/README.md says) copied under
# blender/wheels/ (ignored), then blender/ zipped into artifacts/blender/, caches left out and
# the README's pictures and their script (docs/, tools/) too: Blender has no use for them. Prints
# the zip's path.
#
#   scripts/build-blender-extension.sh [WHEEL]
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

wheel=${1:-$(ls artifacts/python/screwbender-*-cp39-abi3-*.whl 2>/dev/null | head -n1 || true)}
[[ -f $wheel ]] || die "no abi3 wheel in artifacts/python/: run scripts/test.d/python.sh first"
name=$(basename "$wheel")
grep -qF "\"./wheels/$name\"" blender/blender_manifest.toml ||
  die "blender/blender_manifest.toml does not list ./wheels/$name (update its wheels list)"
rm -rf blender/wheels
mkdir -p blender/wheels artifacts/blender
cp "$wheel" blender/wheels/
version=$(sed -n 's/^version = "\(.*\)"/\1/p' blender/blender_manifest.toml)
out=$REPO_ROOT/artifacts/blender/screwbender-$version.zip
rm -f "$out"
python3 - "$out" <<'PY'
import pathlib, sys, zipfile
root = pathlib.Path("blender")
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED) as z:
    for path in sorted(root.rglob("*")):
        inside = path.relative_to(root).parts
        if path.is_file() and "__pycache__" not in inside and inside[0] not in ("docs", "tools"):
            z.write(path, path.relative_to(root))
PY
echo "$out"
