#!/usr/bin/env bash
# pip install . into a fresh venv, as README's "Install" says (no package index: the Debian packages through
# --system-site-packages), then: kerf-forces and kerf-dem on the venv's PATH, `import kerf` from the venv (not the
# build tree) reading the installed data, and the Python tests (tests/python) against the installed package.
# The CMake build directory of the install is kept in BUILD_DIR/pip-venv (the first run builds everything, about
# as long as a first build; later runs rebuild what changed).
# Usage: pip_venv.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1" src="$2"
fail() { echo "FAIL: $*" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
unset PYTHONPATH KERF_DATA_DIR KERF_MATERIAL_PATH

/usr/bin/python3 -m venv --system-site-packages "$work/V"
KERF_PIP_BUILD_DIR="$build/pip-venv" "$work/V/bin/pip" install --no-build-isolation --no-index "$src" \
  >"$work/pip.log" 2>&1 || { tail -40 "$work/pip.log"; fail "pip install"; }

export PATH="$work/V/bin:$PATH"
cd "$work"
for program in kerf-forces kerf-dem; do
  [ "$(command -v "$program")" = "$work/V/bin/$program" ] || fail "$program is not the venv's"
  "$program" --version | grep -Eq "^$program [0-9]+\.[0-9]+\.[0-9]+" || fail "$program --version"
done
kerf-forces predict "$work/V/share/kerf/data/scenes/psic_liu_li.json" >/dev/null || fail "installed kerf-forces predict"
python - "$work/V" <<'PY' || fail "import kerf from the venv"
import pathlib, sys
import kerf
venv = pathlib.Path(sys.argv[1])
assert pathlib.Path(kerf.__file__).is_relative_to(venv), kerf.__file__
assert kerf.scene_path("psic_liu_li").is_relative_to(venv / "share" / "kerf" / "data"), kerf.scene_path("psic_liu_li")
assert kerf.predict(kerf.scene_path("psic_liu_li"))["cutting_force_N"] > 0
import kerf.stats, kerf.records  # the pure-Python submodules, in the folder kerf/ beside the module
assert pathlib.Path(kerf.stats.__file__).is_relative_to(venv), kerf.stats.__file__
print("kerf", kerf.__version__, "from", kerf.__file__)
PY
KERF_TOOLS="$work/V/bin" OMP_NUM_THREADS=1 python -m pytest -q -rs -p no:cacheprovider "$src/tests/python" ||
  fail "the Python tests against the installed package"
