#!/usr/bin/env bash
# Configures and builds kerf in Release with warnings on (as errors when KERF_WERROR=ON, as in CI).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KERF_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DKERF_WERROR="${KERF_WERROR:-OFF}" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
