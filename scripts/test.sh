#!/usr/bin/env bash
# Run every test of the project, installing what is missing first.
#
#   ./scripts/test.sh                   # every stage: installs, then rust, web, python, e2e
#   ./scripts/test.sh rust              # one lane (rust | web | python | e2e), with the stages
#   ./scripts/test.sh web python        #   it needs from other lanes; several lanes at once
#   ./scripts/test.sh --list [LANE…]    # the stages that would run, and nothing else
#   SKIP_SETUP=1 ./scripts/test.sh …    # skip the install stages (fast local reruns)
#   STAGES=FILE ./scripts/test.sh …     # another table (tests/suite/ tests the scheduler so)
#
# The stages are declared in scripts/stages.txt: name, lane, how it runs (in the foreground, beside
# the others, or alone) and the stages it needs. A stage fails by exiting non-zero, and the run
# stops at the first failure it sees. At the end a table gives each stage's wall time, CPU
# seconds and how busy the cores were, then the slowest tests, and the last line is
# `stages: N passed, M failed`.
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

list_only=0
lanes=()
for arg in "$@"; do
  case $arg in
    --list) list_only=1 ;;
    rust | web | python | e2e) lanes+=("$arg") ;;
    -h | --help)
      sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *) die "unknown lane or option '$arg' (lanes: rust web python e2e; options: --list)" ;;
  esac
done

# wasm-bindgen-test-runner drives Debian's Chromium through its ChromeDriver, with the extra
# Chrome flags that enable WebGPU/WebGL on SwiftShader (no GPU here) and keep Chromium off the
# network. SwiftShader is slow, hence the generous per-test-binary timeout (default 20 s).
export CHROMEDRIVER=${CHROMEDRIVER:-/usr/bin/chromedriver}
export WASM_BINDGEN_TEST_WEBDRIVER_JSON=${WASM_BINDGEN_TEST_WEBDRIVER_JSON:-$REPO_ROOT/webdriver.json}
export WASM_BINDGEN_TEST_TIMEOUT=${WASM_BINDGEN_TEST_TIMEOUT:-120}
# No incremental caches: the suite's runs are mostly cold (CI clones afresh), where they only cost
# time and disk (docs/speed/suite.md). CARGO_INCREMENTAL=1 brings them back for edit-and-rerun loops.
export CARGO_INCREMENTAL=${CARGO_INCREMENTAL:-0}

