#!/usr/bin/env bash
# A compiler and linker launcher that logs the CPU time (user + system, children included) of every command CMake
# runs through it: one line "SECONDS OUTPUT" per object file or program, appended to LOG. Used by
# scripts/build-cpu-time.sh (docs/performance.md, "Build time"); CPU seconds, unlike wall time, hardly depend on
# what else the machine is doing.
#
#   cmake ... -DCMAKE_CXX_COMPILER_LAUNCHER="$PWD/scripts/cpu-time-launcher.sh;LOG" \
#             -DCMAKE_CXX_LINKER_LAUNCHER="$PWD/scripts/cpu-time-launcher.sh;LOG"
log=$1
shift
out=?
prev=
for arg in "$@"; do
  [ "$prev" = -o ] && out=$arg
  prev=$arg
done
times=$(mktemp)
/usr/bin/time -f "%U %S" -o "$times" "$@"
rc=$?
tail -n 1 "$times" | awk -v out="$out" '{ printf "%.2f %s\n", $1 + $2, out }' >>"$log"
rm -f "$times"
exit $rc
