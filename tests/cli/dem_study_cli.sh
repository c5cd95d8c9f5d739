#!/usr/bin/env bash
# kerf-dem study (issue 21): the bundled smoke study writes its tables and plots; the same tables on 1 and 2
# threads, with no MPI and (built with MPI, mpirun present) under mpirun with 1 and 3 ranks; a rerun reuses
# every item; a study killed mid-way and rerun gives the tables of an uninterrupted one, an item killed inside
# continues from its checkpoint; adaptive replicates
# stop at the count the prefix rule gives on the values of a known distribution (the test kind "synthetic" of
# kerf-dem-test-kinds, tests/tools/kerf_dem_test_kinds.cpp, which kerf-dem refuses as any unknown kind);
# a bad override fails its items only; bad study files exit 2 naming the key.
# Usage: dem_study_cli.sh <dir of built programs> <source dir> <dir of the test programs>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
[ -x "$test_bin" ] || fail "no test program $test_bin (the third argument: the test programs' directory)"
smoke="$src/data/studies/smoke.json"
src_abs="$(cd "$src" && pwd)"  # study files written here name the scene by an absolute path
mpi=(mpirun --allow-run-as-root --oversubscribe)
with_mpi=0
"$bin" study --help | grep -q "under mpirun -np N: across ranks" && command -v mpirun >/dev/null && with_mpi=1

# The columns of items.csv that depend only on the scenes and seeds (wall time, host and rank left out).
results_of() { python3 - "$1" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    print(",".join(f"{k}={v}" for k, v in r.items() if k not in ("wall_time_s", "host", "rank")))
EOF
}
same_tables() {  # same_tables <dir a> <dir b> <what>
  cmp -s "$1/conditions.csv" "$2/conditions.csv" || fail "$3: conditions.csv differs: $(diff "$1/conditions.csv" "$2/conditions.csv" | head -5)"
  diff <(results_of "$1/items.csv") <(results_of "$2/items.csv") >"$work/diff" || fail "$3: items.csv differs: $(head -5 "$work/diff")"
}

# The smoke study on one machine: tables, summary, plots (PNG and PDF), one item directory per item.
"$bin" study "$smoke" --out "$work/s2" --threads 2 >"$work/log" 2>"$work/err" || fail "smoke study: $(cat "$work/err")"
for f in items.csv conditions.csv summary.json; do [ -s "$work/s2/$f" ] || fail "smoke: no $f"; done
[ "$(tail -n +2 "$work/s2/items.csv" | wc -l)" -eq 4 ] || fail "smoke: expected 4 items: $(cat "$work/s2/items.csv")"
head -1 "$work/s2/items.csv" | grep -q "^condition,loading.speed_m_per_s,replicate,seed,status,.*tensile_strength_MPa.*,wall_time_s,host,rank,error$" ||
  fail "items.csv header: $(head -1 "$work/s2/items.csv")"
head -1 "$work/s2/conditions.csv" | grep -qx "condition,loading.speed_m_per_s,result,n,failed,mean,std,sem,ci95_low,ci95_high,relative_sem_percent,target_relative_sem_percent,target_met" ||
  fail "conditions.csv header: $(head -1 "$work/s2/conditions.csv")"
ls "$work/s2/items" | sort | tr '\n' ' ' | grep -qx "condition_1_seed_1 condition_1_seed_2 condition_2_seed_1 condition_2_seed_2 " ||
  fail "item directories: $(ls -a "$work/s2/items")"
for f in plots/tensile_strength_MPa_vs_loading_speed_m_per_s.png plots/tensile_strength_MPa_vs_loading_speed_m_per_s.pdf; do
  [ -s "$work/s2/$f" ] || fail "smoke: no $f"
