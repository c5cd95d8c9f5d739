#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job on a bundled scene
# (a p-SiC edge-radius force prediction), writing its CSV row to out/psic_liu_li.csv.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
mkdir -p "$root/out"
"${KERF_BUILD_DIR:-$root/build}/tools/kerf-forces" predict "$root/data/scenes/psic_liu_li.json" \
  --csv "$root/out/psic_liu_li.csv"
