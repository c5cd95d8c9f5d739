#!/usr/bin/env bash
# kerf-dem kind "cut" (orthogonal cutting, Yang et al. 2018, Section 4): bad cut parameters exit 2 naming the key;
# a small cut writes forces.csv, cracks.csv (with place), summary.json, frames and a PNG; the grooved
# scene removes disks; a rerun gives identical forces, on one thread or a team of two.
# Usage: dem_cut_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

scene="$src/data/scenes/dem_cut.json"
grooved="$src/data/scenes/dem_cut_grooved.json"
expect_input_error "cut.depth_of_cut_mm = -0.1" run "$scene" --set cut.depth_of_cut_mm=-0.1 --out "$work/x"
expect_input_error "tool.rake_deg = 95" run "$scene" --set tool.rake_deg=95 --out "$work/x"
expect_input_error "grooves.shape = triangle" run "$grooved" --set grooves.shape=triangle --out "$work/x"
expect_input_error "grooves.bottom_width_mm = 0.08" run "$grooved" --set grooves.shape=trapezoidal \
    --set grooves.bottom_width_mm=0.08 --out "$work/x"
expect_input_error "did you mean 'depth_of_cut_mm'" run "$scene" --set cut.depth_of_cut=0.1 --out "$work/x"
[ ! -e "$work/x/summary.json" ] || fail "a rejected scene wrote output"

small=(--set specimen.width_mm=0.4 --set specimen.height_mm=0.25 --set specimen.growth_steps=2000
       --set specimen.relax_steps=500 --set cut.depth_of_cut_mm=0.05 --set cut.length_mm=0.08
       --set output.frame_every_samples=500 --set cut.speed_m_per_s=2)
# Checked once the workpiece and its time step are known (after genesis), still exit 2 and no output.
expect_input_error "cut.speed_m_per_s = 1e+06: expected a speed of at most" run "$scene" "${small[@]}" \
    --set cut.speed_m_per_s=1e6 --out "$work/x"
expect_input_error "cut.length_mm = 1: expected a travel of at most" run "$scene" "${small[@]}" \
    --set cut.length_mm=1 --out "$work/x"
[ ! -e "$work/x/summary.json" ] || fail "a rejected cut wrote output"
# With replicates, the first replicate that fails stops the study, and its input error stays one (exit 2).
expect_input_error "cut.length_mm = 1: expected a travel of at most" run "$scene" "${small[@]}" \
    --set cut.length_mm=1 --replicates 3 --threads 2 --out "$work/xr"
[ ! -e "$work/xr/summary.json" ] || fail "a rejected replicated cut wrote a summary"
[ -z "$(ls "$work/xr/replicates/items" 2>/dev/null)" ] || fail "a rejected replicated cut left items"
"$bin" run "$scene" "${small[@]}" --out "$work/c1" --threads 1 >/dev/null 2>"$work/err" || fail "cut run: $(cat "$work/err")"
for f in summary.json forces.csv cracks.csv result.pvd frame_0000.vtp cracks_0000.vtp specimen.png forces.png; do
  [ -s "$work/c1/$f" ] || fail "missing $f"
done
# The bundled steady-state scene, shrunk: its active window runs and is reported.
"$bin" run "$src/data/scenes/dem_cut_steady.json" "${small[@]}" --set specimen.width_mm=0.8 --set cut.length_mm=0.3 \
    --set cut.window_mm=0.1 --set cut.entry_fraction=0.25 --set active_window.below_depths=6 --out "$work/steady" --threads 1 >/dev/null 2>"$work/err" ||
  fail "steady scene: $(cat "$work/err")"