done
# A result that only repeats the varied input (the test's speed_m_per_s) gets no plot.
[ ! -e "$work/s2/plots/speed_m_per_s_vs_loading_speed_m_per_s.png" ] || fail "smoke: a plot of the input against itself"
grep -q "^study: condition_1_seed_1 done in" "$work/log" || fail "no log line per item when stdout is not a terminal: $(cat "$work/log")"
# With --log-every N, also each item's stage lines (as kerf-dem run's), named by item; no performance line.
"$bin" study "$smoke" --out "$work/s_log" --threads 2 --log-every 5 >"$work/log" 2>&1 || fail "smoke study with --log-every"
for item in condition_1_seed_1 condition_2_seed_2; do
  grep -q "^$item: tension: step [0-9]* time .* stress .* MPa" "$work/log" || fail "no stage lines of $item: $(head -5 "$work/log")"
  grep -q "^$item: tension: done: " "$work/log" || fail "no stage end line of $item"
done
! grep -q "^performance:" "$work/log" || fail "a study printed a run's performance line"
# The statistics are those of the items: mean, sample std and the Student-t interval, recomputed here.
python3 - "$work/s2" <<'EOF' || fail "conditions.csv does not match items.csv"
import csv, math, statistics, sys
d = sys.argv[1]
items = list(csv.DictReader(open(f"{d}/items.csv")))
rows = [r for r in csv.DictReader(open(f"{d}/conditions.csv")) if r["result"] == "tensile_strength_MPa"]
assert len(rows) == 2, rows
t975_1 = 12.706204736174698  # Student t, 1 degree of freedom, 97.5 %
for r in rows:
    v = [float(i["tensile_strength_MPa"]) for i in items if i["condition"] == r["condition"]]
    assert int(r["n"]) == len(v) == 2
    m, s = statistics.mean(v), statistics.stdev(v)
    assert math.isclose(float(r["mean"]), m, rel_tol=1e-12) and math.isclose(float(r["std"]), s, rel_tol=1e-12), r
    assert math.isclose(float(r["ci95_high"]) - m, t975_1 * s / math.sqrt(2), rel_tol=1e-9), r
EOF
# Seeds: replicate k is specimen.seed + k - 1; different packings give different results.
python3 - "$work/s2/items.csv" <<'EOF' || fail "seeds or results of the replicates"
import csv, sys
items = list(csv.DictReader(open(sys.argv[1])))
assert [i["seed"] for i in items] == ["1", "2", "1", "2"], [i["seed"] for i in items]
assert items[0]["tensile_strength_MPa"] != items[1]["tensile_strength_MPa"]
EOF

# One thread: the same tables. A rerun reuses every item and writes the same tables.
"$bin" study "$smoke" --out "$work/s1" --threads 1 >/dev/null 2>&1 || fail "smoke study, 1 thread"
same_tables "$work/s2" "$work/s1" "1 and 2 threads"
cp "$work/s1/items.csv" "$work/s1_items_first.csv"
"$bin" study "$smoke" --out "$work/s1" --threads 1 >"$work/log" 2>&1 || fail "rerun"
grep -q "4 items (0 failed, 4 reused)" "$work/log" || fail "rerun did not reuse the 4 items: $(tail -1 "$work/log")"
cmp -s "$work/s1_items_first.csv" "$work/s1/items.csv" || fail "rerun: items.csv changed"
# A reworded description of the base scene changes no result: the items are reused.
sed 's/"description": "/"description": "Reworded. /' "$src/data/scenes/dem_tension.json" >"$work/tension_reworded.json"
grep -q '"Reworded. ' "$work/tension_reworded.json" || fail "the reworded scene has no reworded description"
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["scene"] = sys.argv[2]; json.dump(s, open(sys.argv[3], "w"))' \
  "$smoke" "$work/tension_reworded.json" "$work/smoke_reworded.json" || fail "reworded study"
