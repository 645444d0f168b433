#!/usr/bin/env bash
# Stage: the SIMD lanes are compiled in place. In the release CLI (x86-64), no function calls an
# x86 intrinsic (`core::arch`'s `_mm512_mul_pd`, `_mm256_add_pd`, …) out of line.
#
# Why a disassembly check: the batches run their arithmetic inside a function compiled for
# AVX-512 or AVX2 (`lanes::run_widest`), and an intrinsic is one instruction only when it is
# inlined into such a function. Any helper that the compiler declines to inline there (a function
# passed as a value is called through its `FnOnce` shim, which is not always inlined) is compiled
# without those features, and then every lane operation in it becomes a call: the results stay
# the same, but the subdivisions take several times as long. Tests cannot see it and timed tests
# are not allowed here, so the compiled code itself is checked.
#
# Allowed: the zero lanes that `Avx8::detect` / `Avx4::detect` build before the dispatch (once per
# batch) and the feature detection's `xgetbv`.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

if [[ $(uname -m) != x86_64 ]]; then
  log "not x86-64: the AVX lanes are not compiled here, nothing to check"
  exit 0
fi
command -v objdump >/dev/null || die "objdump is missing (Debian: binutils)"

timed "cargo build --release --bin screwbender" cargo build --release -p screwbender-cli --bin screwbender
target_dir=$(cargo metadata --format-version 1 --no-deps | node -e \
  'let s="";process.stdin.on("data",d=>s+=d).on("end",()=>console.log(JSON.parse(s).target_directory))')
bin=$target_dir/release/screwbender
[[ -x $bin ]] || die "no binary at $bin"

calls=$(objdump -d --no-show-raw-insn "$bin" | grep -E '\scall\s.*core_arch' | sed 's/.*<//; s/>$//' || true)
total=$(grep -c . <<<"$calls" || true)
bad=$(grep -vE 'setzero_pd|xgetbv' <<<"$calls" | sort | uniq -c | sort -rn || true)
if [[ -n $bad ]]; then
  log "out-of-line calls to x86 intrinsics in $bin (a lanes helper was not inlined into the code compiled for AVX):"
  echo "$bad" | head -20
  exit 1
fi
log "no lane operation called out of line ($total allowed calls: zero lanes before the dispatch, xgetbv)"
