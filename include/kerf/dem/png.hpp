#pragma once
// A PNG picture of a specimen (PLplot, cairo driver): disks in grey outline, cracks as short segments
// along the broken interface, red for tension and blue for shear. Written whole or not at all.
//
//   write_specimen_png("out/specimen.png", sim, "compression, final state");
#include <filesystem>
#include <string>

#include "kerf/dem/simulation.hpp"

namespace kerf::dem {

void write_specimen_png(const std::filesystem::path& path, const Simulation& sim, const std::string& title);

}  // namespace kerf::dem