"$bin" study "$work/smoke_reworded.json" --out "$work/s1" --threads 1 >"$work/log" 2>&1 || fail "reworded rerun"
grep -q "4 items (0 failed, 4 reused)" "$work/log" || fail "a reworded description did not reuse the items: $(tail -1 "$work/log")"
# A grid that gains a value renumbers its conditions (0.2 m/s: condition 2 -> 3): the finished items move to
# their new names and are reused; only the new value's items run, and the old values' rows are unchanged.
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["conditions"]["grid"]["loading.speed_m_per_s"] = [0.1, 0.15, 0.2]; json.dump(s, open(sys.argv[2], "w"))' \
  "$work/smoke_reworded.json" "$work/smoke_more.json" || fail "study with one more speed"
"$bin" study "$work/smoke_more.json" --out "$work/s1" --threads 1 >"$work/log" 2>&1 || fail "study with one more speed: $(tail -3 "$work/log")"
grep -q "6 items (0 failed, 4 reused)" "$work/log" || fail "one more speed did not reuse the 4 items: $(tail -1 "$work/log")"
grep -q "^study: condition_2_seed_1 done" "$work/log" || fail "the new speed's items did not run: $(cat "$work/log")"
python3 - "$work/s1_items_first.csv" "$work/s1/items.csv" <<'EOF' || fail "the reused rows differ from the first run's"
import csv, sys
strip = lambda r: {k: v for k, v in r.items() if k not in ("condition", "wall_time_s", "host", "rank")}
first = [strip(r) for r in csv.DictReader(open(sys.argv[1]))]
now = [strip(r) for r in csv.DictReader(open(sys.argv[2])) if r["loading.speed_m_per_s"] != "0.15"]
assert first == now, (first, now)
EOF

if [ $with_mpi -eq 1 ]; then
  "${mpi[@]}" -np 1 "$bin" study "$smoke" --out "$work/m1" >"$work/log" 2>&1 || fail "mpirun -np 1: $(tail -3 "$work/log")"
  same_tables "$work/s2" "$work/m1" "no MPI and mpirun -np 1"
  "${mpi[@]}" -np 3 "$bin" study "$smoke" --out "$work/m3" >"$work/log" 2>&1 || fail "mpirun -np 3: $(tail -3 "$work/log")"
  grep -q "over 2 worker ranks" "$work/log" || fail "mpirun -np 3: not 2 workers: $(head -3 "$work/log")"
  same_tables "$work/s2" "$work/m3" "no MPI and mpirun -np 3"
  python3 -c "
import csv, sys
ranks = {r['rank'] for r in csv.DictReader(open('$work/m3/items.csv'))}
sys.exit(0 if ranks <= {'1', '2'} and ranks else 1)" || fail "mpirun -np 3: items not run by ranks 1 and 2"
else
  echo "dem study cli: built without MPI or no mpirun: the MPI cases are skipped"
fi

# The test kind is the test program's only: kerf-dem refuses it as any unknown kind, naming the kinds it knows.
printf '%s\n' '{"kind": "synthetic"}' >"$work/synthetic.json"
expect_input_error "kerf-dem: error: kind = synthetic: expected one of 'specimen', 'tension', 'compression', 'calibrate', 'cut', 'calibrate_cut', 'toughness'" \
  run "$work/synthetic.json" --out "$work/synthetic_out"
"$test_bin" run "$work/synthetic.json" --out "$work/synthetic_out" >/dev/null 2>"$work/err" || fail "kerf-dem-test-kinds run: $(cat "$work/err")"
grep -q '"value"' "$work/synthetic_out/summary.json" || fail "kerf-dem-test-kinds: no value in the summary"
"$test_bin" run --help | grep -q "toughness, synthetic" || fail "kerf-dem-test-kinds does not list its kind after the library's"

# A list study whose conditions differ by a key only one of them sets (one value: no axis) is plotted by condition,
# a point per condition named by its tags in the legend (the grid study below keeps its axis: synthetic.std).
cat >"$work/list.json" <<'EOF'
{"scene": {"kind": "synthetic", "synthetic": {"mean": 10}},
 "conditions": {"list": [{"tags": {"case": "base"}}, {"tags": {"case": "shifted"}, "synthetic.mean": 12}]},
 "replicates": {"policy": "fixed", "count": 3}}
