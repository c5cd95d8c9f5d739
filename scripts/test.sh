#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite through ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
ctest --test-dir "${KERF_BUILD_DIR:-$root/build}" --output-on-failure --parallel "$(nproc)"
