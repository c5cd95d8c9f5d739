#!/usr/bin/env bash
# Regenerates the validation reports (validation/<case>/) into out/validation/<case>/ and checks the
# acceptance bands: exit status 0 when all hold. Installs and builds first, like the quick start.
#
#   bash scripts/validate.sh                      # every case
#   bash scripts/validate.sh soda_lime_cutting    # one case: k9_trepanning (seconds), soda_lime_cutting
#                                                 # (18 kerf-dem cuts, 19-35 min on 2 cores; rerunning
#                                                 # reuses the replicates already finished),
#                                                 # soda_lime_cutting_cut_fitted (12 cuts, 13-34 min) or
#                                                 # soda_lime_cutting_steady (six conditions x 8-20 packings,
#                                                 # about 60 11-mm cuts at 2 m/s, about 10 CPU-hours)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case="${1:-all}"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
out="$root/out/validation"
[ "$case" = all ] || out="$out/$case"
"${KERF_BUILD_DIR:-$root/build}/validation/run_validation" "$case" "$out"