EOF
"$test_bin" study "$work/list.json" --out "$work/l" --threads 2 >/dev/null 2>"$work/err" || fail "list study: $(cat "$work/err")"
[ -s "$work/l/plots/value_by_condition.png" ] || fail "list study: no plot by condition: $(ls "$work/l/plots" 2>&1)"
[ ! -e "$work/l/plots/value_vs_synthetic_mean.png" ] || fail "list study: a plot against a key with one value"

# Adaptive replicates on the synthetic kind (value ~ N(10, std^2) by seed): each condition stops at the
# smallest n in [min, max] whose first n values have sem / |mean| <= 5 %, computed here from a fixed study of
# max_count packings of the same conditions.
cat >"$work/adaptive.json" <<'EOF'
{"scene": {"kind": "synthetic", "synthetic": {"mean": 10}},
 "conditions": {"grid": {"synthetic.std": [1, 2, 20]}},
 "replicates": {"policy": "adaptive", "results": ["value"], "target_relative_sem_percent": 5, "min_count": 3, "max_count": 25}}
EOF
sed 's/"policy": "adaptive".*/"policy": "fixed", "count": 25}}/' "$work/adaptive.json" >"$work/fixed.json"
"$test_bin" study "$work/adaptive.json" --out "$work/a" --threads 2 >/dev/null 2>"$work/err" || fail "adaptive study: $(cat "$work/err")"
"$test_bin" study "$work/fixed.json" --out "$work/f" --threads 2 >/dev/null 2>"$work/err" || fail "fixed study: $(cat "$work/err")"
[ -s "$work/f/plots/value_vs_synthetic_std.png" ] || fail "grid study: no plot against its key: $(ls "$work/f/plots" 2>&1)"
python3 - "$work/a" "$work/f" <<'EOF' || fail "adaptive stopping"
import csv, math, statistics, sys
a, f = sys.argv[1], sys.argv[2]
full = list(csv.DictReader(open(f"{f}/items.csv")))
got = {r["condition"]: r for r in csv.DictReader(open(f"{a}/conditions.csv")) if r["result"] == "value"}
counts = set()
for c in ("1", "2", "3"):
    v = [float(r["value"]) for r in full if r["condition"] == c]
    assert len(v) == 25
    n = next((n for n in range(3, 26) if statistics.stdev(v[:n]) / math.sqrt(n) <= 0.05 * abs(statistics.mean(v[:n]))), 25)
    met = statistics.stdev(v[:n]) / math.sqrt(n) <= 0.05 * abs(statistics.mean(v[:n]))
    assert int(got[c]["n"]) == n, (c, got[c]["n"], n)
    assert got[c]["target_met"] == ("yes" if met else "no"), (c, got[c]["target_met"], met)
    assert math.isclose(float(got[c]["mean"]), statistics.mean(v[:n]), rel_tol=1e-12)
    counts.add(n)
assert len(counts) == 3, f"the three conditions should stop at different counts: {counts}"
items = list(csv.DictReader(open(f"{a}/items.csv")))
assert len(items) == sum(int(got[c]["n"]) for c in got), len(items)
EOF
if [ $with_mpi -eq 1 ]; then
  "${mpi[@]}" -np 3 "$test_bin" study "$work/adaptive.json" --out "$work/am" >"$work/log" 2>&1 || fail "adaptive, mpirun -np 3: $(tail -3 "$work/log")"
  same_tables "$work/a" "$work/am" "adaptive: no MPI and mpirun -np 3"
fi

# Killed mid-way (-9, items in flight) and rerun: the tables of an uninterrupted run, the finished items reused.
cat >"$work/slow.json" <<'EOF'
{"scene": {"kind": "synthetic", "synthetic": {"mean": 5, "std": 1, "sleep_s": 0.15}},
 "conditions": {"list": [{"synthetic.mean": 5}, {"synthetic.mean": 7}]},
 "replicates": {"policy": "fixed", "count": 5}}
