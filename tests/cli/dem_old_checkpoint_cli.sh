#!/usr/bin/env bash
# Checkpoints of earlier kerf-dems still resume, to the bit (issue 39 item 4): tests/dem/reference/kerfdem6_cut
# holds a checkpoint written by kerf 4a34e1f (its engine state "KERFDEM6" stores the laws as raw variants, index
# included) of a tiny cut with the parallel bond, the second law of that build's list, and a friction coefficient
# and a tensile strength of its own. Resumed by this build, the cut's forces and cracks are those of an
# uninterrupted run of the same scene; an engine state of an unknown version is refused with exit 3 naming it.
# Made with: kerf-dem run scene.json --threads 1 --checkpoint-every 3 --out DIR, killed (-9) at its first
# checkpoint (kerf 4a34e1f, x86-64).
# Usage: dem_old_checkpoint_cli.sh <dir of built programs> <source dir>
source "$(dirname "$0")/lib/dem_common.sh" "$@"

# resumes_as_uninterrupted FIXTURE NAME BUILD: the fixture's checkpoint resumed (in a copy, as WORK/NAME) gives the
# forces and cracks of an uninterrupted run of its scene.
resumes_as_uninterrupted() {
  local fixture=$1 name=$2 build=$3
  cp -r "$fixture" "$work/$name"
  chmod -R u+w "$work/$name"
  "$bin" resume "$work/$name" --threads 1 >/dev/null 2>"$work/err" || fail "resume of the $build checkpoint: $(cat "$work/err")"
  "$bin" run "$fixture/scene.json" --threads 1 --out "$work/$name-full" >/dev/null 2>"$work/err" || fail "run: $(cat "$work/err")"
  for f in forces.csv cracks.csv; do
    cmp -s "$work/$name-full/$f" "$work/$name/$f" || fail "$f resumed from the $build checkpoint differs from an uninterrupted run"
  done
}

fixture="$src/tests/dem/reference/kerfdem6_cut"
resumes_as_uninterrupted "$fixture" old 4a34e1f
grep -q '"bond_model": "parallel_bond"' "$work/old/summary.json" || fail "the resumed cut's material is not the parallel bond"

# A checkpoint of the build before Weibull joint strengths (kerf a0ff3ea: engine state "KERFDEM8", its laws' records
# without the Weibull keys, no strength factors) of a tiny cut with the softening flat joint (element damage): resumed
# by this build, the forces and cracks of an uninterrupted run. Made as the one above.
resumes_as_uninterrupted "$src/tests/dem/reference/kerfdem8_cut" old8 a0ff3ea

# The engine state's tag made "KERFDEM5" (the file's checksum made right): refused, naming the versions.
python3 - "$fixture/checkpoint.bin" "$work/bad/checkpoint.bin" <<'PY'
import os, sys, zlib
b = bytearray(open(sys.argv[1], "rb").read())
at = b.find(b"KERFDEM6")
assert at > 0
b[at:at + 8] = b"KERFDEM5"
body = bytes(b[:-4])
os.makedirs(os.path.dirname(sys.argv[2]), exist_ok=True)
open(sys.argv[2], "wb").write(body + zlib.crc32(body).to_bytes(4, "little"))
PY
"$bin" resume "$work/bad" --threads 1 >/dev/null 2>"$work/err"
status=$?
[ $status -eq 3 ] || fail "an engine state of KERFDEM5: exit $status (expected 3): $(cat "$work/err")"
grep -qF "another kerf-dem version (KERFDEM5, this one reads KERFDEM9 or KERFDEM8 or KERFDEM7 or KERFDEM6)" "$work/err" ||
  fail "the refusal does not name the versions: $(cat "$work/err")"
echo "dem_old_checkpoint_cli: ok"
