#!/usr/bin/env bash
# The SIMD lanes are compiled in place: in FILE, a release build holding the core (x86-64), no
# function calls an x86 intrinsic (`core::arch`'s `_mm512_mul_pd`, `_mm256_add_pd`, …) out of
# line. The Python stage (scripts/test.d/python.sh) checks its extension module, a release
# build of the core it already made, rather than compiling a release CLI for this alone.
#
#   scripts/check-lanes-inlined.sh FILE
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
# batch) and the feature detection's `xgetbv`. A FILE with no call to an intrinsic at all fails:
# without symbols (a stripped build) the check could not see a bad call.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if [[ $(uname -m) != x86_64 ]]; then
  log "not x86-64: the AVX lanes are not compiled here, nothing to check"
  exit 0
fi
command -v objdump >/dev/null || die "objdump is missing (Debian: binutils)"

bin=${1:?usage: scripts/check-lanes-inlined.sh FILE}
[[ -f $bin ]] || die "no file $bin"

calls=$(objdump -d --no-show-raw-insn "$bin" | grep -E '\scall\s.*core_arch' | sed 's/.*<//; s/>$//' || true)
total=$(grep -c . <<<"$calls" || true)
((total > 0)) || die "no call to an x86 intrinsic in $bin: without symbols it cannot be checked"
bad=$(grep -vE 'setzero_pd|xgetbv' <<<"$calls" | sort | uniq -c | sort -rn || true)
if [[ -n $bad ]]; then
  log "out-of-line calls to x86 intrinsics in $bin (a lanes helper was not inlined into the code compiled for AVX):"
  echo "$bad" | head -20
  exit 1
fi
log "$(basename "$bin"): no lane operation called out of line ($total allowed calls: zero lanes before the dispatch, xgetbv)"