EOF
"$test_bin" study "$work/slow.json" --out "$work/full" --threads 1 >/dev/null 2>&1 || fail "uninterrupted slow study"
"$test_bin" study "$work/slow.json" --out "$work/killed" --threads 1 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 500); do [ "$(ls "$work/killed/items" 2>/dev/null | wc -l)" -ge 3 ] && break; sleep 0.01; done
kill -9 $pid 2>/dev/null || fail "the study ended before it could be killed"
wait $pid 2>/dev/null  # bash reports the kill; the rest of the test is quiet
[ ! -e "$work/killed/items.csv" ] || fail "the killed study had already finished"
"$test_bin" study "$work/slow.json" --out "$work/killed" --threads 1 >"$work/log" 2>&1 || fail "rerun after kill: $(tail -2 "$work/log")"
grep -Eq "10 items \(0 failed, [3-9] reused\)" "$work/log" || fail "rerun after kill did not reuse the finished items: $(tail -1 "$work/log")"
same_tables "$work/full" "$work/killed" "killed and rerun vs uninterrupted"
[ -z "$(ls -a "$work/killed/items" | grep partial)" ] || fail "a killed item's partial directory was left: $(ls -a "$work/killed/items")"
# Killed inside an item (checkpoints every sample or so here; by default every 10 minutes): the rerun continues
# the item from its checkpoint, and every item's curve and cracks equal those of the uninterrupted smoke study.
"$bin" study "$smoke" --out "$work/ck" --threads 1 --checkpoint-minutes 0.00001 >/dev/null 2>&1 &
pid=$!
for _ in $(seq 3000); do compgen -G "$work/ck/items/.partial-*/checkpoint.bin" >/dev/null && break; sleep 0.01; done
kill -9 $pid 2>/dev/null || fail "the checkpointed study ended before it could be killed"
wait $pid 2>/dev/null
compgen -G "$work/ck/items/.partial-*/checkpoint.bin" >/dev/null || fail "no item checkpoint: $(ls -a "$work/ck/items")"
"$bin" study "$smoke" --out "$work/ck" --threads 1 >"$work/log" 2>&1 || fail "rerun after a kill inside an item: $(tail -2 "$work/log")"
grep -Eq "^study: condition_[12]_seed_[12] done \(resumed from sample [1-9][0-9]*\)" "$work/log" ||
  fail "no item continued from its checkpoint: $(cat "$work/log")"
same_tables "$work/s2" "$work/ck" "killed inside an item and rerun vs uninterrupted"
for item in "$work"/s2/items/condition_*; do
  for f in curve.csv cracks.csv; do
    cmp -s "$item/$f" "$work/ck/items/$(basename "$item")/$f" || fail "resumed study: $(basename "$item")/$f differs"
  done
done
[ -z "$(ls -a "$work/ck/items" | grep partial)" ] || fail "a resumed item's directory was left: $(ls -a "$work/ck/items")"
grep -q '"resumed_from_sample": [1-9]' "$work"/ck/items/condition_*/summary.json || fail "no summary records the resume"
if [ $with_mpi -eq 1 ]; then
  # The same under mpirun, stopped as a batch system stops a job (SIGTERM to mpirun, which gives its ranks about a
  # second), rerun on 3 ranks: the tables of an uninterrupted run on one machine.
  sed 's/"count": 5/"count": 8/; s/"sleep_s": 0.15/"sleep_s": 0.4/' "$work/slow.json" >"$work/slower.json"
  "$test_bin" study "$work/slower.json" --out "$work/mfull" --threads 2 >/dev/null 2>&1 || fail "uninterrupted slower study"
  "${mpi[@]}" -np 3 "$test_bin" study "$work/slower.json" --out "$work/mkilled" >/dev/null 2>&1 &
  pid=$!
  for _ in $(seq 1000); do [ "$(ls "$work/mkilled/items" 2>/dev/null | wc -l)" -ge 2 ] && break; sleep 0.01; done
  kill -TERM $pid 2>/dev/null || fail "mpirun ended before it could be stopped"
  wait $pid 2>/dev/null
  [ ! -e "$work/mkilled/items.csv" ] || fail "the stopped MPI study had already finished"
  n_items=$(ls "$work/mkilled/items" | wc -l)
  sleep 1
  [ "$(ls "$work/mkilled/items" | wc -l)" -eq "$n_items" ] || fail "ranks went on after mpirun was stopped"
  "${mpi[@]}" -np 3 "$test_bin" study "$work/slower.json" --out "$work/mkilled" >"$work/log" 2>&1 || fail "MPI rerun after stop: $(tail -2 "$work/log")"
  grep -Eq "16 items \(0 failed, ([2-9]|1[0-5]) reused\)" "$work/log" || fail "MPI rerun did not reuse the finished items: $(tail -1 "$work/log")"
  same_tables "$work/mfull" "$work/mkilled" "MPI: stopped and rerun vs uninterrupted (no MPI)"
