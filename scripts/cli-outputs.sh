#!/usr/bin/env bash
# Write the CLI's outputs for every preset × scheme × rule set into a folder, one file each:
# `subdivide`, `eval`, `export --format csv` and `compare --json`. Two runs of it diff with
# `diff -r` to prove a change kept the command-line behaviour byte for byte (see
# scripts/cli-compare.sh, which builds a git revision and the work tree and compares them).
#
#   scripts/cli-outputs.sh BINARY OUTDIR
set -euo pipefail
bin=$1
out=$2
mkdir -p "$out"
presets=$("$bin" preset | awk '{print $1}')
for p in $presets; do
  "$bin" preset "$p" >"$out/$p.json"
  "$bin" compare --json "$out/$p.json" >"$out/$p.compare.json" 2>&1 || echo "exit $?" >>"$out/$p.compare.json"
  for scheme in bspline fourpoint jarek; do
    for rules in direct split; do
      tag="$p.$scheme.$rules"
      opts=(--scheme "$scheme" --rules "$rules")
      "$bin" subdivide "${opts[@]}" --levels 4 "$out/$p.json" >"$out/$tag.subdivide.json" 2>&1 ||
        echo "exit $?" >>"$out/$tag.subdivide.json"
      "$bin" eval "${opts[@]}" --levels 5 --u 0 --u 0.37 --u 1.5 --u 2.999 "$out/$p.json" \
        >"$out/$tag.eval.json" 2>&1 || echo "exit $?" >>"$out/$tag.eval.json"
      "$bin" export --format csv "${opts[@]}" --levels 4 "$out/$p.json" >"$out/$tag.csv" 2>&1 ||
        echo "exit $?" >>"$out/$tag.csv"
    done
  done
  for s in 0.25 0.75; do
    "$bin" subdivide --s "$s" --levels 4 "$out/$p.json" >"$out/$p.j$s.subdivide.json" 2>&1 ||
      echo "exit $?" >>"$out/$p.j$s.subdivide.json"
  done
done
