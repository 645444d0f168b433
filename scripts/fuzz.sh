#!/usr/bin/env bash
# Fuzz the parsers and the math core with cargo-fuzz (libFuzzer), each target for a bounded time.
#
#   ./scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#   ./scripts/fuzz.sh                      # every target, 60 s each
#   ./scripts/fuzz.sh 600 screw subdivide  # two targets, 10 minutes each
#
# Targets (fuzz/fuzz_targets/, see docs/fuzzing.md): document_json, subdivide, screw, csv_import,
# gltf_import. Not part of scripts/test.sh (too long); every crash it finds becomes a named test
# in crates/screwbender/tests/properties/fuzz_regressions.rs, which is.
#
# Installs cargo-fuzz (`cargo install cargo-fuzz --locked`) when missing. libFuzzer needs nightly
# compiler flags: only stable Rust exists here, so the build runs with RUSTC_BOOTSTRAP=1. Built
# with debug assertions (overflow checks) and without a sanitizer (the crate forbids `unsafe`).
# Corpora grow in fuzz/corpus/TARGET (seeded from the CLI's presets on the first run), crash
# inputs land in fuzz/artifacts/TARGET, logs in artifacts/fuzz/TARGET.log; none is committed.
# Exits non-zero when a target found a crash. Extra libFuzzer flags: FUZZ_ARGS="-jobs=2 …".
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

ALL_TARGETS=(document_json subdivide screw csv_import gltf_import)
seconds=${1:-60}
[[ $seconds =~ ^[0-9]+$ ]] || die "SECONDS_PER_TARGET must be a whole number, not '$seconds'"
shift $(($# > 0 ? 1 : 0))
targets=("$@")
((${#targets[@]} > 0)) || targets=("${ALL_TARGETS[@]}")
for t in "${targets[@]}"; do
  [[ " ${ALL_TARGETS[*]} " == *" $t "* ]] || die "unknown target '$t' (known: ${ALL_TARGETS[*]})"
done

if ! cargo fuzz --version >/dev/null 2>&1; then
  timed "cargo install cargo-fuzz" cargo install cargo-fuzz --locked
fi
export RUSTC_BOOTSTRAP=1
fuzz_flags=(--sanitizer none --debug-assertions)
if [[ -n ${CARGO_TARGET_DIR:-} ]]; then
  fuzz_flags+=(--target-dir "$CARGO_TARGET_DIR/fuzz")
fi

# seed_corpus: the first run starts every corpus from valid inputs (presets through the CLI).
seed_corpus() {
  local need=0 t
  for t in "${targets[@]}"; do
    [[ -d fuzz/corpus/$t ]] || need=1
  done
  ((need)) || return 0
  timed "cargo build --release -p screwbender-cli --bin screwbender (seeds)" cargo build --release -p screwbender-cli --bin screwbender
  local bin target_dir work
  target_dir=$(cargo_target_dir)
  bin=$target_dir/release/screwbender
  work=$(mktemp -d)
  mkdir -p fuzz/corpus/{document_json,subdivide,screw,csv_import,gltf_import}
  local id k=0
  for id in $("$bin" preset | awk '{print $1}'); do
    k=$((k + 1))
    "$bin" preset "$id" >"fuzz/corpus/document_json/$id.json"
    "$bin" export --format glb "fuzz/corpus/document_json/$id.json" -o "fuzz/corpus/gltf_import/$id.glb"
    if ((k <= 3)); then
      "$bin" export --format gltf "fuzz/corpus/document_json/$id.json" -o "$work/$id.gltf"
      cp "$work/$id.gltf" "fuzz/corpus/gltf_import/$id.gltf"
    fi
    node -e '
      const d = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
      const rows = d.poses.map((p) => [...p.origin, ...p.rotation].join(","));
      process.stdout.write("x,y,z,qw,qx,qy,qz\n" + rows.join("\n") + "\n");
    ' "fuzz/corpus/document_json/$id.json" >"fuzz/corpus/csv_import/$id.csv"
  done
  printf '1,2,3,1,0,0,0\n4,5,6,0,1,0,0\n# comment\n\n7,8,9,0.5,0.5,0.5,0.5\n' >fuzz/corpus/csv_import/plain.csv
  rm -rf "$work"
  log "seeded corpora from $k presets"
}
seed_corpus

mkdir -p artifacts/fuzz
failed=()
summary=()
for t in "${targets[@]}"; do
  header "fuzz $t for $seconds s"
  max_len=4096
  [[ $t == gltf_import ]] && max_len=65536
  log_file=artifacts/fuzz/$t.log
  rc=0
  cargo fuzz run "${fuzz_flags[@]}" "$t" "fuzz/corpus/$t" -- \
    -max_total_time="$seconds" -timeout=10 -max_len="$max_len" -print_final_stats=1 \
    ${FUZZ_ARGS:-} >"$log_file" 2>&1 || rc=$?
  execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log_file" | tail -1)
  rate=$(awk '/stat::average_exec_per_sec/ {print $2}' "$log_file" | tail -1)
  cov=$(grep -E '^#[0-9]+' "$log_file" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*' || true)
  line="$t: ${seconds} s, ${execs:-?} executions, ${rate:-?} exec/s, ${cov:-no coverage line}"
  if ((rc != 0)); then
    line+=", FAILED (exit $rc; see $log_file and fuzz/artifacts/$t/)"
    failed+=("$t")
    tail -40 "$log_file" >&2
  else
    line+=", no crash"
  fi
  log "$line"
  summary+=("$line")
done

header "fuzz summary"
printf '%s\n' "${summary[@]}"
((${#failed[@]} == 0)) || die "crashes in: ${failed[*]}"
