# Shared prelude of the kerf-dem CLI tests (sourced, not a test itself): $bin, $test_bin (kerf-dem with the test
# suite's own kinds, tests/tools/kerf_dem_test_kinds.cpp; from the third argument, the test programs' directory),
# $src, a scratch $work, fail and expect_input_error. Usage in a test: source "$(dirname "$0")/lib/dem_common.sh" "$@"
set -uo pipefail
bin="$1/kerf-dem"
src="$2"
test_bin="${3:-}/kerf-dem-test-kinds"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export KERF_DATA_DIR="$src/data"
fail() { echo "FAIL: $*" >&2; exit 1; }

expect_input_error() {  # expect_input_error <text expected on stderr> <args...>
  local want="$1"; shift
  "$bin" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "exit $rc (expected 2) for: $* ($(cat "$work/err"))"
  grep -qF -- "$want" "$work/err" || fail "stderr lacks '$want' for: $*: $(cat "$work/err")"
}

# kill_after_checkpoint <pid> <dir> [signal]: waits until the run <pid> has written <dir>/checkpoint.bin (up to
# 300 s, or until the run ends: on a loaded machine the first checkpoint can take many seconds), kills it (with
# the signal, default KILL) and waits for it, leaving its exit status in $killed_status; fails, saying which, if
# the run ended first or wrote no checkpoint.
kill_after_checkpoint() {
  local pid=$1 dir=$2 signal=${3:-KILL} start=$SECONDS
  until [ -e "$dir/checkpoint.bin" ] || ! kill -0 "$pid" 2>/dev/null || [ $((SECONDS - start)) -ge 300 ]; do
    sleep 0.01
  done
  kill -s "$signal" "$pid" 2>/dev/null || fail "the run ended before it could be killed ($dir)"
  wait "$pid" 2>/dev/null
  killed_status=$?
  [ -e "$dir/checkpoint.bin" ] || fail "no checkpoint in $dir after $((SECONDS - start)) s"
}

# expect_kill_resume_equal <full dir> <kill dir> "<files>" <run args...>: runs kerf-dem with the args and
# --out <kill dir> in the background, kills it (-9) once it has written a checkpoint, resumes it, and checks
# that each file equals the one in <full dir> (an uninterrupted run of the same args) and that no
# checkpoint is left.
expect_kill_resume_equal() {
  local full="$1" kill_dir="$2" files="$3"; shift 3
  "$bin" "$@" --out "$kill_dir" >/dev/null 2>&1 &
  local pid=$!
  kill_after_checkpoint $pid "$kill_dir"
  [ ! -e "$kill_dir/summary.json" ] || fail "the killed run had already finished: $*"
  "$bin" resume "$kill_dir" --threads 1 >/dev/null 2>"$work/err" || fail "resume: $(cat "$work/err")"
  local f
  for f in $files; do
    cmp -s "$full/$f" "$kill_dir/$f" || fail "resumed $f differs from the uninterrupted run: $*"
  done
  [ ! -e "$kill_dir/checkpoint.bin" ] || fail "checkpoint left after the finished run: $*"
}
