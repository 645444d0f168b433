#!/usr/bin/env bash
# Proves that a change kept the command-line behaviour byte for byte: builds the `screwbender`
# CLI of git revision REV (in a temporary worktree) and of the work tree, runs
# scripts/cli-outputs.sh with each (every preset × scheme × rule set: subdivide, eval,
# export --format csv, compare --json) and diffs the two folders.
#
#   scripts/cli-compare.sh REV     # e.g. scripts/cli-compare.sh origin/main
#
# Exit status 0 when every output is identical, 1 (with the differing files listed) otherwise.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

rev=${1:?usage: scripts/cli-compare.sh REV}
work=$(mktemp -d)
trap 'git worktree remove --force "$work/before" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT

git worktree add --detach "$work/before" "$rev" >/dev/null
# A revision before the workspace had the binary in the root package; after, in screwbender-cli.
build() {
  local dir=$1
  (cd "$dir" && cargo build --release --quiet --bin screwbender --target-dir "$work/target-$2")
  echo "$work/target-$2/release/screwbender"
}
timed "build $rev" build "$work/before" before >/dev/null
timed "build work tree" build "$REPO_ROOT" after >/dev/null

# The outputs are made by this work tree's script for both binaries, so both answer the same calls.
scripts/cli-outputs.sh "$work/target-before/release/screwbender" "$work/out-before"
scripts/cli-outputs.sh "$work/target-after/release/screwbender" "$work/out-after"
count=$(find "$work/out-after" -type f | wc -l)
if diff -rq "$work/out-before" "$work/out-after"; then
  log "identical: $count outputs of $rev and the work tree"
else
  log "the outputs above differ between $rev and the work tree"
  exit 1
fi
