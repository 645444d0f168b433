#!/usr/bin/env bash
# List the playground files a lesson package for an LMS holds (www/pkg-lesson/files.json, built
# output like www/pkg-webgpu/), made by 70-lesson-package.mjs beside this file.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
node scripts/serve.d/70-lesson-package.mjs
