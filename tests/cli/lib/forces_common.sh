# Shared prelude of the kerf-forces error tests (sourced, not a test itself): $bin, $src, a scratch $tmp,
# $failures and expect. Usage in a test: source "$(dirname "$0")/lib/forces_common.sh" "$@"
set -u
bin="$1/kerf-forces"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
# expect_of NAME PROGRAM STATUS PATTERN -- ARGS...: PROGRAM's status, the pattern on stderr, one 'NAME: error:'
# line there (issue 24), and no NaN or inf in what was printed. expect: the same for kerf-forces.
expect_of() {
  local name=$1 program=$2 status=$3 pattern=$4; shift 5
  "$program" "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" -ne "$status" ] || ! grep -qF -- "$pattern" "$tmp/err"; then
    echo "FAIL: $name $* -> status $got (want $status), stderr: $(head -c 400 "$tmp/err")"; failures=$((failures + 1))
  fi
  if [ "$(wc -l <"$tmp/err")" -ne 1 ] || ! grep -q "^$name: error: " "$tmp/err"; then
    echo "FAIL: $name $*: not one '$name: error:' line: $(head -c 400 "$tmp/err")"; failures=$((failures + 1))
  fi
  if grep -qiE "nan|inf( |$)" "$tmp/out"; then echo "FAIL: a non-finite number in the output of $*"; failures=$((failures + 1)); fi
}
expect() { expect_of kerf-forces "$bin" "$@"; }
