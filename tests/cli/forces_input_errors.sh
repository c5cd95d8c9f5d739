#!/usr/bin/env bash
# kerf-forces: every kind of bad input gives exit status 2 and one line naming the field, value and expectation.
source "$(dirname "$0")/lib/forces_common.sh" "$@"
scene="$src/data/scenes/psic_orthogonal.json"
printf '{"material": "psic", "tool": {' >"$tmp/malformed.json"
expect 2 "malformed JSON" -- predict "$tmp/malformed.json"
expect 2 "tool.rake_dg = 5: expected a known key (did you mean 'rake_deg'?)" -- predict "$scene" --set tool.rake_dg=5
expect 2 "models.force = liu_lee: expected one of 'auto', 'merchant', 'liu_li', 'oxley', 'transition', 'trepanning' (did you mean 'liu_li'?)" -- predict "$scene" --set models.force=liu_lee
expect 2 "cut.uncut_chip_thickness_um = -1: expected a positive value in um" -- predict "$scene" --set cut.uncut_chip_thickness_um=-1
expect 2 "cut.uncut_chip_thickness_um = 0: expected a positive value in um" -- predict "$scene" --set cut.uncut_chip_thickness_um=0
expect 2 "tool.rake_deg = 95: expected a value in (-90, 90) deg" -- predict "$scene" --set tool.rake_deg=95
expect 2 "material = unobtainium: expected one of" -- predict "$scene" --set material=unobtainium
expect 2 "cut.speed_m_per_min = (missing)" -- predict "$scene" --set 'cut={"uncut_chip_thickness_um": 1, "width_mm": 1, "friction_coefficient": 0.3}'
expect 2 "models.flow_stress = grain: expected one of" -- predict "$scene" --set 'models.flow_stress=["grain"]'
# The ploughing model's friction factor tau/k lies in [0, 1) (issue 38).
expect 2 "cut.friction_factor = 1: expected a value in [0, 1) (tau/k)" -- predict "$scene" --set cut.friction_factor=1
expect 2 "cut.friction_factor = -0.1: expected a value in [0, 1) (tau/k)" -- predict "$scene" --set cut.friction_factor=-0.1
expect 2 "models.ploughing = waves: expected one of 'wave', 'none' (did you mean 'wave'?)" -- predict "$scene" --set models.ploughing=waves
expect 2 "no-such-file.json" -- predict "$src/no-such-file.json"
expect 2 "--vary" -- sweep "$scene" --vary cut.width_mm=1:2 --csv "$tmp/x.csv"
expect 2 "" -- predict
expect 2 "" -- frobnicate
# An unwritable CSV path is not an input error of the scene: status 4 (found before any work), no partial file.
expect 4 "cannot" -- predict "$scene" --csv /proc/kerf-cannot-write/x.csv
[ "$failures" -eq 0 ] && echo "all input-error checks passed"
exit "$failures"
