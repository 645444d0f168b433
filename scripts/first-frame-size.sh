#!/usr/bin/env bash
# The playground's first visit on a budget: what headless Chromium downloads before the first
# frame (scripts/first-frame.mjs: the files fetched until the renderer drew the motion, each
# counted at its gzip -9 size), from www/ as scripts/serve.sh builds it, and fails over budget:
#   a plain visit on WebGPU                       ≤ FIRST_FRAME_GZIP_BUDGET bytes (default 500 000)
#   a lesson link (?lesson=LESSON, KaTeX and the
#   lesson card too) on WebGPU                    ≤ LESSON_GZIP_BUDGET bytes (default 600 000)
# The WebGL2 first visit (the WebGL2 module instead of the WebGPU one) is logged, not budgeted.
#
#   ./scripts/first-frame-size.sh [WWW_DIR]
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

www=${1:-www}
FIRST_FRAME_GZIP_BUDGET=${FIRST_FRAME_GZIP_BUDGET:-500000}
LESSON_GZIP_BUDGET=${LESSON_GZIP_BUDGET:-600000}
LESSON=${LESSON:-01-screw}
[[ -f $www/pkg-webgpu/screwbender_bg.wasm ]] || die "no playground build in $www (scripts/serve.sh: BUILD_ONLY=1)"

measure() { # LABEL ARGS...: prints the files and returns the total via $total
  local label=$1 out
  shift
  header "first frame: $label"
  out=$(node scripts/first-frame.mjs --dir "$www" "$@")
  echo "$out" >&2
  total=$(echo "$out" | tail -1 | awk '{print $1}')
  [[ $total =~ ^[0-9]+$ ]] || die "$label: no total measured"
}

measure "plain visit, WebGPU" --backend webgpu
plain=$total
measure "lesson link ?lesson=$LESSON, WebGPU" --backend webgpu --lesson "$LESSON"
lesson=$total
measure "plain visit, WebGL2" --backend webgl2
webgl=$total

log "plain visit, WebGPU: $plain bytes gzip before the first frame (budget $FIRST_FRAME_GZIP_BUDGET)"
log "lesson link, WebGPU: $lesson bytes gzip before the first frame and the card (budget $LESSON_GZIP_BUDGET)"
log "plain visit, WebGL2: $webgl bytes gzip (not budgeted)"
((plain <= FIRST_FRAME_GZIP_BUDGET)) || die "plain visit: $plain bytes gzip, over the budget of $FIRST_FRAME_GZIP_BUDGET"
((lesson <= LESSON_GZIP_BUDGET)) || die "lesson link: $lesson bytes gzip, over the budget of $LESSON_GZIP_BUDGET"
log "first-frame sizes within budget"
