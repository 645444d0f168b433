#!/usr/bin/env bash
# Stage: the test suite itself. scripts/stages.txt is whole and consistent
# (scripts/check-stages.py), and scripts/test.sh schedules made-up tables as it says: lanes,
# stages beside others, waits, and stopping at a failure (tests/suite/).
set -euo pipefail
# shellcheck source=scripts/lib.sh
source "$(dirname "${BASH_SOURCE[0]}")/../lib.sh"
cd "$REPO_ROOT"

python3 scripts/check-stages.py
timed "scheduler tests" node --test tests/suite/
