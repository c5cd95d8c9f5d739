#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the test suite through ctest.
#   bash scripts/test.sh          the quick suite: every test but those labelled "long" (minutes on 2 cores)
#   bash scripts/test.sh --long   the whole suite, the long checks included (what CI runs, .ci/run)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
select=(--label-exclude long)
deps=()
case "${1:-}" in
  "") ;;
  --long) select=() deps=(--long) ;;  # the long checks' packages too (ParaView: tests/long/vtk_paraview.sh)
  *) echo "scripts/test.sh: error: option = $1: expected none (the quick suite) or --long (the whole suite)" >&2
     exit 2 ;;
esac
bash "$root/scripts/install-deps.sh" "${deps[@]}"
bash "$root/scripts/build.sh"
ctest --test-dir "${KERF_BUILD_DIR:-$root/build}" --output-on-failure --parallel "$(nproc)" "${select[@]}"
