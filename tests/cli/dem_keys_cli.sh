#!/usr/bin/env bash
# kerf-dem keys: the key tables in docs/dem-keys.md are the ones generated from the field tables (regenerate:
# build/tools/kerf-dem keys, pasted between the markers); an unknown section lists the valid ones. And one
# error prefix across both programs: "kerf-dem: error:" / "kerf-forces: error:" for input errors, model
# errors and command-line parse errors, exit status 2 for bad input.
# Usage: dem_keys_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"
forces="$1/kerf-forces"

"$bin" keys >"$work/keys.md" || fail "kerf-dem keys failed"
sed -n '/<!-- kerf-dem keys: begin -->/,/<!-- kerf-dem keys: end -->/p' "$src/docs/dem-keys.md" | sed '1d;$d' >"$work/doc.md"
diff -u "$work/doc.md" "$work/keys.md" >"$work/diff" || fail "docs/dem-keys.md's key tables differ from kerf-dem keys: $(head -20 "$work/diff")"
for section in material specimen engine loading cut tool grooves calibration calibration.targets toughness output study study.replicates; do
  grep -q "^#### \`$section\`" "$work/keys.md" || fail "no key table for $section"
done
"$bin" keys cut | grep -q '`depth_of_cut_mm` | mm |' || fail "keys cut: no depth_of_cut_mm row"
# Every registered law's keys are in the material's reference (from a file: grep -q may close a pipe early, and
# pipefail would count the writer's SIGPIPE as a failure).
"$bin" keys material >"$work/material.md" || fail "kerf-dem keys material failed"
grep -q '`tensile_strength_MPa` | MPa |' "$work/material.md" || fail "keys material: no tensile_strength_MPa row"
for law in linear flat_joint parallel_bond softening_flat_joint; do
  grep -q "^\`$law\`: " "$work/material.md" || fail "keys material: no table for the law $law"
done

"$bin" keys specimn >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "unknown section: expected exit 2"
grep -q "^kerf-dem: error: SECTION = specimn: .*did you mean 'specimen'" "$work/err" || fail "unknown section: $(cat "$work/err")"

# Input errors, parse errors, model errors: one prefix per program, exit 2 (input) or 3 (model).
"$bin" run --bogus >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "kerf-dem parse error: expected exit 2"
grep -q "^kerf-dem: error: " "$work/err" || fail "kerf-dem parse error prefix: $(cat "$work/err")"
"$forces" predict --bogus >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "kerf-forces parse error: expected exit 2"
grep -q "^kerf-forces: error: " "$work/err" || fail "kerf-forces parse error prefix: $(cat "$work/err")"
echo '{"kind": "cutt"}' >"$work/bad.json"
"$bin" run "$work/bad.json" --out "$work/out" >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "unknown kind: expected exit 2"
grep -q "^kerf-dem: error: kind = cutt: expected one of 'specimen', 'tension', 'compression', 'calibrate', 'cut', 'calibrate_cut', 'toughness' (did you mean 'cut'?)" "$work/err" ||
  fail "unknown kind: $(cat "$work/err")"
"$forces" predict "$work/bad.json" >/dev/null 2>"$work/err"
[ $? -eq 2 ] || fail "kerf-forces input error: expected exit 2"
grep -q "^kerf-forces: error: " "$work/err" || fail "kerf-forces input error prefix: $(cat "$work/err")"
mkdir -p "$work/ckp" && printf KERFCKP2 >"$work/ckp/checkpoint.bin"
"$bin" resume "$work/ckp" >/dev/null 2>"$work/err"
[ $? -eq 3 ] || fail "truncated checkpoint: expected exit 3 (model error)"
grep -q "^kerf-dem: error: model .dem.: truncated checkpoint" "$work/err" || fail "model error prefix: $(cat "$work/err")"
echo "dem keys cli: ok"
