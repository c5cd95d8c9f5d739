#!/usr/bin/env bash
# run_validation soda_lime_cutting_steady on a miniature copy of the case (a 2 mm x 0.3 mm steady-state cut with
# a small active window, the four paper conditions, two packings; validation.json is the real one's, its
# scene, conditions and threshold changed): "statistics": "within_cuts" combines the cuts' own standard errors as
# sqrt(sum sem_k^2) / n, reports the between-packing one beside it, checks the trends' 95 % intervals against
# the experiments' trends (from the CSV), exits 0 when every mean is resolved and 1, naming the condition, when
# one is not; from acceptance.between_packings_from_replicates packings on the acceptance uses the between-packing
# errors with Student-t intervals (Welch-Satterthwaite degrees of freedom); adaptive packings ("replicates" as the
# study's adaptive policy) stop at min_count when the target is met and run to max_count when it is not;
# --replicates 1 is allowed here; bad acceptance and replicates keys exit 2; the real validation.json reads.
# Usage: validation_soda_lime_cutting_steady.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
validate="$1/../validation/run_validation"
[ -x "$validate" ] || fail "no run_validation next to $1"

# The case is found beside the data directory: a scratch tree with the real data, the seed case's experiments
# (the steady case points at them) and a miniature steady case.
mkdir -p "$work/tree/validation/soda_lime_cutting" "$work/tree/validation/soda_lime_cutting_steady"
ln -s "$(cd "$src" && pwd)/data" "$work/tree/data"
csv="$work/tree/validation/soda_lime_cutting/soda_lime_orthogonal_cutting.csv"
cp "$src/validation/soda_lime_cutting/soda_lime_orthogonal_cutting.csv" "$csv"
case_dir="$work/tree/validation/soda_lime_cutting_steady"
cat >"$case_dir/scene.json" <<'JSON'
{"kind": "cut", "material": {"base": "soda_lime_glass_fj_undamped"},
 "specimen": {"width_mm": 2, "height_mm": 0.3, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
              "growth_steps": 2000, "relax_steps": 500},
 "cut": {"depth_of_cut_mm": 0.1, "speed_m_per_s": 4, "length_mm": 0.5, "entry_fraction": 0.15, "window_mm": 0.05},
 "grooves": {"shape": "none", "pitch_mm": 0.04, "width_mm": 0.015},
 "active_window": {"enabled": true, "ahead_depths": 2, "behind_depths": 1, "below_depths": 1, "above_depths": 1.5},
 "output": {"frame_every_samples": 0}}
JSON
# spec_from_real KEY=VALUE...: the real validation.json, the paper's four conditions, 2 replicates, the changes.
spec_from_real() {
  python3 - "$src/validation/soda_lime_cutting_steady/validation.json" "$case_dir/validation.json" "$@" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
assert spec["statistics"] == "within_cuts", "the real case's statistics"
assert spec["scene"] == "../../data/scenes/dem_cut_steady.json", "the real case cuts the bundled steady scene"
spec["scene"] = "scene.json"  # the miniature scene, not the bundled one
spec["conditions"] = [c for c in spec["conditions"] if c["groove_shape"] != "trapezoidal"]
spec["replicates"] = 2
spec["acceptance"]["max_relative_sem_percent"] = 1000
spec["acceptance"].pop("between_packings_from_replicates", None)  # the cuts' own errors unless a test sets it
for change in sys.argv[3:]:
    key, value = change.split("=", 1)
    *path, last = key.split(".")
    node = spec
    for p in path: node = node[p]
    if value == "DELETE": del node[last]
    else: node[last] = json.loads(value)
json.dump(spec, open(sys.argv[2], "w"), indent=1)
PY
}
spec_from_real
export KERF_DATA_DIR="$work/tree/data"
"$validate" soda_lime_cutting_steady "$work/out" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "exit $rc with every mean resolved to 1000 %: $(tail -5 "$work/log")"
for f in report.md summary.json kerf_dem_replicates.csv kerf_dem_means.csv vs_experiment/report.md vs_paper_dem/report.md \
         study/study.json study/items.csv study/items/condition_4_seed_2/forces.csv; do
  [ -s "$work/out/$f" ] || fail "missing $f"
