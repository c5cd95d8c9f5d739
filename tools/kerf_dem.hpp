#pragma once
// kerf-dem's command line as a function (tools/kerf_dem.cpp), so that a program can register scene kinds of its
// own (kerf/dem/scene.hpp: register_scene_kind) and then be kerf-dem: tools/kerf_dem_main.cpp is kerf-dem itself,
// tests/tools/kerf_dem_test_kinds.cpp the test suite's twin with its test kind.

namespace kerf::dem {

/// kerf-dem with these arguments (argv[0] the program): its exit status.
int kerf_dem_main(int argc, char** argv);

}  // namespace kerf::dem
