#!/usr/bin/env bash
# Installs kerf's build and test dependencies from Debian 12 packages, only those that are missing.
# Needs root (or sudo) the first time; does nothing when everything is present. With --sanitize also clang,
# its OpenMP and its sanitizer and libFuzzer runtimes (scripts/sanitize.sh, CI's second step). With --long also
# ParaView (its pvpython, about 100 MB) and a virtual X server for the long checks (tests/long/vtk_paraview.sh;
# scripts/test.sh --long passes it).
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libgsl-dev libboost-dev libfmt-dev
  catch2 nlohmann-json3-dev libcli11-dev libplplot-dev plplot-driver-cairo python3
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib python3-vtk9
  libopenmpi-dev openmpi-bin)
case "${1:-}" in
  "") ;;
  --sanitize) packages+=(clang libomp-dev libclang-rt-dev) ;;
  --long) packages+=(paraview python3-paraview xvfb xauth) ;;  # python3-paraview: pvpython
  *) echo "install-deps.sh: error: option = $1: expected none, --sanitize or --long" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "kerf: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
