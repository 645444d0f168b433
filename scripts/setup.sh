#!/usr/bin/env bash
# Install everything the build and the tests need, skipping what is already there.
# Idempotent: a second run only checks (a few seconds).
#
#   scripts/setup.sh                  # everything
#   scripts/setup.sh rust npm         # only some parts: rust wasm-bindgen chromium npm
#
# Only package registries (crates.io, Debian, npm) are reachable here: nothing downloads a
# prebuilt binary or a browser build: Chromium comes from Debian, wasm-opt from npm's binaryen.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

# rustup target + the components the lint stages use.
setup_rust() {
  command -v rustup >/dev/null || die "rustup not found: install the Rust toolchain first"
  if rustup target list --installed | grep -qx "$WASM_TARGET"; then
    log "rust target $WASM_TARGET: present"
  else
    timed "rustup target add $WASM_TARGET" rustup target add "$WASM_TARGET"
  fi
  local component
  for component in clippy rustfmt; do
    if rustup component list --installed | grep -q "^$component-"; then
      log "rust component $component: present"
    else
      timed "rustup component add $component" rustup component add "$component"
    fi
  done
}

# wasm-bindgen-cli at exactly the version of the wasm-bindgen crate in Cargo.lock.
setup_wasm_bindgen() {
  local want have
  want=$(locked_wasm_bindgen_version)
  [[ -n $want ]] || die "Cargo.lock has no wasm-bindgen package"
  have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
  if [[ $have == "$want" ]]; then
    log "wasm-bindgen $want: present"
    return
  fi
  log "installing wasm-bindgen-cli $want (found: ${have:-none}); about a minute on 2 cores"
  timed "wasm-bindgen-cli $want" build_wasm_bindgen_cli "$want"
  have=$(wasm-bindgen --version | awk '{print $2}')
  [[ $have == "$want" ]] || die "wasm-bindgen --version says $have, wanted $want"
}

# `cargo install wasm-bindgen-cli --locked` fails here: the crate's Cargo.lock names
# webpki-roots 1.0.11, which the registry index here does not have. So build it from its own
# source with its own lockfile (reproducible), pinning only what the registry lacks.
build_wasm_bindgen_cli() {
  local want=$1 work manifest
  work=$(mktemp -d)
  # cargo has no "download a crate" command: a throwaway project depending on the crate
  # makes `cargo fetch` unpack its source into the registry cache.
  mkdir "$work/fetch"
  cat >"$work/fetch/Cargo.toml" <<TOML
[package]
name = "fetch-wasm-bindgen-cli"
version = "0.0.0"
edition = "2021"
publish = false

[lib]
path = "lib.rs"

[dependencies]
wasm-bindgen-cli = "=$want"

[workspace]
TOML
  touch "$work/fetch/lib.rs"
  (cd "$work/fetch" && cargo fetch --quiet)
  manifest=$(cd "$work/fetch" && cargo metadata --format-version 1 |
    grep -o "\"manifest_path\":\"[^\"]*/wasm-bindgen-cli-$want/Cargo.toml\"" | head -n1 | cut -d'"' -f4)
  [[ -f $manifest ]] || die "could not locate the wasm-bindgen-cli $want source"
  cp -r "$(dirname "$manifest")" "$work/src"
  chmod -R u+w "$work/src"

  (
    cd "$work/src"
    if ! cargo fetch --locked --quiet 2>/dev/null; then
      log "its Cargo.lock names a crate version the registry lacks: pinning webpki-roots 1.0.10"
      cargo update --quiet -p webpki-roots --precise 1.0.10
    fi
    # --force: replaces a wasm-bindgen of another version; the build dir is thrown away.
    # Only the two programs the project runs, without TLS (the test runner talks plain HTTP to
    # the local ChromeDriver; TLS is for remote WebDriver services and costs a C and assembly
    # build), unoptimised: they run for seconds per suite, while any optimised build of them is
    # a large part of a fresh machine's install (docs/speed/suite.md compares the levels).
    CARGO_PROFILE_RELEASE_OPT_LEVEL=0 CARGO_PROFILE_RELEASE_DEBUG=0 \
      cargo install --path . --locked --force --no-default-features \
      --bin wasm-bindgen --bin wasm-bindgen-test-runner --target-dir "$work/target"
  )
  rm -rf "$work"
}

# Debian's Chromium + ChromeDriver for the browser tests (never a downloaded browser).
setup_chromium() {
  if [[ -x /usr/bin/chromium && -x /usr/bin/chromedriver ]]; then
    log "chromium + chromedriver: present"
    return
  fi
  timed "apt-get update" as_root apt-get update -q
  timed "apt-get install chromium chromium-driver" \
    as_root apt-get install -y -q -o Dpkg::Use-Pty=0 chromium chromium-driver
}

# Root node_modules, reinstalled only when package(-lock).json or node changed.
setup_npm() {
  command -v npm >/dev/null || die "npm not found: install Node.js 20 + npm first"
  local stamp=node_modules/.setup-stamp want
  want=$({ node --version; cat package.json package-lock.json; } | sha256sum | cut -d' ' -f1)
  if [[ -f $stamp && $(<"$stamp") == "$want" ]]; then
    log "node_modules: up to date with package-lock.json"
    return
  fi
  timed "npm ci" npm ci --no-audit --no-fund
  echo "$want" >"$stamp"
}

main() {
  local parts=("$@") part start=$SECONDS
  ((${#parts[@]})) || parts=(rust wasm-bindgen chromium npm)
  header "setup: ${parts[*]}"
  for part in "${parts[@]}"; do
    case $part in
      rust) setup_rust ;;
      wasm-bindgen) setup_wasm_bindgen ;;
      chromium) setup_chromium ;;
      npm) setup_npm ;;
      *) die "unknown setup part '$part' (known: rust wasm-bindgen chromium npm)" ;;
    esac
  done
  log "setup finished in $((SECONDS - start)) s"
}

main "$@"