fi

# A bad override fails the items of its condition (recorded in items.csv, exit 3); the others run.
cat >"$work/bad_item.json" <<EOF
{"scene": "$src_abs/data/scenes/dem_tension.json",
 "set": ["specimen.width_mm=0.2", "specimen.height_mm=0.4", "specimen.growth_steps=2000", "specimen.relax_steps=500",
         "loading.quasi_static_check=false", "output.frame_every_samples=0"],
 "conditions": {"list": [{"loading.speed_m_per_s": 0.1}, {"loading.speed_m_per_s": -1}]}}
EOF
"$bin" study "$work/bad_item.json" --out "$work/bi" --threads 2 >/dev/null 2>"$work/err"
[ $? -eq 3 ] || fail "a failed item: expected exit 3 ($(cat "$work/err"))"
python3 - "$work/bi/items.csv" <<'EOF' || fail "the failed item's row: $(cat "$work/bi/items.csv")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["status"] for r in rows] == ["ok", "failed"], rows
assert rows[0]["tensile_strength_MPa"] != "" and rows[1]["tensile_strength_MPa"] == ""
assert "loading.speed_m_per_s = -1" in rows[1]["error"], rows[1]["error"]
EOF
# Rerun beside the finished item with a condition whose override cannot apply (a key under a text): the
# finished item is reused and the new condition's item fails; the study itself does not.
sed 's/{"loading.speed_m_per_s": -1}]/{"loading.speed_m_per_s": -1}, {"material.base.grade": 2}]/' "$work/bad_item.json" >"$work/bad_item2.json"
"$bin" study "$work/bad_item2.json" --out "$work/bi" --threads 2 >"$work/log" 2>"$work/err"
[ $? -eq 3 ] || fail "an override that cannot apply: expected exit 3 ($(cat "$work/err"))"
grep -q "3 items (2 failed, 1 reused)" "$work/log" || fail "an override that cannot apply: $(tail -2 "$work/log")"

# A record (issue 41): a row per finished item with its condition's tags, written as each finishes; a rerun
# into another directory (the first one lost with its machine) reuses every recorded item, runs none and leaves
# the record as it was; a condition that changes runs again and adds its rows; under mpirun the same rows.
record_study() {  # record_study <file> <second speed>
  cat >"$1" <<JSON
{"scene": "$src_abs/data/scenes/dem_tension.json",
 "set": ["specimen.width_mm=0.2", "specimen.height_mm=0.4", "specimen.growth_steps=2000", "specimen.relax_steps=500",
         "loading.quasi_static_check=false", "output.frame_every_samples=0"],
 "conditions": {"list": [{"tags": {"grip": "slow", "rate": 1}, "loading.speed_m_per_s": 0.1},
                         {"tags": {"grip": "fast", "rate": 2}, "loading.speed_m_per_s": $2}]},
 "replicates": {"policy": "fixed", "count": 2},
 "record": {"file": "results/rec.csv", "results": ["tensile_strength_MPa", "no_such_result"]}}
JSON
}
mkdir -p "$work/rec"
record_study "$work/rec/study.json" 0.2
"$bin" study "$work/rec/study.json" --out "$work/rec_a" --threads 2 >"$work/log" 2>"$work/err" || fail "record study: $(cat "$work/err")"
rec="$work/rec/results/rec.csv"
[ -s "$rec" ] || fail "no record written"
head -1 "$rec" | grep -qx "condition,grip,rate,seed,tensile_strength_MPa,no_such_result,cpu_time_s,wall_time_s,threads,host,kerf_version,git_commit,date,scene_fnv1a64" ||
  fail "record header: $(head -1 "$rec")"