# ---- the table --------------------------------------------------------------------------------
names=()
declare -A lane_of runs_of after_of cmd_of
while read -r name lane runs after cmd; do
  [[ -z $name || $name == \#* ]] && continue
  names+=("$name")
  lane_of[$name]=$lane
  runs_of[$name]=$runs
  after_of[$name]=$after
  [[ $after == - ]] && after_of[$name]=
  cmd_of[$name]=$cmd
done <"${STAGES:-scripts/stages.txt}"

# The selection: every stage, or the chosen lanes' stages and what they need, transitively.
declare -A chosen
choose() {
  local s=$1 dep
  [[ -n ${chosen[$s]:-} ]] && return
  [[ -n ${lane_of[$s]:-} ]] || die "scripts/stages.txt: '$s' is needed but not declared"
  chosen[$s]=1
  IFS=, read -r -a deps <<<"${after_of[$s]}"
  for dep in "${deps[@]}"; do [[ -n $dep ]] && choose "$dep"; done
  return 0
}
for name in "${names[@]}"; do
  if ((${#lanes[@]} == 0)); then
    chosen[$name]=1
  else
    for lane in "${lanes[@]}"; do [[ ${lane_of[$name]} == "$lane" ]] && choose "$name"; done
  fi
done
if [[ ${SKIP_SETUP:-0} == 1 ]]; then
  for name in "${names[@]}"; do [[ ${lane_of[$name]} == setup ]] && unset "chosen[$name]"; done
fi
if ((list_only)); then
  for name in "${names[@]}"; do
    [[ -n ${chosen[$name]:-} ]] && printf '%-20s %-7s %-7s %s\n' "$name" "${lane_of[$name]}" "${runs_of[$name]}" "${cmd_of[$name]}"
  done
  exit 0
fi

# ---- running ----------------------------------------------------------------------------------
mkdir -p artifacts
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
declare -A state pid_of start_of end_of cpu_of busy_of
passed=0
failed=0
clk_tck=$(getconf CLK_TCK)

# machine_ticks: the machine's busy and total CPU ticks since boot (/proc/stat, all cores; idle
# and waiting for I/O count as not busy).
machine_ticks() {
  local -a c
  read -r -a c </proc/stat
  echo "$((c[1] + c[2] + c[3] + c[6] + c[7] + c[8])) $((c[1] + c[2] + c[3] + c[4] + c[5] + c[6] + c[7] + c[8]))"
}

# run_wrapped NAME OUT: runs a stage's command in this (sub)shell's child and writes to OUT the
# CPU seconds (user + system) of its processes, the clock, the exit status and how busy the
# machine's cores were meanwhile (percent). With two cores, a stage whose CPU time is near twice
# its wall time cannot go faster beside another one, while a stage far below it waits on
# something. A browser's processes escape the first count (they are not reaped by the stage's
# shell), so for a stage that runs alone the second is the one to read: well under 100 % means
# idle cores. Call it in a subshell, so that /proc counts only it.
run_wrapped() {
  local name=$1 out=$2 rc=0 b0 t0 b1 t1
  read -r b0 t0 < <(machine_ticks)
  bash -c "${cmd_of[$name]}" || rc=$?
  read -r b1 t1 < <(machine_ticks)
  local -a t
  read -r -a t <"/proc/$BASHPID/stat"
  echo "$(((t[15] + t[16]) / clk_tck)) $SECONDS $rc $(((b1 - b0) * 100 / (t1 - t0 > 0 ? t1 - t0 : 1)))" >"$out"
  return "$rc"
}

# summary: the per-stage table, the slowest tests, then the closing count line.
summary() {
  local name
  header "stage times (wall; CPU of the stage's own processes; how busy both cores were meanwhile)"
  for name in "${names[@]}"; do
    [[ -n ${start_of[$name]:-} ]] || continue
    printf '%6d s %6d cpu s %4s %% busy  %-20s %s\n' "$((${end_of[$name]:-$SECONDS} - ${start_of[$name]}))" \
      "${cpu_of[$name]:-0}" "${busy_of[$name]:-?}" "$name" "${state[$name]:-running}" >&2
  done
  printf '%6d s  total\n' "$SECONDS" >&2
  python3 scripts/slowest-tests.py >&2 || true
  printf 'stages: %d passed, %d failed\n' "$passed" "$failed"
}

# finish NAME: collect a background stage that has ended (its output printed whole).
finish() {
  local name=$1 cpu end rc=0 busy
  wait "${pid_of[$name]}" || true
  header "stage $name (ran beside the others)"
  cat "$logs/$name.log" >&2
  read -r cpu end rc busy <"$logs/$name.end" || { cpu=0 end=$SECONDS rc=1 busy=?; }
  busy_of[$name]=$busy
  record "$name" "$cpu" "$end" "$rc"
}

# record NAME CPU END RC: a stage's result; the run stops at a failure.
record() {
  local name=$1 rc=$4
  cpu_of[$name]=$2
  end_of[$name]=$3
  if ((rc == 0)); then
    state[$name]=passed
    passed=$((passed + 1))
    log "stage '$name' passed in $((end_of[$name] - start_of[$name])) s"
  else
    state[$name]="FAILED (exit $rc)"
    failed=$((failed + 1))
    log "stage '$name' FAILED (exit $rc) after $((end_of[$name] - start_of[$name])) s"
    local other
    for other in "${!pid_of[@]}"; do
      [[ ${state[$other]} == running ]] && kill -- "-${pid_of[$other]}" 2>/dev/null || true
    done
    [[ -n ${fg_pid:-} ]] && kill -- "-$fg_pid" 2>/dev/null || true
    summary
    exit "$rc"
  fi
}

# reap: collect every background stage that has ended.
reap() {
  local name
  for name in "${!pid_of[@]}"; do
    [[ ${state[$name]} == running && -s $logs/$name.end ]] && finish "$name"
  done
  return 0
}

# needs_passed NAME: whether every chosen stage that NAME needs has passed.
needs_passed() {
  local dep
  local -a deps
  IFS=, read -r -a deps <<<"${after_of[$1]}"
  for dep in "${deps[@]}"; do
    [[ -z $dep || -z ${chosen[$dep]:-} || ${state[$dep]:-} == passed ]] || return 1
  done
}

# launch_ready: starts, in the background, every beside stage whose needs have passed, wherever
# it stands in the table before the next alone stage (none while an alone stage runs).
launch_ready() {
  local name
  ((alone_running)) && return 0
  for name in "${names[@]}"; do
    [[ -n ${chosen[$name]:-} && ${runs_of[$name]} == alone && ${state[$name]:-} != passed ]] && return 0
    [[ -n ${chosen[$name]:-} && ${runs_of[$name]} == beside && -z ${state[$name]:-} ]] || continue
    needs_passed "$name" || continue
    start_of[$name]=$SECONDS
    state[$name]=running
    header "stage $name (starts now, beside the others; its output when it ends)"
    (run_wrapped "$name" "$logs/$name.end") >"$logs/$name.log" 2>&1 &
    pid_of[$name]=$!
  done
}

# tick: what the scheduler does every second while it waits.
tick() {
  reap
  launch_ready
}

# wait_until CONDITION…: ticks until the command CONDITION… succeeds.
wait_until() {
  until "$@"; do
    tick
    "$@" && break
    sleep 1
  done
}

# all_before_passed NAME: every chosen stage before NAME in the table has passed.
all_before_passed() {
  local other
  for other in "${names[@]}"; do
    [[ $other == "$1" ]] && return 0
    [[ -z ${chosen[$other]:-} || ${state[$other]:-} == passed ]] || return 1
  done
}

# every_chosen_passed: every chosen stage has passed.
every_chosen_passed() {
  local name
  for name in "${names[@]}"; do
    [[ -z ${chosen[$name]:-} || ${state[$name]:-} == passed ]] || return 1
  done
}

set -m # each stage in its own process group, so that a failure can stop it whole
alone_running=0
fg_pid=
for name in "${names[@]}"; do
  [[ -n ${chosen[$name]:-} && ${runs_of[$name]} != beside ]] || continue
  if [[ ${runs_of[$name]} == alone ]]; then
    wait_until all_before_passed "$name"
    alone_running=1
  else
    wait_until needs_passed "$name"
  fi
  start_of[$name]=$SECONDS
  state[$name]=running
  header "stage $name"
  # In the background, so that the scheduler starts beside stages while it runs.
  (run_wrapped "$name" "$logs/$name.end") &
  fg_pid=$!
  while kill -0 "$fg_pid" 2>/dev/null; do
    sleep 1
    tick
  done
  rc=0
  wait "$fg_pid" || rc=$?
  fg_pid=
  read -r cpu end _ busy <"$logs/$name.end" || { cpu=0 end=$SECONDS busy=?; }
  busy_of[$name]=$busy
  alone_running=0
  record "$name" "$cpu" "$end" "$rc"
  tick
done
wait_until every_chosen_passed

summary
