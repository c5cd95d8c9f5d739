#!/usr/bin/env bash
# Regenerates the validation reports (validation/<case>/) into out/validation/<case>/ and checks the
# acceptance bands: exit status 0 when all hold. Installs and builds first, like the quick start.
#
#   bash scripts/validate.sh                      # every case
#   bash scripts/validate.sh soda_lime_cutting    # one case: k9_trepanning (seconds), glass_transition
#                                                 # (seconds: the transition model of soda-lime glass against
#                                                 # Yang et al. 2018's Table 6, a report without acceptance bands),
#                                                 # soda_lime_cutting
#                                                 # (18 kerf-dem cuts, 19-35 min on 2 cores; rerunning
#                                                 # reuses the replicates already finished),
#                                                 # soda_lime_cutting_cut_fitted (12 cuts, 13-34 min) or
#                                                 # soda_lime_cutting_steady (the Yang et al. 2018 study's record:
#                                                 # kerf-dem study data/studies/seed000_steady.json runs the
#                                                 # cuts not yet recorded, 14-23 CPU-hours from nothing, then
#                                                 # validation/soda_lime_cutting_steady/trends.py --report, with
#                                                 # the built module kerf (kerf.stats); exit 0 when every
#                                                 # verdict asked is resolved)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case="${1:-all}"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
out="$root/out/validation"
[ "$case" = all ] || out="$out/$case"
build="${KERF_BUILD_DIR:-$root/build}"
# The interpreter the module kerf was built for (python/CMakeLists.txt), and the module on its path.
python="$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null)"
python="${python:-python3}"
steady() {  # the steady case's acceptance comes from the study's record (its README)
  "$build/tools/kerf-dem" study "$root/data/studies/seed000_steady.json" --out "$1/study" --checkpoint-minutes 5
  PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" "$python" \
    "$root/validation/soda_lime_cutting_steady/trends.py" --report --out "$1"
}
glass() { python3 "$root/validation/glass_transition/report.py" --kerf-forces "$build/tools/kerf-forces" --out "$1"; }
case "$case" in
  soda_lime_cutting_steady) steady "$out" ;;
  glass_transition) glass "$out" ;;
  all) rc=0
       for c in k9_trepanning soda_lime_cutting soda_lime_cutting_cut_fitted; do
         "$build/validation/run_validation" "$c" "$out/$c" || rc=1
       done
       glass "$out/glass_transition" || rc=1
       steady "$out/soda_lime_cutting_steady" || rc=1
       exit $rc ;;
  *) "$build/validation/run_validation" "$case" "$out" ;;
esac