python3 - "$rec" "$work/rec_a/items.csv" <<'EOF' || fail "the record does not hold the items' results"
import csv, sys
rec = list(csv.DictReader(open(sys.argv[1])))
items = {(r["condition"], r["seed"]): r for r in csv.DictReader(open(sys.argv[2]))}
assert len(rec) == 4, rec
assert [(r["condition"], r["grip"], r["rate"], r["seed"]) for r in rec] == \
    [("1", "slow", "1", "1"), ("1", "slow", "1", "2"), ("2", "fast", "2", "1"), ("2", "fast", "2", "2")], rec
for r in rec:
    assert float(r["tensile_strength_MPa"]) == float(items[(r["condition"], r["seed"])]["tensile_strength_MPa"]), r
    assert r["no_such_result"] == "" and float(r["cpu_time_s"]) > 0 and r["threads"] == "1", r
    assert len(r["scene_fnv1a64"]) == 16 and r["kerf_version"] and r["date"], r
assert len({r["scene_fnv1a64"] for r in rec}) == 4
EOF
cp "$rec" "$work/rec_first.csv"
"$bin" study "$work/rec/study.json" --out "$work/rec_b" --threads 2 >"$work/log" 2>"$work/err" || fail "record rerun: $(cat "$work/err")"
grep -q "study: 4 items (0 failed, 4 reused)" "$work/log" || fail "record rerun did not reuse every item: $(cat "$work/log")"
[ ! -e "$work/rec_b/items/condition_1_seed_1" ] || fail "record rerun ran an item"
cmp -s "$rec" "$work/rec_first.csv" || fail "record rerun changed the record: $(diff "$rec" "$work/rec_first.csv" | head -5)"
same_means() { grep tensile_strength "$1/conditions.csv" | cut -d, -f1-6; }
diff <(same_means "$work/rec_a") <(same_means "$work/rec_b") >/dev/null || fail "record rerun: other means: $(cat "$work/rec_b/conditions.csv")"
record_study "$work/rec/study.json" 0.3
"$bin" study "$work/rec/study.json" --out "$work/rec_c" --threads 2 >"$work/log" 2>"$work/err" || fail "record, changed condition: $(cat "$work/err")"
grep -q "study: 4 items (0 failed, 2 reused)" "$work/log" || fail "a changed condition: $(cat "$work/log")"
[ "$(tail -n +2 "$rec" | wc -l)" -eq 6 ] || fail "a changed condition's rows were not added: $(cat "$rec")"
if [ "$with_mpi" = 1 ]; then
  record_study "$work/rec/study.json" 0.2
  rm "$rec"
  "${mpi[@]}" -np 3 "$bin" study "$work/rec/study.json" --out "$work/rec_mpi" >"$work/log" 2>"$work/err" || fail "record under mpirun: $(cat "$work/err")"
  diff <(cut -d, -f1-5,14 "$rec") <(cut -d, -f1-5,14 "$work/rec_first.csv") >/dev/null ||
    fail "record under mpirun differs: $(diff "$rec" "$work/rec_first.csv" | head -5)"
fi