done
grep -q "Acceptance is statistical" "$work/out/report.md" || fail "report.md lacks the statistical acceptance paragraph"
grep -q "^- RESOLVED \*\*regular_0.1\*\*" "$work/out/report.md" || fail "report.md does not resolve regular_0.1"
[ "$(grep -c '^kerf_dem,' "$work/out/kerf_dem_replicates.csv")" -eq 8 ] || fail "expected 8 replicate rows"
head -1 "$work/out/kerf_dem_replicates.csv" | grep -q ',wall_time_s,main_force_sem_N,thrust_force_sem_N,' ||
  fail "replicate table lacks the within-cut columns at its end"

# The numbers, recomputed from the cuts' own summary.json files and the experiments' CSV.
check_numbers() {  # check_numbers <expected packings> [between: the acceptance uses the between-packing errors]
  python3 - "$work/out" "$csv" "$1" "${2:-within}" <<'PY'
import csv, json, math, statistics, sys
out, n_expected, between_mode = sys.argv[1], int(sys.argv[3]), sys.argv[4] == "between"
summary = json.load(open(out + "/summary.json"))
assert summary["statistics"] == "within_cuts", summary["statistics"]
assert summary["replicates"] == n_expected or summary["replicates"]["policy"] == "adaptive", summary["replicates"]
items = list(csv.DictReader(open(out + "/study/items.csv")))
means_csv = {r["surface"] + "_" + r["depth_of_cut_mm"]: r for r in csv.DictReader(open(out + "/kerf_dem_means.csv"))}
close = lambda a, b: abs(a - b) <= 1e-9 * max(1.0, abs(b))
spec_names = ["regular_0.1", "regular_0.2", "grooved_0.1", "grooved_0.2"]
est = {}
for ci, cond in enumerate(summary["conditions"]):
    assert cond["condition"] == spec_names[ci], cond["condition"]
    assert cond["replicates"] == n_expected
    for force in ("main", "thrust"):
        vals, sems = [], []
        for k in range(1, n_expected + 1):
            r = json.load(open(f"{out}/study/items/condition_{ci + 1}_seed_{k}/summary.json"))["results"]
            vals.append(r[force + "_force_N"]); sems.append(r[force + "_force_sem_N"])
        mean = sum(vals) / len(vals)
        within = math.sqrt(sum(s * s for s in sems)) / len(sems)
        between = cond[force + "_force_between_packings_sem_N"]
        if n_expected >= 2:
            assert close(between, statistics.stdev(vals) / math.sqrt(len(vals))), (cond["condition"], force, "between")
        else:
            assert between is None, "a between-packing standard error from one packing"
        # The acceptance's standard error and its degrees of freedom: the spread between the packings (n - 1) or
        # the cuts' own (a normal quantile).
        used, df = (between, n_expected - 1) if between_mode else (within, math.inf)
        assert cond["standard_error_from"] == ("between_packings" if between_mode else "within_cuts")
        assert close(cond[force + "_force_N"], mean), (cond["condition"], force, "mean")
        assert close(cond[force + "_force_sem_N"], used), (cond["condition"], force, cond[force + "_force_sem_N"], used)
        assert close(cond[force + "_force_relative_sem_percent"], 100 * used / abs(mean))
        row = means_csv[cond["surface"] + "_" + str(cond["depth_of_cut_mm"])]
        assert close(float(row[force + "_force_sem_N"]), within), "kerf_dem_means.csv's within-cut standard error"
        est[(cond["condition"], force)] = (mean, used, df)
    assert cond["resolved"] == all(cond[f + "_force_relative_sem_percent"] <= summary["max_relative_sem_percent"]
                                   for f in ("main", "thrust")), (cond["condition"], "resolved")
print("conditions: means, within-cut and between-packing standard errors as recomputed")

# The experiments' and the paper's DEM's trends: ratios of the means of their CSV rows.
rows = list(csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")))
def ref(source, surface, depth, force):
    v = [float(r[force + "_force_N"]) for r in rows
         if r["source"] == source and r["surface"] == surface and float(r["depth_of_cut_mm"]) == depth]
    assert len(v) == 3, (source, surface, depth)
    return sum(v) / len(v)
expected = {}
for force in ("main", "thrust"):
    expected[f"depth_effect_regular_{force}_force"] = (("regular_0.2", "regular_0.1"), [
        ref(s, "regular", 0.2, force) / ref(s, "regular", 0.1, force) for s in ("experiment", "paper_dem")])
    for depth in (0.1, 0.2):
        expected[f"grooved_to_regular_{force}_force_{depth}"] = ((f"grooved_{depth}", f"regular_{depth}"), [
            ref(s, "grooved", depth, force) / ref(s, "regular", depth, force) for s in ("experiment", "paper_dem")])
checks = {c["id"]: c for c in summary["checks"]}
assert set(checks) == set(expected), sorted(checks)
for cid, ((num, den), (exp, paper)) in expected.items():
    c = checks[cid]
    force = "main" if "main" in cid else "thrust"
    (a, sa, dfa), (b, sb, dfb) = est[(num, force)], est[(den, force)]
    value = a / b
    se = value * math.hypot(sa / a, sb / b)
    assert close(c["value"], value) and close(c["standard_error"], se), (cid, c["value"], value, c["standard_error"], se)
    # Welch-Satterthwaite's degrees of freedom of the two relative variances, and the quantile q with
    # P(|t_df| <= q) = 0.95 (the t density integrated by Simpson's rule; 1.96 without degrees of freedom).
    va, vb = (sa / a) ** 2, (sb / b) ** 2
    df = (va + vb) ** 2 / (va * va / dfa + vb * vb / dfb) if math.isfinite(dfa + dfb) else math.inf
    q = c["ci95_quantile"]
    if math.isfinite(df):
        assert close(c["degrees_of_freedom"], df), (cid, c["degrees_of_freedom"], df)
        k = math.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2)) / math.sqrt(df * math.pi)
        f = lambda t: k * (1 + t * t / df) ** (-(df + 1) / 2)
        m = 4000
        h = q / m
        area = h / 3 * (f(0) + f(q) + sum((4 if i % 2 else 2) * f(i * h) for i in range(1, m)))
        assert abs(2 * area - 0.95) < 1e-7, (cid, "t quantile", q, df, 2 * area)
    else:
        assert c["degrees_of_freedom"] is None and q == 1.96, (cid, c["degrees_of_freedom"], q)
    assert close(c["ci95_low"], value - q * se) and close(c["ci95_high"], value + q * se), (cid, "95 % interval")
    assert close(c["experiment"], exp) and close(c["paper_dem"], paper), (cid, c["experiment"], exp, c["paper_dem"], paper)
    inside = c["ci95_low"] <= exp <= c["ci95_high"]
    assert c["verdict"] == ("AGREES" if inside else "DISAGREES"), (cid, c["verdict"])
    assert close(c["standard_errors_from_experiment"], abs(exp - value) / se)
    if n_expected == 1: assert c["standard_error_between_packings"] is None
