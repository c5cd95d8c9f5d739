#!/usr/bin/env bash
# run_validation soda_lime_cutting on a miniature copy of the case (tiny workpiece, two conditions, two
# packings): it runs kerf-dem, writes the tables, both comparison reports and the acceptance summary, exits
# 0 or 1 (bands held or not; never a crash), reuses finished replicates on a rerun, and rejects a bad
# validation.json with exit status 2. Without bands (the real case's validation.json) it is a reproduction:
# exit 0, no pass or fail, and each trend's verdict is the one its 95 % interval gives.
# Usage: validation_soda_lime_cutting.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
validate="$1/../validation/run_validation"
[ -x "$validate" ] || fail "no run_validation next to $1"

# The case is found beside the data directory: a scratch tree with the real data and a miniature case.
mkdir -p "$work/tree/validation/soda_lime_cutting"
ln -s "$(cd "$src" && pwd)/data" "$work/tree/data"
case_dir="$work/tree/validation/soda_lime_cutting"
cp "$src/validation/soda_lime_cutting/soda_lime_orthogonal_cutting.csv" "$case_dir/"
cat >"$case_dir/scene.json" <<'JSON'
{"kind": "cut", "material": {"base": "soda_lime_glass_fj"},
 "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
              "growth_steps": 2000, "relax_steps": 500},
 "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.05},
 "grooves": {"shape": "none", "pitch_mm": 0.04, "width_mm": 0.015},
 "output": {"frame_every_samples": 0}}
JSON
cat >"$case_dir/validation.json" <<'JSON'
{"scene": "scene.json", "experiments": "soda_lime_orthogonal_cutting.csv", "replicates": 2,
 "conditions": [
   {"name": "regular_0.1", "surface": "regular", "depth_of_cut_mm": 0.1, "groove_shape": "none"},
   {"name": "grooved_0.1", "surface": "grooved", "depth_of_cut_mm": 0.1, "groove_shape": "rectangular"}],
 "acceptance": {"regular_force_max_abs_error_vs_paper_dem_percent": 20, "grooved_to_regular_main_force_ratio_max": 0.3333}}
JSON
export KERF_DATA_DIR="$work/tree/data"
"$validate" soda_lime_cutting "$work/out" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || [ $rc -eq 1 ] || fail "exit $rc: $(tail -5 "$work/log")"
for f in report.md summary.json kerf_dem_replicates.csv kerf_dem_means.csv vs_experiment/report.md vs_paper_dem/report.md \
         vs_experiment/parity_main_force_per_width.png snapshot_regular_0.1.png study/study.json study/items.csv study/items/condition_2_seed_2/forces.csv; do
  [ -s "$work/out/$f" ] || fail "missing $f"
done
grep -q "per_unit_width" "$work/out/vs_experiment/report.md" || fail "no per-unit-width view"
grep -q "grooved / regular main force at 0.1 mm" "$work/out/report.md" || fail "no groove ratio check"
grep -q '"passed"' "$work/out/summary.json" || fail "no verdict in summary.json"
[ "$(grep -c '^kerf_dem,' "$work/out/kerf_dem_replicates.csv")" -eq 4 ] || fail "expected 4 replicate rows"
# The cuts are one study: its items side by side, one thread each, as many as there are hardware threads.
workers=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["workers"])' "$work/out/study/summary.json")
[ "$workers" -eq "$(( $(nproc) < 4 ? $(nproc) : 4 ))" ] || fail "study ran $workers items side by side on $(nproc) threads"
grep -q '^kerf-dem study .*study.json' "$work/log" || fail "the log does not give the study's command"
# The grooves removed disks: the grooved rows differ from the regular ones.
awk -F, 'NR > 1 { m[$2] = $6 } END { exit !(m["regular"] != m["grooved"]) }' "$work/out/kerf_dem_means.csv" ||
  fail "grooved and regular forces identical"
# A rerun reuses every finished replicate and gives the same table.
cp "$work/out/kerf_dem_replicates.csv" "$work/first.csv"
"$validate" soda_lime_cutting "$work/out" >"$work/log" 2>&1
[ "$(grep -c " reused in " "$work/log")" -eq 4 ] || fail "rerun did not reuse the 4 replicates: $(cat "$work/log")"
cmp -s "$work/first.csv" "$work/out/kerf_dem_replicates.csv" || fail "rerun changed the table"
# Every check carries its standard error: for the groove ratio, ratio x hypot of the two relative standard
# errors of the mean (sample std / sqrt(n)) of kerf-dem's replicates; against the paper's DEM, kerf's and the
# paper's replicates alike.
grep -q "standard error" "$work/out/report.md" || fail "report.md gives no standard errors"
python3 - "$work/out" "$case_dir/soda_lime_orthogonal_cutting.csv" <<'PY' || fail "standard errors of the checks"
import csv, json, math, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/kerf_dem_replicates.csv")))
def mean_sem(surface):
    v = [float(r["main_force_N"]) for r in rows if r["surface"] == surface]
    return statistics.mean(v), statistics.stdev(v) / math.sqrt(len(v))