# Bad study files: exit 2, one line naming the key.
bad() {  # bad <expected text> <study JSON>
  printf '%s\n' "$2" >"$work/bad.json"
  expect_input_error "$1" study "$work/bad.json" --out "$work/bad_out"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "not one line for $2: $(cat "$work/err")"
}
tension="\"scene\": \"$src_abs/data/scenes/dem_tension.json\""
bad "kerf-dem: error: scene = (missing)" '{"replicates": {"count": 2}}'
expect_input_error "kerf-dem: error: study = $work/none.json: expected a study JSON file" study "$work/none.json" --out "$work/bad_out"
bad "kerf-dem: error: scene = nowhere.json: expected an existing scene file" '{"scene": "nowhere.json"}'
bad "did you mean 'conditions'" "{$tension, \"condtions\": {}}"
bad "kerf-dem: error: conditions = " "{$tension, \"conditions\": {\"grid\": {\"a.b\": [1]}, \"list\": [{\"a.b\": 1}]}}"
bad "kerf-dem: error: conditions.grid.loading.speed_m_per_s = []: expected a non-empty list" "{$tension, \"conditions\": {\"grid\": {\"loading.speed_m_per_s\": []}}}"
bad "kerf-dem: error: conditions.list[1] = 3: expected an object" "{$tension, \"conditions\": {\"list\": [{\"a.b\": 1}, 3]}}"
bad "kerf-dem: error: replicates.policy = sometimes" "{$tension, \"replicates\": {\"policy\": \"sometimes\"}}"
bad "kerf-dem: error: replicates.count = 0" "{$tension, \"replicates\": {\"count\": 0}}"
bad "kerf-dem: error: replicates.min_count = (given): expected only with \"policy\": \"adaptive\"" "{$tension, \"replicates\": {\"min_count\": 3}}"
bad "kerf-dem: error: replicates.results = (missing)" "{$tension, \"replicates\": {\"policy\": \"adaptive\"}}"
bad "kerf-dem: error: replicates.max_count = 3: expected at least min_count (5)" "{$tension, \"replicates\": {\"policy\": \"adaptive\", \"results\": [\"x\"], \"min_count\": 5, \"max_count\": 3}}"
bad "kerf-dem: error: replicates.target_relative_sem_percent = 0" "{$tension, \"replicates\": {\"policy\": \"adaptive\", \"results\": [\"x\"], \"target_relative_sem_percent\": 0}}"
bad "kerf-dem: error: set = 3" "{$tension, \"set\": [3]}"
bad "kerf-dem: error: record.results = []" "{$tension, \"record\": {\"file\": \"r.csv\", \"results\": []}}"
bad "kerf-dem: error: conditions.list[0].tags = 3" "{$tension, \"conditions\": {\"list\": [{\"tags\": 3}]}}"
bad "kerf-dem: error: scene.specimen.radius_min_um = -1" "{$tension, \"set\": [\"specimen.radius_min_um=-1\"]}"
bad "kerf-dem: error: scene.kind = bending" "{\"scene\": {\"kind\": \"bending\"}}"
bad "kerf-dem: error: scene.kind = synthetic: expected one of 'specimen', 'tension', 'compression', 'calibrate', 'cut', 'calibrate_cut', 'toughness'" \
  '{"scene": {"kind": "synthetic"}}'
[ ! -e "$work/bad_out/items.csv" ] || fail "a rejected study wrote output"
# An output directory that cannot be written: exit 4 before any work.
"$bin" study "$smoke" --out /proc/kerf_study >/dev/null 2>"$work/err"
[ $? -eq 4 ] || fail "unwritable --out: expected exit 4 ($(cat "$work/err"))"

# The study keys are in kerf-dem keys (and so in docs/dem-keys.md: dem_keys_cli.sh).
"$bin" keys study.replicates | grep -q '`target_relative_sem_percent` | % |' || fail "keys study.replicates"
"$bin" keys study | grep -q '`conditions.grid`' || fail "keys study"
echo "dem study cli: ok"
