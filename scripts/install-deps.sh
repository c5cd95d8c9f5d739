#!/usr/bin/env bash
# Installs kerf's build and test dependencies from Debian 12 packages, only those that are missing.
# Needs root (or sudo) the first time; does nothing when everything is present. With --sanitize also clang,
# its OpenMP and its sanitizer and libFuzzer runtimes (scripts/sanitize.sh, CI's second step). With --long also
# ParaView (its pvpython, about 100 MB) and a virtual X server for the long checks (tests/long/vtk_paraview.sh;
# scripts/test.sh --long passes it). Python's VTK module comes from python3-vtk9 or, with --long, from
# python3-paraview, which ships the same `vtk` module and conflicts with python3-vtk9 (installing either removes the
# other): either one satisfies the quick suite, and --long asks for python3-paraview.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libgsl-dev libboost-dev libfmt-dev
  catch2 nlohmann-json3-dev libcli11-dev libplplot-dev plplot-driver-cairo python3
  python3-dev python3-pybind11 python3-numpy python3-pil python3-pytest python3-matplotlib
  python3-venv python3-setuptools python3-wheel
  libopenmpi-dev openmpi-bin
  clang-format)  # tests/cli/format_check.sh: the layout of the C++ files (.clang-format)
vtk=(python3-vtk9 python3-paraview)  # either gives Python's vtk; the first is installed when neither is
case "${1:-}" in
  "") ;;
  --sanitize) packages+=(clang libomp-dev libclang-rt-dev) ;;
  --long) packages+=(paraview xvfb xauth) vtk=(python3-paraview) ;;  # python3-paraview: pvpython, and vtk
  *) echo "install-deps.sh: error: option = $1: expected none, --sanitize or --long" >&2; exit 2 ;;
esac
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "${packages[@]}"; do
  installed "$p" || missing+=("$p")
done
have_vtk=""
for p in "${vtk[@]}"; do installed "$p" && have_vtk=1; done
[ -n "$have_vtk" ] || missing+=("${vtk[0]}")
[ ${#missing[@]} -eq 0 ] && exit 0
echo "kerf: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