(g, sg), (r, sr) = mean_sem("grooved"), mean_sem("regular")
want = g / r * math.hypot(sg / g, sr / r)
check = [c for c in json.load(open(sys.argv[1] + "/summary.json"))["checks"] if c["check"].startswith("grooved / regular")][0]
ok = abs(check["standard_error"] - want) <= 1e-9 * want and check["resolved"] == (abs(check["value"] - 0.3333) >= 2 * want)
print("groove ratio: standard error", check["standard_error"], "expected", want)
# The regular main force against the paper's DEM: error = kerf / paper - 1, both means with their standard errors.
paper = [float(r["main_force_N"]) for r in csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#"))
         if r["source"] == "paper_dem" and r["surface"] == "regular" and float(r["depth_of_cut_mm"]) == 0.1]
p, sp = statistics.mean(paper), statistics.stdev(paper) / math.sqrt(len(paper))
want = r / p * math.hypot(sr / r, sp / p)
check = [c for c in json.load(open(sys.argv[1] + "/summary.json"))["checks"] if c["check"].startswith("regular 0.1 mm: main")][0]
ok = ok and abs(check["standard_error"] - want) <= 1e-9 * want and abs(check["value"] - (r / p - 1)) <= 1e-9
print("regular main error: standard error", check["standard_error"], "expected", want)
sys.exit(0 if ok else 1)
PY
# --replicates runs more packings and reuses the finished ones; out of range is a usage error (exit 2).
"$validate" soda_lime_cutting "$work/out" --replicates 3 >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || [ $rc -eq 1 ] || fail "--replicates 3: exit $rc: $(tail -5 "$work/log")"
[ "$(grep -c " reused in " "$work/log")" -eq 4 ] || fail "--replicates 3 did not reuse the 4 finished replicates"
[ "$(grep -c '^kerf_dem,' "$work/out/kerf_dem_replicates.csv")" -eq 6 ] || fail "expected 6 replicate rows"
grep -q "3 replicates per condition" "$work/out/report.md" || fail "report.md does not say 3 replicates"
"$validate" soda_lime_cutting "$work/out" --replicates 1 >"$work/log" 2>&1
[ $? -eq 2 ] || fail "--replicates 1 did not exit 2"
grep -q "replicates" "$work/log" || fail "--replicates 1: error does not name the option"
# The fitted case: the same runs with a note and the check of the fitted force reported as FITTED, outside the verdict.
fitted_dir="$work/tree/validation/soda_lime_cutting_cut_fitted"
cp -r "$case_dir" "$fitted_dir"
sed -i 's/"acceptance": {/"note": "Material fitted to one cut.", "acceptance": {"fitted": {"depth_of_cut_mm": 0.1, "force": "main"}, /' \
  "$fitted_dir/validation.json"
"$validate" soda_lime_cutting_cut_fitted "$work/fitted" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || [ $rc -eq 1 ] || fail "fitted case: exit $rc: $(tail -5 "$work/log")"
grep -q "^Material fitted to one cut.$" "$work/fitted/report.md" || fail "fitted case: no note in report.md"
grep -q "^- FITTED \*\*regular 0.1 mm: main force" "$work/fitted/report.md" || fail "fitted case: no FITTED check"
! grep -q "^- [A-Z]* \*\*regular 0.1 mm: main force.*(band: |error| <= 20 %)$" "$work/fitted/report.md" ||
  fail "fitted case: the fitted check was also judged"