python3 - "$work/steady/summary.json" <<'PY' || fail "steady scene: no active window in the summary"
import json, sys
s = json.load(open(sys.argv[1]))
w = s["active_window"]
assert s["cut"]["active_window"]["enabled"] is True
assert w["rebuilds"] >= 20 and 0 < w["mean_window_particles"] < s["n_particles"], w
# The window reaches below this 0.25 mm workpiece (6 depths of 0.05 mm under a cut line 0.2 mm up): the damage is
# censored by the workpiece's bottom, not by the window's floor, and the limit says so.
r, cut_line_um = s["results"], 1000 * s["results"]["cut_line_y_mm"]
floor_um = 1000 * s["cut"]["active_window"]["below_depths"] * s["cut"]["cut"]["depth_of_cut_mm"]
assert cut_line_um < floor_um, (cut_line_um, floor_um)
assert abs(w["damage_depth_limit_um"] - cut_line_um) <= s["specimen"]["radius_max_um"], w
assert r["subsurface_damage_depth_um"] <= w["damage_depth_limit_um"], (r, w)
PY
head -1 "$work/c1/forces.csv" | grep -qx "tool_travel_mm,time_s,cutting_force_N,thrust_force_N,cutting_force_N_per_mm,thrust_force_N_per_mm,main_force_N" ||
  fail "forces.csv header"
head -1 "$work/c1/cracks.csv" | grep -qx "time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element,place" || fail "cracks.csv header"
grep -q ",chip$" "$work/c1/cracks.csv" || fail "no chip cracks in cracks.csv"
result() { sed -n '/^  "results": {/,/^  }/p' "$1/summary.json" | grep -o "\"$2\": [-0-9.e+]*" | head -1 | awk '{print $2}'; }
value() { grep -o "\"$2\": [-0-9.e+]*" "$1/summary.json" | head -1 | awk '{print $2}'; }
in_range() { awk -v x="$1" -v lo="$2" -v hi="$3" 'BEGIN { exit !(x > lo && x < hi) }'; }
in_range "$(result "$work/c1" main_force_N)" 0 1e4 || fail "main_force_N = $(result "$work/c1" main_force_N)"
in_range "$(result "$work/c1" thrust_force_N)" 0 1e4 || fail "thrust_force_N = $(result "$work/c1" thrust_force_N)"
in_range "$(result "$work/c1" width_mm)" 0.999 1.001 || fail "width_mm"
for k in main_force_std_N thrust_force_std_N cracks_tensile cracks_shear subsurface_damage_depth_um cracks_subsurface_steady \
    subsurface_damage_depth_steady_um steady_machined_from_x_mm steady_machined_to_x_mm; do
  in_range "$(result "$work/c1" $k)" -1 1e30 || fail "$k missing"
done
for k in n_particles steps wall_time_s particle_steps_per_s; do
  in_range "$(value "$work/c1" $k)" 0 1e30 || fail "$k missing or not positive"
done
"$bin" run "$grooved" "${small[@]}" --set cut.length_mm=0.03 --set grooves.depth_mm=0.05 --set grooves.pitch_mm=0.05 --set grooves.width_mm=0.04 \
    --out "$work/g1" --threads 1 >/dev/null 2>"$work/err" || fail "grooved cut: $(cat "$work/err")"
in_range "$(result "$work/g1" particles_removed_by_grooves)" 0 1e9 || fail "grooves removed no disks"
awk -v a="$(value "$work/g1" n_particles)" -v b="$(value "$work/c1" n_particles)" 'BEGIN { exit !(a < b) }' ||
  fail "grooved workpiece has no fewer disks"
# A rerun (other frame spacing) gives identical forces; killed and resumed equals uninterrupted (forces,
# crack table, frame list, frames).
"$bin" run "$scene" "${small[@]}" --set output.frame_every_samples=200 --out "$work/k_full" --threads 1 >/dev/null 2>&1 ||
  fail "uninterrupted cut"
cmp -s "$work/c1/forces.csv" "$work/k_full/forces.csv" || fail "a rerun gave different forces"
# The frames too (displacements since the first frame: their reference read back by the resumed run).
[ "$(ls "$work/k_full"/frame_*.vtp | wc -l)" -ge 3 ] || fail "fewer than 3 frames in the kill/resume cut"
! ls "$work/k_full"/frame_*.png >/dev/null 2>&1 || fail "frame PNGs without output.frame_png"
expect_kill_resume_equal "$work/k_full" "$work/k_kill" \
  "forces.csv cracks.csv result.pvd $(cd "$work/k_full" && echo frame_*.vtp cracks_*.vtp)" \
  run "$scene" "${small[@]}" --set output.frame_every_samples=200 --threads 1 --checkpoint-every 40

