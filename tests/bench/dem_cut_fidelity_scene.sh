#!/usr/bin/env bash
# bench_dem_cut_fidelity --scene: packing seed k of the benchmark is kerf-dem's replicate k of the same
# scene (same workpiece, same cut, same forces), the other knobs' studies hold the scene's speed, damping and
# time step (the base setting of every knob is one cut, reused through the study), the time-step study sets
# engine.time_step_safety as kerf-dem does, and a results directory of one base case refuses another.
# Usage: dem_cut_fidelity_scene.sh <bench_dem_cut_fidelity> <kerf-dem> <source dir>
set -uo pipefail
bench="$1" dem="$2" src="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export KERF_DATA_DIR="$src/data"
fail() { echo "FAIL: $*" >&2; exit 1; }
# The main force of a kerf-dem run's summary.json (its results object), and equality to 1e-12 relative.
summary_main() { sed -n '/^  "results": {/,/^  }/p' "$1/summary.json" | grep -o '"main_force_N": [-0-9.e+]*' | head -1 | awk '{print $2}'; }
same_force() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d <= 1e-12 * a) }'; }

cat >"$work/small.json" <<'JSON'
{
  "kind": "cut",
  "description": "a small cut for the test",
  "material": {"base": "soda_lime_glass_fj"},
  "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
               "growth_steps": 2000, "relax_steps": 500},
  "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.05},
  "tool": {"rake_deg": -15, "clearance_deg": 15},
  "output": {"frame_every_samples": 0}
}
JSON
"$dem" run "$work/small.json" --threads 1 --out "$work/dem" >/dev/null 2>"$work/err" || fail "kerf-dem: $(cat "$work/err")"
"$bench" --scene "$work/small.json" --knob speed --speeds 2 --replicates 1 --threads 1 --out-dir "$work/b" \
  >/dev/null 2>"$work/err" || fail "bench: $(cat "$work/err")"
dem_main=$(summary_main "$work/dem")
col=$(head -1 "$work/b/runs.csv" | tr ',' '\n' | grep -nx main_force_N | cut -d: -f1)
bench_main=$(sed -n 2p "$work/b/runs.csv" | cut -d, -f"$col")
[ -n "$dem_main" ] && [ -n "$bench_main" ] || fail "no main force (kerf-dem '$dem_main', bench '$bench_main')"
same_force "$dem_main" "$bench_main" ||
  fail "bench seed 1 main force $bench_main N differs from kerf-dem's $dem_main N"
grep -qxF "$work/small.json" "$work/b/base_case.txt" || fail "base_case.txt does not name the scene"

# The damping study holds the scene's own speed (2 m/s) and damping (0.7): its 0.7 case is the cut just run.
"$bench" --scene "$work/small.json" --knob damping --dampings 0.7 --replicates 1 --threads 1 --out-dir "$work/b" \
  >"$work/log" 2>"$work/err" || fail "bench damping: $(cat "$work/err")"
grep -qF "1 items (0 failed, 1 reused)" "$work/log" || fail "the damping study did not reuse the scene's cut: $(cat "$work/log")"
grep -q '^damping,0.7,1,' "$work/b/runs.csv" || fail "no damping 0.7 row in runs.csv"

# The time-step study: f 0.8 (the scene's, the engine's default) is the cut just run; f 0.4 is kerf-dem's cut
# with engine.time_step_safety 0.4 (same forces) and takes twice the steps.
"$bench" --scene "$work/small.json" --knob time_step --time-step-safeties 0.8 0.4 --replicates 1 --threads 1 \
  --out-dir "$work/b" >"$work/log" 2>"$work/err" || fail "bench time_step: $(cat "$work/err")"
grep -qF "2 items (0 failed, 1 reused)" "$work/log" || fail "the time-step study did not reuse the scene's cut: $(cat "$work/log")"
"$dem" run "$work/small.json" --set engine.time_step_safety=0.4 --threads 1 --out "$work/dem04" >/dev/null 2>"$work/err" ||
  fail "kerf-dem f 0.4: $(cat "$work/err")"
dem04_main=$(summary_main "$work/dem04")
row04=$(grep '^time_step,0.4,1,' "$work/b/runs.csv") || fail "no time_step 0.4 row in runs.csv"
row08=$(grep '^time_step,0.8,1,' "$work/b/runs.csv") || fail "no time_step 0.8 row in runs.csv"
steps_col=$(head -1 "$work/b/runs.csv" | tr ',' '\n' | grep -nx steps | cut -d: -f1)
same_force "$dem04_main" "$(echo "$row04" | cut -d, -f"$col")" ||
  fail "bench f 0.4 main force $(echo "$row04" | cut -d, -f"$col") N differs from kerf-dem's $dem04_main N"
awk -v a="$(echo "$row04" | cut -d, -f"$steps_col")" -v b="$(echo "$row08" | cut -d, -f"$steps_col")" \
  'BEGIN { r = a / b; exit !(r > 1.9 && r < 2.1) }' || fail "f 0.4 does not take about twice the steps of f 0.8"

# The same directory with the built-in base case: refused, exit 2, nothing run.
cp "$work/b/runs.csv" "$work/runs_before.csv"
"$bench" --knob speed --speeds 2 --replicates 1 --threads 1 --out-dir "$work/b" >/dev/null 2>"$work/err"
rc=$?
[ $rc -eq 2 ] || fail "exit $rc (expected 2) for another base case in the same directory"
grep -qF "another base case" "$work/err" || fail "stderr lacks the reason: $(cat "$work/err")"
cmp -s "$work/runs_before.csv" "$work/b/runs.csv" || fail "the refused run changed runs.csv"
[ "$(ls "$work/b/study/items" | wc -l)" -eq 2 ] || fail "the refused run added cuts: $(ls "$work/b/study/items")"
exit 0
