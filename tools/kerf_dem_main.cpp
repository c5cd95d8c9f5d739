// kerf-dem: the command line of tools/kerf_dem.cpp with the library's scene kinds, no others.
#include "kerf_dem.hpp"

int main(int argc, char** argv) {
  return kerf::dem::kerf_dem_main(argc, argv);
}