grep -q "^- \(PASS\|FAIL\) \*\*regular 0.1 mm: thrust force" "$work/fitted/report.md" || fail "fitted case: thrust not judged"
grep -q '"fitted": true' "$work/fitted/summary.json" || fail "fitted case: summary.json does not mark the fitted check"
# Without bands: a reproduction. Exit 0, REPORTED, and the trends' verdicts recomputed here from the replicate
# table and the experiments' table: ratio of the means, first-order standard error from the two standard errors
# of the means (std / sqrt(n)), Welch-Satterthwaite dof, Student's t quantile (by integrating its density).
mkdir -p "$work/tree2/validation"
ln -s "$(cd "$src" && pwd)/data" "$work/tree2/data"
repro_dir="$work/tree2/validation/soda_lime_cutting"
cp -r "$case_dir" "$repro_dir"
sed -i 's/"acceptance": {.*}}$/"acceptance": {}}/' "$repro_dir/validation.json"
grep -q '"acceptance": {}}' "$repro_dir/validation.json" || fail "reproduction case: acceptance not emptied"
sed -i 's/"replicates": 2/"replicates": 3/' "$repro_dir/validation.json"
KERF_DATA_DIR="$work/tree2/data" "$validate" soda_lime_cutting "$work/repro" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "reproduction case: exit $rc: $(tail -5 "$work/log")"
grep -q "soda_lime_cutting: REPORTED" "$work/log" || fail "reproduction case: not reported as such: $(tail -3 "$work/log")"
grep -q "^## What this case compares, and why" "$work/repro/report.md" || fail "reproduction: no lead section"
grep -q "a reproduction reference, not a band" "$work/repro/report.md" || fail "reproduction: paper's DEM not a reference"
! grep -q "^- \(PASS\|FAIL\) " "$work/repro/report.md" || fail "reproduction: a band was judged"
python3 - "$work/repro" "$case_dir/soda_lime_orthogonal_cutting.csv" <<'PY' || fail "reproduction: trend verdicts"
import csv, json, math, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/kerf_dem_replicates.csv")))
exp = [r for r in csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")) if r["source"] == "experiment"]
def t_cdf(x, dof):  # Student's t, by Simpson's rule on its density from 0 to x
    c = math.gamma((dof + 1) / 2) / (math.sqrt(dof * math.pi) * math.gamma(dof / 2))
    f = lambda u: c * (1 + u * u / dof) ** (-(dof + 1) / 2)
    n = 2000; h = x / n
    return 0.5 + h / 3 * sum((1 if k in (0, n) else 4 if k % 2 else 2) * f(k * h) for k in range(n + 1))
summary = json.load(open(sys.argv[1] + "/summary.json"))
assert summary["passed"] is None and summary["role"] == "reproduction", summary.get("passed")
trends = {t["id"]: t for t in summary["trends"]}
checked = 0
for force in ("main", "thrust"):
    key = force + "_force_N"
    g = [float(r[key]) for r in rows if r["surface"] == "grooved"]
    r = [float(r[key]) for r in rows if r["surface"] == "regular"]
    (mg, sg), (mr, sr) = [(statistics.mean(v), statistics.stdev(v) / math.sqrt(len(v))) for v in (g, r)]
    value = mg / mr
    va, vb = (sg / mg) ** 2, (sr / mr) ** 2
    se = value * math.sqrt(va + vb)
    dof = (va + vb) ** 2 / (va ** 2 / (len(g) - 1) + vb ** 2 / (len(r) - 1))
    lo_q, hi_q = 0.0, 100.0
    for _ in range(60):  # bisection for the 97.5 % quantile
        mid = 0.5 * (lo_q + hi_q)
        lo_q, hi_q = (mid, hi_q) if t_cdf(mid, dof) < 0.975 else (lo_q, mid)
    q = 0.5 * (lo_q + hi_q)
    mean_exp = lambda s: statistics.mean(float(e[key]) for e in exp if e["surface"] == s and float(e["depth_of_cut_mm"]) == 0.1)
    ratio_exp = mean_exp("grooved") / mean_exp("regular")
    lo, hi = value - q * se, value + q * se  # AGREES also needs the interval within +-50 % of the experiment's
    want = "DISAGREES" if not lo <= ratio_exp <= hi else "AGREES" if 0.5 * ratio_exp <= lo and hi <= 1.5 * ratio_exp \
        else "UNRESOLVED"
    t = trends[f"grooved_to_regular_{force}_force_0.1"]
    print(force, "ratio", value, "+-", se, "dof", dof, "q", q, "experiment", ratio_exp, "->", want, "report:", t["verdict"])
    assert abs(t["value"] - value) <= 1e-9 * value and abs(t["standard_error"] - se) <= 1e-9 * se
    assert abs(t["ci95_quantile"] - q) <= 1e-3 * q and abs(t["experiment"] - ratio_exp) <= 1e-12
    assert t["verdict"] == want
    assert t["check"] in summary["trend_verdicts"][want]
    checked += 1
assert checked == 2
PY
# Bad input: exit 2 naming the field.
sed -i 's/"surface": "grooved"/"surface": "polished"/' "$case_dir/validation.json"
"$validate" soda_lime_cutting "$work/bad" >"$work/log" 2>&1
[ $? -eq 2 ] || fail "bad surface did not exit 2"
grep -q "validation.conditions\[1\].surface" "$work/log" || fail "error does not name the field: $(cat "$work/log")"
# The steady case is not run by run_validation: its acceptance is the Yang et al. 2018 study's record, and the error says
# where to go (one line, exit 2).
"$validate" soda_lime_cutting_steady "$work/steady" >"$work/log" 2>&1
[ $? -eq 2 ] || fail "soda_lime_cutting_steady did not exit 2"
grep -q "scripts/validate.sh soda_lime_cutting_steady" "$work/log" || fail "no pointer to the record: $(cat "$work/log")"
[ ! -e "$work/steady" ] || fail "soda_lime_cutting_steady wrote $work/steady"
echo "validation_soda_lime_cutting: ok"
