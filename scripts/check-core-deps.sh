#!/usr/bin/env bash
# The core crate `screwbender` must stay free of the web: on every target, wasm32 included, its
# normal dependency tree has no wasm-bindgen, js-sys, web-sys or wgpu (they belong to
# crates/screwbender-web). Checked with every feature combination that matters.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

forbidden='^(wasm-bindgen|js-sys|web-sys|wgpu)( |$)'
status=0
for target in "$WASM_TARGET" x86_64-unknown-linux-gnu; do
  for features in "--no-default-features" "" "--all-features"; do
    # shellcheck disable=SC2086
    found=$(cargo tree -p screwbender --target "$target" -e normal --prefix none $features |
      awk '{print $1}' | grep -E "$forbidden" | sort -u || true)
    if [[ -n $found ]]; then
      log "screwbender on $target ${features:-(default features)} depends on: $(echo "$found" | tr '\n' ' ')"
      status=1
    else
      log "screwbender on $target ${features:-(default features)}: no web dependencies"
    fi
  done
done
exit "$status"
