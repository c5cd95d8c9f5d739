#!/usr/bin/env bash
# kerf-dem starts OpenMP with OMP_WAIT_POLICY=passive unless the user chose a policy (kerf/openmp_env.hpp):
# libgomp reads its environment at load, so kerf-dem sets it and executes itself again, with the same
# arguments. summary.json's provenance says which policy ran; with libgomp, OMP_DISPLAY_ENV shows the runtime
# took it (spin count 0). A user's OMP_WAIT_POLICY or GOMP_SPINCOUNT is left as it is.
# Usage: dem_wait_policy_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
small=(run "$src/data/scenes/dem_specimen.json" --set specimen.width_mm=0.1 --set specimen.height_mm=0.1
       --set specimen.growth_steps=300 --set specimen.relax_steps=100 --threads 2)
policy_of() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["provenance"]["openmp_wait_policy"])' "$1/summary.json"; }

env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$bin" "${small[@]}" --out "$work/default" >/dev/null 2>"$work/err" ||
  fail "run without a policy: $(cat "$work/err")"
[ "$(policy_of "$work/default")" = "OMP_WAIT_POLICY=passive" ] || fail "default policy: $(policy_of "$work/default")"
# The overrides reached the re-executed program: the specimen is the small one.
grep -q '"width_mm": 0.1' "$work/default/summary.json" || fail "the --set arguments were lost in the re-execution"

env -u GOMP_SPINCOUNT OMP_WAIT_POLICY=active "$bin" "${small[@]}" --out "$work/active" >/dev/null 2>&1 || fail "active run"
[ "$(policy_of "$work/active")" = "OMP_WAIT_POLICY=active" ] || fail "the user's policy was replaced: $(policy_of "$work/active")"
env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=1000 "$bin" "${small[@]}" --out "$work/spin" >/dev/null 2>&1 || fail "spin-count run"
[ "$(policy_of "$work/spin")" = "GOMP_SPINCOUNT=1000" ] || fail "the user's spin count was replaced: $(policy_of "$work/spin")"

# libgomp: OMP_DISPLAY_ENV=verbose prints the environment it read, once per start; the last is the one in use.
env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT OMP_DISPLAY_ENV=verbose "$bin" --version >"$work/out" 2>"$work/display"
if grep -q "GOMP_SPINCOUNT" "$work/display"; then
  [ "$(grep "GOMP_SPINCOUNT" "$work/display" | tail -1 | tr -d " '")" = "GOMP_SPINCOUNT=0" ] ||
    fail "libgomp does not run passive: $(cat "$work/display")"
else
  echo "dem_wait_policy_cli: the OpenMP runtime is not libgomp: its display is not checked"
fi
grep -q "^kerf-dem " "$work/out" || fail "--version after the re-execution: $(cat "$work/out")"
echo "dem_wait_policy_cli: ok"
