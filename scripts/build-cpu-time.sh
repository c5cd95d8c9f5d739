#!/usr/bin/env bash
# A clean build of kerf whose every compile and link is timed in CPU seconds (scripts/cpu-time-launcher.sh), then
# the seconds summed by folder, compiles and links apart, and the slowest translation units. The load average is
# printed before and after; the wall time of `cmake --build -j JOBS` is printed too, comparable only on a quiet
# machine. docs/performance.md, "Build time".
#
#   bash scripts/build-cpu-time.sh BUILD_DIR [JOBS [CMAKE_ARGS...]]   # BUILD_DIR is removed first
#   bash scripts/build-cpu-time.sh --summary LOG                      # the summary of an earlier build's log
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
summary() {  # LOG: "SECONDS OUTPUT" lines, OUTPUT relative to the build directory
  awk '{
      split($2, part, "/"); folder = (part[2] == "" ? "." : part[1]);
      kind = ($2 ~ /\.(o|gch)$/) ? "compile" : "link";
      key = folder " " kind; sum[key] += $1; n[key]++; total[kind] += $1; all += $1
    }
    END {
      for (k in sum) printf "%-24s %8.1f s  %4d\n", k, sum[k], n[k] | "sort";
      close("sort");
      printf "%-24s %8.1f s\n%-24s %8.1f s\n%-24s %8.1f s\n", "compile (all)", total["compile"],
        "link (all)", total["link"], "total", all
    }' "$1"
  echo "slowest 25:"
  sort -rn "$1" | head -n 25
}
if [ "${1:-}" = --summary ]; then
  summary "$2"
  exit 0
fi
build=$1
jobs=${2:-2}
shift $(( $# >= 2 ? 2 : 1 ))
launcher="$root/scripts/cpu-time-launcher.sh"
log="$(cd "$(dirname "$build")" && pwd)/$(basename "$build")/cpu-time.log"
rm -rf "$build"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher;$log" "-DCMAKE_CXX_LINKER_LAUNCHER=$launcher;$log" "$@" >/dev/null
: >"$log"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)  $(date -u +%FT%TZ)"
start=$(date +%s)
( cd "$build" && cmake --build . -j "$jobs" >build.out 2>&1 ) || { tail -n 40 "$build/build.out"; exit 1; }
echo "wall: $(( $(date +%s) - start )) s for cmake --build -j $jobs"
echo "load after:  $(cut -d' ' -f1-3 /proc/loadavg)  $(date -u +%FT%TZ)"
summary "$log"