# Near the issue's reading of the tables (a check of the CSV, not of the driver).
assert abs(checks["depth_effect_regular_main_force"]["experiment"] - 1.16) < 0.01
assert abs(checks["grooved_to_regular_main_force_0.1"]["experiment"] - 0.15) < 0.01
assert abs(checks["grooved_to_regular_main_force_0.2"]["paper_dem"] - 0.20) < 0.01
print("trends: values, delta-method standard errors, 95 % intervals, references and verdicts as recomputed")
PY
}
check_numbers 2 || fail "the within-cut statistics of two packings"

# From two packings on, the between-packing errors (acceptance.between_packings_from_replicates): the same cuts
# (reused), each condition's error the spread of its packings, the trends' intervals Student's t.
spec_from_real "acceptance.between_packings_from_replicates=2"
"$validate" soda_lime_cutting_steady "$work/out" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "between-packing errors: exit $rc: $(tail -5 "$work/log")"
[ "$(grep -c " reused in " "$work/log")" -eq 8 ] || fail "between-packing errors did not reuse the 8 cuts"
check_numbers 2 between || fail "the between-packing statistics of two packings"
grep -q "^- RESOLVED \*\*regular_0.1\*\*: .*; 2 packings, between-packing errors" "$work/out/report.md" ||
  fail "report.md does not say regular_0.1's error is the between-packing one"

