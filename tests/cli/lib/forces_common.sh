# Shared prelude of the kerf-forces error tests (sourced, not a test itself): $bin, $src, a scratch $tmp,
# $failures and expect. Usage in a test: source "$(dirname "$0")/lib/forces_common.sh" "$@"
set -u
bin="$1/kerf-forces"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
# expect STATUS PATTERN -- ARGS...: the status, the pattern on stderr, one 'kerf-forces: error:' line there
# (issue 24), and no NaN or inf in what was printed.
expect() {
  local status=$1 pattern=$2; shift 3
  "$bin" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -ne "$status" ] || ! grep -qF -- "$pattern" "$tmp/err"; then
    echo "FAIL: kerf-forces $* -> status $got (want $status), stderr: $(head -c 400 "$tmp/err")"; failures=$((failures + 1))
  fi
  if [ "$(wc -l <"$tmp/err")" -ne 1 ] || ! grep -q "^kerf-forces: error: " "$tmp/err"; then
    echo "FAIL: kerf-forces $*: not one 'kerf-forces: error:' line: $(head -c 400 "$tmp/err")"; failures=$((failures + 1))
  fi
  if grep -qiE "nan|inf( |$)" "$tmp/out"; then echo "FAIL: a non-finite number in the output of $*"; failures=$((failures + 1)); fi
}