# Replicates: a study of one condition in OUT/replicates (one item directory per packing seed, the study
# file to rerun it), mean and spread in the top summary.
expect_input_error "--replicates = 2" run "$src/data/scenes/dem_tension.json" --replicates 2 --out "$work/x"
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.03 --replicates 2 --out "$work/r" --threads 1 >/dev/null 2>"$work/err" ||
  fail "replicates: $(cat "$work/err")"
item="replicates/items/condition_1_seed"
for f in summary.json replicates/study.json replicates/items.csv replicates/conditions.csv "${item}_1/forces.csv" \
         "${item}_2/forces.csv" "${item}_2/summary.json"; do
  [ -s "$work/r/$f" ] || fail "replicates: missing $f"
done
grep -q '"seed": 2' "$work/r/${item}_2/summary.json" || fail "replicate 2 does not use seed 2"
grep -q "\"directory\": \"${item}_2\"" "$work/r/summary.json" || fail "summary.json does not point at replicate 2's directory"
in_range "$(result "$work/r" main_force_replicate_std_N)" 0 1e4 || fail "main_force_replicate_std_N"
# The standard error from the cuts' own signals: sqrt(sum sem_k^2) / n, null when a cut has none.
python3 - "$work/r/summary.json" <<'PY' || fail "main_force_sem_within_cuts_N is not sqrt(sum sem_k^2) / n"
import json, math, sys
s = json.load(open(sys.argv[1]))
for key in ("main_force", "thrust_force"):
    sems = [row[key + "_sem_N"] for row in s["replicates"]]
    got = s["results"][key + "_sem_within_cuts_N"]
    want = None if None in sems else math.sqrt(sum(x * x for x in sems)) / len(sems)
    assert (got is None and want is None) or abs(got - want) <= 1e-12 * want, (key, got, want)
PY
# One cut on a team of two threads (every engine loop split, even on this small workpiece: moving tool
# walls, breaks, neighbour rebuilds): the same forces and cracks as on one thread, to the bit.
OMP_WAIT_POLICY=passive "$bin" run "$scene" "${small[@]}" --set engine.min_parallel_items=0 --out "$work/c2" \
  --threads 2 >/dev/null 2>"$work/err" || fail "cut on 2 threads: $(cat "$work/err")"
cmp -s "$work/c1/forces.csv" "$work/c2/forces.csv" || fail "forces differ between 1 and 2 threads"
cmp -s "$work/c1/cracks.csv" "$work/c2/cracks.csv" || fail "cracks differ between 1 and 2 threads"

# Side by side on two threads: the same forces as one after the other on one thread.
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.03 --replicates 2 --out "$work/r2" --threads 2 >/dev/null 2>"$work/err" ||
  fail "replicates on 2 threads: $(cat "$work/err")"
for k in 1 2; do
  cmp -s "$work/r/${item}_$k/forces.csv" "$work/r2/${item}_$k/forces.csv" || fail "replicate $k differs on 2 threads"
done
# A rerun reuses finished replicates and redoes only a missing one; a changed scene redoes all.
rm "$work/r2/${item}_2/summary.json"
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.03 --replicates 2 --out "$work/r2" --threads 2 >"$work/log" 2>&1 ||
  fail "replicates rerun: $(cat "$work/log")"
grep -q "condition_1_seed_1 reused" "$work/log" || fail "finished replicate 1 was not reused"
grep -q "condition_1_seed_2 done" "$work/log" || fail "replicate 2 had no summary but was not run again"
cmp -s "$work/r/${item}_2/forces.csv" "$work/r2/${item}_2/forces.csv" || fail "rerun replicate 2 differs"
# The study file in OUT/replicates reruns the same items with kerf-dem study (all reused).
"$bin" study "$work/r2/replicates/study.json" --out "$work/r2/replicates" >"$work/log" 2>&1 || fail "study rerun: $(cat "$work/log")"
[ "$(grep -c " reused in " "$work/log")" -eq 2 ] || fail "kerf-dem study on OUT/replicates/study.json did not reuse both items"
"$bin" run "$scene" "${small[@]}" --set cut.length_mm=0.03 --set cut.speed_m_per_s=1.5 --replicates 2 --out "$work/r2" --threads 2 \
    >"$work/log" 2>&1 || fail "replicates with a changed scene: $(cat "$work/log")"
! grep -q " reused in " "$work/log" || fail "a changed scene reused old replicates"
echo "dem_cut_cli: ok"