# Packings by the error reached (validation.json "replicates" as the study's adaptive policy): a target every
# condition meets stops each at min_count (the 2 cuts reused); one none meets runs each to max_count.
spec_from_real 'replicates={"policy": "adaptive", "min_count": 2, "max_count": 3, "results": ["main_force_N"]}' \
  "acceptance.max_relative_sem_percent=100"
"$validate" soda_lime_cutting_steady "$work/out" >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "adaptive, target met: exit $rc: $(tail -5 "$work/log")"
[ "$(grep -c " reused in " "$work/log")" -eq 8 ] || fail "adaptive, target met: not the 8 cuts reused: $(cat "$work/log")"
check_numbers 2 || fail "adaptive packings, target met at min_count"
spec_from_real 'replicates={"policy": "adaptive", "min_count": 2, "max_count": 3, "results": ["main_force_N"]}' \
  "acceptance.max_relative_sem_percent=0.001"
"$validate" soda_lime_cutting_steady "$work/out" >"$work/log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "adaptive, target missed: exit $rc (expected 1: the means not resolved): $(tail -5 "$work/log")"
[ -s "$work/out/study/items/condition_4_seed_3/summary.json" ] || fail "adaptive, target missed: no third packing"
[ ! -e "$work/out/study/items/condition_1_seed_4" ] || fail "adaptive: a packing beyond max_count"
check_numbers 3 || fail "adaptive packings, target missed: max_count"

# A rerun with one packing (allowed under within_cuts) reuses the finished cuts: the standard error is the
# cut's own, and there is no between-packing one.
spec_from_real
"$validate" soda_lime_cutting_steady "$work/out" --replicates 1 >"$work/log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "--replicates 1: exit $rc: $(tail -5 "$work/log")"
[ "$(grep -c " reused in " "$work/log")" -eq 4 ] || fail "--replicates 1 did not reuse the 4 cuts: $(cat "$work/log")"
check_numbers 1 || fail "the within-cut statistics of one packing"

# A threshold between the conditions' relative standard errors: exactly those above it are NOT RESOLVED,
# named on stderr and in report.md, and the run exits 1.
read -r threshold worst others < <(python3 - "$work/out/summary.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["conditions"]
rel = sorted(((max(x["main_force_relative_sem_percent"], x["thrust_force_relative_sem_percent"]), x["condition"]) for x in c),
             reverse=True)
print((rel[0][0] + rel[1][0]) / 2, rel[0][1], ",".join(name for _, name in rel[1:]))
PY
)
spec_from_real "acceptance.max_relative_sem_percent=$threshold"
"$validate" soda_lime_cutting_steady "$work/out" --replicates 1 >"$work/log" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "a condition above the threshold $threshold %: exit $rc (expected 1): $(tail -5 "$work/log")"
grep -q "FAILED: $worst NOT RESOLVED: .*relative standard error .* > " "$work/log" ||
  fail "the log does not name $worst: $(cat "$work/log")"
