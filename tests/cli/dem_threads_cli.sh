#!/usr/bin/env bash
# kerf-dem's threads: summary.json's provenance records the OpenMP wait policy of the environment (kerf leaves
# it to the user); engine.adaptive_threads (the team governor, kerf/dem/engine/team_governor.hpp) is a scene key,
# on by default, and a cut on two threads gives the same forces and cracks with it off, to the bit.
# Usage: dem_threads_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
policy_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["provenance"]["openmp_wait_policy"])' "$1/summary.json"; }
small=(run "$src/data/scenes/dem_cut.json" --set specimen.width_mm=0.4 --set specimen.height_mm=0.25
       --set specimen.growth_steps=2000 --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05
       --set cut.length_mm=0.05 --set output.frame_every_samples=0 --set cut.speed_m_per_s=2
       --set engine.min_parallel_items=0 --threads 2)

env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$bin" "${small[@]}" --out "$work/on" >/dev/null 2>"$work/err" ||
  fail "cut: $(cat "$work/err")"
[ "$(policy_of "$work/on")" = "libgomp default" ] || fail "no policy set, provenance says: $(policy_of "$work/on")"
env -u GOMP_SPINCOUNT OMP_WAIT_POLICY=passive "$bin" "${small[@]}" --set engine.adaptive_threads=false \
  --out "$work/off" >/dev/null 2>"$work/err" || fail "cut without the governor: $(cat "$work/err")"
[ "$(policy_of "$work/off")" = "OMP_WAIT_POLICY=passive" ] || fail "the user's policy, provenance says: $(policy_of "$work/off")"
for f in forces.csv cracks.csv; do
  cmp -s "$work/on/$f" "$work/off/$f" || fail "$f differs with engine.adaptive_threads off"
done
expect_input_error "engine.adaptive_threads" "${small[@]}" --set engine.adaptive_threads=3 --out "$work/x"
echo "dem_threads_cli: ok"
