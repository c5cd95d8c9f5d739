#!/usr/bin/env bash
# cmake --install of this build into a fresh prefix, then what a user of the install sees:
# 1. a tiny downstream CMake project finds the package (find_package(kerf 0.2)), links kerf::analytic and kerf::dem,
#    builds and predicts the bundled p-SiC scene with the library;
# 2. the installed kerf-forces and kerf-dem print the version and read the installed data (share/kerf/data), also
#    once the prefix is moved elsewhere: a material added there is listed, the source tree's data is not used.
# Usage: find_package.sh BUILD_DIR SOURCE_DIR CMAKE_GENERATOR CXX_COMPILER
set -euo pipefail
build="$1" src="$2" generator="$3" cxx="$4"
fail() { echo "FAIL: $*" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
unset KERF_DATA_DIR KERF_MATERIAL_PATH

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>&1 ||
  { cat "$work/install.log"; fail "cmake --install"; }
for f in bin/kerf-forces bin/kerf-dem include/kerf/version.hpp include/kerf/analytic/kinds/evaluate.hpp \
    lib/cmake/kerf/kerfConfig.cmake lib/cmake/kerf/kerfConfigVersion.cmake share/kerf/data/materials/psic.json; do
  [ -e "$work/prefix/$f" ] || fail "not installed: $f"
done

mkdir -p "$work/app"
cat >"$work/app/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(kerf_downstream LANGUAGES CXX)
find_package(kerf 0.2 REQUIRED)
add_executable(app main.cpp)
target_compile_features(app PRIVATE cxx_std_20)
target_link_libraries(app PRIVATE kerf::analytic kerf::dem)
file(WRITE ${CMAKE_BINARY_DIR}/data_dir.txt "${kerf_DATA_DIR}")
CMAKE
cat >"$work/app/main.cpp" <<'CPP'
#include <kerf/analytic/kinds/evaluate.hpp>
#include <kerf/dem/scene.hpp>
#include <kerf/json_reader.hpp>
#include <kerf/version.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::printf("%s\n", kerf::version_line("app").c_str());
  std::printf("dem kinds %zu\n", kerf::dem::scene_kind_names().size());
  kerf::MaterialCache cache;
  for (const auto& [name, text] : kerf::evaluate_scene_columns(kerf::read_json_file(argv[1]), &cache)) {
    if (name == "cutting_force_N") std::printf("cutting_force_N %s\n", text.c_str());
  }
}
CPP
cmake -S "$work/app" -B "$work/app/build" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/app.log" 2>&1 || { cat "$work/app.log"; fail "downstream configure"; }
cmake --build "$work/app/build" >>"$work/app.log" 2>&1 || { cat "$work/app.log"; fail "downstream build"; }
data="$(cat "$work/app/build/data_dir.txt")"
[ "$data" = "$work/prefix/share/kerf/data" ] || fail "kerf_DATA_DIR is '$data'"
KERF_DATA_DIR="$data" "$work/app/build/app" "$data/scenes/psic_liu_li.json" >"$work/app.out" ||
  { cat "$work/app.out"; fail "downstream app"; }
grep -Eq '^app [0-9]+\.[0-9]+\.[0-9]+' "$work/app.out" || fail "app: no version line"
grep -Eq '^dem kinds [1-9]' "$work/app.out" || fail "app: no DEM scene kinds"
grep -Eq '^cutting_force_N [0-9.eE+-]+$' "$work/app.out" || { cat "$work/app.out"; fail "app: no cutting force"; }

# The installed programs read the installed data, wherever the prefix lies.
mv "$work/prefix" "$work/moved"
cp "$work/moved/share/kerf/data/materials/psic.json" "$work/moved/share/kerf/data/materials/zz_installed_only.json"
cd "$work"
for program in kerf-forces kerf-dem; do
  "$work/moved/bin/$program" --version | grep -Eq "^$program [0-9]" || fail "$program --version"
done
"$work/moved/bin/kerf-forces" materials >"$work/materials" 2>&1 ||
  { cat "$work/materials"; fail "kerf-forces materials"; }
grep -q zz_installed_only "$work/materials" ||
  { cat "$work/materials"; fail "kerf-forces does not read share/kerf/data"; }
"$work/moved/bin/kerf-forces" predict "$work/moved/share/kerf/data/scenes/psic_liu_li.json" --csv "$work/p.csv" \
  >"$work/predict" 2>&1 || { cat "$work/predict"; fail "installed kerf-forces predict"; }
echo "installed, found by find_package(kerf), built against, and the installed programs read their own data"