[ "$(grep -c "NOT RESOLVED" "$work/log")" -eq 1 ] || fail "more than $worst not resolved at $threshold %"
grep -q "^- NOT RESOLVED \*\*$worst\*\*" "$work/out/report.md" || fail "report.md does not mark $worst"
for name in ${others//,/ }; do
  grep -q "^- RESOLVED \*\*$name\*\*" "$work/out/report.md" || fail "report.md does not resolve $name"
done
grep -q '"passed": false' "$work/out/summary.json" || fail "summary.json does not fail"
# A tiny threshold: every condition is NOT RESOLVED.
spec_from_real "acceptance.max_relative_sem_percent=0.001"
"$validate" soda_lime_cutting_steady "$work/out" --replicates 1 >"$work/log" 2>&1
[ $? -eq 1 ] || fail "threshold 0.001 %: not exit 1"
[ "$(grep -c "NOT RESOLVED" "$work/log")" -eq 4 ] || fail "threshold 0.001 %: not all four conditions named"

# Bad input: exit 2 naming the field, before any cut runs.
expect_validation_error() {  # expect_validation_error <text expected on stderr> <spec changes...>
  local want="$1"; shift
  spec_from_real "$@"
  "$validate" soda_lime_cutting_steady "$work/bad" >"$work/log" 2>&1
  local rc=$?
  [ $rc -eq 2 ] || fail "exit $rc (expected 2) for $*: $(cat "$work/log")"
  grep -qF -- "$want" "$work/log" || fail "the error lacks '$want' for $*: $(cat "$work/log")"
}
expect_validation_error "validation.statistics" 'statistics="between"'
expect_validation_error "validation.acceptance.max_relative_sem_percent" "acceptance.max_relative_sem_percent=0"
expect_validation_error "validation.acceptance.max_relative_sem_percent" "acceptance.max_relative_sem_percent=DELETE"
expect_validation_error "validation.acceptance.trends" 'acceptance.trends="yes"'
expect_validation_error "validation.acceptance.regular_force_max_abs_error_vs_paper_dem_percent" \
  "acceptance.regular_force_max_abs_error_vs_paper_dem_percent=20"
expect_validation_error "validation.replicates" "replicates=0"
expect_validation_error "validation.replicates.min_count" 'replicates={"policy": "adaptive", "min_count": 1}'
expect_validation_error "validation.replicates.max_count" 'replicates={"policy": "adaptive", "min_count": 4, "max_count": 3}'
expect_validation_error "validation.replicates.results" 'replicates={"policy": "adaptive", "results": ["cracks_chip"]}'
expect_validation_error "validation.replicates.policy" 'replicates={"policy": "fixed", "count": 3}'
expect_validation_error "validation.replicates.target_relative_sem_percent" \
  'replicates={"policy": "adaptive", "target_relative_sem_percent": 5}'
expect_validation_error "validation.acceptance.between_packings_from_replicates" \
  "acceptance.between_packings_from_replicates=1"
expect_validation_error "validation.acceptance.max_relative_sem_percent" 'replicates={"policy": "adaptive"}' \
  "acceptance.max_relative_sem_percent=101"
expect_validation_error "validation.replicates" "statistics=DELETE" 'replicates={"policy": "adaptive"}' \
  'acceptance={"regular_force_max_abs_error_vs_paper_dem_percent": 20, "grooved_to_regular_main_force_ratio_max": 0.33}'
# One packing needs the cuts' own standard errors: with the default statistics it is refused, naming both.
expect_validation_error "within_cuts" "statistics=DELETE" "replicates=1" \
  'acceptance={"regular_force_max_abs_error_vs_paper_dem_percent": 20, "grooved_to_regular_main_force_ratio_max": 0.33}'
expect_validation_error "validation.acceptance.max_relative_sem_percent" "statistics=\"replicates\""
[ ! -e "$work/bad/study" ] || fail "a bad validation.json started cuts"
# The real validation.json as it is (its adaptive packings and acceptance), only its scene the miniature one, reads
# without an error: the first error is the out-of-range --replicates checked after it.
python3 - "$src/validation/soda_lime_cutting_steady/validation.json" "$case_dir/validation.json" <<'PY'
import json, sys
spec = json.load(open(sys.argv[1]))
spec["scene"] = "scene.json"
json.dump(spec, open(sys.argv[2], "w"))
PY
"$validate" soda_lime_cutting_steady "$work/bad" --replicates 101 >"$work/log" 2>&1
[ $? -eq 2 ] && grep -q -- "--replicates = 101" "$work/log" || fail "the real validation.json does not read: $(cat "$work/log")"
echo "validation_soda_lime_cutting_steady: ok"
