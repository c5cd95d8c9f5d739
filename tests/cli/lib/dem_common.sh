# Shared prelude of the kerf-dem CLI tests (sourced, not a test itself): $bin, $src, a scratch $work,
# fail and expect_input_error. Usage in a test: source "$(dirname "$0")/lib/dem_common.sh" "$@"
set -uo pipefail
bin="$1/kerf-dem"
src="$2"
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
