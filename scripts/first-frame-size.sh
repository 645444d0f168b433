#!/usr/bin/env bash
# The playground's first visit on a budget: everything headless Chromium downloads on a visit until
# the page is idle (scripts/first-frame.mjs: every response from the page's start until no request
# has been in flight for half a second after the first frame, or 5 s after it; each file counted
# at its gzip -9 size), from www/ as scripts/serve.sh builds it, and fails over budget:
#   a plain visit on WebGPU                       ≤ FIRST_FRAME_GZIP_BUDGET bytes (default 500 000)
#   a plain visit on WebGL2 (the WebGL2 module
#   instead of the WebGPU one)                    ≤ WEBGL2_FIRST_VISIT_BUDGET bytes (default 1 410 000)
#   a lesson link (?lesson=LESSON, with the
#   lesson player and KaTeX) on WebGPU            ≤ LESSON_GZIP_BUDGET bytes (default 612 000)
# docs/speed/first-visit.md says where each budget comes from.
#
#   ./scripts/first-frame-size.sh [WWW_DIR]
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$REPO_ROOT"

www=${1:-www}
FIRST_FRAME_GZIP_BUDGET=${FIRST_FRAME_GZIP_BUDGET:-500000}
LESSON_GZIP_BUDGET=${LESSON_GZIP_BUDGET:-612000}
WEBGL2_FIRST_VISIT_BUDGET=${WEBGL2_FIRST_VISIT_BUDGET:-1410000}
LESSON=${LESSON:-01-screw}
[[ -f $www/pkg-webgpu/screwbender_bg.wasm ]] || die "no playground build in $www (scripts/serve.sh: BUILD_ONLY=1)"

# One browser per backend: the lesson link after the plain visit in the WebGPU one.
header "first visit until idle: plain visit, then a lesson link ?lesson=$LESSON, WebGPU"
out=$(node scripts/first-frame.mjs --dir "$www" --backend webgpu --and-lesson "$LESSON")
echo "$out" >&2
mapfile -t totals < <(echo "$out" | awk '/ bytes gzip in /{print $1}')
plain=${totals[0]:-}
lesson=${totals[1]:-}
header "first visit until idle: plain visit, WebGL2"
out=$(node scripts/first-frame.mjs --dir "$www" --backend webgl2)
echo "$out" >&2
webgl=$(echo "$out" | awk '/ bytes gzip in /{print $1}')
[[ $plain =~ ^[0-9]+$ && $lesson =~ ^[0-9]+$ && $webgl =~ ^[0-9]+$ ]] || die "a visit was not measured"

log "plain visit, WebGPU: $plain bytes gzip until idle (budget $FIRST_FRAME_GZIP_BUDGET)"
log "plain visit, WebGL2: $webgl bytes gzip until idle (budget $WEBGL2_FIRST_VISIT_BUDGET)"
log "lesson link, WebGPU: $lesson bytes gzip until idle (budget $LESSON_GZIP_BUDGET)"
over=0
((plain <= FIRST_FRAME_GZIP_BUDGET)) || { log "plain visit, WebGPU: $plain bytes gzip, over the budget of $FIRST_FRAME_GZIP_BUDGET"; over=1; }
((webgl <= WEBGL2_FIRST_VISIT_BUDGET)) || { log "plain visit, WebGL2: $webgl bytes gzip, over the budget of $WEBGL2_FIRST_VISIT_BUDGET"; over=1; }
((lesson <= LESSON_GZIP_BUDGET)) || { log "lesson link: $lesson bytes gzip, over the budget of $LESSON_GZIP_BUDGET"; over=1; }
((over == 0)) || die "first visit over budget (docs/speed/first-visit.md)"
log "first-visit sizes within budget"
